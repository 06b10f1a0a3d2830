"""A crossing of the centre line said in the course of a turn is the turn's path.

A left turn from a two-way road crosses the centre line by its nature, and a turn swinging wide or cutting the
corner crosses it as part of the turn: "As V2 turned left, it partially crossed the centerline of [XXX] and the
left side of V2 made contact with V1" is a turn, not a drive against the traffic, as a turn across the other
direction's lanes is no wrong-way driving either (`actions._found`).
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.clauses import Piece

# A turn under way, said in a clause of time: "As V2 turned left, it partially crossed the centerline".
_TURN_UNDER_WAY = (
    r"\b(?:as|while) {} (?:was |were )?(?:\w+ly )?(?:turn(?:ed|ing)|(?:making|made) (?:a|the|its) (?:\w+ )?turn)"
)


def crossed_in_turn(piece: Piece, crossing: str) -> bool:
    """Whether a crossing of the centre line is said in the course of the vehicle's turn: a left turn crosses
    the line by its nature, and one swinging wide or cutting the corner crosses it as part of the turn, so it
    is the turn's path and not driving against the traffic (as a turn across the other direction's lanes is)."""
    if not piece.who:
        return False
    under_way = re.search(_TURN_UNDER_WAY.format(piece.who[0]), piece.context, re.I)
    return under_way is not None and piece.context.find(crossing, under_way.end()) >= 0
