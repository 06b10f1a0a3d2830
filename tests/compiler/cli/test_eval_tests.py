"""`sovarc eval tests`: report-derived ego tests against the random baseline, in the Table 6 form."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.compiler.cli.test_cli import sovarc
from tests.conftest import EXAMPLES
from tests.targets.fmu.fake_fmu import write_fmu

WRONG_WAY = EXAMPLES / "scenarios" / "straight_double_yellow_pass_frontal.sov"
STOPPED_TRAFFIC = EXAMPLES / "scenarios" / "straight_rear_end_stopped_traffic.sov"


def _never_meet(folder: Path) -> Path:
    """Stopped traffic, but V2 faces the other way: V1 cannot rear-end it on any site."""
    text = STOPPED_TRAFFIC.read_text(encoding="utf-8").replace("straight_rear_end_stopped_traffic", "never_meet")
    head, v2 = text.split("vehicle V2")
    path = folder / "never_meet.sov"
    path.write_text(head + "vehicle V2" + v2.replace("heading east", "heading west", 1), encoding="utf-8")
    return path


@pytest.mark.slow  # lowering, synthesis, SUMO and the reference FMU
def test_json_counts_every_test_of_both_methods_and_is_reproducible(tmp_path: Path) -> None:
    first = sovarc("eval", "tests", str(WRONG_WAY), "--roads", "1", "--json", "-o", str(tmp_path))
    assert first.returncode == 0, first.stderr
    data = json.loads(first.stdout)["town.net.xml"]
    straight = data["rows"]["straight"]
    assert straight["planned"] == 1 and straight["unplanned"] == 0
    assert straight["report"]["tests"] == 2 and straight["random"]["tests"] == 2  # V1 and V2 each the ego
    assert data["total"] == {m: straight[m] for m in ("report", "random")}
    assert sum(data["classes"]["report"].values()) == straight["report"]["failed"]
    assert sum(data["violations"]["report"].values()) == straight["report"]["failed"]
    methods = [(v["facts"]["ego"], v["facts"]["method"]) for v in data["verdicts"]]
    assert methods == [("V1", "report"), ("V2", "report"), ("V1", "random"), ("V2", "random")]
    failed = [v for v in data["verdicts"] if not v["passed"]]
    assert all(v["facts"]["failure"] and v["facts"]["violation"] for v in failed)
    assert sovarc("eval", "tests", str(WRONG_WAY), "--roads", "1", "--json").stdout == first.stdout
    written = sorted(p.name for p in (tmp_path / "town.net.xml").iterdir())
    assert len([n for n in written if n.endswith(".json")]) == 4
    assert len([n for n in written if n.endswith(".png")]) == len(failed)  # a picture of each failure
    assert f"verdicts written to {tmp_path}/" in first.stderr


@pytest.mark.slow  # lowering, synthesis, SUMO and the reference FMU
def test_the_table_names_what_could_not_be_planned(tmp_path: Path) -> None:
    result = sovarc("eval", "tests", str(_never_meet(tmp_path)), str(STOPPED_TRAFFIC), "--baseline", "none")
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert "2 scenario(s) x 3 site(s) (the paper's Table 6 form)" in out
    row = next(line.split() for line in out.splitlines() if line.startswith("straight"))
    assert row[:3] == ["straight", "6", "3"] and row[-1] == "-"  # 6 scenario-sites, 3 planned; no baseline run
    assert "not planned: 3 scenario-site(s), no tests (unsat 3)" in out
    assert "report-derived / random" not in out and "wall time per test: median" in out


def test_inputs_are_checked_before_anything_runs(tmp_path: Path) -> None:
    missing = sovarc("eval", "tests", str(tmp_path / "missing.sov"))
    assert missing.returncode == 1 and "missing.sov: error: no such file" in missing.stderr
    empty = sovarc("eval", "tests", str(tmp_path))
    assert empty.returncode == 1 and "no .sov scenarios in this folder" in empty.stderr
    broken = write_fmu(tmp_path / "broken.fmu", drop=("steer", "obj_count"))
    ego = sovarc("eval", "tests", str(STOPPED_TRAFFIC), "--ego", str(broken))
    assert ego.returncode == 1 and "steer" in ego.stderr and "obj_count" in ego.stderr
    assert ego.stdout == ""


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("--roads", "0"), "argument --roads: must be at least 1, not 0"),
        (("--baseline", "fuzz"), "argument --baseline: invalid choice: 'fuzz'"),
        ((), "the following arguments are required: scenarios"),
    ],
)
def test_command_line_mistakes_are_usage_errors(args: tuple[str, ...], message: str) -> None:
    scenarios = () if not args else (str(STOPPED_TRAFFIC),)
    result = sovarc("eval", "tests", *scenarios, *args)
    assert result.returncode == 2 and message in result.stderr


def test_help_shows_the_truth_example() -> None:
    out = sovarc("eval", "tests", "--help").stdout
    assert "sovarc eval tests truth --roads 3 -m examples/maps/town.net.xml --baseline random" in out
    assert (
        "tests     ego failures: report-derived tests against random ones (Table 6)" in sovarc("eval", "--help").stdout
    )


@pytest.mark.slow  # lowering, synthesis, SUMO and the reference FMU, in two worker processes
def test_two_workers_give_the_same_json_as_one(tmp_path: Path) -> None:
    args = ("eval", "tests", str(WRONG_WAY), str(STOPPED_TRAFFIC), "--roads", "1", "--json")
    one, two = sovarc(*args, "-j", "1"), sovarc(*args, "-j", "2")
    assert one.returncode == 0 and two.returncode == 0, one.stderr + two.stderr
    assert one.stdout == two.stdout
    assert json.loads(one.stdout)["town.net.xml"]["rows"]["straight"]["planned"] == 2
