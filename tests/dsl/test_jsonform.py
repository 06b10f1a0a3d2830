"""The JSON form: generated schema, conversion both ways, and errors naming the bad field."""

from __future__ import annotations

import json

import jsonschema
import pytest
from sovarc.dsl import ParseError, from_json, json_schema, parse, to_json

from tests.conftest import EXAMPLES

EXAMPLE = EXAMPLES / "reports" / "left_turn_oncoming_pickup.sov"


def test_schema_is_valid_and_closed() -> None:
    schema = json_schema()
    jsonschema.Draft202012Validator.check_schema(schema)
    assert schema["$ref"] == "#/$defs/Scenario"
    for name, node in schema["$defs"].items():
        if node.get("type") == "object":
            assert node["additionalProperties"] is False, name
            assert set(node["required"]) == set(node["properties"]), name
    assert '"meta"' not in json.dumps(schema) and "Meta" not in schema["$defs"]


def test_schema_tells_what_actions_mean() -> None:
    assert (
        "retrograde: drive in a lane of the opposite direction" in json_schema()["$defs"]["ActionKind"]["description"]
    )


def test_example_round_trips_through_json() -> None:
    scenario = parse(EXAMPLE.read_text(encoding="utf-8"))
    data = json.loads(json.dumps(to_json(scenario)))
    jsonschema.validate(data, json_schema())
    assert from_json(data) == scenario
    assert data["road"]["speed_limit"] == {"value": 72, "unit": "km/h"}
    assert data["participants"][0]["actions"][0] == {"kind": "turn_left", "to": None}


def test_bad_json_names_every_bad_field() -> None:
    data = to_json(parse(EXAMPLE.read_text(encoding="utf-8")))
    data["road"]["lanes"] = "four"
    data["participants"][1]["heading"] = "northbound"
    data["crash"]["colour"] = "red"
    del data["name"]
    with pytest.raises(ParseError) as caught:
        from_json(data, "answer.json")
    assert [d.message for d in caught.value.diagnostics] == [
        "answer.json: name: is missing",
        "answer.json: road.lanes: expected int or \"unknown\", got 'four'",
        "answer.json: participants[1].heading: expected north, east, south, west or \"unknown\", got 'northbound'",
        "answer.json: crash.colour: is not a field of Crash",
    ]


def test_json_rejects_wrong_shapes() -> None:
    with pytest.raises(ParseError, match="expected an object, got a list"):
        from_json([], "x.json")
    with pytest.raises(ParseError, match=r"participants: expected a list, got a string"):
        from_json({"name": "a", "participants": "V1"}, "x.json")
