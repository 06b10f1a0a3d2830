"""Terse and news-style narratives (issue 18): a kind's noun opening a sentence without an article ("Motorcycle
was northbound"), a driver's vehicle ("Driver A's car"), a vehicle called by its model or its wider kind ("the
Civic", "the truck"), and a person driving a vehicle whose "his car" is it. Sentences written for these tests."""

from __future__ import annotations

from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.names import label_parties
from sovarc.compiler.frontend.text import number_vehicles
from sovarc.dsl.explain import check_evidence
from sovarc.dsl.ir import CrashType, Heading, VehicleKind
from sovarc.dsl.span import Source


def read(text: str):
    return FrontEnd("none").extract(Source("report.txt", text)).scenario


def vehicle(scenario, pid: str):
    return next(p for p in scenario.participants if p.id == pid)


def test_a_bare_kind_opening_a_sentence_introduces_that_road_user() -> None:
    text = (
        "Motorcycle was westbound on Hill Road. A van eastbound turned left into a car park in front of the "
        "motorcycle. The motorcycle struck the right side of the van."
    )
    named, _ = label_parties(text)
    assert named.startswith("V1 was westbound")  # renamed in place: the evidence keeps the report's words
    scenario = read(text)
    assert vehicle(scenario, "V1").kind is VehicleKind.MOTORCYCLE
    assert vehicle(scenario, "V1").heading is Heading.WEST
    assert (scenario.crash.striker, scenario.crash.victim) == ("V1", "V2")
    assert scenario.provenance is not None
    assert check_evidence(text, scenario.provenance.evidence) == []


def test_a_bare_kind_is_no_label_nor_a_name() -> None:
    # "Vehicle one" numbers a party; "Van Ness" is a street; neither is a bare kind
    named, _ = label_parties("Van Ness Avenue was wet. A bus stopped and a car struck the bus.")
    assert named.startswith("Van Ness Avenue was wet.")
    named, _ = label_parties("Pickup turned left. Car struck the pickup.")
    assert named == "V1 turned left. V2 struck V1."  # (numbered in the order the report names them)


def test_a_drivers_vehicle_is_the_drivers_unit() -> None:
    text = "Driver A went north. Driver B went south. Driver A's car struck Driver B's van."
    assert number_vehicles(text).endswith("V1 struck V2.")
    assert number_vehicles("The driver of Vehicle 2's truck stopped.") == "V2 stopped."


def test_a_model_and_a_wider_kind_name_the_vehicle_said_with_them() -> None:
    named, _ = label_parties(
        "A Kia Rio was stopped at a light when a tractor-trailer struck it. Police said the truck had failed to "
        "brake and the Rio was pushed forward."
    )
    assert "Police said V2 had failed to brake and V1 was pushed forward." in named


def test_the_car_of_a_person_said_driving_it_is_that_vehicle() -> None:
    text = (
        "A 30-year-old woman driving a Mazda sedan was hurt when her car was rear-ended by a box truck on "
        "northbound Route 9."
    )
    named, _ = label_parties(text)
    assert "when V1 was rear-ended by V2" in named
    scenario = read(text)
    assert scenario.crash.type is CrashType.REAR_END
    assert (scenario.crash.striker, scenario.crash.victim) == ("V2", "V1")


def test_a_bare_make_opening_a_sentence_is_that_road_user() -> None:
    text = (
        "A 2004 Toyota Corolla was stopped at the light on Oak Street. A Mazda pickup was eastbound behind it. "
        "Mazda failed to stop and struck the rear of the Toyota. Toyota was pushed forward."
    )
    named, _ = label_parties(text)
    assert "V2 failed to stop and struck the rear of V1. V1 was pushed forward." in named
    scenario = read(text)
    assert (scenario.crash.type, scenario.crash.striker, scenario.crash.victim) == (CrashType.REAR_END, "V2", "V1")
    # a make that is a word or a name too is no road user without its article
    named, _ = label_parties("Lincoln was the nearest town. A Kia stopped and a Ford struck the Kia.")
    assert named.startswith("Lincoln was the nearest town.")
