"""Participants named any way (issue 18): numbering forms, a report's own labels, the automated-vehicle rule,
bystanders, a crash party first named late, and the refusal of a partner the IR cannot hold."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd, FrontEndError
from sovarc.compiler.frontend.names import label_parties
from sovarc.compiler.frontend.text import normalize_names
from sovarc.dsl.ir import ActionKind, Role
from sovarc.dsl.span import Source


def read(text: str):
    return FrontEnd("none").extract(Source("report.txt", text))


@pytest.mark.parametrize(
    "name",
    ["V1", "V-1", "V 1", "Vehicle #1", "Vehicle # 1", "Unit 1", "Unit #1", "Vehicle No. 1", "vehicle one", "Vehicle 1"],
)
def test_every_numbering_form_is_v1(name: str) -> None:
    assert normalize_names(f"{name} initiated a left turn.") == "V1 initiated a left turn."


def test_a_space_inside_the_name_keeps_the_action() -> None:
    text = (
        "V 1 was traveling north and V 2 was traveling south on a two-lane road. V 1 initiated a left turn at the "
        "intersection. The front of V 2 struck the right side of V 1."
    )
    scenario = read(text).scenario
    v1 = next(p for p in scenario.participants if p.id == "V1")
    assert ActionKind.TURN_LEFT in [a.kind for a in v1.actions]
    assert [p.id for p in scenario.participants] == ["V1", "V2"]


LABELLED = (
    "A Acme shuttle (Vehicle 1) in autonomy was traveling east on Elm Street in the right lane. "
    "A grey hatchback (Vehicle 2) traveling east behind the Acme shuttle changed lanes to the left. "
    "The grey hatchback then merged back and its front right corner contacted the rear left of the Acme shuttle."
)


def test_a_report_that_labels_its_parties_uses_its_labels() -> None:
    named, note = label_parties(LABELLED)
    assert "(Vehicle" not in named and "Acme shuttle" not in named and "hatchback" not in named
    assert note is not None and "own labels" in note
    extraction = read(LABELLED)
    assert [p.id for p in extraction.scenario.participants] == ["V1", "V2"]
    assert any("own labels" in n for n in extraction.notes)


AUTOMATED = (
    'On a weekday at 3:10 PM a Robo Autonomous Vehicle ("Robo AV") operating in Springfield was in a collision '
    "involving a passenger car. The Robo AV was stopped facing north for a red light at the intersection when a "
    "passenger car traveling north approached from behind. The front of the passenger car made contact with the "
    "rear of the Robo AV. The passenger car sustained damage."
)


def test_the_automated_vehicle_is_v1_and_the_road_user_it_met_v2_by_a_stated_rule() -> None:
    named, _ = label_parties(AUTOMATED)
    assert "Robo AV" not in named and "passenger car" not in named
    assert "The front of V2 made contact with the rear of V1." in named
    extraction = read(AUTOMATED)
    assert [p.id for p in extraction.scenario.participants] == ["V1", "V2"]
    assert any(
        "the automated vehicle" in n and "is V1" in n and "V2 'the passenger car'" in n for n in extraction.notes
    )


@pytest.mark.parametrize(
    "av", ["the Zoox vehicle", "the Cruise AV", "the ADS vehicle", "the test vehicle", "our vehicle", "the ego vehicle"]
)
def test_automated_vehicle_phrases(av: str) -> None:
    text = (
        f"{av[0].upper()}{av[1:]} in autonomous mode was traveling west in the left lane. An SUV traveling west "
        f"behind {av} made contact with the rear of {av}."
    )
    named, _ = label_parties(text)
    assert "made contact with the rear of V1" in named and "SUV" not in named


def test_a_bystander_is_not_a_participant() -> None:
    text = (
        "The Robo AV was traveling south and slowed, yielding to a pedestrian crossing in the crosswalk. A pickup "
        "truck traveling south behind the Robo AV made contact with the rear of the Robo AV."
    )
    scenario = read(text).scenario
    assert [p.id for p in scenario.participants] == ["V1", "V2"]
    assert all(p.role is Role.VEHICLE for p in scenario.participants)


def test_a_party_first_named_in_a_later_impact_sentence_is_a_participant() -> None:
    text = (
        "V1 was traveling north on Main Street in daylight. V1 swerved and collided with the curb. The front of V1 "
        "then struck a pedestrian who was crossing the street."
    )
    scenario = read(text).scenario  # once: "crash victim 'P1' is not a participant"
    assert [p.id for p in scenario.participants] == ["V1", "P1"]
    assert scenario.crash.victim == "P1"


def test_a_partner_the_ir_cannot_hold_is_refused_clearly() -> None:
    text = (
        "The Robo AV was traveling east in autonomous mode when a deer ran into the road. The front of the Robo AV "
        "struck the deer."
    )
    with pytest.raises(FrontEndError, match=r"report.txt: the crash partner \('(?:a|the) deer'\) is not a road user"):
        read(text)


def test_no_road_user_at_all_is_refused_with_what_was_looked_for() -> None:
    with pytest.raises(FrontEndError, match=r"names no vehicle or pedestrian .*the Waymo AV"):
        read("Something happened on the street near the market and someone called it in later that day.")


def test_the_note_names_the_words_the_report_used_for_each_party() -> None:
    text = (
        'At 3:10 PM a Robo Autonomous Vehicle ("Robo AV") was in a collision involving an SUV. The Robo AV was '
        "traveling north and slowed, yielding to a pedestrian crossing in the crosswalk. An SUV traveling north "
        "behind the Robo AV made contact with the rear of the Robo AV. The SUV left the scene."
    )
    extraction = read(text)
    assert extraction.notes[0] == (
        "participants numbered by rule: the automated vehicle ('a Robo Autonomous Vehicle') is V1; "
        "the other road users in the first impact are V2 'An SUV'"
    )
    crash = extraction.scenario.crash
    assert (crash.striker, crash.victim) == ("V2", "V1")
    assert [p.id for p in extraction.scenario.participants] == ["V1", "V2"]
