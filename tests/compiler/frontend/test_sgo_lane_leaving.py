"""A road user leaving its lane, said any way (issue 18, sgo10a), on sentences written for these tests: into the
lane beside it, over a lane line, across the centre line or against the traffic, off the road; each form in
several verbs and tenses, and what is not such a move (a turn's path, a lane named where a driveway exit lands)."""

from __future__ import annotations

import pytest
from sovarc.dsl.ir import ActionKind, Side

from tests.compiler.frontend.sgo_reading import by_id, kinds, read

_HEAD = "A Waymo Autonomous Vehicle was in a collision involving a sedan on Pine Avenue. "


def _beside(move: str) -> str:
    """The sedan in the lane left of the Waymo AV makes the move, then its right side meets the AV's left."""
    return (
        _HEAD + "The Waymo AV was traveling north on Pine Avenue in the right lane. A sedan traveling north in "
        f"the left lane {move}. The right side of the sedan made contact with the left side of the Waymo AV."
    )


def _oncoming(move: str) -> str:
    return (
        _HEAD + "The Waymo AV was traveling north on Pine Avenue. A sedan traveling south on Pine Avenue "
        f"{move}, and the front of the sedan made contact with the front left of the Waymo AV."
    )


def _any(move: str) -> str:
    return _HEAD + f"The Waymo AV was traveling north on Pine Avenue. A sedan {move} and struck the Waymo AV."


@pytest.mark.parametrize(
    "move",
    [
        "shifted lanes",
        "swapped lanes",
        "was in the process of changing lanes",
        "cut in front of the Waymo AV",
        "cut back in ahead of the Waymo AV",
        "crossed into the adjacent lane",
        "entered the right adjacent lane",
        "partially entered the adjacent lane",
        "moved over into the next lane",
        "went into the neighboring lane",
        "crossed the dashed lane line",
        "was crossing over a solid white line",
        "crossed over the lane line",
        "was straddling two lanes",
        "straddled the lane line",
        "left its lane",
        "departed its own lane",
        "drifted out of its travel lane",
        "veered toward the Waymo AV",
        "drifted into the Waymo AV",
        "swerved into the side of the Waymo AV",
        "intruded into the Waymo AV's lane",
        "veered across the lane line",
    ],
)
def test_a_move_into_the_lane_beside_is_a_lane_change_toward_the_side_met(move: str) -> None:
    v2 = by_id(read(_beside(move)), "V2")
    assert kinds(v2)[-1] is ActionKind.CHANGE_LANE
    assert isinstance(v2.actions, tuple) and v2.actions[-1].to is Side.RIGHT


def test_a_lane_named_before_the_verb_gives_no_side() -> None:
    # "the left lane changing lanes": the lane it is in, not the noun "lane change" with its side
    v2 = by_id(read(_beside("changing lanes to the right")), "V2")
    assert isinstance(v2.actions, tuple) and v2.actions[-1].to is Side.RIGHT
    v2 = by_id(read(_beside("changed into the right lane")), "V2")
    assert isinstance(v2.actions, tuple) and [a.to for a in v2.actions[1:]] == [Side.RIGHT]


@pytest.mark.parametrize(
    "move",
    [
        "crossed the solid double-yellow line",
        "crossed the yellow center line",
        "crossed over the double yellow lines",
        "was straddling the double yellow line",
        "veered into oncoming traffic",
        "drove into opposing traffic",
        "drove against traffic",
        "was traveling against the flow of traffic",
        "was heading south in the northbound lanes",
        "went around a stopped truck through the oncoming lane",
        "overtook a stopped truck by way of the opposing lane",
        "was traveling in the opposing lane",
        "drove partially in the oncoming lane",
    ],
)
def test_going_into_the_other_directions_lanes_is_retrograde(move: str) -> None:
    assert kinds(by_id(read(_oncoming(move)), "V2"))[-1] is ActionKind.RETROGRADE


@pytest.mark.parametrize(
    "move",
    [
        "was driving against traffic",
        "drove wrong-way down Pine Avenue",
        "was traveling northbound in a southbound lane",
    ],
)
def test_driving_the_wrong_way_is_retrograde_whatever_the_heading_read(move: str) -> None:
    assert kinds(by_id(read(_any(move)), "V2"))[-1] is ActionKind.RETROGRADE


def test_wrong_way_travel_goes_on_through_the_junction() -> None:
    s = read(
        _HEAD + "The Waymo AV was traveling south on Pine Avenue and entered the intersection with Oak Street. A "
        "sedan traveling eastbound in a westbound-only section of Oak Street entered the intersection against a red "
        "light. The front of the sedan made contact with the right side of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.RETROGRADE


def test_a_turn_into_the_other_directions_lanes_is_the_turn() -> None:
    s = read(
        _HEAD + "The Waymo AV was traveling north on Pine Avenue. A sedan traveling east on Oak Street turned left "
        "into oncoming traffic and the front of the sedan made contact with the left side of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.TURN_LEFT


def test_a_lane_crossed_into_as_a_turn_swings_wide_is_the_turn() -> None:
    s = read(
        # the overview names the partner the narrative tells of (one that names another is a different report)
        _HEAD.replace("a sedan", "a heavy truck")
        + "The Waymo AV was stopped facing north in the left lane of Pine Avenue at a red light. A heavy truck "
        "in the right lane proceeded to make a right turn onto Oak Street. As the heavy truck attempted the right "
        "turn, its trailer crossed into the adjacent lane and made contact with the front of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.TURN_RIGHT


def test_a_lane_entered_from_a_driveway_is_where_it_entered_the_road() -> None:
    s = read(
        _HEAD + "The Waymo AV was traveling west on Pine Avenue in the left lane. A sedan pulled out of a driveway "
        "and moved into the right lane. The front of the sedan made contact with the right side of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.DRIVE_INTO


@pytest.mark.parametrize(
    "move",
    [
        "went off the road",
        "veered off the roadway",
        "drove off of the pavement",
        "mounted the curb",
        "jumped the curb",
        "went up onto the curb",
        "drove onto the sidewalk",
    ],
)
def test_leaving_the_road_surface_is_driving_off(move: str) -> None:
    assert kinds(by_id(read(_any(move)), "V2"))[-1] is ActionKind.DRIVE_OFF


def test_a_lane_change_meant_is_not_made_and_one_attempted_is() -> None:
    # The development half codes "attempted to change lanes" as Changing Lanes (4 of 4) and a vehicle "preparing
    # to merge" as stopped: an attempt cut short by the impact was under way, a preparation had not begun.
    tried = by_id(read(_beside("attempted to change lanes")), "V2")
    assert kinds(tried)[-1] is ActionKind.CHANGE_LANE
    meant = by_id(read(_beside("slowed, preparing to change lanes,")), "V2")
    assert ActionKind.CHANGE_LANE not in kinds(meant)


@pytest.mark.parametrize(
    ("introduced", "move"),
    [
        ("A merging SUV", ActionKind.CHANGE_LANE),
        ("A lane-changing SUV", ActionKind.CHANGE_LANE),
        ("A wrong-way SUV", ActionKind.RETROGRADE),
        ("An SUV entering Pine Avenue from the on-ramp", ActionKind.CHANGE_LANE),
    ],
)
def test_the_words_that_introduce_a_road_user_say_it_left_its_lane(introduced: str, move: ActionKind) -> None:
    s = read(
        _HEAD.replace("a sedan", "an SUV") + "The Waymo AV was traveling north on Pine Avenue in the right lane. "
        f"{introduced} made contact with the left side of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is move
