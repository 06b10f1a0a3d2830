"""Verifier rules beyond the golden error files: warnings, JSON-built IR, clean examples."""

from __future__ import annotations

from sovarc.dsl import Severity, from_json, parse, to_json, to_text, verify

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


def test_a_kind_is_for_vehicles_and_parked_comes_first() -> None:
    """A vehicle's kind and the parked start (issue 20): a pedestrian has no kind; `parked` is a first action."""
    kinded = BASE.replace("  vehicle V2 {\n", "  vehicle V2 {\n    kind bus\n")
    assert messages(kinded) == []
    walker = BASE.replace("  vehicle V2 {\n", "  pedestrian V2 {\n    kind bus\n")
    walker = walker.replace("      stop\n", "      walk\n")
    assert messages(walker) == ["error: V2 is a pedestrian, which has no vehicle kind"]
    assert messages(BASE.replace("      stop\n", "      parked\n      reverse\n")) == []
    late = BASE.replace("      stop\n", "      stop\n      parked\n")
    assert messages(late) == ["error: V2 is parked only after stop"]
    assert messages(BASE.replace("      stop\n", "      reverse(to: 1)\n")) == ["error: reverse takes no target lane"]


def test_an_unknown_kind_is_not_written_and_a_known_one_is() -> None:
    """Files from before kinds keep their canonical form; a stated kind prints right after the role line."""
    assert to_text(parse(BASE)) == BASE
    kinded = BASE.replace("  vehicle V2 {\n", "  vehicle V2 {\n    kind motorcycle\n")
    assert to_text(parse(kinded)) == kinded
    assert to_text(parse(BASE.replace("    heading east\n", "    heading east\n    kind truck\n", 1))) == BASE.replace(
        "  vehicle V1 {\n", "  vehicle V1 {\n    kind truck\n"
    )
