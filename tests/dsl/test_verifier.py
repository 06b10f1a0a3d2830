"""Verifier rules beyond the golden error files: warnings, JSON-built IR, clean examples."""

from __future__ import annotations

from sovarc.dsl import Severity, from_json, parse, to_json, verify

from tests.conftest import EXAMPLES

BASE = (EXAMPLES / "scenarios" / "straight_rear_end_stopped_traffic.sov").read_text(encoding="utf-8")


def messages(text: str) -> list[str]:
    return [f"{d.severity}: {d.message}" for d in verify(parse(text))]


def test_examples_verify_clean() -> None:
    for path in EXAMPLES.glob("**/*.sov"):
        assert verify(parse(path.read_text(encoding="utf-8"), str(path))) == [], path


def test_unknown_striker_is_a_warning_not_an_error() -> None:
    found = verify(parse(BASE.replace("striker V1", "striker unknown")))
    assert [(d.severity, d.message) for d in found] == [(Severity.WARNING, "the crash striker is unknown")]


def test_no_participants_and_no_actions() -> None:
    assert messages("scenario e {\n}\n") == ["error: the scenario has no participants"]
    assert messages("scenario e { vehicle V1 { actions { } } }") == ["error: V1 has no actions"]


def test_non_positive_speed_limit() -> None:
    assert messages(BASE.replace("speed_limit 55 mph", "speed_limit 0 mph")) == [
        "error: the speed limit must be positive"
    ]


def test_argument_where_none_is_taken_and_bad_sha() -> None:
    text = BASE.replace("      stop\n", "      stop(to: 1)\n").replace(
        "scenario straight_rear_end_stopped_traffic {",
        'scenario s {\n  provenance {\n    report "r.txt"\n    sha256 "xyz"\n    frontend hand\n'
        "    model unknown\n    assumed V9.lane, road.width\n  }",
    )
    assert messages(text) == [
        "error: sha256 must be 64 lower-case hex digits",
        "error: assumed fact 'V9.lane' names no field of this scenario",
        "error: assumed fact 'road.width' names no field of this scenario",
        "error: stop takes no target lane",
    ]


def test_ids_from_json_must_be_writable_as_text() -> None:
    data = to_json(parse(BASE))
    data["participants"][0]["id"] = "Vehicle 1"
    data["crash"]["striker"] = "Vehicle 1"
    found = verify(from_json(data))
    assert [d.message for d in found] == ["participant id 'Vehicle 1' is not a plain name"]
