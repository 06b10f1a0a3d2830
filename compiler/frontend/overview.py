"""The overview: a narrative's opening summary names the collision's other party.

Fleet narratives open by saying who was in the collision ("A Waymo Autonomous Vehicle ... was in a collision
involving a passenger car on ..."), and then tell it with whatever words come to hand: "a vehicle approached
from behind", "the other vehicle made contact", or a part of it alone ("the ramp of the heavy truck made
contact"). The overview's road user is the partner, so where the telling names it without a kind, or not at
all, the overview says which road user and what kind it is.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.kinds import kind_named
from sovarc.compiler.frontend.sentences import sentences

# "was in a collision with / involving", "was involved in a collision / crash with"
SUMMARY = re.compile(r"\bcollision (?:with|involving)\b|\binvolved in a (?:collision|crash)\b", re.I)


def only_other(text: str, words_of: dict[str, str]) -> str | None:
    """The id of the one party besides V1 that `text` names, if only one is named."""
    others = [pid for pid in words_of if pid != "V1" and re.search(r"\b" + pid + r"\b", text)]
    return others[0] if len(others) == 1 else None


def overview_users(sents: list[str], users: re.Pattern[str]) -> list[re.Match[str]]:
    """The road users (matches of `users`) the first overview naming V1 names after its verb ("involving a
    passenger car"), unless it names them as several ("two passenger vehicles", which `users` does not match)."""
    for sentence in sents:
        if (said := SUMMARY.search(sentence)) and re.search(r"\bV1\b", sentence[: said.start()]):
            return list(users.finditer(sentence, said.end()))
    return []


def name_overview(text: str, words_of: dict[str, str], users: re.Pattern[str]) -> tuple[str, dict[str, str]]:
    """The one other party, told with no kind ("a vehicle", "the other vehicle"), is the road user the overview
    names, when it names one with a kind: that phrase there is the party's id, and its words say the kind."""
    pid = only_other(text, words_of)
    if pid is None or not pid.startswith("V") or kind_named(words_of[pid]) is not None:
        return text, words_of
    found = overview_users(sentences(text), users)
    if len(found) != 1 or kind_named(found[0].group()) is None:
        return text, words_of
    m, noun = found[0], kind_named(found[0].group())
    at = text.find(m.string)
    if at < 0:
        return text, words_of
    # (the noun alone beside its words: "a vehicle (passenger car)"; they still say what it was doing)
    assert noun is not None
    said = f"{words_of[pid]} ({m.group()[noun[1] : noun[2]]})"
    return text[: at + m.start()] + pid + text[at + m.end() :], {**words_of, pid: said}
