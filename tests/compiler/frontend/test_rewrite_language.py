"""Wordings the metamorphic benchmark (`benchmarks/bench_rewrites.py`) found the rules reading otherwise than the
same fact said the usual way, each a general fact of English or of report writing, on reports written here:

- a speed's unit said in words ("30 miles per hour", "48 kilometers per hour") or as "km/hr", "mi/h";
- police forms' direction abbreviations ("traveling N/B", "the S/B lanes", "EB");
- an aside in brackets describes as one between commas ("V2 (a 1998 Ford Taurus sedan)");
- "a left-hand turn" is a left turn;
- a course said as "in a northerly direction" between the verb of motion and the road;
- a narrative told in the present ("V2 stops ... and strikes V1", "its left side is struck") says what one told in
  the past does (a plural noun before "and" that looks like a verb, "signals and stops", is read as one: rare in a
  narrative, and "got out and stops" is common).
Each test also reads the usual wording, so it fails if the two readings part.
"""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.rules import extract
from sovarc.compiler.frontend.text import in_past, normalize_names
from sovarc.dsl.ir import CrashType, Heading, Participant, RoadKind, Speed, SpeedUnit, Unknown, VehicleKind
from sovarc.dsl.span import Source

CROSS = "The crash occurred at a four-leg intersection controlled by stop signs. "


def _actions(text: str) -> dict[str, list[str]]:
    s = extract(text, "t")
    return {p.id: [] if isinstance(p.actions, Unknown) else [a.kind.value for a in p.actions] for p in s.participants}


def _participant(text: str, pid: str) -> Participant:
    return next(p for p in extract(text, "t").participants if p.id == pid)


@pytest.mark.parametrize(
    ("said", "limit"),
    [
        ("48 kmph (30 mph)", Speed(48, SpeedUnit.KMH)),
        ("48 kilometers per hour (30 miles per hour)", Speed(48, SpeedUnit.KMH)),
        ("48 kilometres per hour", Speed(48, SpeedUnit.KMH)),
        ("48 km/hr (30 mi/h)", Speed(48, SpeedUnit.KMH)),
        ("30 miles per hour", Speed(30, SpeedUnit.MPH)),
        ("30 miles an hour", Speed(30, SpeedUnit.MPH)),
    ],
)
def test_a_speed_limit_is_read_in_any_spelling_of_its_unit(said: str, limit: Speed) -> None:
    text = f"The road had a posted speed limit of {said}. V1 was traveling north. V1 struck the rear of V2."
    assert extract(text, "t").road.speed_limit == limit


def test_a_bare_number_of_miles_is_no_speed() -> None:
    text = "The road was posted. V1 had driven 30 miles that day. V1 was traveling north and struck the rear of V2."
    assert isinstance(extract(text, "t").road.speed_limit, Unknown)


@pytest.mark.parametrize(("short", "long"), [("N/B", "northbound"), ("S/B", "southbound"), ("EB", "eastbound")])
def test_a_direction_abbreviated_as_police_forms_write_it_reads_as_written_out(short: str, long: str) -> None:
    template = CROSS + "V1 was traveling {} in the {} lane. V2 was traveling west. The front of V2 struck V1."
    spelled = extract(template.format(long, long), "t")
    abbreviated = extract(template.format(short, short), "t")
    assert _participant(template.format(short, short), "V1").heading == Heading(long.removesuffix("bound"))
    assert abbreviated.participants == spelled.participants


def test_a_capital_n_and_b_inside_a_word_or_a_name_is_no_direction() -> None:
    text = "V1, a NB-2 model, was traveling east on Route NBA. V1 struck the rear of V2."
    assert _participant(text, "V1").heading == Heading.EAST


@pytest.mark.parametrize(
    ("aside", "kind"),
    [
        ("(a 1998 Ford Taurus sedan)", VehicleKind.CAR),
        ("( a 2004 Ford F-150 pickup )", VehicleKind.PICKUP),
        ("(a 2010 Blue Bird school bus)", VehicleKind.BUS),
    ],
)
def test_an_aside_in_brackets_names_the_kind_as_one_between_commas(aside: str, kind: VehicleKind) -> None:
    text = CROSS + f"V1 was traveling north. V2 {aside} was traveling east. The front of V1 struck V2."
    commas = CROSS + f"V1 was traveling north. V2, {aside.strip('() ')}, was traveling east. The front of V1 struck V2."
    assert _participant(text, "V2").kind == kind == _participant(commas, "V2").kind


@pytest.mark.parametrize("hand", ["left-hand", "left hand"])
def test_a_left_hand_turn_is_a_left_turn(hand: str) -> None:
    template = (
        "The crash occurred on a four lane undivided road. V2 was traveling north when it stopped to let traffic "
        "pass before proceeding to make an intended {} turn into a driveway. V1 was traveling north behind V2. "
        "The front of V1 struck the rear of V2."
    )
    assert _actions(template.format(hand)) == _actions(template.format("left"))
    made = CROSS + f"V1 was traveling north. V2 was traveling south and made a {hand} turn. V1 struck V2."
    assert _actions(made)["V2"][-1] == "turn_left"


def test_a_left_hand_turn_lane_is_a_left_turn_lane() -> None:
    template = (
        CROSS + "V1 was traveling north in the second {} turn lane. V1 made a left turn and struck V2, which was "
        "traveling south."
    )
    assert _participant(template.format("left-hand"), "V1").lane == _participant(template.format("left"), "V1").lane


def test_a_course_said_as_a_direction_between_the_verb_and_the_road_keeps_the_one_lane_road() -> None:
    template = (
        "The crash occurred at a T-intersection. V1 was traveling {} on the two-way roadway with one lane in "
        "each direction. V2 was turning left out of a driveway. The front of V1 struck V2."
    )
    assert _participant(template.format("in a northerly direction"), "V1").lane == 1
    assert _participant(template.format("north"), "V1").lane == 1


PAST = (
    CROSS + "V1 was traveling north. V2 was traveling east. V2 stopped at the stop sign, then entered the intersection "
    "and turned left. The front of V1 struck the left side of V2. V1 came to rest facing north."
)
PRESENT = (
    CROSS + "V1 is traveling north. V2 is traveling east. V2 stops at the stop sign, then enters the intersection "
    "and turns left. The front of V1 strikes the left side of V2. V1 comes to rest facing north."
)


def test_a_narrative_told_in_the_present_reads_as_told_in_the_past() -> None:
    past, present = extract(PAST, "t"), extract(PRESENT, "t")
    assert _actions(PRESENT) == _actions(PAST) == {"V1": ["follow_lane"], "V2": ["follow_lane", "stop", "turn_left"]}
    assert (present.crash.type, present.crash.striker) == (past.crash.type, past.crash.striker)


def test_a_strike_in_the_present_passive_reads_as_in_the_past() -> None:
    template = CROSS + "V1 was traveling north. V2 turned left and its left side {} struck by the front of V1."
    now, then = extract(template.format("is"), "t"), extract(template.format("was"), "t")
    assert (now.crash.type, now.crash.striker) == (then.crash.type, then.crash.striker)
    assert then.crash.striker == "V1"


@pytest.mark.parametrize(
    "text",
    [
        "The front brakes failed.",  # a noun after a part
        "V1 made two quarter turns, stops included.",
    ],
)
def test_nouns_that_look_like_present_verbs_are_left_alone(text: str) -> None:
    assert in_past(text) == text


def test_the_present_after_a_comma_going_on_with_the_subject_is_read_as_past() -> None:
    assert in_past("V1 overcorrected, comes back across the lane") == "V1 overcorrected, came back across the lane"


@pytest.mark.parametrize(
    ("active", "passive"),
    [
        ("V1 struck V2 in the left side with its front.", "V2 was struck by V1 in the left side with its front."),
        ("V2 impacted V1 on the right side with its front.", "V1 was impacted by V2 on the right side with its front."),
        ("V1 struck V2 in the rear with its front.", "V2 was struck by V1 in the rear with its front."),
    ],
)
def test_a_strike_said_in_the_passive_reads_as_said_in_the_active(active: str, passive: str) -> None:
    # the part struck with is the striker's (the agent's); where it struck is on the one struck (the subject)
    lead = CROSS + "V1 was traveling north. V2 was traveling east. "
    said, turned = extract(lead + active, "t").crash, extract(lead + passive, "t").crash
    assert (turned.type, turned.striker, turned.victim) == (said.type, said.striker, said.victim)
    assert said.type in (CrashType.SIDE, CrashType.REAR_END)


SENTENCES = (
    CROSS + "V1 was traveling north. V2 was traveling east and stopped at the stop sign. V2 entered the intersection. "
    "The front of V1 struck the left side of V2. V1 continued across the intersection and came to rest."
)


def test_clauses_parted_by_a_semicolon_read_as_sentences() -> None:
    # (what V1 did after the impact is no move of its crash, in either)
    joined = SENTENCES.replace(". V", "; V").replace(". The front", "; the front")
    assert _actions(joined) == _actions(SENTENCES)
    said, semi = extract(SENTENCES, "t").crash, extract(joined, "t").crash
    assert (semi.type, semi.striker, semi.victim) == (said.type, said.striker, said.victim)


def test_a_sentence_opening_on_a_pronoun_is_about_the_one_it_carries_on_with() -> None:
    named = CROSS + "V2 was traveling south. V1 stopped at the sign. V1 proceeded to turn left and struck V2."
    pronoun = CROSS + "V2 was traveling south. V1 stopped at the sign. It proceeded to turn left and struck V2."
    assert extract(pronoun, "t").crash.striker == extract(named, "t").crash.striker == "V1"


@pytest.mark.parametrize("driver", ["Driver #1", "Driver 1", "Driver one", "Driver No. 1"])
def test_a_numbered_driver_is_the_driver_of_that_vehicle(driver: str) -> None:
    template = (
        "The crash occurred on a straight road. V1 and V2 were traveling west. The vehicle in front of V1 slowed "
        "and {} steered left, and its right front made contact with the front right of V2."
    )
    got, want = extract(template.format(driver), "t").crash, extract(template.format("the driver of V1"), "t").crash
    assert (got.type, got.striker, got.victim) == (want.type, want.striker, want.victim)


def test_a_driver_of_so_many_years_is_no_numbered_driver() -> None:
    assert "V2" not in normalize_names("The driver 2 years ago was V1.")


@pytest.mark.parametrize(
    ("british", "american"),
    [
        ("at a four-way junction", "at a four-way intersection"),
        ("at a crossroads", "at an intersection"),
        ("at a T-junction", "at a T-intersection"),
    ],
)
def test_a_junction_is_an_intersection(british: str, american: str) -> None:
    template = "The crash occurred {}. V1 was traveling north. V2 was traveling east. The front of V1 struck V2."
    assert extract(template.format(british), "t").road.kind == extract(template.format(american), "t").road.kind
    assert extract(template.format(british), "t").road.kind != RoadKind.STRAIGHT


@pytest.mark.parametrize("place", ["a non-junction roadway", "a non-intersection roadway", "a non intersection area"])
def test_a_road_away_from_any_junction_is_no_intersection(place: str) -> None:
    text = f"The crash occurred on {place}. V1 was traveling north. The front of V1 struck the rear of V2."
    assert extract(text, "t").road.kind == RoadKind.STRAIGHT


def test_a_carriageway_is_a_roadway() -> None:
    template = (
        "The crash occurred on a two lane undivided {}. V1 was traveling west on the {}. V1 crossed over the left "
        "lane line and its front struck the front of V2, which was traveling east."
    )
    got = extract(template.format("carriageway", "carriageway"), "t")
    want = extract(template.format("roadway", "roadway"), "t")
    assert (got.road.lanes, got.participants) == (want.road.lanes, want.participants)


def test_evidence_of_a_respelt_report_quotes_its_own_words() -> None:
    # a report that respells throughout, its opening repeated at its end (as some database exports are), still
    # aligns word for word: each fact quotes the report, never the respelling
    opening = (
        "This crash occurred on a two lane undivided carriageway slightly curving to the left with no grade and a "
        "posted speed limit of 72KMPH (45MPH). This crash occurred on a weekday afternoon."
    )
    text = (
        opening + "Vehicle #1, a 1988 Ford Mustang, was traveling westbound on the two lane undivided carriageway when "
        "it observed Vehicle #2, a motorcycle, in its westbound lane traveling east. Vehicle #1 crossed over the left "
        "lane line into the eastbound lane. The motorcycle returned to its original eastbound lane whereupon Vehicle "
        "#1 impacted with Vehicle #2 with its front. Vehicle #2 came to rest in the center of the carriageway, facing "
        "eastward." + opening
    )
    scenario = FrontEnd("none").extract(Source("respelt.txt", text)).scenario
    assert scenario.provenance is not None
    quotes = {e.fact: e.quote for e in scenario.provenance.evidence}
    assert "westbound" in quotes["V1.heading"]
    assert all(e.quote == text[e.start : e.end] for e in scenario.provenance.evidence)


def test_a_one_syllable_verb_doubles_its_last_consonant_in_the_past() -> None:
    # "skids" is "skidded", as "stops" is "stopped"; "turns" and "pulls" are not doubled
    text = "V1 skids on the ice and then stops. V2 turns left and pulls over."
    assert in_past(text) == "V1 skidded on the ice and then stopped. V2 turned left and pulled over."
