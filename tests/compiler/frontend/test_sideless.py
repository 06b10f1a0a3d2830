"""A lane change said without its side is read as a lane change whose side is not known (`change_lane` with no
target), not dropped; words that only say a move sideways ("maneuvered around traffic") still say no lane change.
Sentences written for these tests."""

from __future__ import annotations

from sovarc.compiler.frontend import FrontEnd
from sovarc.dsl import parse, to_text, verify
from sovarc.dsl.errors import Severity
from sovarc.dsl.ir import Action, ActionKind, Scenario, Side, Unknown
from sovarc.dsl.span import Source


def read(text: str) -> Scenario:
    return FrontEnd("none").extract(Source("case.txt", text)).scenario


def actions(s: Scenario, pid: str) -> list[Action]:
    p = next(p for p in s.participants if p.id == pid)
    return [] if isinstance(p.actions, Unknown) else list(p.actions)


def lane_changes(s: Scenario, pid: str) -> list[Action]:
    return [a for a in actions(s, pid) if a.kind is ActionKind.CHANGE_LANE]


def test_a_lane_change_with_no_side_is_read_without_one() -> None:
    s = read(
        "V1 was traveling north on a four-lane road. V2 was also traveling north. V2 changed lanes and struck the "
        "rear of V1."
    )
    assert lane_changes(s, "V2") == [Action(ActionKind.CHANGE_LANE)]
    assert s.crash.striker == "V2"


def test_a_switching_lanes_striker_rear_ends_with_a_side_less_lane_change() -> None:
    s = read(
        "An Acme Autonomous Vehicle (Acme AV) was stopped at a red light on [XXX]. The Acme AV was rear-ended by a "
        "passenger vehicle that was switching lanes."
    )
    assert lane_changes(s, "V2") == [Action(ActionKind.CHANGE_LANE)]
    assert s.crash.striker == "V2" and s.crash.victim == "V1"


def test_merging_is_a_lane_change_said_without_its_side() -> None:
    s = read("V1 was traveling east in the right lane. V2 was merging and its front struck the rear of V1.")
    assert lane_changes(s, "V2") == [Action(ActionKind.CHANGE_LANE)]


def test_the_side_of_the_partner_struck_still_gives_the_side() -> None:
    """It struck V1's right side: it came from V1's right, so it moved left."""
    s = read("V1 was traveling north. V2 was also traveling north. V2 changed lanes and struck the right side of V1.")
    assert lane_changes(s, "V2") == [Action(ActionKind.CHANGE_LANE, Side.LEFT)]


def test_a_side_said_anywhere_is_the_one_lane_change() -> None:
    s = read(
        "V1 was traveling north. V2 was changing lanes. During its lane change to the left, V2 struck the right "
        "side of V1."
    )
    assert lane_changes(s, "V2") == [Action(ActionKind.CHANGE_LANE, Side.LEFT)]


def test_a_move_around_traffic_with_no_side_is_no_lane_change() -> None:
    s = read("V1 was traveling south. A motorcycle, V2, maneuvered around other traffic and struck the rear of V1.")
    assert lane_changes(s, "V2") == []


def test_the_read_scenario_prints_verifies_and_reads_back() -> None:
    s = read("V1 was traveling north. V2 changed lanes and struck V1.")
    text = to_text(s)
    assert "      change_lane\n" in text
    again = parse(text)
    assert not [d for d in verify(again) if d.severity is Severity.ERROR]
    assert to_text(again) == text
