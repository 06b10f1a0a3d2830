"""An opened door met by a passing road user.

A door that opens stands out from the side of a vehicle that is not moving along, into the way of one that is:
the one moving along runs into it. So whatever the sentence makes its subject ("the front driver side door of
V2 opened and made contact with the passenger side of V1"), the striker is the other party, and what it met
is a side of the door's vehicle.
"""

from __future__ import annotations

import re

from sovarc.dsl.ir import Crash, CrashType

_V = r"(?:V\d)"
_DOOR = r"(?:[\w'-]+ ){0,6}?doors?\b"
# whose the door is: "V2's rear door", "the front passenger door of V2"
_TIED = re.compile(r"\b(?P<v>" + _V + r")'s " + _DOOR + r"|\bdoors? of (?:the )?(?P<w>" + _V + r")\b", re.I)
_ANY_DOOR = re.compile(r"\bdoors?\b", re.I)
_OPENED = re.compile(
    r"\b(?:opened|opens|opening|swung open|flung open|(?:was|were|been) open|open (?:[\w-]+ ){0,3}?doors?)\b", re.I
)
# "the passengers inside V2 opened the front doors", "V1 rider opened the rear door": who opened it is the
# last one named before the verb whose object is a door
_OPENED_DOOR = re.compile(r"\b(?:opened|opens|opening|swung open|flung open)\b (?:the |a |an |its |their )?" + _DOOR)


def _owner(sentence: str, before: list[str]) -> str | None:
    """Whose door the impact sentence names: tied to a participant in it, else the one the sentences up to it
    (`before`, the impact sentence last) say opened a door."""
    if m := _TIED.search(sentence):
        return m.group("v") or m.group("w")
    if not _ANY_DOOR.search(sentence):
        return None
    for said in reversed(before):
        if m := _OPENED_DOOR.search(said):
            named = re.findall(r"\b" + _V + r"\b", said[: m.start()])
            return named[-1] if named else None
    return None


def door_met(crash: Crash, sents: list[str], at: int) -> Crash:
    """The crash with the door's vehicle as the victim met on its side, when the impact sentence (index `at`)
    names a door that it or an earlier sentence says opened; else the crash as read."""
    if not 0 <= at < len(sents):
        return crash
    sentence = sents[at]
    owner = _owner(sentence, sents[: at + 1])
    if owner is None or not any(_OPENED.search(s) and _ANY_DOOR.search(s) for s in sents[: at + 1]):
        return crash
    others = [p for p in (crash.striker, crash.victim) if isinstance(p, str) and p != owner]
    others = others or [n for n in re.findall(r"\b" + _V + r"\b", sentence) if n != owner]
    if not others:
        return crash
    return Crash(CrashType.SIDE, others[0], owner)
