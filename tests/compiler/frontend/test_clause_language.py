"""Wordings the metamorphic benchmark's clause and naming rewrites (`compiler/evaluation/rewrite_clauses.py`) found
the rules reading otherwise than the same fact said the usual way, each a general fact of English or of report
writing, on reports written here:

- a police narrative's abbreviations, with their full stops inside a sentence ("Veh. #1", "approx. 30 mph");
- vehicles numbered by ordinal ("the first vehicle", "the second vehicle"), when the report numbers them no other
  way and one opens a sentence; one "first vehicle" alone (in a queue), or ones placed ("the first vehicle to the
  right", met in turn), names no participant;
- a motion said in the progressive after a time clause ("When V2 stopped ..., it was traveling north") was under
  way when the clause's event happened: it came first ("after" orders it second).
Each test also reads the usual wording, so it fails if the two readings part.
"""

from __future__ import annotations

from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.ordinals import ordinal_names
from sovarc.compiler.frontend.rules import extract
from sovarc.compiler.frontend.spelling import spell_out
from sovarc.compiler.frontend.text import prepare
from sovarc.dsl.ir import Unknown
from sovarc.dsl.span import Source

ROAD = "The crash occurred on a two-lane undivided roadway with a posted speed limit of 56 kmph (35 mph). "


def _actions(text: str) -> dict[str, list[str]]:
    s = extract(text, "t")
    return {p.id: [] if isinstance(p.actions, Unknown) else [a.kind.value for a in p.actions] for p in s.participants}


def _read(text: str) -> tuple[object, ...]:
    s = extract(text, "t")
    return (s.road, s.crash, s.participants)


def test_police_abbreviations_read_as_the_words_written_out() -> None:
    usual = (
        ROAD + "Vehicle #1 was traveling east at approximately 50 mph. Vehicle #2 was stopped in the eastbound lane "
        "waiting to turn left. The front of Vehicle #1 struck the rear of Vehicle #2."
    )
    short = usual.replace("Vehicle #", "Veh. #").replace("approximately", "approx.")
    assert short != usual
    assert _read(short) == _read(usual)
    assert _actions(short)["V2"] == ["stop"]


def test_an_abbreviated_vehicle_is_one_only_before_its_number() -> None:
    said = spell_out("Veh 2 and Veh. #1 passed a veh. in lane 1 at approx. 30 mph.")
    # (unnumbered, "a veh." is a vehicle, not a participant's label: see `forms`)
    assert said == "Vehicle 2 and Vehicle #1 passed a vehicle in lane 1 at approximately 30 mph."


def test_evidence_of_an_abbreviated_report_quotes_its_own_words() -> None:
    text = ROAD + "Veh. #1 was traveling east at approx. 50 mph. The front of Veh. #1 struck the rear of Veh. #2."
    scenario = FrontEnd("none").extract(Source("abbreviated.txt", text)).scenario
    assert scenario.provenance is not None
    assert all(e.quote == text[e.start : e.end] for e in scenario.provenance.evidence)


def test_vehicles_numbered_by_ordinal_are_named_by_it() -> None:
    usual = (
        ROAD + "Vehicle 1 was traveling west. Vehicle 2 was traveling east. Vehicle 1 crossed the center line and "
        "its front struck the front of Vehicle 2."
    )
    ordinal = (
        usual.replace("Vehicle 1", "The first vehicle", 1)
        .replace("Vehicle 2", "The second vehicle", 1)
        .replace("Vehicle 1", "The first vehicle")
        .replace("Vehicle 2", "the second vehicle")
    )
    assert _read(ordinal) == _read(usual)


def test_a_first_vehicle_alone_or_beside_numbered_ones_names_no_participant() -> None:
    queue = "V2 stopped behind the first vehicle in line. V1 struck V2."
    assert prepare(queue) == queue
    alone = "The first vehicle in the queue stopped. The pickup behind it braked."
    assert "V1" not in prepare(alone)
    # vehicles met in turn: the order of the impacts, not names
    met = (
        "The test vehicle drifted right and made contact with the first vehicle to the right. The operator braked "
        "but the test vehicle made contact with the second vehicle."
    )
    assert ordinal_names(met) == met


def test_a_motion_under_way_at_a_time_clause_came_before_its_event() -> None:
    usual = (
        ROAD + "V2, a 1999 Ford Taurus, was traveling north when it stopped to let traffic pass before turning "
        "left into a driveway. V1, a 2003 Honda Civic, was traveling north behind V2. V1 struck the rear of V2 "
        "with its front."
    )
    fronted = usual.replace(
        "V2, a 1999 Ford Taurus, was traveling north when it stopped to let traffic pass before turning left into a "
        "driveway.",
        "When V2, a 1999 Ford Taurus, stopped to let traffic pass before turning left into a driveway, it was "
        "traveling north.",
    )
    assert fronted != usual
    assert _actions(usual)["V2"] == ["follow_lane", "stop"]
    assert _actions(fronted) == _actions(usual)


def test_a_motion_after_a_time_clause_of_after_came_after_its_event() -> None:
    # "after" orders the motion second: it moved off once it had stopped, the stop came first
    text = (
        ROAD + "After V2 stopped at the stop sign, it was traveling north into the intersection. V1 struck the "
        "left side of V2 with its front."
    )
    assert _actions(text)["V2"][0] == "stop"
