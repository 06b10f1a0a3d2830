"""Kinds of language in fleet narratives that name who met whom, each on sentences written for these tests:
corners named from a side, a bare side of passing, "rear ended" spelt open, the striker behind the victim,
lane changes said any way, and the report's own labels used beside its short names."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.crash import _kind, read_sentence
from sovarc.dsl.ir import ActionKind, CrashType, Scenario, Side, Unknown
from sovarc.dsl.span import Source


def read(text: str) -> Scenario:
    return FrontEnd("none").extract(Source("sgo.txt", text)).scenario


def actions(s: Scenario, pid: str) -> list[tuple[ActionKind, object]]:
    p = next(p for p in s.participants if p.id == pid)
    return [] if isinstance(p.actions, Unknown) else [(a.kind, a.to) for a in p.actions]


@pytest.mark.parametrize(
    ("part", "kind"),
    [
        ("driver's side rear", CrashType.REAR_END),  # an end named after a side: that end's corner
        ("passenger side front", CrashType.FRONTAL),
        ("rear left sensor", CrashType.REAR_END),
        ("front left fender", CrashType.FRONTAL),
        ("rear quarter panel", CrashType.REAR_END),
        ("left rear quarter panel", CrashType.SIDE),  # the head noun is the side's panel
        ("right front side", CrashType.SIDE),  # the front half of a side, as the labelled reports read it
        ("rear driver side door", CrashType.SIDE),  # a door is on a side, whatever end it is near
        ("passenger side mirror", CrashType.SIDE),
        ("cab", CrashType.FRONTAL),
        ("tailgate", CrashType.REAR_END),
        ("bumper", None),  # front or rear: not said
    ],
)
def test_a_part_is_an_end_or_a_side(part: str, kind: CrashType | None) -> None:
    assert _kind(part) is kind


def test_passing_on_a_side_is_no_part() -> None:
    """ "pass V1 on the left" says where V2 went, not which part of V1 was struck."""
    crash = read_sentence(
        "V2 moved out to pass the stopped V1 on the left and the front right corner of V2 struck the rear left "
        "corner of V1."
    )
    assert crash is not None and (crash.striker, crash.victim, crash.type) == ("V2", "V1", CrashType.REAR_END)


@pytest.mark.parametrize(
    "sentence",
    [
        "V1 was waiting at the light when it was rear ended by V2.",
        "V2 rear ended the stationary V1 at the light.",
        "V1 was slowing in traffic when V2 behind made contact with it.",
        "V1 was stopped at the light when V2 struck V1 from the rear.",
        "V1 was braking for a queue when V2, which was traveling directly behind, made contact with V1's bumper.",
    ],
)
def test_one_that_comes_from_behind_strikes_the_rear(sentence: str) -> None:
    crash = read_sentence(sentence)
    assert crash is not None and (crash.striker, crash.victim, crash.type) == ("V2", "V1", CrashType.REAR_END)


def test_a_bumper_met_by_a_follower_is_the_rear() -> None:
    s = read(
        "The Waymo AV was slowing for a queue on [XXX] when a sedan behind the Waymo AV sped up and the front of "
        "the sedan made contact with the bumper of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim, s.crash.type) == ("V2", "V1", CrashType.REAR_END)


AV = "On June [XXX], 2024 at 9:10 AM PT a Waymo Autonomous Vehicle (Waymo AV) was in a collision involving a sedan. "


@pytest.mark.parametrize(
    ("said", "side"),
    [
        ("the sedan, in the left adjacent lane, initiated a right lane change", Side.RIGHT),  # side before
        ("the sedan began to lane change left", Side.LEFT),  # side after
        ("the sedan traveling in the rightmost lane began to change lanes into the center lane", Side.LEFT),
        ("the sedan traveling in the left adjacent lane drifted into the Waymo AV's lane", Side.RIGHT),
        ("the sedan maneuvered into the left turn lane to get by", Side.LEFT),
        ("the sedan changed lanes, passing the Waymo AV on the left", Side.LEFT),
    ],
)
def test_a_lane_change_goes_to_the_lane_entered_or_away_from_the_lane_left(said: str, side: Side) -> None:
    s = read(
        AV + f"The Waymo AV was traveling north on [XXX] in the center lane when {said}, and the passenger side of "
        "the sedan made contact with the driver side of the Waymo AV."
    )
    assert (ActionKind.CHANGE_LANE, side) in actions(s, "V2")
    assert ActionKind.CHANGE_LANE not in [k for k, _ in actions(s, "V1")]


def test_a_participant_beside_another_is_an_object() -> None:
    """ "alongside V1", "around V1" name V1 as an object: what follows is still the subject's doing."""
    s = read(
        AV + "The Waymo AV was traveling west on [XXX]. The sedan traveling alongside the Waymo AV initiated a "
        "right lane change, and the front passenger side of the sedan made contact with the driver side of the "
        "Waymo AV."
    )
    assert (ActionKind.CHANGE_LANE, Side.RIGHT) in actions(s, "V2")
    assert [k for k, _ in actions(s, "V1")] == [ActionKind.FOLLOW_LANE]


def test_an_object_said_in_a_state_is_the_subject_of_it() -> None:
    s = read(
        AV + "The Waymo AV was traveling north on [XXX] when it approached the sedan stopped in the left lane. "
        "As the Waymo AV was passing, the rear door of the sedan opened and made contact with the Waymo AV."
    )
    assert [k for k, _ in actions(s, "V1")] == [ActionKind.FOLLOW_LANE]
    assert actions(s, "V2")[-1][0] is ActionKind.STOP


def test_an_opportunity_to_change_lanes_is_not_a_lane_change() -> None:
    s = read(
        AV + "The Waymo AV was stopped in the right lane, awaiting an opportunity to move into the left lane, when "
        "the sedan behind it made contact with the rear of the Waymo AV."
    )
    assert [k for k, _ in actions(s, "V1")] == [ActionKind.STOP]


def test_an_unnumbered_road_user_does_not_act_for_a_participant() -> None:
    s = read(
        AV + "The Waymo AV was traveling in the middle lane when a slower van in the left lane began a right lane "
        "change in front of the Waymo AV, and the Waymo AV braked. The sedan traveling behind the Waymo AV then "
        "made contact with the rear of the Waymo AV."
    )
    assert ActionKind.CHANGE_LANE not in [k for k, _ in actions(s, "V1")]
    assert (s.crash.striker, s.crash.type) == ("V2", CrashType.REAR_END)


@pytest.mark.parametrize(
    "said",
    [
        "the sedan in the oncoming lane veered out of its lane and made contact with the left side of the Waymo AV",
        "the sedan traveling in the opposite lane swerved into the Waymo AV's lane, contacting the front of the "
        "Waymo AV",
    ],
)
def test_out_of_the_oncoming_lane_into_anothers_is_the_wrong_side(said: str) -> None:
    s = read(AV + f"The Waymo AV was traveling east on [XXX] when {said}.")
    assert actions(s, "V2")[-1][0] is ActionKind.RETROGRADE


def test_out_of_its_own_lane_is_a_lane_change_away_from_it() -> None:
    s = read(
        AV + "The Waymo AV was traveling east on [XXX] in the right lane. The sedan in the left lane drifted out of "
        "its lane and its passenger side made contact with the driver side of the Waymo AV."
    )
    assert (ActionKind.CHANGE_LANE, Side.RIGHT) in actions(s, "V2")


@pytest.mark.parametrize(
    "said",
    [
        "In autonomy, the Waymo AV came to a stop at the light. The sedan behind the Waymo AV then rear-ended it.",
        "As the Waymo AV moved ahead, yielding to approaching traffic, it stopped again. The sedan traveling "
        "behind the Waymo AV then made contact with the rear of the Waymo AV.",
        "The Waymo AV was slowing to a gradual stop for a light when it was rear-ended by the sedan.",
        "The Waymo AV was leaving a parking lot and yielding to traffic as it stopped at the curb line, when the "
        "sedan made contact with the rear of the Waymo AV.",
    ],
)
def test_a_stop_said_any_way_is_the_last_move(said: str) -> None:
    """A pronoun after the other road users ("traffic, it stopped") is the participant again; "came to a stop"
    describes a vehicle."""
    s = read(AV + said)
    assert actions(s, "V1")[-1][0] is ActionKind.STOP


@pytest.mark.parametrize(
    ("sentence", "tower", "want"),
    [
        # a trailer's rear is its tower's rear; a cab is the front of its truck, whichever side of it met
        (
            "As V2 pulled ahead, its trailer (the left side, rear section) drifted over and made contact with the "
            "passenger side of V1 cab.",
            None,
            ("V1", "V2", CrashType.REAR_END),
        ),
        (
            "V1 was waiting when the driver side of the box trailer attached to V2 made contact with the front "
            "driver side corner of V1.",
            None,
            ("V1", "V2", CrashType.SIDE),
        ),
        (
            "V1 braked late and made contact with the rear of the flat-bed trailer.",
            "V2",
            ("V1", "V2", CrashType.REAR_END),
        ),
        # "to the left of V1" is where V2 went, not a part of V1
        (
            "V2 moved up to the left of V1 and the driver side of V2 made contact with the front passenger side of V1.",
            None,
            ("V1", "V2", CrashType.SIDE),
        ),
    ],
)
def test_a_trailer_or_a_cab_is_part_of_its_vehicle(sentence: str, tower: str | None, want: tuple) -> None:
    crash = read_sentence(sentence, None, tower)
    assert crash is not None and (crash.striker, crash.victim, crash.type) == want


def test_the_report_says_which_vehicle_tows_the_trailer() -> None:
    s = read(
        "On May [XXX], 2024 a Waymo Autonomous Vehicle (Waymo AV) was in a collision involving a pickup truck and "
        "trailer on [XXX]. The pickup truck towing a utility trailer was passing the Waymo AV on the left. The "
        "Waymo AV slowed, and the front of the Waymo AV made contact with the rear corner of the utility trailer."
    )
    assert (s.crash.striker, s.crash.victim, s.crash.type) == ("V1", "V2", CrashType.REAR_END)


def test_driving_around_another_describes_the_vehicle() -> None:
    """ "drove around the Waymo AV" is a move: the sedan is described, and goes by on the side said."""
    s = read(
        AV + "The Waymo AV was stopped at the curb. The sedan drove around the left side of the Waymo AV and its "
        "rear passenger side made contact with the rear driver side door of the Waymo AV."
    )
    assert actions(s, "V2") == [(ActionKind.FOLLOW_LANE, None), (ActionKind.CHANGE_LANE, Side.LEFT)]


@pytest.mark.parametrize(
    "said",
    [
        "the sedan pulled out of the parked position on the right and made contact with the Waymo AV",
        "the sedan pulled away from the curb and made contact with the Waymo AV",
        "the sedan, departing a parking space, made contact with the Waymo AV",
    ],
)
def test_leaving_the_curb_or_a_parking_space_enters_the_road(said: str) -> None:
    s = read(AV + f"The Waymo AV was traveling north on [XXX] at the intersection with [XXX] when {said}.")
    assert [k for k, _ in actions(s, "V2")][-1] is ActionKind.DRIVE_INTO


@pytest.mark.parametrize(
    "said",
    [
        "slowed to a stop in anticipation of turning right into a driveway",
        "came to a stop at the light in preparation for a left turn",
        "came to a stop for a pedestrian as it prepared to make a right turn",
        "remained stopped at the line to await an opening to complete the left turn",
    ],
)
def test_getting_ready_to_turn_is_not_the_turn(said: str) -> None:
    s = read(
        AV + f"The Waymo AV was traveling north on [XXX] and {said} at the intersection with [XXX]. The sedan "
        "behind the Waymo AV then made contact with the rear of the Waymo AV."
    )
    assert actions(s, "V1")[-1][0] is ActionKind.STOP


def test_in_a_chain_collision_the_crash_is_the_automated_vehicles() -> None:
    s = read(
        "On June [XXX], 2024 a Waymo Autonomous Vehicle (Waymo AV) was in a collision involving two sedans. The "
        "Waymo AV was stopped at a red light with a sedan (Vehicle 2) behind it. Vehicle 2 was rear-ended by a "
        "pickup truck (Vehicle 3), pushing the front of Vehicle 2 to make contact with the rear of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim, s.crash.type) == ("V2", "V1", CrashType.REAR_END)


@pytest.mark.parametrize(
    "said",
    [
        "the sedan behind the Waymo AV passed it by driving in the oncoming traffic lane",
        "the sedan passed the Waymo AV in the opposing lane",
        "the sedan passed the Waymo AV using the opposing lane",  # "using" says how the sedan passed
    ],
)
def test_passing_by_way_of_the_oncoming_lane_is_the_wrong_side(said: str) -> None:
    s = read(
        AV + f"The Waymo AV was stopped at a stop sign on [XXX] when {said}, and the passenger side of the sedan "
        "made contact with the driver side of the Waymo AV."
    )
    assert actions(s, "V2")[-1][0] is ActionKind.RETROGRADE


@pytest.mark.parametrize(
    "said",
    [
        "the sedan directly behind the Waymo AV attempted to pass the left side of the Waymo AV",
        "the sedan immediately behind the Waymo AV began to accelerate toward the right side of the Waymo AV",
    ],
)
def test_a_vehicle_passing_or_accelerating_is_described(said: str) -> None:
    s = read(AV + f"The Waymo AV was stopped at a red light on [XXX] when {said} and made contact with it.")
    assert actions(s, "V2") != []


def test_a_striker_behind_the_other_was_driving() -> None:
    s = read(AV + "The Waymo AV was slowing in traffic on [XXX] when the sedan behind made contact at 10 mph.")
    assert actions(s, "V2") == [(ActionKind.FOLLOW_LANE, None)]
