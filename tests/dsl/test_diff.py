"""The semantic diff says what changed by meaning."""

from __future__ import annotations

from sovarc.dsl import diff, parse, to_text

from tests.conftest import EXAMPLES

BASE = (EXAMPLES / "scenarios" / "intersection_left_turn_across_path_side.sov").read_text(encoding="utf-8")


def changed(old: str, new: str) -> list[str]:
    return [c.message for c in diff(parse(old), parse(new))]


def test_identical_scenarios_have_no_changes() -> None:
    assert changed(BASE, BASE) == []


def test_layout_and_comments_are_not_changes() -> None:
    assert changed(BASE, "# new comment\n" + BASE.replace("\n", "\n\n")) == []


def test_one_action_changed_is_one_line() -> None:
    new = BASE.replace("turn_left", "go_across", 1)
    assert changed(BASE, new) == ["V1 action 1: turn_left → go_across"]
    # ... and the text diff is one line as well
    old_lines, new_lines = to_text(parse(BASE)).splitlines(), to_text(parse(new)).splitlines()
    assert sum(a != b for a, b in zip(old_lines, new_lines, strict=True)) == 1


def test_inserted_and_removed_actions() -> None:
    new = BASE.replace("      turn_left\n", "      stop\n      turn_left\n", 1)
    assert changed(BASE, new) == ["V1 action 1: added stop"]
    assert changed(new, BASE) == ["V1 action 1: removed stop"]


def test_fields_participants_and_crash() -> None:
    new = (
        BASE.replace("lanes 4", "lanes 6")
        .replace("striker V2", "striker V1")
        .replace("victim V1", "victim V2")
        .replace("weather clear", "weather clear, rainy")
    )
    assert changed(BASE, new) == [
        "environment.weather: clear → clear, rainy",
        "road.lanes: 4 → 6",
        "crash.striker: V2 → V1",
        "crash.victim: V1 → V2",
    ]


def test_participant_added_and_removed() -> None:
    extra = (
        "  pedestrian P1 {\n    heading east\n    lane unknown\n    speed unknown\n"
        "    actions {\n      cross\n    }\n  }\n"
    )
    new = BASE.replace("  crash {", extra + "  crash {")
    assert changed(BASE, new) == ["P1: added (pedestrian, cross)"]
    assert changed(new, BASE) == ["P1: removed (pedestrian)"]


def test_json_form_of_changes() -> None:
    new = BASE.replace("turn_left", "turn_right", 1)
    (change,) = diff(parse(BASE), parse(new))
    assert change.to_json() == {
        "path": "V1.actions[1]",
        "old": "turn_left",
        "new": "turn_right",
        "message": "V1 action 1: turn_left → turn_right",
    }


def test_kind_and_twilight_are_facts_the_diff_names() -> None:
    kinded = BASE.replace("  vehicle V2 {\n", "  vehicle V2 {\n    kind bicycle\n")
    assert changed(BASE, kinded) == ["V2.kind: unknown → bicycle"]
    dusk = BASE.replace("lighting daylight", "lighting twilight")
    assert changed(BASE, dusk) == ["environment.lighting: daylight → twilight"]
