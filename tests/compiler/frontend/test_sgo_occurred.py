"""A partner named where the report says only that a collision occurred, or by a noun for a vehicle of a trade ("a
taxi", "an ambulance") (issue 18, sgo8), on sentences written for
these tests; and a road user's words broken across a line, as narratives wrapped at a fixed width break them."""

from __future__ import annotations

import pytest
from sovarc.dsl.ir import ActionKind, VehicleKind

from tests.compiler.frontend.sgo_reading import by_id, read


def test_the_other_party_of_a_collision_that_occurred_is_named() -> None:
    s = read(
        "An autonomous shuttle was driving in autonomous mode along the service road of a campus. A delivery van "
        "began reversing out of a loading bay into the path of the autonomous shuttle. Although the autonomous "
        "shuttle had almost stopped, a collision still occurred, causing damage to the rear of the delivery van."
    )
    assert [p.id for p in s.participants] == ["V1", "V2"]
    v2 = by_id(s, "V2")
    assert v2.kind is VehicleKind.VAN
    assert isinstance(v2.actions, tuple) and v2.actions[-1].kind is ActionKind.REVERSE


def test_a_road_users_words_broken_across_a_line_are_still_its_words() -> None:
    s = read(
        "An autonomous shuttle was driving in autonomous mode along the service road of a campus. A parked passenger\n"
        "vehicle began reversing out of a space into the path of the autonomous shuttle. The front of the autonomous "
        "shuttle made contact with the rear of the passenger vehicle."
    )
    v2 = by_id(s, "V2")
    assert isinstance(v2.actions, tuple) and v2.actions[-1].kind is ActionKind.REVERSE


@pytest.mark.parametrize(
    ("words", "kind"),
    [("a taxi", VehicleKind.CAR), ("a limousine", VehicleKind.CAR), ("a convertible", VehicleKind.CAR)],
)
def test_a_partner_named_by_any_noun_for_a_vehicle_is_found(words: str, kind: VehicleKind) -> None:
    s = read(
        f"A Waymo Autonomous Vehicle was in a collision involving {words} on Pine Avenue. The Waymo AV was stopped "
        f"at a red light on northbound Pine Avenue. {words.capitalize()} traveling north behind the Waymo AV made "
        "contact with the rear of the Waymo AV."
    )
    v2 = by_id(s, "V2")
    assert v2.kind is kind
    assert isinstance(v2.actions, tuple) and v2.actions[-1].kind is ActionKind.FOLLOW_LANE


def test_an_ambulance_is_a_road_user() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving an ambulance on Pine Avenue. The Waymo AV was "
        "stopped on northbound Pine Avenue. An ambulance traveling north behind the Waymo AV made contact with the "
        "rear of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


def test_a_partner_named_by_model_year_and_make_is_found() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision on Pine Avenue. The Waymo AV was stopped at a red light on "
        "northbound Pine Avenue when a 2015 Honda Civic traveling north behind the Waymo AV made contact with the "
        "rear of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")
