"""A partner's move at the impact (issue 18, sgo8), on sentences written for these tests:
"entered V1's lane" is a lane change as "moved into V1's lane" is, and a lane change said twice in one clause
chain ("was changing lanes ..., it entered V1's lane") is one move; a move the impact's time clause tells again
("While passing V1, ...") was under way at the impact, so what was told after it came later."""

from __future__ import annotations

import pytest
from sovarc.dsl.ir import ActionKind

from tests.compiler.frontend.sgo_reading import by_id, kinds, read


@pytest.mark.parametrize("verb", ["entered", "partially entered", "moved into"])
def test_entering_the_other_vehicles_lane_is_a_lane_change(verb: str) -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a sedan on Pine Avenue. The Waymo AV was traveling "
        "south on Pine Avenue in the right lane. A sedan traveling south in the left lane beside the Waymo AV "
        f"drove through the intersection and {verb} the Waymo AV's lane. The right side of the sedan made contact "
        "with the left side of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.CHANGE_LANE


def test_a_lane_change_said_again_as_entering_the_lane_is_one_move() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a van on Pine Avenue. The Waymo AV was traveling "
        "west on Pine Avenue in the rightmost lane. A van in the leftmost lane began to cross the lanes to turn "
        "right into a driveway. As the van was changing lanes and beginning the right turn, it entered the Waymo "
        "AV's lane of travel, and the right rear of the van made contact with the front left of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.TURN_RIGHT


def test_what_came_after_the_move_the_impact_happened_during_is_no_pre_crash_move() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a sedan on Pine Avenue. The Waymo AV was stopped "
        "in the left lane of Pine Avenue at a red light. When the light turned green, a sedan that had been stopped "
        "behind the Waymo AV passed the Waymo AV on the left and proceeded into the intersection. While passing the "
        "Waymo AV, the right side of the sedan made contact with the left rear of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.FOLLOW_LANE


def test_what_a_retold_turn_is_said_to_be_stays_the_turns_own() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a sedan on Pine Avenue. The Waymo AV was stopped "
        "facing north on Pine Avenue at a red light. A sedan traveling west made a left turn onto Pine Avenue "
        "(turning the wrong way onto a one-way street). As the sedan turned onto Pine Avenue, the front of the "
        "sedan made contact with the front of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.RETROGRADE


@pytest.mark.parametrize("move", ["encroached into the Waymo AV's lane", "drifted right into the Waymo AV's lane"])
def test_intruding_or_drifting_sideways_into_the_other_vehicles_lane_is_a_lane_change(move: str) -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a sedan on Pine Avenue. The Waymo AV was traveling "
        f"north on Pine Avenue in the right lane. A sedan traveling in the left lane {move}. The right side of the "
        "sedan made contact with the left side of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.CHANGE_LANE


def test_one_that_overtook_drove_on_past() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a sedan on Pine Avenue. The Waymo AV was stopped "
        "at the curb on Pine Avenue. A sedan overtook the Waymo AV on the left. The right side of the sedan made "
        "contact with the left rear of the Waymo AV."
    )
    assert kinds(by_id(s, "V2")) == [ActionKind.FOLLOW_LANE]


def test_one_emerging_from_an_alley_entered_the_road() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a sedan on Pine Avenue. The Waymo AV was traveling "
        "north on Pine Avenue. A sedan emerging from an alley made contact with the right side of the Waymo AV."
    )
    assert kinds(by_id(s, "V2")) == [ActionKind.DRIVE_INTO]
