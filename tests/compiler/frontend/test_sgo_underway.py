"""A move under way at the impact (issue 18, sgo7), on sentences written for these tests: a vehicle that came to a
stop is met by the one said moving as they met, a centre line crossed in the course of a turn is the turn's, and
the side a move heads for names no subject of the strike."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend.crash import read_sentence
from sovarc.dsl.ir import ActionKind, CrashType

from tests.compiler.frontend.sgo_reading import by_id, kinds, read


@pytest.mark.parametrize(
    "impact",
    [
        "As the delivery truck turned right, the right side of the truck made contact with the front bumper of "
        "the Waymo AV.",
        "While the delivery truck was passing the Waymo AV, the rear side of the truck made contact with the "
        "front left corner of the Waymo AV.",
    ],
)
def test_one_that_came_to_a_stop_is_met_by_the_one_moving_as_they_met(impact: str) -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a delivery truck on Oak Street. The Waymo AV was "
        "traveling east on Oak Street and came to a stop at the intersection with Elm Street to yield to a "
        f"delivery truck. {impact} Both vehicles sustained damage."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")
    assert kinds(by_id(s, "V1"))[-1] is ActionKind.STOP


def test_one_that_moved_off_again_still_strikes() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a delivery truck on Oak Street. The Waymo AV was "
        "traveling east on Oak Street and came to a stop at the intersection with Elm Street. The Waymo AV then "
        "proceeded into the intersection, and as the delivery truck turned right, the front bumper of the Waymo "
        "AV made contact with the right side of the truck."
    )
    assert (s.crash.striker, s.crash.victim) == ("V1", "V2")


def test_a_centre_line_crossed_in_the_course_of_a_turn_is_the_turn() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a box truck on Oak Street. The Waymo AV was "
        "traveling south on Oak Street when a box truck was making a left turn from Elm Street onto Oak Street. "
        "As the box truck turned left, it crossed the center line of Oak Street and the left side of the truck "
        "made contact with the front of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.TURN_LEFT


def test_a_centre_line_crossed_with_no_turn_is_the_wrong_way() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a box truck on Oak Street. The Waymo AV was "
        "traveling south on Oak Street when a box truck traveling north crossed the center line of Oak Street and "
        "the front of the truck made contact with the front of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.RETROGRADE


@pytest.mark.parametrize(
    "sentence",
    [
        "V2 behind V1 began to accelerate toward the right side of V1 and made contact with the rear bumper of V1.",
        "V2 steered towards the left side of V1 and then made contact with the rear of V1.",
    ],
)
def test_the_side_a_move_heads_for_is_no_subject_of_the_strike(sentence: str) -> None:
    crash = read_sentence(sentence)
    assert crash is not None and (crash.striker, crash.victim, crash.type) == ("V2", "V1", CrashType.REAR_END)


@pytest.mark.parametrize("approach", ["approached a right turn onto", "was approaching a left turn onto"])
def test_a_turn_approached_is_not_yet_made(approach: str) -> None:
    s = read(
        f"A Waymo Autonomous Vehicle was in a collision involving an SUV. As the Waymo AV {approach} Oak Street, it "
        "braked behind stopped traffic. An SUV following behind the Waymo AV made contact with the rear of the "
        "Waymo AV."
    )
    assert kinds(by_id(s, "V1"))[-1] is ActionKind.FOLLOW_LANE


def test_a_turn_made_after_the_approach_is_the_turn() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving an SUV. The Waymo AV approached a right turn onto "
        "Oak Street and then turned right onto Oak Street. An SUV following behind the Waymo AV made contact with "
        "the rear of the Waymo AV."
    )
    assert kinds(by_id(s, "V1"))[-1] is ActionKind.TURN_RIGHT


@pytest.mark.parametrize("begun", ["began to initiate the turn", "initiated its turn", "began to execute the turn"])
def test_a_meant_turn_set_going_is_the_turn(begun: str) -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a sedan. The Waymo AV was traveling north on Pine "
        "Street and preparing to make a left turn onto Oak Street. The Waymo AV slowed to yield to oncoming "
        f"traffic. As the traffic passed and the Waymo AV {begun}, a sedan approached from behind and made contact "
        "with the rear of the Waymo AV."
    )
    assert kinds(by_id(s, "V1"))[-1] is ActionKind.TURN_LEFT


@pytest.mark.parametrize(
    "lane", ["a lane designated for both straight through and left turn maneuvers", "the lane for left turns"]
)
def test_what_a_lane_is_for_is_no_move(lane: str) -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a pickup truck. The Waymo AV was traveling north "
        f"on Pine Street in {lane} and drove through the intersection with Oak Street. A pickup truck in the right "
        "adjacent lane changed lanes to the left and made contact with the front passenger side of the Waymo AV."
    )
    assert ActionKind.TURN_LEFT not in kinds(by_id(s, "V1"))


def test_a_move_continued_after_a_stop_is_resumed() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a sedan. The Waymo AV was traveling west on Pine "
        "Street when a sedan began to exit from a driveway of a parking lot to the right of the Waymo AV. The sedan "
        "entered the right lane and stopped. The sedan then continued its trajectory into the left lane, and the "
        "front of the sedan made contact with the passenger side of the Waymo AV."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.DRIVE_INTO


def test_a_stop_with_nothing_continued_stays_the_last_move() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a sedan. The Waymo AV was traveling west on Pine "
        "Street when a sedan began to exit from a driveway of a parking lot to the right of the Waymo AV. The sedan "
        "entered the right lane and stopped. The Waymo AV made contact with the front of the sedan."
    )
    assert kinds(by_id(s, "V2"))[-1] is ActionKind.STOP


@pytest.mark.parametrize("other", ["approaching traffic", "a delivery truck", "the traffic ahead"])
def test_the_subject_s_verb_after_another_road_user_it_yielded_for(other: str) -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a sedan. The Waymo AV was attempting a right turn "
        f"from a parking lot onto Pine Street when it began yielding for {other} and came to a stop. A sedan behind "
        "the Waymo AV then struck the rear of the Waymo AV."
    )
    assert kinds(by_id(s, "V1"))[-1] is ActionKind.STOP


def test_the_subject_after_a_fronted_phrase_is_no_aside_of_its_object() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a minivan. The Waymo AV was traveling west on "
        "Pine Street in the left lane. In the right lane ahead of the Waymo AV, a passenger car was double parked. "
        "A minivan traveling behind the Waymo AV then changed lanes to the left and the front of the minivan made "
        "contact with the rear of the Waymo AV."
    )
    assert ActionKind.PARKED not in kinds(by_id(s, "V1"))


def test_an_object_described_on_the_spot_is_still_an_aside() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a sedan. The Waymo AV struck the sedan, a grey "
        "Honda that was parked at the curb."
    )
    assert kinds(by_id(s, "V2")) == [ActionKind.PARKED]
