"""A turn made before the impact, then driving along the road turned onto.

"V2 turned left onto Elm Street and was traveling west when ...", "After turning right onto Elm Street, V1 was
traveling north", "V1 made a left turn onto Elm Street. V1 was proceeding west on Elm Street when ...": a motion
along a road said in a finite verb after the turn is told places the turn before it, so the turn was over and the
move under way at the impact is driving along the lane. A turn told as under way ("was turning left when",
"as it completed its left turn") has no such motion after it, and one said with how fast ("was traveling at
10 mph") says nothing of where, so neither ends the turn.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.clauses import Piece
from sovarc.dsl.ir import Action, ActionKind

_TURNS = (ActionKind.TURN_LEFT, ActionKind.TURN_RIGHT, ActionKind.U_TURN)
# a finite motion along a road: "was traveling west", "were heading along Elm Street", "then proceeded north"
_ALONG = re.compile(
    r"\b(?:was|were) (?:then |now |still )?(?:travel(?:l)?ing|driving|proceeding|heading|continuing) "
    r"(?:(?:north|south|east|west)\w*|along|down|up|straight)\b"
    r"|\b(?:then|and) (?:continued|proceeded|travel(?:l)?ed|drove) "
    r"(?:(?:north|south|east|west)\w*|along|down|straight)\b",
    re.I,
)


def driven_on(found: list[tuple[int, Action]], pieces: list[Piece]) -> list[tuple[int, Action]]:
    """`found` (ordered by where each was read), with driving along added after a last turn that a motion along a
    road is told after (see the module); unchanged otherwise."""
    if not found or found[-1][1].kind not in _TURNS:
        return found
    turned = found[-1][0]
    along = [p.at + m.start() for p in pieces for m in _ALONG.finditer(p.text) if p.at + m.start() > turned]
    return [*found, (min(along), Action(ActionKind.FOLLOW_LANE))] if along else found
