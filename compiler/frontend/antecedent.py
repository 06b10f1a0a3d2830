"""A definite wider noun points back: "A minivan in the oncoming lane veered into the eastbound lane. The vehicle
made contact with V1." "The vehicle" names no road user of its own; said with "the" and nothing that picks one
out, it is the road user last introduced before it ("a minivan"), which a wider noun covers (any road user is a
vehicle). So a partner named only so is that road user, and its kind is the one that introduction says.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.kinds import kind_named
from sovarc.compiler.frontend.overview import only_other

_BARE = re.compile(r"the vehicle", re.I)
# Words after a noun that pick one road user out ("the vehicle behind V1", "the vehicle that had been following")
_PICKED = re.compile(
    r"\s+(?:\w+ly )?(?:behind|ahead|in|on|at|that|which|who|next|beside|alongside|to|from|with|of|"
    r"\w+ing)\b",
    re.I,
)


def name_antecedent(text: str, words_of: dict[str, str], users: re.Pattern[str]) -> tuple[str, dict[str, str]]:
    """The one other party, named only as "the vehicle", is the road user introduced last before its first
    mention (a match of `users` said with "a" or "an", of a kind): that introduction is its id, and its noun is
    added to its words."""
    pid = only_other(text, words_of)
    if pid is None or not _BARE.fullmatch(words_of[pid]):
        return text, words_of
    first = re.search(r"\b" + pid + r"\b", text)
    assert first is not None
    if _PICKED.match(text, first.end()):  # "the vehicle behind V1", "the vehicle that struck": a new one
        return text, words_of
    before = [m for m in users.finditer(text, 0, first.start()) if re.match(r"an? ", m.group(), re.I)]
    if not before or (noun := kind_named(before[-1].group())) is None:
        return text, words_of
    m, said = before[-1], before[-1][0][noun[1] : noun[2]]
    rest = re.sub(r"\b[Tt]he " + re.escape(said) + r"\b(?![\w-])", pid, text[m.end() :])  # "the minivan" after it
    return text[: m.start()] + pid + rest, {**words_of, pid: f"{words_of[pid]} ({said})"}
