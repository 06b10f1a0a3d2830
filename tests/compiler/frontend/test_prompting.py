"""The layered prompt and its worked examples: complete, valid against the answer form, covering the vocabulary."""

from __future__ import annotations

import re

import jsonschema
import pytest
from sovarc.compiler.frontend import prompting
from sovarc.compiler.frontend.hybrid import parse_answer
from sovarc.compiler.frontend.layers import motion_layer
from sovarc.compiler.frontend.text import normalize_names, participants
from sovarc.dsl.ir import ActionKind, CrashType

EXAMPLES = prompting.examples()


def test_there_are_twenty_or_more_examples_and_only_the_motion_layer_is_asked() -> None:
    assert len(EXAMPLES) >= 20
    system = prompting.system_prompt()
    assert "Layer 3: dynamic objects" in system and "Worked examples" in system
    # the rules read environment and road exactly: the model is not asked them, so they are not in the prompt
    assert "Layer 1: environment" not in system and "Layer 2: road network" not in system
    for rule in ("intended", "double yellow", "front", "Most vehicles", "Cite only sentences"):
        assert rule in system
    assert system.count("Report:\n") == len(EXAMPLES)
    assert system == prompting.system_prompt()  # the same bytes every time: the model's prefix cache relies on it


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda e: e.name)
def test_each_example_answer_fits_the_answer_form_and_cites_sentences_about_its_facts(
    example: prompting.Example,
) -> None:
    ids = participants(normalize_names(example.narrative))
    assert list(example.answer["participants"]) == ids
    jsonschema.validate(example.answer, prompting.full_schema(ids))  # the whole reading, documented
    shown = motion_layer(example.narrative)
    view = prompting.answer_view(example.answer, shown)  # the part the model answers
    jsonschema.Draft7Validator(prompting.answer_schema(ids, shown.numbers())).validate(view)  # the tuple form
    answer = parse_answer(prompting.compact_json(view), ids, shown)
    assert set(answer.actions) == set(ids)
    for pid in ids:  # every cited sentence is about the participant it is cited for
        assert answer.evidence[f"{pid}.actions"] and all(shown.about(n, pid) for n in answer.evidence[f"{pid}.actions"])
    assert answer.spans["crash.type"]


def test_examples_cover_every_action_crash_type_and_road_kind() -> None:
    words = {a for e in EXAMPLES for p in e.answer["participants"].values() for a in p["actions"]}
    kinds = {re.sub(r"_(left|right)$", "", w) if w.startswith("change_lane") else w for w in words}
    assert kinds == {k.value for k in ActionKind} - prompting.RULES_ONLY
    assert prompting.RULES_ONLY.isdisjoint(prompting.VEHICLE_WORDS)  # the model is never offered them
    assert {"change_lane_left", "change_lane_right"} <= words
    assert {e.answer["crash"]["type"] for e in EXAMPLES} == {c.value for c in CrashType}
    assert {e.answer["road"] for e in EXAMPLES} == set(prompting.ROAD_KINDS)
    sizes = {len(e.answer["participants"]) for e in EXAMPLES}
    assert {1, 2, 3} <= sizes  # single-vehicle, two, and three participants


def test_prepared_narrative_names_participants_and_stops_at_the_first_impact() -> None:
    text = "Vehicle #1 was northbound. Vehicle #2 was southbound. The front of V1 struck V2. V2 rolled over."
    assert prompting.prepared_narrative(text) == "V1 was northbound. V2 was southbound. The front of V1 struck V2."


def test_the_motion_layer_shows_only_sentences_about_participants_numbered_with_their_spans() -> None:
    text = (
        "The road was wet and the posted limit was 45 mph. Vehicle #1 was northbound. He then turned left.  "
        "Traffic was heavy. Vehicle #2 was southbound. The front of V2 struck V1. V1 rolled over."
    )
    shown = motion_layer(text)
    assert shown.numbers() == [2, 3, 5, 6]  # not the road, the traffic or the aftermath
    assert shown.text().splitlines()[0] == "[2] V1 was northbound."
    assert [text[a:b] for a, b in (s.span for s in shown.sentences)] == [
        "Vehicle #1 was northbound.",
        "He then turned left.",
        "Vehicle #2 was southbound.",
        "The front of V2 struck V1.",
    ]
    assert shown.about(3, "V1") and not shown.about(3, "V2")  # "he" carries V1
    assert shown.about(6, "V2") and not shown.about(5, "V1")


def test_the_answer_form_is_compact_and_bound_to_the_report() -> None:
    schema = prompting.answer_schema(["V1", "P1"], [2, 4])
    assert schema["required"] == ["V1", "P1", "crash"] and schema["additionalProperties"] is False
    assert schema["properties"]["P1"]["items"]["anyOf"] == [{"enum": ["cross", "walk"]}, {"enum": [2, 4]}]
    assert schema["properties"]["crash"]["items"][1]["enum"] == ["V1", "P1", "unknown"]  # a draft-07 tuple
    assert "string" not in str(schema)  # no free text anywhere: every value is a word of an enum or a number
