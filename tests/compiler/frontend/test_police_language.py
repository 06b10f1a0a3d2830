"""Police data conventions, on reports written here: a narrative exported in capitals is read as a writer in
sentence case would have written it (`capitals`), the forms' short labels for the units and their drivers
("VEH 1", "U1", "Car A", "D1", "the #2 vehicle") are the participants (`labels`), and the forms' abbreviations
("RT LN", "INTX", "OPP DIR", "FTYROW", "EBL") are the words they stand for (`forms`). Each reading test also
reads the usual wording, so it fails if the two readings part; the false matches are read as nothing.
"""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.capitals import in_capitals, sentence_case
from sovarc.compiler.frontend.rules import extract
from sovarc.compiler.frontend.spelling import spell_out
from sovarc.compiler.frontend.text import number_vehicles, prepare
from sovarc.dsl.span import Source

USUAL = (
    "The crash occurred at an intersection controlled by a traffic signal. The posted speed limit was 40 mph. "
    "V1, a 2004 Honda Civic sedan, was traveling northbound in the left lane at approximately 35 mph. V2, a 2011 "
    "Ford Escape, was traveling southbound and turned left in front of V1. The front of the Honda struck the "
    "right side of V2. It was raining and dark."
)


def _read(text: str) -> tuple[object, ...]:
    s = extract(text, "t")
    return (s.environment, s.road, s.crash, s.participants)


# ---- capitals ---------------------------------------------------------------------------------------------
def test_a_report_in_capitals_reads_as_the_same_report_in_sentence_case() -> None:
    assert _read(USUAL.upper()) == _read(USUAL)


def test_sentence_case_keeps_codes_and_names_and_changes_only_case() -> None:
    said = (
        "VEH 1 WAS TRAVELING N/B ON SR 42 NEAR ELM ST AT APPROX. 30 MPH ON MONDAY. V2, A 2004 HONDA CIVIC SEDAN, "
        "HIT IT."
    )
    got = sentence_case(said)
    assert got == (
        "Veh 1 was traveling N/B on SR 42 near Elm St at approx. 30 mph on Monday. V2, a 2004 Honda Civic sedan, "
        "hit it."
    )
    assert len(got) == len(said) and got.upper() == said


def test_a_label_letter_after_its_noun_stays_a_capital_an_article_does_not() -> None:
    assert sentence_case("CAR A WAS STOPPED WHEN CAR B HIT CAR A.") == "Car A was stopped when car B hit car A."
    assert sentence_case("THE CAR WAS PARKED A FEW METRES AWAY IN A CAR A FEW PEOPLE OWN.").startswith(
        "The car was parked a few metres away in a car a few"
    )


def test_a_sentence_case_report_is_left_as_it_is() -> None:
    text = "V1 passed a sign that said STOP AHEAD and the driver of V1 saw V2 on US 1 (e.g. NB traffic)."
    assert not in_capitals(text)
    assert sentence_case(text) == text


def test_evidence_of_a_report_in_capitals_quotes_its_own_capitals() -> None:
    text = USUAL.replace("V1", "Vehicle #1").replace("V2", "Vehicle #2").upper()
    scenario = FrontEnd("none").extract(Source("capitals.txt", text)).scenario
    assert scenario.provenance is not None and scenario.provenance.evidence
    for e in scenario.provenance.evidence:
        assert e.quote == text[e.start : e.end] and e.quote.upper() == e.quote


# ---- labels -----------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("said", "named"),
    [
        ("VEH 1 struck VEH 2.", "V1 struck V2."),
        ("VEH#1 struck VEH. 2.", "V1 struck V2."),
        ("V#1 struck V#2.", "V1 struck V2."),
        ("U1 struck U2.", "V1 struck V2."),
        ("UNIT #1 struck UNIT #2.", "V1 struck V2."),
        ("Car A struck Car B.", "V1 struck V2."),
        ("Vehicle A struck Vehicle B.", "V1 struck V2."),
        ("The #1 vehicle struck the #2 vehicle.", "V1 struck V2."),
        ("D1 stated that U1 struck U2.", "The driver of V1 stated that V1 struck V2."),
        ("DRV 1 stated that VEH 1 struck VEH 2.", "The driver of V1 stated that V1 struck V2."),
        ("Driver 2 said D1's vehicle struck V2.", "The driver of V2 said V1 struck V2."),
        ("V1 struck PED 1.", "V1 struck P1."),
    ],
)
def test_police_forms_labels_name_the_participants(said: str, named: str) -> None:
    assert prepare(spell_out(said)) == named


@pytest.mark.parametrize(
    "said",
    [
        "V1 was playing U2 on the radio when it struck V2.",  # the band: no form numbers a U2 without a U1
        "The driver of V1, who held a D1 visa, struck V2.",  # a kind of visa: a label takes no article
        "V1 stopped by Unit 4 of the apartment building and V2 struck it.",  # a unit of a place
        "V1 stopped a car a few metres ahead and V2 struck it.",  # an article, in lower case
        "V2 struck V1 and bent a vehicle A-pillar.",  # a part's name, joined by its hyphen
    ],
)
def test_words_like_labels_name_no_participant(said: str) -> None:
    assert number_vehicles(said) == said


def test_a_report_labelled_by_the_forms_reads_as_the_usual_report() -> None:
    lettered = USUAL.replace("V1", "Car A").replace("V2", "Car B")
    assert _read(lettered) == _read(USUAL)
    numbered = USUAL.replace("V1", "VEH 1").replace("V2", "U2").replace("VEH 1,", "U1,")
    assert _read(numbered) == _read(USUAL)


# ---- forms' abbreviations -----------------------------------------------------------------------------------
def test_forms_abbreviations_are_written_out_where_they_mean_one_thing() -> None:
    said = spell_out(
        "Veh 2 was in the RT LN in the opp dir and FTYROW at the INTX. It was in the EBL at approx 30 mph. "
        "The ped was in LN 2 and made a LT turn."
    )
    assert said == (
        "Vehicle 2 was in the right lane in the opposite direction and failed to yield the right of way at the "
        "intersection. It was in the eastbound lane at approximately 30 mph. The pedestrian was in lane 2 and made "
        "a left turn."
    )


def test_words_like_abbreviations_are_left_as_they_are() -> None:
    text = "V1 was on RT 9 near Elm Ln when Lt. Smith saw it; the inter-city bus and V2 were opposite."
    assert spell_out(text) == text


def test_a_report_in_the_forms_abbreviations_reads_as_the_usual_report() -> None:
    short = (
        USUAL.replace("left lane", "LT LN")
        .replace("approximately", "approx")
        .replace("an intersection", "an INTX")
        .replace("turned left", "turned LT")
    )
    assert short != USUAL
    assert _read(short) == _read(USUAL)
    assert _read(short.upper()) == _read(USUAL)
