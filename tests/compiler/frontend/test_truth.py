"""Importing SoVAR-style ground truth: every repair is a note, nothing is invented."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from sovarc.compiler.frontend.truth import import_truth, import_truth_file
from sovarc.dsl import ParseError, parse, to_text, verify
from sovarc.dsl.ir import Speed, SpeedUnit

from tests.compiler.cli.test_cli import sovarc
from tests.conftest import SHARED, requires_shared

TRUTH = SHARED / "data" / "nmvccs" / "truth"

RECORD = {
    "weather": ["rainy", "cloudy"],
    "lighting": ["dark", "light"],
    "speedlimit": "45MPH",
    "intersection": "yes",
    "T": "no",
    "carCount": 2,
    "laneCount": 4,
    "striker": "V2",
    "impactPart": 2,
    "carInformation": {
        "V1": {"behaviors": [["turn left", 2]], "direction": 1, "laneNumber": 2},
        "V2": {"behaviors": [["follow lane", 1], ["go across"]], "direction": 3, "laneNumber": 0},
    },
}


def test_a_record_becomes_the_scenario_it_states() -> None:
    imported = import_truth(RECORD, "case")
    assert to_text(imported.scenario) == (
        "scenario case {\n"
        "  environment {\n    weather cloudy, rainy\n    lighting dark, street_lights\n  }\n"
        "  road {\n    kind intersection\n    lanes 4\n    speed_limit 45 mph\n  }\n"
        "  vehicle V1 {\n    heading north\n    lane 2\n    speed unknown\n"
        "    actions {\n      turn_left(to: 2)\n    }\n  }\n"
        "  vehicle V2 {\n    heading south\n    lane unknown\n    speed unknown\n"
        "    actions {\n      follow_lane\n      go_across\n    }\n  }\n"
        "  crash {\n    type side\n    striker V2\n    victim V1\n  }\n"
        "}\n"
    )
    assert imported.notes == ("V2: follow lane takes no lane; dropped its lane 1",)


@pytest.mark.parametrize(
    ("given", "kind", "limit"),
    [
        ({"T": "yes", "intersection": "yes", "speedlimit": 48}, "t_junction", "48 km/h"),
        ({"T": "no", "intersection": "no", "speedlimit": "89KPH"}, "straight", "89 km/h"),
        ({"speedlimit": "40kph"}, "intersection", "40 km/h"),
        ({"speedlimit": 0, "laneCount": 0}, "intersection", "unknown"),
    ],
)
def test_road_kinds_and_speed_limits(given: dict, kind: str, limit: str) -> None:
    scenario = import_truth({**RECORD, **given}, "x").scenario
    assert (str(scenario.road.kind), to_text(scenario).split("speed_limit ")[1].split("\n")[0]) == (kind, limit)


def test_unknown_behaviour_is_unknown_not_invented() -> None:
    record = {**RECORD, "carInformation": {**RECORD["carInformation"], "V2": {"behaviors": [["unknown"]]}}}
    imported = import_truth(record, "x")
    assert "actions unknown" in to_text(imported.scenario)
    assert imported.notes[-1] == "V2: no known behaviour; actions are unknown"


def test_bad_records_are_errors() -> None:
    with pytest.raises(ParseError, match="speedlimit: cannot read 'fast'"):
        import_truth({**RECORD, "speedlimit": "fast"}, "x", "bad.json")
    with pytest.raises(ParseError, match="weather: unknown word 'hail'"):
        import_truth({**RECORD, "weather": ["hail"]}, "x", "bad.json")


@requires_shared
def test_every_shared_record_imports_and_verifies() -> None:
    files = sorted(TRUTH.glob("*/*.json"))
    assert len(files) == 90
    kinds = {"crossing": "intersection", "t": "t_junction", "straight": "straight"}
    for path in files:
        scenario = import_truth_file(path, TRUTH.parent / "reports").scenario
        assert verify(scenario) == [], path
        assert str(scenario.road.kind) == kinds[path.parent.name], path
        assert parse(to_text(scenario)) == scenario
        assert scenario.provenance is not None and len(scenario.provenance.sha256) == 64


@requires_shared
def test_import_truth_command(tmp_path: Path) -> None:
    result = sovarc("import-truth", str(TRUTH / "t"), "-o", str(tmp_path / "out"))
    assert result.returncode == 0, result.stderr
    assert "30 of 30 scenario(s) written" in result.stderr
    assert "t/12.json: note: lighting: read misspelt 'birght' as 'bright'" in result.stderr
    assert len(list((tmp_path / "out").glob("t_*.sov"))) == 30
    assert sovarc("check", *map(str, (tmp_path / "out").glob("*.sov"))).returncode == 0
    bad = tmp_path / "bad.json"
    bad.write_text("{not json")
    failed = sovarc("import-truth", str(bad), "-o", str(tmp_path / "o2"))
    assert failed.returncode == 1 and f"{bad}:1:2: error: invalid JSON" in failed.stderr
    assert not (tmp_path / "o2").exists()


def test_a_bare_speed_limit_is_in_the_unit_the_report_states(tmp_path: Path) -> None:
    (tmp_path / "truth" / "t").mkdir(parents=True)
    (tmp_path / "reports" / "t").mkdir(parents=True)
    record = tmp_path / "truth" / "t" / "1.json"
    record.write_text(json.dumps({**RECORD, "speedlimit": 35}))
    (tmp_path / "reports" / "t" / "1.txt").write_text("The road had a posted speed of 35 MPH. V1 struck V2.")
    imported = import_truth_file(record)  # finds the report beside truth/, as in shared/data
    assert imported.scenario.road.speed_limit == Speed(35, SpeedUnit.MPH)
    assert "speedlimit: bare 35 read in mph, the only unit the report states it in" in imported.notes
    (tmp_path / "reports" / "t" / "1.txt").write_text("The speed limit was 35 km/h (22 mph). V1 struck V2.")
    assert import_truth_file(record).scenario.road.speed_limit == Speed(35, SpeedUnit.KMH)
