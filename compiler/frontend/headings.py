"""A road user's heading as a report says it: with a verb of motion, by its lane's direction, as a compass
"-bound", by where it faced, by a course's two ends or where it came from, or from a turn said with where it led."""

from __future__ import annotations

import re

from sovarc.compiler.frontend.actions import what_was_done
from sovarc.compiler.frontend.clauses import Piece
from sovarc.compiler.frontend.words import opposite, turned
from sovarc.dsl.ir import UNKNOWN, Heading, Unknown

# A heading said with a verb of motion ("traveling west", "was eastbound") is the vehicle's own; a lane's
# direction ("in the westbound lane") is where it was; "to travel westbound", "a westbound left turn",
# "onto a northbound road", "two westbound and two eastbound lanes" and "facing east at rest" are not its heading.
# "northwest" counts as north, as the ground truth reads it
_COMPASS = r"(north|south|east|west)(?:east|west)?(?: ?bound|ward|erly)?(?![a-z/-])"
_MOVING_HEADING = re.compile(
    r"\b(?:travel\w*|driv(?:ing|es|e)|drove|head(?:ed|ing)|going|proceed\w*|moving|was|were|continu\w*|approach\w*"
    r"|walk\w*|runn\w*|jogg\w*|rid(?:ing|e)"
    r"|negotiat\w*|stopped facing|(?:was|were) (?:\w+ )?facing)(?: due| in an?| generally)? " + _COMPASS,
    re.I,
)
_FACING = re.compile(r"(?<!rest )(?<!rest, )\bfacing (?:due |generally )?" + _COMPASS, re.I)
# A course said by its two ends heads to the second: "crossing from south to north", "from the east to the west side".
_FROM_TO = re.compile(
    r"\bfrom (?:the )?(?:north|south|east|west)(?:ern)? (?:side |curb |kerb |end )?to (?:the )?"
    r"(north|south|east|west)\b",
    re.I,
)
# Where a road user came from is behind it: "coming from the south" is heading north. Only with a verb of
# arriving and the point alone ("from the south side", "from the north leg" name a place, not a course).
_FROM = re.compile(
    r"\b(?:com(?:ing|es|e)|came|approach\w*|arriv\w*|travel\w*|driv(?:ing|es|e)|drove|proceed\w*) from the "
    r"(north|south|east|west)(?![\w-])(?! (?:side|leg|end|edge|corner|curb|kerb|shoulder|lanes?|approach)\b)",
    re.I,
)
_LANE_HEADING = re.compile(
    r"\b(?:in|on|within|from) (?:the|its|his|her) (?:\w+ )?(north|south|east|west) ?bound\b", re.I
)
_NOT_HEADING = re.compile(
    r"\b(?:to (?:travel|go|head|proceed|turn)|onto|into|toward|towards)\b[^.,;]*?$"
    r"|\b(?:\d|one|two|three|four|five|both) $",
    re.I,
)
_BOUND = re.compile(
    r"\b(north|south|east|west) ?bound\b(?! (?:and|or|/)\b)(?!(?: \w+)? (?:left|right|u)[- ]?turn)", re.I
)


# The ways of saying a heading before the impact, surest first.
_SAID_BEFORE = (_MOVING_HEADING, _LANE_HEADING, _BOUND, _FACING, _FROM_TO, _FROM)


def read_heading(pieces: list[Piece], after_impact: bool = False) -> tuple[Heading | Unknown, Piece | None, int]:
    """The heading the pieces state, the surest way of saying it first (see above). After the impact only a
    verb of motion counts: vehicles spin, come to rest facing anywhere and end up in other lanes."""
    for pattern in (_MOVING_HEADING,) if after_impact else _SAID_BEFORE:
        for piece in pieces:
            text = what_was_done(piece.text)
            for m in pattern.finditer(text):
                if pattern is _BOUND and _NOT_HEADING.search(text[: m.start()]):
                    continue
                if re.search(r"\bto $", text[: m.start()]):  # "to travel westbound" is where it was going
                    continue
                if after_impact and re.search(r"\brest\b", text[max(0, m.start() - 20) : m.start()]):
                    continue
                said = Heading(m.group(1).lower())
                return (opposite(said) if pattern is _FROM else said), piece, m.start()
    return UNKNOWN, None, 0


# A turn said with where it led ("making a left turn to travel east"): a left turn ends a quarter turn
# anticlockwise of where the vehicle was heading, a right turn clockwise; so it was heading the other way round.
_TURN_TO = re.compile(
    r"\b(?:(left|right)[- ]turn|turn(?:ed|ing|s)? (left|right))\b[^.;]{0,30}?\bto (?:travel|go|head|proceed)"
    r"(?: \w+)? " + _COMPASS,
    re.I,
)


def heading_before_turn(pieces: list[Piece]) -> tuple[Heading | Unknown, Piece | None, int]:
    """The heading before a turn said with the way it led (see above), when no heading is said outright."""
    for piece in pieces:
        if m := _TURN_TO.search(what_was_done(piece.text)):
            after = Heading(m.group(3).lower())
            return turned(after, 1 if (m.group(1) or m.group(2)).lower() == "left" else -1), piece, m.start()
    return UNKNOWN, None, 0
