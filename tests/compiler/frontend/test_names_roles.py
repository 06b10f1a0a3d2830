"""Participants named any way (issue 18) in reports that number nobody and name no automated vehicle: the
narrator's or the insured's vehicle is V1, else the first road user named in the first impact; the others in
the first impact are V2, ...; bystanders stay unnamed; two road users named alike are refused. Sentences written
for these tests."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd, FrontEndError
from sovarc.compiler.frontend.names import label_parties
from sovarc.compiler.frontend.ordinals import ordinal_names
from sovarc.dsl.explain import check_evidence
from sovarc.dsl.ir import ActionKind, CrashType, VehicleKind
from sovarc.dsl.span import Source


def read(text: str):
    return FrontEnd("none").extract(Source("report.txt", text))


def vehicle(scenario, pid: str):
    return next(p for p in scenario.participants if p.id == pid)


def test_the_insured_is_v1_and_the_claimant_v2() -> None:
    text = (
        "Our insured was driving north on Elm Road in the right lane. The claimant vehicle was stopped at the red "
        "light ahead. Our insured looked away and rear-ended the claimant vehicle."
    )
    named, note = label_parties(text)
    assert named.startswith("The driver of V1 was driving north") and "rear-ended V2" in named
    assert note is not None and "the insured's vehicle ('Our insured') is V1" in note
    crash = read(text).scenario.crash
    assert (crash.type, crash.striker, crash.victim) == (CrashType.REAR_END, "V1", "V2")


def test_insurer_acronyms_name_the_parties() -> None:
    named, _ = label_parties("IV was northbound. CV turned left in front of IV and IV struck CV.")
    assert named == "V1 was northbound. V2 turned left in front of V1 and V1 struck V2."


def test_the_narrator_is_v1_in_every_person() -> None:
    text = (
        "I was driving west on Pine Street at a green light. The other driver was going east and turned left in "
        "front of me. I could not stop and my front hit the passenger side of her car."
    )
    named, note = label_parties(text)
    assert "in front of V1" in named and "V1's front hit the passenger side of V2" in named
    assert note is not None and "the narrator's vehicle ('I') is V1" in note
    scenario = read(text).scenario
    assert vehicle(scenario, "V2").actions[-1].kind is ActionKind.TURN_LEFT
    assert (scenario.crash.striker, scenario.crash.victim) == ("V1", "V2")


def test_a_road_numbered_with_i_is_no_narrator() -> None:
    named, note = label_parties("A sedan on I-95 struck a pickup truck.")
    assert named == "V1 on I-95 struck V2." and note is not None and "first road user" in note


def test_the_first_road_user_in_the_first_impact_is_v1_and_later_mentions_are_it() -> None:
    text = (
        "The Mazda was northbound on Route 9 when the driver lost control, crossed the center line and struck a "
        "southbound Ford pickup head-on. The Ford came to rest in a ditch."
    )
    named, note = label_parties(text)
    # (the introduction's course stays beside the number, said of V2)
    assert named.startswith("V1 was northbound") and "struck V2, a southbound Ford pickup, head-on." in named
    assert "V2 came to rest" in named
    assert note is not None and "V2 'a southbound Ford pickup'" in note
    scenario = read(text).scenario
    assert vehicle(scenario, "V2").kind is VehicleKind.PICKUP
    assert (scenario.crash.type, scenario.crash.striker) == (CrashType.FRONTAL, "V1")


def test_an_introduction_with_its_year_is_kept_beside_the_number() -> None:
    named, _ = label_parties(
        "A 1999 Kia Rio was traveling east. A 2004 Suzuki motorcycle was traveling west. The Kia turned left and "
        "was struck by the Suzuki."
    )
    assert named.startswith("V1, a 1999 Kia Rio, was traveling east. V2, a 2004 Suzuki motorcycle, was")
    assert "V1 turned left and was struck by V2" in named


def test_a_bystander_does_not_become_a_participant() -> None:
    text = (
        "A parked delivery van was on the shoulder. A pickup truck traveling west failed to stop at the stop sign "
        "and struck the left side of a northbound sedan."
    )
    extraction = read(text)
    assert [p.id for p in extraction.scenario.participants] == ["V1", "V2"]
    assert vehicle(extraction.scenario, "V1").kind is VehicleKind.PICKUP
    assert any("not in the crash: 'A parked delivery van'" in n for n in extraction.notes)


def test_two_road_users_named_alike_are_refused_with_the_reason() -> None:
    text = "A Toyota was stopped at the light. Another Toyota struck the Toyota from behind."
    with pytest.raises(FrontEndError, match="two road users are named alike"):
        read(text)


def test_two_of_one_make_told_apart_by_model_are_not_refused_when_the_impact_says_the_make_once() -> None:
    named, note = label_parties("A Honda Civic was stopped. A Kia struck the Honda Civic from behind.")
    assert "V2 struck V1 from behind" in named and note is not None


def test_the_evidence_is_quoted_from_the_report_as_written() -> None:
    text = "I was driving east on Oak Avenue. The claimant vehicle pulled out in front of me and I struck it."
    scenario = read(text).scenario
    assert scenario.provenance is not None
    assert check_evidence(text, scenario.provenance.evidence) == []  # every span is the report's own text
    quotes = [text[e.start : e.end] for e in scenario.provenance.evidence]
    assert any(q.startswith("I was driving east") for q in quotes)


def test_a_report_with_no_road_user_is_still_refused() -> None:
    with pytest.raises(FrontEndError, match="names no vehicle or pedestrian"):
        read("It was raining. The road was wet. Something happened near the bridge.")


def test_me_in_capitals_is_no_narrator() -> None:
    named, _ = label_parties("I was driving east when a truck hit me. The ME was called.")
    assert named == "V1 was driving east when V2 hit V1. The ME was called."


def test_a_pedestrian_struck_by_the_one_vehicle_the_report_does_not_number() -> None:
    scenario = read(
        "Pedestrian was crossing Main Street in the crosswalk from south to north when a westbound SUV turning left "
        "struck her. It was dusk."
    ).scenario
    assert [p.id for p in scenario.participants] == ["V1", "P1"]
    assert (scenario.crash.striker, scenario.crash.victim) == ("V1", "P1")
    assert str(vehicle(scenario, "V1").heading) == "west"  # "a westbound SUV": its course stays said of it
    assert str(vehicle(scenario, "P1").heading) == "north"  # "from south to north"


def test_a_course_in_an_introduction_is_said_of_the_one_it_introduces() -> None:
    scenario = read(
        "The Toyota was northbound on Highway 1 when the driver lost control, crossed the center line and struck "
        "a southbound Ford pickup head-on."
    ).scenario
    assert [str(vehicle(scenario, pid).heading) for pid in ("V1", "V2")] == ["north", "south"]
    assert scenario.crash.type is CrashType.FRONTAL


@pytest.mark.parametrize("noun", ["car", "truck", "vehicle"])
def test_vehicles_named_by_ordinal_with_any_noun(noun: str) -> None:
    scenario = read(
        f"The first {noun} was stopped at the red light facing west. The second {noun}, also westbound, failed to "
        f"stop and hit the back of the first {noun}."
    ).scenario
    crash = scenario.crash
    assert (crash.type, crash.striker, crash.victim) == (CrashType.REAR_END, "V2", "V1")


def test_a_car_placed_by_its_order_in_a_queue_is_not_named_by_the_ordinal() -> None:
    text = "A van struck the first car in line and then the second car in line."
    assert ordinal_names(text) == text
