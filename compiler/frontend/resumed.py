"""A move continued after a stop is the move before the stop, resumed.

"Continue" carries on what was being done: "V2 began to exit from a driveway ... entered the rightmost lane and
stopped ... V2 continued its perpendicular trajectory, proceeding straight into the leftmost lane" goes on
entering the road after the stop, and the move under way at the impact is that entry again.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.clauses import Piece
from sovarc.dsl.ir import Action, ActionKind

_CONTINUED = re.compile(
    r"\bcontinu(?:ed|es|ing) (?:on )?(?:its|their|his|her|the) (?:[\w-]+ )?"
    r"(?:trajectory|path|course|maneuver|manoeuvre|movement|motion|turn)\b",
    re.I,
)
_NO_MOVE = (ActionKind.STOP, ActionKind.PARKED, ActionKind.FOLLOW_LANE)


def resumed(found: list[tuple[int, Action]], pieces: list[Piece]) -> list[tuple[int, Action]]:
    """`found` (ordered by where each was read) with the move before a stop again where the report says that
    move continued after it."""
    out = list(found)
    for piece in pieces:
        for m in _CONTINUED.finditer(piece.text):
            at = piece.at + m.start()
            before = [a for w, a in found if w < at]
            if not before or before[-1].kind is not ActionKind.STOP:
                continue
            if (move := next((a for a in reversed(before) if a.kind not in _NO_MOVE), None)) is not None:
                out.append((at, move))
    return sorted(out, key=lambda item: item[0])
