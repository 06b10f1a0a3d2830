"""Facts no road can reconcile are refused once, before any site is searched, naming the facts."""

from __future__ import annotations

import pytest
from sovarc.compiler.lower import sites_for
from sovarc.compiler.lower.consistency import check_headings
from sovarc.dsl import parse
from sovarc.dsl.errors import Severity, UnsatError
from sovarc.dsl.ir import Scenario

from tests.compiler.lower.staging import town
from tests.compiler.lower.test_errors import _line_of, _scenario, _vehicle


def _pair(
    crash: str, h1: str, h2: str, a1: str = "follow_lane", a2: str = "follow_lane", kind: str = "straight"
) -> tuple[str, Scenario]:
    text = _scenario("pair", kind, 2, [_vehicle("V1", h1, 1, a1), _vehicle("V2", h2, 1, a2)], crash)
    return text, parse(text, "pair.sov")


def test_a_rear_end_between_opposite_headings_names_the_crash_and_both_headings() -> None:
    text, scenario = _pair("rear_end", "south", "north", a1="follow_lane\n      retrograde")
    with pytest.raises(UnsatError) as caught:
        check_headings(scenario)
    head, *notes = caught.value.diagnostics
    assert head.message == (
        "rear_end needs V1's front into V2's rear, headings within 45 degrees, but V1 heads south and V2 north, "
        "and neither turns: closing on each other, V1's front can reach V2's front or a side, never its rear: "
        "no road can stage it"
    )
    assert head.span is not None and head.span.line == _line_of(text, "type rear_end")
    assert head.hint is not None and "frontal" in head.hint and "V2's rear corner as they pass" in head.hint
    assert [n.severity for n in notes] == [Severity.NOTE, Severity.NOTE]
    assert notes[0].message == "V1 heads south and then: follow_lane, retrograde"
    assert [n.span.line for n in notes if n.span] == [_line_of(text, "heading south"), _line_of(text, "heading north")]


def test_a_frontal_crash_between_the_same_headings_is_refused() -> None:
    _, scenario = _pair("frontal", "east", "east", a1="change_lane(to: 2)")
    with pytest.raises(
        UnsatError, match="going the same way, V1's front can reach V2's rear or a side, never its front"
    ):
        check_headings(scenario)


@pytest.mark.parametrize(
    ("crash", "h1", "h2", "a1"),
    [
        ("rear_end", "north", "north", "follow_lane"),  # the usual rear-end
        ("frontal", "north", "south", "follow_lane"),  # the usual head-on
        ("rear_end", "south", "north", "u_turn"),  # turns round first
        ("frontal", "north", "north", "turn_left"),  # a turn changes the heading
        ("rear_end", "north", "east", "follow_lane"),  # crossing headings: a swerve may meet either way
        ("side", "south", "north", "follow_lane"),  # any angle
    ],
)
def test_headings_a_crash_can_have_pass(crash: str, h1: str, h2: str, a1: str) -> None:
    kind = "intersection" if "north" in (h1, h2) and "east" in (h1, h2) else "straight"
    check_headings(_pair(crash, h1, h2, a1=a1, kind=kind)[1])


def test_sites_for_refuses_before_searching_the_map() -> None:
    _, scenario = _pair("rear_end", "west", "east")
    with pytest.raises(UnsatError, match="no road can stage it"):
        sites_for(scenario, town(), roads=3)
