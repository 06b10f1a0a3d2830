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

from sovarc.dsl.ir import UNKNOWN, Unknown

_NUM = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "single": 1}
_ORDINAL = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5}
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


def _number(word: str) -> int:
    return int(word) if word.isdigit() else _NUM[word.lower()]


def per_direction(own: str, report: str, lanes: int | Unknown, one_road: bool) -> int | Unknown:
    """Lanes in a vehicle's direction: all of a one-way road's, or half a two-way road's, or what the report
    states when the road's count is not known. `own` is the vehicle's own clauses: at a junction a one-way road
    elsewhere in the report (the cross street) says nothing of its road; away from one (`one_road`) the report
    describes the one road there is. `lanes` is the widest road's count."""
    if isinstance(lanes, Unknown):
        return _number(m.group(1)) if (m := _EACH_WAY.search(report)) else UNKNOWN
    road = report if one_road else own
    if _ONE_WAY.search(road) and not re.search(r"\btwo[- ]way\b", road, re.I):
        return lanes
    return max(1, lanes // 2)


def placed_lane(text: str, each_way: int | Unknown) -> int | Unknown:
    """The lane a clause places a vehicle in by the lane's place across the road (left, middle, n-th from the
    left), counted from the right; unknown when the words need the lane count and it is not known."""
    if m := _FROM.search(text):
        n = _ORDINAL[m.group(1).lower()]
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
