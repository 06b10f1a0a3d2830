"""The target contract: a fourth target, defined here and registered at run time, runs through the
same path as the built-in ones, and every registered target satisfies the protocol."""

from __future__ import annotations

import csv
import dataclasses
import json
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import pytest
from sovarc.compiler import emit
from sovarc.compiler.cli import main
from sovarc.compiler.cli.parser import build_parser, target_names
from sovarc.compiler.plan import Plan
from sovarc.targets import registry
from sovarc.targets.contract import Artifacts, Target, flags, option, options_from, write_verdicts
from sovarc.targets.verdict import Finding, Verdict

from tests.compiler.cli.test_cli import LEFT_TURN
from tests.targets.fmu.plans import car_following


@dataclass(frozen=True)
class CsvOptions:
    every: int = option(1, "--csv-every", "with -t csv: write every Nth sample (default 1)")


class CsvTarget:
    """A tiny target: the trajectories as a CSV; its check reads the file back against the plan."""

    name = "csv"
    Options: ClassVar[type[CsvOptions]] = CsvOptions
    needs_opendrive = False
    one_verdict = True

    def emit(self, plan: Plan, folder: Path, options: CsvOptions) -> Artifacts:
        folder.mkdir(parents=True, exist_ok=True)
        path = folder / "trajectories.csv"
        with path.open("w", newline="", encoding="utf-8") as handle:
            writer = csv.writer(handle)
            writer.writerow(["participant", "t", "x", "y", "heading", "speed"])
            for t in plan.trajectories:
                for s in t.samples[:: options.every]:
                    writer.writerow([t.participant, s.t, s.x, s.y, s.heading, s.speed])
        return Artifacts(folder, (path,))

    def check(self, plan: Plan, artifacts: Artifacts, options: CsvOptions) -> list[Verdict]:
        with artifacts.main.open(newline="", encoding="utf-8") as handle:
            rows = list(csv.DictReader(handle))
        expected = sum(len(t.samples[:: options.every]) for t in plan.trajectories)
        ok = len(rows) == expected
        finding = Finding("rows", ok, f"{len(rows)} rows for {expected} samples")
        return [Verdict(self.name, plan.scenario.name, plan.site, (finding,), {"rows": len(rows)})]


@pytest.fixture
def csv_target() -> Iterator[CsvTarget]:
    target = registry.register(CsvTarget())
    try:
        yield target
    finally:
        registry.unregister("csv")


def test_every_registered_target_satisfies_the_contract() -> None:
    assert registry.names() == ("sumo", "openscenario", "fmu")
    for name in registry.names():
        target = registry.get(name)
        assert isinstance(target, Target) and target.name == name
        assert dataclasses.is_dataclass(target.Options) and target.Options.__dataclass_params__.frozen
        target.Options()  # every option has a default
        assert isinstance(target.needs_opendrive, bool) and isinstance(target.one_verdict, bool)
    assert registry.get("openscenario").needs_opendrive and not registry.get("fmu").one_verdict


def test_the_cli_flags_come_from_the_targets_options() -> None:
    (osc,) = flags(registry.get("openscenario"))
    assert (osc.flag, osc.dest, osc.choices, osc.default) == (
        "--osc-version",
        "osc_version",
        ("1.0", "1.1", "1.2", "1.3"),
        "1.3",
    )
    assert options_from(registry.get("openscenario"), {"osc_version": "1.0"}).version == "1.0"
    assert options_from(registry.get("fmu"), {"ego": None, "seed": 7}) == registry.get("fmu").Options(None, 7)


def test_an_unknown_target_or_one_off_contract_is_refused() -> None:
    with pytest.raises(KeyError, match="unknown target 'carla'; choose from sumo, openscenario, fmu"):
        registry.get("carla")
    with pytest.raises(TypeError, match="does not implement the target contract"):
        registry.register(object())  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="already registered"):
        registry.register(registry.get("sumo"))


def test_a_fourth_target_runs_through_the_compilers_path(csv_target: CsvTarget, tmp_path: Path) -> None:
    plan = car_following()
    verdict = emit.run_target("csv", plan, tmp_path, csv_every=5)
    assert isinstance(verdict, Verdict) and verdict.passed
    rows = (tmp_path / "csv" / "trajectories.csv").read_text(encoding="utf-8").splitlines()
    assert len(rows) == 1 + sum(len(t.samples[::5]) for t in plan.trajectories)
    written = tmp_path / "verdict-csv.json"
    assert written.read_text(encoding="utf-8") == verdict.dumps()  # as every one-verdict target's is written
    assert json.loads(written.read_text(encoding="utf-8"))["facts"] == {"rows": len(rows) - 1}


def test_verdicts_are_written_the_same_way_for_every_target(csv_target: CsvTarget, tmp_path: Path) -> None:
    verdicts = [Verdict("fmu", "s", "site", (Finding("ego", passed, "m"),)) for passed in (True, False)]
    path = write_verdicts(tmp_path, registry.get("fmu"), verdicts)
    assert path == tmp_path / "verdict-fmu.json"
    assert json.loads(path.read_text(encoding="utf-8")) == [v.to_json() for v in verdicts]
    with pytest.raises(ValueError, match="gave 2 verdicts, expected one"):
        write_verdicts(tmp_path, csv_target, verdicts)


def test_the_target_choices_come_from_the_registry(csv_target: CsvTarget) -> None:
    assert target_names("all") == ("sumo", "openscenario", "fmu", "csv") == registry.names()
    args = build_parser().parse_args(["run", "report.txt", "-t", "csv", "--csv-every", "3"])
    assert args.target == ("csv",) and args.csv_every == 3
    assert build_parser().parse_args(["run", "report.txt"]).csv_every == 1


@pytest.mark.slow  # lowering and synthesis on the bundled town
def test_the_cli_runs_a_registered_target(csv_target: CsvTarget, tmp_path: Path, capsys: pytest.CaptureFixture) -> None:
    out = tmp_path / "out"
    assert main([str(LEFT_TURN), "-t", "csv", "-o", str(out)]) == 0
    assert capsys.readouterr().out.splitlines()[0].split() == ["site", "impact", "csv"]
    (site,) = [p for p in out.iterdir() if p.is_dir()]
    assert json.loads((site / "verdict-csv.json").read_text(encoding="utf-8"))["passed"] is True
    assert (site / "csv" / "trajectories.csv").is_file() and (site / "plan.json").is_file()
