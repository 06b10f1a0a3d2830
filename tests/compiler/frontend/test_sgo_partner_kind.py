"""Who the partner is and what kind (issue 18, sgo10c), on sentences written for these tests: a partner told with
no kind, or a wider one, whose kind another of its mentions, the narrative's overview or the road user introduced
before it says; body words; a fleet's name before a model; road users that only say where another was; two of one
kind told apart by colour, and the refusal where nothing tells them apart."""

from __future__ import annotations

import pytest
from sovarc.compiler.evaluation.sgo import parties
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.choice import FrontEndError
from sovarc.dsl.ir import UNKNOWN, Scenario, VehicleKind
from sovarc.dsl.span import Source

from tests.compiler.frontend.sgo_reading import read


def partner(s: Scenario) -> VehicleKind:
    cp = parties(s)[1]
    assert cp is not None and [p.id for p in s.participants] == ["V1", cp.id]
    return cp.kind


def overview(verb: str, user: str) -> str:
    return f"On May 2, 2024 at 3:10 PM a Waymo Autonomous Vehicle operating in Phoenix {verb} {user} on Oak Street. "


@pytest.mark.parametrize(
    "verb", ["was in a collision involving", "was in a collision with", "was involved in a collision with"]
)
@pytest.mark.parametrize(
    ("user", "kind"),
    [
        ("a passenger car", VehicleKind.CAR),
        ("an SUV", VehicleKind.CAR),
        ("a box truck", VehicleKind.TRUCK),
        ("a motorcycle", VehicleKind.MOTORCYCLE),
        ("a pickup truck", VehicleKind.PICKUP),
        ("a city bus", VehicleKind.BUS),
    ],
)
@pytest.mark.parametrize(
    "told",
    [
        "A vehicle approached from behind and made contact with the rear bumper of the Waymo AV.",
        "The vehicle immediately behind the Waymo AV made contact with the rear bumper of the Waymo AV.",
        "The other vehicle made contact with the rear bumper of the Waymo AV.",
        "The Waymo AV was rear-ended by a vehicle that had been following it.",
    ],
)
def test_a_partner_told_with_no_kind_is_the_road_user_the_overview_names(
    verb: str, user: str, kind: VehicleKind, told: str
) -> None:
    s = read(overview(verb, user) + "The Waymo AV was stopped at a red light on northbound Oak Street. " + told)
    assert partner(s) is kind


@pytest.mark.parametrize(
    ("introduced", "later", "kind"),
    [
        ("a passenger vehicle", "The vehicle", VehicleKind.CAR),
        ("a pick-up truck", "The oncoming truck", VehicleKind.PICKUP),
        ("a box truck", "The truck", VehicleKind.TRUCK),
        ("a passenger car", "The car", VehicleKind.CAR),
    ],
)
def test_a_later_mention_with_a_wider_noun_keeps_the_kind_it_was_introduced_with(
    introduced: str, later: str, kind: VehicleKind
) -> None:
    s = read(
        "A Waymo AV was traveling north on Oak Street in autonomous mode. "
        f"{introduced[0].upper() + introduced[1:]} in the oncoming lane veered out of its lane and into the "
        f"northbound lane. {later} made contact with the left rear door of the Waymo AV."
    )
    assert partner(s) is kind


def test_a_partner_said_only_by_a_part_of_it_is_the_road_user_the_overview_names() -> None:
    s = read(
        overview("was in a collision involving", "a heavy truck")
        + "The Waymo AV was stopped for a passenger drop off, with a heavy truck parked directly in front of it. "
        "The Waymo AV then came to a stop to yield to an SUV that was approaching in the left lane. "
        "As the Waymo AV was proceeding forward, the corner of the lowered loading ramp made contact with the "
        "passenger side of the Waymo AV."
    )
    assert partner(s) is VehicleKind.TRUCK


def test_an_overview_of_several_road_users_names_no_one_partner() -> None:
    s = read(
        overview("was in a collision involving", "two passenger vehicles")
        + "The Waymo AV was stopped at a red light. A vehicle approached from behind and made contact with the "
        "rear bumper of the Waymo AV."
    )
    cp = parties(s)[1]
    assert cp is not None and cp.kind is UNKNOWN


def test_a_partner_told_with_its_kind_keeps_it_against_the_overview() -> None:
    s = read(
        overview("was in a collision involving", "a passenger car")
        + "The Waymo AV was stopped at a red light. A cyclist riding on the sidewalk entered the crosswalk and "
        "made contact with the rear passenger door of the Waymo AV."
    )
    assert partner(s) is VehicleKind.BICYCLE


def test_the_words_that_introduce_a_partner_still_say_what_it_was_doing() -> None:
    s = read(
        overview("was in a collision involving", "a passenger car")
        + "The Waymo AV was stopped at a red light. An approaching vehicle made contact with the rear bumper of "
        "the Waymo AV."
    )
    cp = parties(s)[1]
    assert cp is not None and cp.kind is VehicleKind.CAR
    assert isinstance(cp.actions, tuple) and [a.kind.value for a in cp.actions] == ["follow_lane"]


@pytest.mark.parametrize(
    ("user", "kind"),
    [
        ("A crossover", VehicleKind.CAR),
        ("A jeep", VehicleKind.CAR),
        ("A station wagon", VehicleKind.CAR),
        ("A semi", VehicleKind.TRUCK),
        ("An 18-wheeler", VehicleKind.TRUCK),
        ("A box truck", VehicleKind.TRUCK),
        ("A minivan", VehicleKind.VAN),
        ("A moped", VehicleKind.MOTORCYCLE),
        ("A motorbike", VehicleKind.MOTORCYCLE),
        ("An e-bike", VehicleKind.BICYCLE),
        ("An ebike", VehicleKind.BICYCLE),
        ("A scooter", VehicleKind.BICYCLE),
        ("A Honda motorcycle", VehicleKind.MOTORCYCLE),
    ],
)
def test_a_partner_named_by_a_body_word_is_that_kind(user: str, kind: VehicleKind) -> None:
    s = read(f"A Waymo AV was stopped at a red light on Oak Street. {user} made contact with the rear of the Waymo AV.")
    assert partner(s) is kind


@pytest.mark.parametrize(
    "named",
    [
        "A Nuro Prius operating in manual mode",
        "A Nuro Prius operating in autonomous mode",
        "The Waymo Pacifica, in autonomous mode,",
        "A Cruise Bolt with its ADS engaged",
    ],
)
def test_a_fleets_name_before_a_cars_model_is_the_automated_vehicle(named: str) -> None:
    fleet, model = named.split()[1:3]
    model = model.rstrip(",")
    s = read(
        f"{named} was stopped at a red light on Oak Street. A sedan traveling behind the {fleet} {model} made "
        f"contact with the rear of the {fleet} {model}."
    )
    assert partner(s) is VehicleKind.CAR
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


def test_a_carmakers_name_before_its_model_is_no_fleet() -> None:
    s = read(
        "A Toyota Prius was traveling north on Oak Street. A Zoox vehicle in autonomous mode was stopped at a red "
        "light ahead of it. The Toyota Prius made contact with the rear of the Zoox vehicle."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


@pytest.mark.parametrize(
    ("where", "kind"),
    [
        ("traveling directly behind a heavy truck", VehicleKind.CAR),
        ("traveling in the right lane behind the box truck the Waymo AV had yielded to", VehicleKind.CAR),
        ("passing between the Waymo AV and a parked passenger vehicle", VehicleKind.CAR),
        ("traveling next to a city bus", VehicleKind.CAR),
        ("stopped in front of a pickup truck", VehicleKind.CAR),
        ("traveling alongside a parked van", VehicleKind.CAR),
    ],
)
def test_a_road_user_that_only_says_where_the_partner_was_is_no_party(where: str, kind: VehicleKind) -> None:
    s = read(
        "A Waymo AV was stopped at a red light on Oak Street, yielding to a box truck. "
        f"A sedan {where} made contact with the rear of the Waymo AV."
    )
    assert partner(s) is kind


def test_a_road_user_said_where_it_was_and_then_meeting_the_automated_vehicle_is_the_partner() -> None:
    s = read(
        "A Waymo AV was stopped on Oak Street behind a box truck when the box truck reversed and made contact with "
        "the front of the Waymo AV."
    )
    assert partner(s) is VehicleKind.TRUCK


@pytest.mark.parametrize(("one", "other"), [("white", "black"), ("silver", "red"), ("gray", "blue")])
def test_two_road_users_of_one_kind_told_apart_by_colour_are_two(one: str, other: str) -> None:
    s = read(
        f"A Waymo AV was traveling north on Oak Street. A {one} sedan was stopped at a red light ahead of the "
        f"Waymo AV, and the Waymo AV stopped behind the {one} sedan. A {other} sedan traveling north approached "
        f"from behind and made contact with the rear of the Waymo AV. The {one} sedan then drove away."
    )
    cp = parties(s)[1]
    assert cp is not None and [p.id for p in s.participants] == ["V1", cp.id]
    assert isinstance(cp.actions, tuple) and [a.kind.value for a in cp.actions] == ["follow_lane"]


@pytest.mark.parametrize(
    ("introduced", "kind"),
    [("A minivan", VehicleKind.VAN), ("A city bus", VehicleKind.BUS), ("A motorcycle", VehicleKind.MOTORCYCLE)],
)
def test_the_vehicle_said_with_nothing_picking_it_out_is_the_road_user_introduced_before_it(
    introduced: str, kind: VehicleKind
) -> None:
    s = read(
        "A Waymo AV was traveling north on Oak Street in autonomous mode. "
        f"{introduced} in the oncoming lane veered out of its lane and into the northbound lane. "
        "The vehicle made contact with the left rear door of the Waymo AV."
    )
    assert partner(s) is kind


def test_the_vehicle_a_phrase_picks_out_is_not_the_road_user_introduced_before_it() -> None:
    s = read(
        "A Waymo AV was stopped at a red light on Oak Street behind a box truck. The vehicle behind the Waymo AV "
        "made contact with the rear of the Waymo AV."
    )
    cp = parties(s)[1]
    assert cp is not None and cp.kind is UNKNOWN


@pytest.mark.parametrize(
    "text",
    [
        "A white Toyota was stopped at the light on Oak Street. A black Toyota struck the white Toyota from behind.",
        "A red sedan was stopped at the light on Oak Street. A blue sedan traveling north struck the red sedan from "
        "behind.",
    ],
)
def test_two_road_users_of_one_make_or_kind_told_apart_by_colour_are_read_in_any_report(text: str) -> None:
    s = read(text)
    assert [p.id for p in s.participants] == ["V1", "V2"]
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


@pytest.mark.parametrize(
    "text",
    [
        "A Toyota was stopped at the light. Another Toyota struck the Toyota from behind.",
        "A white Toyota was stopped at the light. A white Toyota struck the white Toyota from behind.",
        "A white Toyota was stopped at the light. Another Toyota struck the Toyota from behind.",
    ],
)
def test_two_road_users_no_reading_tells_apart_are_refused_naming_the_file_and_the_reason(text: str) -> None:
    with pytest.raises(FrontEndError, match=r"alike\.txt: two road users are named alike"):
        FrontEnd("none").extract(Source("alike.txt", text))


@pytest.mark.parametrize(
    ("told", "kind"),
    [
        (
            "Shortly after the Waymo AV came to a stop, the SUV behind the Waymo AV was rear-ended by a pickup truck, "
            "and the SUV then made contact with the rear of the Waymo AV.",
            VehicleKind.CAR,
        ),
        (
            "A minivan traveling behind the Waymo AV was struck by a box truck, and the minivan then struck the rear "
            "of the Waymo AV.",
            VehicleKind.VAN,
        ),
        (
            "The city bus behind the Waymo AV was hit by a sedan; the city bus then made contact with the rear of "
            "the Waymo AV.",
            VehicleKind.BUS,
        ),
    ],
)
def test_in_a_chain_the_partner_is_the_one_in_the_automated_vehicles_own_meeting(told: str, kind: VehicleKind) -> None:
    s = read(
        "A Waymo Autonomous Vehicle was traveling west on Oak Street in autonomous mode and stopped for a red "
        f"light. {told}"
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")
    assert next(p for p in s.participants if p.id == "V2").kind is kind


def test_a_first_clause_that_tells_no_meeting_is_not_cut_off() -> None:
    s = read(
        "A Waymo AV was stopped at a red light on Oak Street. A sedan traveling behind the Waymo AV braked late, "
        "and struck the rear of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")
    assert partner(s) is VehicleKind.CAR
