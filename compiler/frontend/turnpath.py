"""A crossing of the centre line, or into another lane, said in the course of a turn is the turn's path.

A left turn from a two-way road crosses the centre line by its nature, and a turn swinging wide or cutting the
corner crosses it as part of the turn: "As V2 turned left, it partially crossed the centerline of [XXX] and the
left side of V2 made contact with V1" is a turn, not a drive against the traffic, as a turn across the other
direction's lanes is no wrong-way driving either (`actions._found`). So is a lane its body swings into as it
turns: "As the truck attempted the right turn, its trailer crossed into the left lane" is the turn, not a lane
change.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.clauses import Piece

# A turn under way, said in a clause of time: "As V2 turned left, it partially crossed the centerline".
_TURN_UNDER_WAY = (
    r"\b(?:as|while) {} (?:was |were )?(?:\w+ly )?(?:turn(?:ed|ing)|(?:making|made|attempt(?:ed|ing)"
    r"|complet(?:ed|ing)|negotiat(?:ed|ing)|execut(?:ed|ing)|initiat(?:ed|ing)|beg(?:an|inning)|start(?:ed|ing))"
    r" (?:a|the|its) (?:\w+ )?turn)"
)


def crossed_in_turn(piece: Piece, crossing: str) -> bool:
    """Whether a crossing of the centre line (or into another lane) is said in the course of the vehicle's turn:
    a left turn crosses the line by its nature, and one swinging wide or cutting the corner crosses it as part of
    the turn, so it is the turn's path and not driving against the traffic (as a turn across the other
    direction's lanes is) nor a lane change."""
    if not piece.who:
        return False
    under_way = re.search(_TURN_UNDER_WAY.format(piece.who[0]), piece.context, re.I)
    return under_way is not None and piece.context.find(crossing, under_way.end()) >= 0


# A turn said in the same clause before the lanes it goes into or through: "turned left into oncoming traffic",
# "made a left turn through the opposing lanes".
_TURN_IN_CLAUSE = re.compile(r"\b(?:turn(?:ed|ing|s)?|u-?turn)\b[^.,;]*$", re.I)
_CLAUSE_START = re.compile(r".*(?:[.,;]|\b(?:and|then|but|when|while|as|after|before)\b)", re.I | re.S)


def turned_into(done: str, start: int) -> bool:
    """Whether the clause before `start` turns: a turn across or into the other direction's lanes is the turn's
    path, not driving against the traffic."""
    before = done[:start]
    cut = _CLAUSE_START.match(before)
    return _TURN_IN_CLAUSE.search(before[cut.end() if cut else 0 :]) is not None
