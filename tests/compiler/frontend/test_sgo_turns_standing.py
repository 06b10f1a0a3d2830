"""Turns, entries onto the road and standing, said any way (issue 18, sgo10b), on sentences written for these
tests: each form of English that says the move (a verb in any tense, a participle used as an adjective, a noun,
an idiom), against the forms that say it was only meant, awaited or signalled, and a turn over before the impact
against one under way at it."""

from __future__ import annotations

import pytest
from sovarc.dsl.ir import ActionKind, Participant

from tests.compiler.frontend.sgo_reading import by_id, read

HEAD = "A Zoox robotaxi was in a collision involving a sedan on Pine Avenue. "
THEN = "The Zoox robotaxi was traveling south on Pine Avenue when "
FRONT_HIT = " The front of the sedan made contact with the driver side of the Zoox robotaxi."
REAR_HIT = " The rear of the sedan made contact with the driver side of the Zoox robotaxi."
STRUCK = " when a sedan made contact with the rear of the Zoox robotaxi."
_K = ActionKind


def last(p: Participant) -> ActionKind:
    assert isinstance(p.actions, tuple)
    return p.actions[-1].kind


def partner(move: str, hit: str = FRONT_HIT) -> ActionKind:
    return last(by_id(read(HEAD + THEN + move + hit), "V2"))


def robotaxi(sentence: str) -> ActionKind:
    return last(by_id(read(HEAD + sentence), "V1"))


@pytest.mark.parametrize(
    ("move", "kind"),
    [
        ("a sedan took a right onto Pine Avenue.", _K.TURN_RIGHT),
        ("a sedan hung a left from Birch Road.", _K.TURN_LEFT),
        ("a sedan was taking a left into the garage entrance.", _K.TURN_LEFT),
        ("a sedan was in the process of turning right onto Pine Avenue.", _K.TURN_RIGHT),
        ("a sedan was completing a left turn onto Pine Avenue.", _K.TURN_LEFT),
        ("a sedan executed a U-turn across the road.", _K.U_TURN),
        ("a sedan was performing a three-point turn.", _K.U_TURN),
        ("a sedan attempted a K-turn in the roadway.", _K.U_TURN),
    ],
)
def test_a_turn_said_any_way_is_that_turn(move: str, kind: ActionKind) -> None:
    assert partner(move) is kind


@pytest.mark.parametrize(
    "move",
    [
        "a sedan pulled out of a parallel parking spot.",
        "a sedan was pulling out of an angled parking space.",
        "a sedan merged into traffic from the curb.",
        "a sedan accelerated away from the shoulder.",
    ],
)
def test_joining_the_road_from_a_space_the_kerb_or_the_shoulder_is_an_entry(move: str) -> None:
    assert partner(move) is _K.DRIVE_INTO


@pytest.mark.parametrize(
    "move", ["a sedan pulled into a parking space.", "a sedan was pulling forward into a diagonal parking stall."]
)
def test_pulling_into_a_space_leaves_the_road(move: str) -> None:
    assert partner(move) is _K.DRIVE_OFF


@pytest.mark.parametrize(
    ("introduced", "kind"),
    [
        ("a reversing sedan", _K.REVERSE),
        ("a left-turning sedan", _K.TURN_LEFT),
        ("a right-turning sedan", _K.TURN_RIGHT),
        ("a stationary sedan", _K.STOP),
        ("a stopped sedan", _K.STOP),
        ("an idling sedan", _K.STOP),
    ],
)
def test_a_participle_that_introduces_a_road_user_says_what_it_was_doing(introduced: str, kind: ActionKind) -> None:
    s = read(
        "The Zoox robotaxi was traveling south on Pine Avenue. "
        f"{introduced[0].upper()}{introduced[1:]} made contact with the driver side of the Zoox robotaxi."
    )
    assert last(by_id(s, "V2")) is kind


def test_a_state_said_after_the_name_says_what_it_was_doing() -> None:
    s = read(HEAD + "The Zoox robotaxi was traveling south on Pine Avenue when it struck a sedan parked at the curb.")
    assert last(by_id(s, "V2")) is _K.PARKED


@pytest.mark.parametrize(
    "state",
    [
        "The Zoox robotaxi was queued behind traffic on Pine Avenue",
        "The Zoox robotaxi sat queued at the ramp meter on Pine Avenue",
        "The Zoox robotaxi was standing still on Pine Avenue",
        "The Zoox robotaxi was at a complete stop on Pine Avenue",
        "The Zoox robotaxi was motionless at the crosswalk on Pine Avenue",
        "The Zoox robotaxi paused at the stop line on Pine Avenue",
        "The Zoox robotaxi was not moving on Pine Avenue",
        "The Zoox robotaxi sat at the red signal on Pine Avenue",
        "The Zoox robotaxi held its position at the stop line on Pine Avenue",
        "The Zoox robotaxi was pulled over on Pine Avenue for a rider pickup",
    ],
)
def test_standing_said_any_way_is_a_stop(state: str) -> None:
    assert robotaxi(state + STRUCK) is _K.STOP


def test_being_in_a_lane_says_where_not_that_it_stood() -> None:
    assert robotaxi("The Zoox robotaxi was in the right lane on Pine Avenue" + STRUCK) is not _K.STOP


@pytest.mark.parametrize(
    "meant",
    [
        "The Zoox robotaxi was stopped, awaiting a green arrow for a left turn onto Birch Road,",
        "The Zoox robotaxi was waiting at the red light to make a right turn onto Birch Road",
        "The Zoox robotaxi was queued to turn left onto Birch Road",
        "The Zoox robotaxi was lined up to make a right turn onto Birch Road and was stopped",
    ],
)
def test_a_turn_awaited_or_waited_for_is_not_made(meant: str) -> None:
    assert robotaxi(meant + STRUCK) is _K.STOP


def test_a_turn_signalled_is_not_made() -> None:
    assert robotaxi("The Zoox robotaxi signaled a right turn on Pine Avenue" + STRUCK) is not _K.TURN_RIGHT


@pytest.mark.parametrize(
    "told",
    [
        "The Zoox robotaxi turned left onto Birch Road and was traveling east",
        "After turning left onto Birch Road, the Zoox robotaxi was heading east",
        "The Zoox robotaxi had made a left turn onto Birch Road. The Zoox robotaxi was proceeding east on Birch Road",
    ],
)
def test_a_turn_then_driving_along_the_road_turned_onto_is_driving_along(told: str) -> None:
    assert robotaxi(told + STRUCK) is _K.FOLLOW_LANE


@pytest.mark.parametrize(
    "told",
    [
        "The Zoox robotaxi was turning left onto Birch Road",
        "The Zoox robotaxi turned left onto Birch Road and was traveling at 8 mph",
    ],
)
def test_a_turn_under_way_at_the_impact_is_the_turn(told: str) -> None:
    assert robotaxi(told + STRUCK.replace("rear", "passenger side")) is _K.TURN_LEFT


def test_reversing_said_any_way_is_the_reverse() -> None:
    for move in ("a sedan shifted into reverse.", "a sedan was traveling backward.", "a sedan backed away from it."):
        assert partner(move, REAR_HIT) is _K.REVERSE


@pytest.mark.parametrize(
    "move",
    [
        "a sedan parked at the curb began to pull out.",
        "a sedan, parked along the east curb, pulled out.",
        "a sedan pulled out into traffic.",
    ],
)
def test_one_parked_that_moves_off_enters_the_road(move: str) -> None:
    assert partner(move) is _K.DRIVE_INTO


def test_one_pulling_out_to_pass_does_not_enter_the_road() -> None:
    assert partner("a sedan behind it pulled out to pass.") is not _K.DRIVE_INTO


@pytest.mark.parametrize("move", ["a sedan was parallel parking.", "a sedan was attempting to park."])
def test_parking_under_way_is_a_move_into_a_space(move: str) -> None:
    assert partner(move, REAR_HIT) is _K.DRIVE_OFF


@pytest.mark.parametrize(
    ("impact", "kind"),
    [
        ("A sedan struck the stationary Zoox robotaxi.", _K.STOP),
        ("A sedan made contact with the parked Zoox robotaxi.", _K.PARKED),
    ],
)
def test_standing_said_only_at_the_impact_is_what_it_was_doing(impact: str, kind: ActionKind) -> None:
    assert robotaxi(impact) is kind


@pytest.mark.parametrize(
    ("move", "kind"),
    [
        ("a left-turning sedan entered the junction from Birch Road.", _K.TURN_LEFT),
        ("the right-turning sedan cut the corner.", _K.TURN_RIGHT),
        ("a reversing sedan came out from a loading dock.", _K.REVERSE),
    ],
)
def test_a_move_said_before_the_noun_of_one_named_before_is_still_its_move(move: str, kind: ActionKind) -> None:
    assert partner(move, REAR_HIT if kind is _K.REVERSE else FRONT_HIT) is kind


@pytest.mark.parametrize(
    ("move", "kind"),
    [
        # heading north: west is on its left, east on its right
        ("a sedan heading north on Birch Road turned onto westbound Pine Avenue.", _K.TURN_LEFT),
        ("a sedan heading north on Birch Road turned sharply east.", _K.TURN_RIGHT),
        ("a sedan traveling east on Birch Road made a turn onto northbound Pine Avenue.", _K.TURN_LEFT),
    ],
)
def test_a_turn_said_by_the_heading_it_led_to_is_the_turn_to_that_side(move: str, kind: ActionKind) -> None:
    assert partner(move) is kind


def test_a_turn_from_a_heading_says_no_side() -> None:
    assert partner("a sedan heading north made a turn from westbound Birch Road.") not in (_K.TURN_LEFT, _K.TURN_RIGHT)


def test_a_turn_across_the_path_of_another_is_a_left_turn() -> None:
    assert partner("a sedan coming the other way turned across the path of the Zoox robotaxi.") is _K.TURN_LEFT


JUNCTION = "A Zoox robotaxi was in a collision involving a sedan at the intersection of Pine Avenue and Birch Road. "


def test_moving_off_after_waiting_to_turn_is_the_turn() -> None:
    s = read(
        JUNCTION + "The Zoox robotaxi was stopped at the stop line on Pine Avenue, waiting to turn left onto Birch "
        "Road. Once the cross traffic cleared, the Zoox robotaxi began to move forward into the intersection. A "
        "sedan made contact with the passenger side of the Zoox robotaxi."
    )
    assert last(by_id(s, "V1")) is _K.TURN_LEFT


def test_still_standing_after_waiting_to_turn_is_a_stop() -> None:
    s = read(
        JUNCTION + "The Zoox robotaxi was stopped at the stop line on Pine Avenue, waiting to turn left onto Birch "
        "Road. A sedan made contact with the rear of the Zoox robotaxi."
    )
    assert last(by_id(s, "V1")) is _K.STOP


@pytest.mark.parametrize(
    "stop",
    [
        "The Zoox robotaxi stopped before entering the intersection with Birch Road",
        "The Zoox robotaxi came to a complete stop just before crossing Birch Road",
    ],
)
def test_a_stop_before_a_move_is_short_of_it(stop: str) -> None:
    s = read(JUNCTION + stop + ". A sedan made contact with the driver side rear of the Zoox robotaxi.")
    assert last(by_id(s, "V1")) is _K.STOP


@pytest.mark.parametrize(
    "move", ["a sedan pulled away from the bus stop.", "a sedan pulled out of a loading zone on the right."]
)
def test_leaving_a_place_at_the_road_edge_is_an_entry(move: str) -> None:
    assert partner(move) is _K.DRIVE_INTO


def test_one_placed_ahead_of_another_that_stopped_is_the_one_that_stopped() -> None:
    s = read(
        HEAD + "The Zoox robotaxi was traveling south on Pine Avenue. A sedan ahead of the Zoox robotaxi stopped "
        "abruptly. The front of the Zoox robotaxi made contact with the rear of the sedan."
    )
    assert last(by_id(s, "V2")) is _K.STOP


@pytest.mark.parametrize(
    "move",
    [
        "a sedan was performing a reverse maneuver.",
        "a sedan began a backing movement.",
        "a sedan was reverse parking.",
        "a sedan shifted to reverse.",
        "a sedan engaged reverse gear.",
        "a sedan moved rearward.",
        "a sedan was going backwards.",
        "a sedan began to roll back.",
        "a sedan backed.",
    ],
)
def test_backing_said_as_a_noun_a_gear_or_a_direction_is_the_reverse(move: str) -> None:
    assert partner(move, REAR_HIT) is _K.REVERSE
