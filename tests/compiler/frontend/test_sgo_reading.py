"""SGO-style narratives (an automated vehicle and the road user it met, named in words): each kind of language
the rules front end reads, on sentences written for these tests."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd
from sovarc.dsl.ir import Action, ActionKind, CrashType, Lighting, Scenario, Unknown
from sovarc.dsl.span import Source

SUMMARY = (
    "On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle (Waymo AV) was in a collision involving {} on [XXX]. "
)


def read(text: str) -> Scenario:
    return FrontEnd("none").extract(Source("sgo.txt", text)).scenario


def last(s: Scenario, pid: str) -> ActionKind | None:
    p = next(p for p in s.participants if p.id == pid)
    return None if isinstance(p.actions, Unknown) else p.actions[-1].kind


@pytest.mark.parametrize(
    "impact",
    [
        "when it was rear-ended by a passenger car",
        "when it was struck by a passenger car from behind",
        "when it was hit by a passenger car from behind",
    ],
)
def test_the_by_agent_of_a_passive_strikes(impact: str) -> None:
    s = read(f"The Waymo AV was stopped at a red light on [XXX] {impact}.")
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")
    assert last(s, "V1") is ActionKind.STOP


def test_a_summary_opening_is_not_the_impact() -> None:
    s = read(
        SUMMARY.format("a passenger car")
        + "The Waymo AV was traveling north on [XXX] and came to a stop at a red light. The passenger car, "
        "following behind the Waymo AV, made contact with the rear of the stationary Waymo AV."
    )
    assert s.crash.type is CrashType.REAR_END and s.crash.striker == "V2"
    assert last(s, "V1") is ActionKind.STOP
    assert last(s, "V2") is ActionKind.FOLLOW_LANE  # "the stationary V1" is V1's state, not V2's


def test_parts_named_from_an_end_decide_the_striker() -> None:
    """The party whose front met the other's side or rear is the striker, whoever the grammatical subject."""
    s = read(
        SUMMARY.format("an SUV")
        + "The Waymo AV was proceeding through the intersection when the SUV began to make a right turn, and the "
        "rear passenger side of the SUV made contact with the front driver side of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.type) == ("V1", CrashType.REAR_END)
    assert last(s, "V2") is ActionKind.TURN_RIGHT


def test_only_the_objects_front_named_makes_it_the_striker() -> None:
    s = read(
        SUMMARY.format("a pickup truck")
        + "The Waymo AV was traveling east on [XXX]. The pickup truck entered the intersection against its red "
        "light, making contact with the front of the Waymo AV."
    )
    assert s.crash.striker == "V1"


def test_its_part_after_contact_with_is_the_other_partys() -> None:
    s = read(
        "The Cruise AV was proceeding through the intersection when a pickup truck began to make a right turn "
        "and made contact with its front passenger side."
    )
    assert s.crash.striker == "V1"


def test_a_colour_is_not_the_lighting() -> None:
    s = read("A dark colored Nissan sedan made contact with the rear bumper of the Waymo AV at a red light.")
    assert isinstance(s.environment.lighting, Unknown)
    s = read("It was dark. A sedan made contact with the rear bumper of the Waymo AV at a red light.")
    assert s.environment.lighting == (Lighting.DARK,)


def test_a_bystander_in_another_clause_is_no_participant() -> None:
    s = read(
        "The Waymo AV was yielding to a pedestrian crossing the street when the driver of a passenger car made "
        "contact with the rear of the Waymo AV."
    )
    assert [p.id for p in s.participants] == ["V1", "V2"]


def test_the_other_driver_is_the_crash_partner() -> None:
    s = read("The Waymo AV was stopped at a red light. The other driver made contact with the rear of the Waymo AV.")
    assert [p.id for p in s.participants] == ["V1", "V2"]
    assert s.crash.striker == "V2"


@pytest.mark.parametrize(
    ("said", "kind"),
    [
        ("was stopped at a red light", ActionKind.STOP),
        ("was slowing to a stop for a queue of traffic", ActionKind.STOP),
        ("was proceeding through the intersection", ActionKind.GO_ACROSS),
        ("began to make a right turn", ActionKind.TURN_RIGHT),
        ("was traveling north on [XXX]", ActionKind.FOLLOW_LANE),
    ],
)
def test_the_automated_vehicles_movement(said: str, kind: ActionKind) -> None:
    s = read(f"The Waymo AV {said} at the intersection when a passenger car made contact with the rear of it.")
    assert last(s, "V1") is kind


def test_moving_off_after_a_stop_and_going_around() -> None:
    s = read(
        SUMMARY.format("an SUV")
        + "The Waymo AV was stopped at a red light. The SUV, which had been stopped behind the Waymo AV, began to "
        "move forward and made contact with the rear of the Waymo AV."
    )
    assert last(s, "V2") is ActionKind.FOLLOW_LANE
    s = read(
        SUMMARY.format("an SUV")
        + "The Waymo AV was stopped in a queue of traffic. The SUV maneuvered around the left side of the Waymo AV "
        "and the passenger side of the SUV made contact with the rear driver side of the stationary Waymo AV."
    )
    assert last(s, "V2") is ActionKind.CHANGE_LANE


@pytest.mark.parametrize(
    "came",
    [
        "a sedan, attempting to enter traffic from a gas station on the right, entered the Waymo AV's path",
        "a sedan pulling out from a parking garage on the right moved into the path of the Waymo AV",
        "a sedan stopped at the curb ahead maneuvered into the roadway",
    ],
)
def test_a_partner_entering_the_road_from_off_it(came: str) -> None:
    """Joining the flow of traffic, or moving onto the road itself, from where it stood off it is `drive_into`;
    "traffic" it joins is no other road user, and a party whose path it entered is its object."""
    s = read(f"The Waymo AV was traveling north on [XXX] when {came}, and the sedan made contact with the Waymo AV.")
    assert last(s, "V2") is ActionKind.DRIVE_INTO


def test_rear_ending_says_the_crash_type_in_any_form() -> None:
    s = read(
        "The Waymo AV was traveling south on [XXX]. A police report later gave the sedan's failure to keep its "
        "distance before rear-ending the Waymo AV as the cause."
    )
    assert s.crash.type is CrashType.REAR_END


def test_a_partner_introduced_as_parked_stood_parked() -> None:
    """Nothing is said of the sedan before the impact but the words that introduce it: "a parked sedan"."""
    s = read(
        "An Acme AV operating in autonomous mode was in a collision involving an empty parked sedan. While backing "
        "out of a driveway, the Acme AV made contact with the rear door of an empty parked sedan."
    )
    p = next(p for p in s.participants if p.id == "V2")
    assert p.actions == (Action(ActionKind.PARKED),)
    assert s.provenance is not None
    assert any(e.fact == "V2.actions[1]" and "parked" in e.quote for e in s.provenance.evidence)


def test_a_partner_introduced_without_a_state_stays_unknown() -> None:
    s = read(
        "An Acme AV operating in autonomous mode was in a collision involving a sedan. While backing out of a "
        "driveway, the Acme AV made contact with the rear door of a sedan."
    )
    assert isinstance(next(p for p in s.participants if p.id == "V2").actions, Unknown)


@pytest.mark.parametrize("moved", ["then pulled slightly forward", "then proceeded westbound"])
def test_moving_off_again_said_with_how_or_where(moved: str) -> None:
    s = read(
        "The Waymo AV was stopped on [XXX] for a passenger pickup. A sedan stopped beside the Waymo AV. The sedan "
        f"{moved} and its passenger side made contact with the driver side of the stationary Waymo AV."
    )
    assert last(s, "V2") is ActionKind.FOLLOW_LANE
