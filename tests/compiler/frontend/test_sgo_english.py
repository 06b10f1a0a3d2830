"""General facts of English about the impact (issue 18, sgo9), on sentences written for these tests: verbs of a
violent blow into another, a collision said to occur between two parties, an impact sentence opening on "It",
the automated vehicle's own impact in a narrative of three road users, and a count after a vehicle's noun."""

from __future__ import annotations

import pytest
from sovarc.dsl.ir import UNKNOWN, ActionKind, CrashType, Participant, VehicleKind

from tests.compiler.frontend.sgo_reading import by_id, read

HEAD = "A Waymo Autonomous Vehicle was in a collision involving a passenger car on Oak Street. "


def last(p: Participant) -> ActionKind:
    assert isinstance(p.actions, tuple)
    return p.actions[-1].kind


@pytest.mark.parametrize("verb", ["bumped into", "smashed into", "slammed into", "plowed into"])
def test_a_blow_into_another_is_an_impact_with_the_subject_as_striker(verb: str) -> None:
    s = read(
        HEAD + "The Waymo AV was stopped at a red light on northbound Oak Street. A passenger car traveling north "
        f"behind the Waymo AV {verb} the rear of the Waymo AV."
    )
    assert (s.crash.type, s.crash.striker, s.crash.victim) == (CrashType.REAR_END, "V2", "V1")
    assert last(by_id(s, "V1")) is ActionKind.STOP


def test_slamming_on_the_brakes_is_no_impact() -> None:
    s = read(
        HEAD + "The Waymo AV was traveling north on Oak Street. The Waymo AV slammed on its brakes. A passenger car "
        "traveling north behind the Waymo AV made contact with the rear of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


@pytest.mark.parametrize(
    "meeting",
    [
        "A collision occurred between the Waymo AV and the passenger car.",
        "The Waymo AV and the passenger car collided.",
    ],
)
def test_a_collision_between_two_names_both_parties_and_no_striker(meeting: str) -> None:
    s = read(
        HEAD + "The Waymo AV was traveling north on Oak Street. A passenger car traveling south turned left in "
        f"front of the Waymo AV. {meeting}"
    )
    assert [p.id for p in s.participants] == ["V1", "V2"]
    assert last(by_id(s, "V2")) is ActionKind.TURN_LEFT
    assert s.crash.striker is UNKNOWN


def test_a_collision_that_occurred_is_still_the_scene() -> None:
    s = read(
        HEAD + "The collision occurred on Oak Street. The Waymo AV was stopped at a red light. A passenger car "
        "traveling north made contact with the rear of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


def test_it_was_struck_is_about_the_one_named_before() -> None:
    s = read(
        HEAD + "The Waymo AV was stopped at a red light on northbound Oak Street. It was rear-ended by a passenger "
        "car traveling north."
    )
    assert (s.crash.type, s.crash.striker, s.crash.victim) == (CrashType.REAR_END, "V2", "V1")
    assert last(by_id(s, "V1")) is ActionKind.STOP


def test_it_struck_is_about_the_one_named_before() -> None:
    s = read(
        HEAD + "The Waymo AV was stopped at a red light on northbound Oak Street. A passenger car traveling north "
        "approached from behind. It rear-ended the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


def test_it_was_dark_is_still_the_scene() -> None:
    s = read(
        HEAD + "It was dark. The Waymo AV was stopped at a red light. A passenger car traveling north made contact "
        "with the rear of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


def test_the_partner_is_the_road_user_of_the_automated_vehicles_own_impact() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was traveling north on Oak Street. A pickup truck traveling south turned left "
        "across the Waymo AV's path and made contact with a sedan traveling north in the left lane. The sedan was "
        "pushed into the Waymo AV, and the left side of the sedan made contact with the front of the Waymo AV."
    )
    met = {s.crash.striker, s.crash.victim}
    assert "V1" in met
    (partner,) = met - {"V1"}
    assert isinstance(partner, str)
    assert by_id(s, partner).kind is VehicleKind.CAR


def test_a_count_after_a_vehicles_noun_numbers_nothing() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was stopped at a red light on northbound Oak Street. A passenger vehicle two "
        "vehicles behind the Waymo AV changed lanes to the left and made contact with the rear of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")
    assert by_id(s, "V2").kind is VehicleKind.CAR
