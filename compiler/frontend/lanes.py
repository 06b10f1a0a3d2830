"""A lane said in words, read against the road: the IR counts a vehicle's lanes from the right-most lane of its
direction, from 1.

Words that name a lane by its place ("the left lane", "the inside lane", "the middle lane", "the second lane
from the left") mean a number only once the lanes in that direction are known:
- a one-way road has all its lanes in the one direction;
- a two-way road has half its lanes each way (a centre turn lane is nobody's travel lane: five lanes
  are two each way); where the road's count is not known, what the report states ("two lanes in each
  direction").
Counting from the right needs nothing ("the right lane", "the curb lane", "lane two", "the second lane").
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.words import ORDINALS, number
from sovarc.dsl.ir import UNKNOWN, Unknown

_N = r"(\d|one|two|three|four|five|six|single)"
_EACH_WAY = re.compile(
    _N + r"[- ](?:travel )?lanes? (?:of travel )?(?:in |for )?(?:each|either|per|both) (?:the \w+ and \w+ )?direction",
    re.I,
)
_ONE_WAY = re.compile(r"\bone[- ]way\b", re.I)
_FROM = re.compile(
    r"\b(first|second|third|fourth|fifth) (?:travel )?lane from the (left|right|curb|median|cent(?:er|re) ?line)\b",
    re.I,
)
_LEFT = re.compile(r"\b(?:left|inside|passing|fast|median|inner) (?:\w+ )?lane\b", re.I)
_MIDDLE = re.compile(r"\b(?:middle|center|centre) (?:travel |through )?lane\b", re.I)


def per_direction(own: str, report: str, lanes: int | Unknown, one_road: bool) -> int | Unknown:
    """Lanes in a vehicle's direction: all of a one-way road's, or half a two-way road's, or what the report
    states when the road's count is not known. `own` is the vehicle's own clauses: at a junction a one-way road
    elsewhere in the report (the cross street) says nothing of its road; away from one (`one_road`) the report
    describes the one road there is. `lanes` is the widest road's count."""
    if isinstance(lanes, Unknown):
        return number(m.group(1)) if (m := _EACH_WAY.search(report)) else UNKNOWN
    road = report if one_road else own
    if _ONE_WAY.search(road) and not re.search(r"\btwo[- ]way\b", road, re.I):
        return lanes
    return max(1, lanes // 2)


def placed_lane(text: str, each_way: int | Unknown) -> int | Unknown:
    """The lane a clause places a vehicle in by the lane's place across the road (left, middle, n-th from the
    left), counted from the right; unknown when the words need the lane count and it is not known."""
    if m := _FROM.search(text):
        n = ORDINALS[m.group(1).lower()]
        if m.group(2).lower() in ("right", "curb"):
            return n
        return each_way - n + 1 if isinstance(each_way, int) and n <= each_way else UNKNOWN
    if isinstance(each_way, Unknown):
        return UNKNOWN
    if _MIDDLE.search(text) and each_way >= 3 and each_way % 2 == 1:
        return (each_way + 1) // 2
    if _LEFT.search(text):
        return each_way
    return UNKNOWN


# Which way a lane change went. A lane change goes to the side of the lane it enters; when the report names
# that lane only by whose it is ("into V1's lane", "into the center lane"), it goes away from the side of the
# lane it left: a vehicle in the lane to the left of another, or in the leftmost lane, can only move right.
_SIDE = r"(left|right)(?:most|[- ]hand)?"
# "a right lane change", "a left-hand lane change" (not a lane named before the verb: "the left lane changed to")
_BEFORE = re.compile(r"(?<!\bthe )\b" + _SIDE + r"[- ]$", re.I)
_TARGETS = (
    # "into the left turn lane", "to the expanded leftmost lane", "toward the right"
    re.compile(
        r"\b(?:in)?to(?:ward)? (?:the |its |an? )?(?:[\w-]+ ){0,2}?" + _SIDE + r"\b(?:[- ][\w-]+){0,2}? lane\b", re.I
    ),
    re.compile(r"\b(?:to|toward) the " + _SIDE + r"\b(?! of\b)", re.I),
    # "around the left side of V1", "passing V1 on the left": the side it went by on
    re.compile(r"\baround (?:the )?" + _SIDE + r"\b|\bon (?:the |its )?" + _SIDE + r"(?: side)?\b(?! of\b)", re.I),
    # "around V1 using the left turn lane", "by way of the right lane": the lane it went by
    re.compile(
        r"\b(?:using|via|through|by way of) (?:the |an? )?(?:[\w-]+ ){0,2}?" + _SIDE + r"\b(?:[- ][\w-]+){0,2}? lane\b",
        re.I,
    ),
    # "around the passenger side of V1": in a car driven from the left, the driver's side is its left
    re.compile(r"\baround (?:the )?(driver|passenger)(?:'?s'?)?[- ]side\b", re.I),
)
# Lanes whose side of the road is fixed by what they are for, in right-hand traffic: a centre turn lane (a two-way
# left-turn lane) lies left of every travel lane of either direction, so entering it is a move left; a bike lane
# runs along the right edge, so leaving it for a travel lane is one too.
_LEFT_BY_USE = re.compile(
    r"\b(?:in)?to (?:the |an? )?(?:(?:cent(?:er|re)|middle)(?: shared| two-way)?(?: left)?|two-way left)"
    r"(?:[- ]turn)? lane\b(?! line)"
    r"|\b(?:out of|from) (?:the |an? |its )?(?:bike|bicycle|cycle) lane\b",
    re.I,
)
_CAR_SIDE = {"driver": "left", "passenger": "right"}
_ORIGIN = re.compile(
    r"\b(?:in|from|within) (?:the |its )?(?:adjacent )?" + _SIDE + r"\b(?:[- ](?:adjacent|travel|through|\w+bound))*"
    r" lanes?\b",
    re.I,
)
_OTHER_SIDE = {"left": "right", "right": "left"}
# A lane named by its number: reports count the lanes of one direction from the right ("lane one", "the number
# one lane" is the rightmost), so from a higher number to a lower one is a move to the right.
NUMBER = r"(?:\d|one|two|three|four|five|six)"
_NUMBERED = r"(?:number (" + NUMBER + r")[- ]lane|lane (?:number |#)?(" + NUMBER + r"))\b"
_INTO_NUMBERED = re.compile(r"\b(?:in)?to (?:the )?" + _NUMBERED, re.I)
_IN_NUMBERED = re.compile(r"\b(?:in|from|within) (?:the )?" + _NUMBERED, re.I)


def _numbered_side(window: str, said_before: str) -> str | None:
    """The side of a move from the numbered lane it was in to the numbered lane it entered, if both are said."""
    into = _INTO_NUMBERED.search(window)
    origins = list(_IN_NUMBERED.finditer(said_before))
    if into is None or not origins:
        return None
    went, was = (number(next(g for g in m.groups() if g)) for m in (into, origins[-1]))
    return None if went == was else ("right" if went < was else "left")


def lane_change_side(text: str, start: int, end: int, said_before: str) -> str | None:
    """ "left" or "right": where the lane change at text[start:end] went (see above). `said_before` is what
    the report said of the vehicle before it (where its lane was)."""
    if m := _BEFORE.search(text[max(0, start - 12) : start]):
        return m.group(1).lower()
    if m := re.match(r"\s*(?:to (?:the )?)?" + _SIDE + r"\b", text[end : end + 16], re.I):  # "lane change right"
        return m.group(1).lower()
    window = text[start : max(end, start + 80)]
    for pattern in _TARGETS:
        if m := pattern.search(window):
            side = next(g for g in m.groups() if g).lower()
            return _CAR_SIDE.get(side, side)
    if _LEFT_BY_USE.search(window):
        return "left"
    origins = [m.group(1).lower() for m in _ORIGIN.finditer(said_before + " " + window)]
    return _OTHER_SIDE[origins[-1]] if origins else _numbered_side(window, said_before)


# What a lane is for is no move: "from a lane designated for both straight through and left turn maneuvers".
LANE_USE = re.compile(
    r"(?:(?<=\blane )|(?<=\blanes ))(?:designated |marked |reserved |used |signed )?for (?:both )?[^.,;]{0,40}?"
    r"\bturn(?:s|ing)?(?: maneuvers?| movements?)?\b",
    re.I,
)
