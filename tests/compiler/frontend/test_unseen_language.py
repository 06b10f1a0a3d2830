"""Kinds of English found on NMVCCS-style reports no rule was written for (issue 18's audit), each with short
reports written here:

- a lane named by its number ("into lane one", "the number two lane"): reports number one direction's lanes
  from the right, so the numbers say the side of the lane change;
- the victim's part as the subject of a passive strike, its owner the clause before ("V1 turned left and the
  right side was struck by the front of V2");
- a vehicle stopped inside a junction drove into it first (one stopped at it need not have).
"""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend.rules import extract
from sovarc.dsl.ir import CrashType, Lighting, Side, Speed, SpeedUnit, Unknown

CROSS = "The crash occurred at a four-leg intersection. "
ROAD = "The crash occurred on a straight road with three lanes in each direction. "


def _actions(text: str) -> dict[str, list[str]]:
    s = extract(text, "t")
    return {p.id: [] if isinstance(p.actions, Unknown) else [a.kind.value for a in p.actions] for p in s.participants}


def _change_side(text: str, pid: str) -> object:
    p = next(p for p in extract(text, "t").participants if p.id == pid)
    assert not isinstance(p.actions, Unknown)
    return next(a.to for a in p.actions if a.kind.value == "change_lane")


@pytest.mark.parametrize(
    ("lane", "said", "side"),
    [
        ("the left lane", "veered sharply to the right into the right lane", Side.RIGHT),
        ("the right lane", "steered quickly to the left into the left lane", Side.LEFT),
        ("the number three lane", "veered to the right crossing over lane two into lane one", Side.RIGHT),
        ("the number three lane", "suddenly moved into lane two", Side.RIGHT),
        ("lane one", "drifted into the number two lane", Side.LEFT),
    ],
)
def test_a_sideways_move_into_a_numbered_lane_is_a_lane_change_to_the_side_the_numbers_say(
    lane: str, said: str, side: Side
) -> None:
    text = ROAD + f"V1 was traveling east in {lane}. V2 was traveling east. V1 {said}."
    text += " The front of V2 struck the left side of V1."
    assert _actions(text)["V1"] == ["follow_lane", "change_lane"]
    assert _change_side(text, "V1") == side


@pytest.mark.parametrize(
    "said",
    [
        "drifted into the number one westbound lane",  # the other direction's lane: not a lane change
        "was traveling in lane two",  # no move at all
        "moved on into the intersection",  # no lane named
    ],
)
def test_a_numbered_lane_of_the_other_direction_or_no_sideways_move_is_no_lane_change(said: str) -> None:
    text = ROAD + f"V1 was traveling east in the number three lane. V1 {said}. The front of V1 struck the rear of V2."
    assert "change_lane" not in _actions(text)["V1"]


@pytest.mark.parametrize(
    ("clause", "kind"),
    [
        ("V1 turned left and the right side was struck by the front of V2.", CrashType.SIDE),
        ("V1 slowed and the rear was struck by the front of V2.", CrashType.REAR_END),
        ("V1 drifted left and its front was violently struck by the front of V2.", CrashType.FRONTAL),
    ],
)
def test_the_victims_part_as_subject_of_a_passive_strike_gives_the_crash_type(clause: str, kind: CrashType) -> None:
    text = CROSS + "V1 was traveling north. V2 was traveling south. " + clause
    crash = extract(text, "t").crash
    assert (crash.type, crash.striker, crash.victim) == (kind, "V2", "V1")


@pytest.mark.parametrize(
    ("said", "acts"),
    [
        ("V1 was stopped in the intersection and made a left turn.", ["follow_lane", "stop", "turn_left"]),
        (
            "V1 made a left turn after being stopped in the middle of the intersection.",
            ["follow_lane", "stop", "turn_left"],
        ),
        ("V1 was stopped at the stop sign and then made a left turn.", ["stop", "turn_left"]),
        ("V1 was stopped for the red light and then made a left turn.", ["stop", "turn_left"]),
    ],
)
def test_a_vehicle_stopped_inside_a_junction_drove_into_it_first(said: str, acts: list[str]) -> None:
    text = CROSS + said + " V2 was traveling south. The front of V2 struck the right side of V1."
    assert _actions(text)["V1"] == acts


@pytest.mark.parametrize(
    ("said", "ids"),
    [
        ("V1 struck three pedestrians.", ["V1", "P1", "P2", "P3"]),
        ("V1 struck two pedestrians standing at the corner.", ["V1", "P1", "P2"]),
        ("V1 struck a pedestrian.", ["V1", "P1"]),
    ],
)
def test_a_group_of_pedestrians_counted_in_words_is_that_many_road_users(said: str, ids: list[str]) -> None:
    text = ROAD + "V1 was traveling east. " + said
    assert [p.id for p in extract(text, "t").participants] == ids


def test_a_pedestrian_met_after_its_striker_left_the_road_was_not_crossing_it() -> None:
    off = ROAD + "V1 was traveling east. V1 traveled off the right side of the road and struck a pedestrian."
    assert _actions(off) == {"V1": ["follow_lane", "drive_off"], "P1": []}  # [] = unknown
    on = ROAD + "V1 was traveling east and struck a pedestrian."
    assert _actions(on)["P1"] == ["cross"]  # on the road, one struck is taken to be crossing it
    walking = ROAD + "V1 traveled off the right side of the road and struck a pedestrian walking along the shoulder."
    assert _actions(walking)["P1"] == ["walk"]  # what it did, when said, stands


@pytest.mark.parametrize(
    ("said", "heading"),
    [
        ("V1 was making a left turn to travel east after being stopped for a stop sign.", "south"),
        ("V1 made a right turn to travel east.", "north"),
        ("V1 turned left to go northbound.", "east"),
        ("V1 was traveling west and made a left turn to travel south.", "west"),  # said outright, it stands
    ],
)
def test_a_turn_said_with_the_way_it_led_gives_the_heading_before_it(said: str, heading: str) -> None:
    text = CROSS + said + " V2 was traveling west. The front of V2 struck the left side of V1."
    v1 = next(p for p in extract(text, "t").participants if p.id == "V1")
    assert str(v1.heading) == heading


def test_road_facts_in_other_words() -> None:
    s = extract(
        "The crash occurred on a highway. The highway is designated 104 kmph (65 mph). The area was dark but lit."
        " The east/west roadway has five lanes; each direction consists of two through lanes and a left turn lane."
        " V1 was traveling east. The front of V1 struck the rear of V2.",
        "t",
    )
    assert s.road.speed_limit == Speed(104, SpeedUnit.KMH)
    assert set(s.environment.lighting) == {Lighting.DARK, Lighting.STREET_LIGHTS}
    assert s.road.lanes == 5
    # a count after another noun is not the road's: "the driver has two lanes of experience" says nothing
    other = extract("V1 was traveling east on a road. The driver has five lanes memorised. V1 struck V2.", "t")
    assert isinstance(other.road.lanes, Unknown)
