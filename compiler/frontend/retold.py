"""A move told before the impact sentence and told again in its time clause was under way at the impact.

"V2 passed V1 on the left and proceeded into the intersection. While passing V1, the side of V2 made contact with
V1": the time clause ("while passing", "as V2 passed") places the impact during the pass, so what the report told
after the pass ("proceeded into the intersection") came after the impact, and is no pre-crash move. The move is
found again by its verb, said the same way or in another form ("passed" ... "passing").
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.clauses import Piece
from sovarc.dsl.ir import Action

_TIME_CLAUSE = re.compile(r"^(?:As|While|When|Just as)\b[^,;]*", re.I)
# the verbs of moves, by stem: "passed" and "passing" are one move
# (in the forms of a verb said of a move made, not a noun, "the turn lane", nor a plan, "to turn left")
_MOVE = re.compile(
    r"(?<!\bto )(?<!\bto make a left )(?<!\bto make a right )"
    r"\b(pass(?:ed|es|ing)|overtak(?:es|ing)|overtook|turn(?:ed|ing)|made a (?:left|right) turn|revers(?:ed|ing)"
    r"|back(?:ed|ing)|merg(?:ed|ing)|chang(?:ed|ing) lanes)\b",
    re.I,
)
_NEXT = re.compile(r",? (?:and|then)\b|;")


def _stem(words: str) -> str:
    """The move a verb says: "passed" and "passing" are one, so are "turned" and "made a left turn"."""
    words = words.lower()
    return "turn" if "turn" in words else "overtake" if words.startswith("overt") else words[:4]


def _end_of_move(text: str, at: int) -> int:
    """Where the clause telling a move ends: at the next move joined to it ("passed V1 and proceeded into the
    intersection"), else at the piece's end (what the clause adds of the move is the move's own: "made a left
    turn (turning the wrong way onto a one-way street)")."""
    joined = _NEXT.search(text, at)
    return joined.start() if joined else len(text)


def under_way_at_impact(found: list[tuple[int, Action]], pieces: list[Piece]) -> list[tuple[int, Action]]:
    """`found` without the moves read after one the impact sentence's time clause tells again."""
    for piece in pieces:
        clause = _TIME_CLAUSE.match(piece.context)
        if clause is None or piece.context.find(piece.text) >= clause.end():
            continue
        told = {_stem(m.group(1)) for m in _MOVE.finditer(clause.group())}
        earlier = [
            p.at + _end_of_move(p.text, m.end())
            for p in pieces
            if p.sentence < piece.sentence
            for m in _MOVE.finditer(p.text)
            if _stem(m.group(1)) in told
        ]
        if earlier:
            last = max(earlier)
            return [(at, a) for at, a in found if at < last or at >= piece.at]
    return found
