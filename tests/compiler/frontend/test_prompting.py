"""The layered prompt and its worked examples: complete, valid against the answer form, covering the vocabulary."""

from __future__ import annotations

import re

import jsonschema
import pytest
from sovarc.compiler.frontend import prompting
from sovarc.compiler.frontend.hybrid import parse_answer
from sovarc.compiler.frontend.text import normalize_names, participants
from sovarc.dsl.ir import ActionKind, CrashType

EXAMPLES = prompting.examples()


def test_there_are_twenty_or_more_examples_and_every_layer_is_in_the_prompt() -> None:
    assert len(EXAMPLES) >= 20
    system = prompting.system_prompt()
    for heading in ("Layer 1: environment", "Layer 2: road network", "Layer 3: dynamic objects", "Worked examples"):
        assert heading in system
    for rule in ("intended", "double yellow", "right-most lane", "front", "Most vehicles"):
        assert rule in system
    assert system.count("Report:\n") == len(EXAMPLES)
    assert system == prompting.system_prompt()  # the same bytes every time: the model's prefix cache relies on it


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda e: e.name)
def test_each_example_answer_fits_the_answer_form(example: prompting.Example) -> None:
    ids = participants(normalize_names(example.narrative))
    assert list(example.answer["participants"]) == ids
    jsonschema.validate(example.answer, prompting.full_schema(ids))  # the whole reading, documented
    shown = prompting.answer_view(example.answer)  # the part the model answers
    jsonschema.validate(shown, prompting.answer_schema(ids))
    assert set(parse_answer(prompting.compact_json(shown), ids).actions) == set(ids)


def test_examples_cover_every_action_crash_type_and_road_kind() -> None:
    words = {a for e in EXAMPLES for p in e.answer["participants"].values() for a in p["actions"]}
    kinds = {re.sub(r"_(left|right)$", "", w) if w.startswith("change_lane") else w for w in words}
    assert kinds == {k.value for k in ActionKind}
    assert {"change_lane_left", "change_lane_right"} <= words
    assert {e.answer["crash"]["type"] for e in EXAMPLES} == {c.value for c in CrashType}
    assert {e.answer["road"] for e in EXAMPLES} == set(prompting.ROAD_KINDS)
    sizes = {len(e.answer["participants"]) for e in EXAMPLES}
    assert {1, 2, 3} <= sizes  # single-vehicle, two, and three participants


def test_prepared_narrative_names_participants_and_stops_at_the_first_impact() -> None:
    text = "Vehicle #1 was northbound. Vehicle #2 was southbound. The front of V1 struck V2. V2 rolled over."
    assert prompting.prepared_narrative(text) == "V1 was northbound. V2 was southbound. The front of V1 struck V2."


def test_the_answer_form_is_compact_and_bound_to_the_report() -> None:
    schema = prompting.answer_schema(["V1", "P1"])
    people = schema["properties"]["participants"]
    assert people["required"] == ["V1", "P1"] and people["additionalProperties"] is False
    assert people["properties"]["P1"]["properties"]["actions"]["items"]["enum"] == ["cross", "walk"]
    assert schema["properties"]["crash"]["properties"]["striker"]["enum"] == ["V1", "P1", "unknown"]
    assert "string" not in str(schema)  # no free text anywhere: every value is a word of an enum or a number
