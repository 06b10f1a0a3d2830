"""`sovarc eval tests`: ego failures found by report-derived tests against a random baseline (Table 6)."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from sovarc.compiler.backend import default_map, first_message, folder_name, plans_for
from sovarc.compiler.cli_backend import add_spare_option
from sovarc.compiler.maps import RoadMap, load_map
from sovarc.compiler.progress import progress
from sovarc.dsl.errors import EXIT_OK, InputError, SovarcError, SynthesisError, UnsatError
from sovarc.dsl.ir import RoadKind, Scenario

if TYPE_CHECKING:
    from sovarc.targets.fmu import EgoFmu, TestsTable

DESCRIPTION = """\
Stage every scenario on --roads sites of each map; on each planned site, every vehicle takes its
turn as the ego (an FMI 2.0 FMU: the reference ego unless --ego) among the participants replaying
the report's crash, and, with --baseline random, among random but plausible NPCs on the same site.
Prints, per road kind, the failed tests of each (the paper's Table 6), the failures by check and by
what the ego did wrong (the paper's violation types), and the scenario-sites that could not be
planned, which have no tests.

examples:
  sovarc import-truth ../shared/data/nmvccs/truth -o truth
  sovarc eval tests truth --roads 3 -m examples/maps/town.net.xml --baseline random
  sovarc eval tests examples/scenarios/straight_double_yellow_pass_frontal.sov --ego my_ads.fmu --json"""


def add_tests_parser(which: Any, formatter: Any) -> None:
    tests = which.add_parser(
        "tests",
        formatter_class=formatter,
        help="ego failures: report-derived tests against random ones (Table 6)",
        description=DESCRIPTION,
    )
    tests.add_argument("scenarios", nargs="+", help=".sov files, or folders of them")
    tests.add_argument("-m", "--map", action="append", help="a map (repeatable; default: the bundled town)")
    tests.add_argument("--roads", type=_positive, default=3, metavar="N", help="sites per scenario (default 3)")
    add_spare_option(tests)
    tests.add_argument(
        "--baseline", choices=("random", "none"), default="random", help="the baseline to compare with (default random)"
    )
    tests.add_argument("--ego", metavar="FMU", help="the driving system under test (default: the reference ego)")
    tests.add_argument("--seed", type=int, default=0, help="seed for the sites and the random NPCs (default 0)")
    tests.add_argument("--json", action="store_true", help="print the figures and every verdict as JSON")
    tests.add_argument("-o", "--output", help="write each test's verdict, and a PNG of each failed test, under here")


def cmd_eval_tests(args: argparse.Namespace) -> int:
    from sovarc.compiler.scenario_io import load_scenario
    from sovarc.dsl import verify_or_raise
    from sovarc.targets.fmu import reference_fmu, validate_fmu

    files = _scenario_files(args.scenarios)
    scenarios: list[Scenario] = []
    for path in files:  # every input is read and checked before the long run starts
        scenario, _ = load_scenario(path)
        verify_or_raise(scenario)
        scenarios.append(scenario)
    ego = validate_fmu(args.ego or reference_fmu())
    baseline = args.baseline == "random"
    report: dict[str, Any] = {}
    for map_path in args.map or [str(default_map())]:
        name = Path(map_path).name
        out = Path(args.output) / folder_name(name) if args.output else None
        road_map = load_map(map_path)
        table = tests_table(
            scenarios,
            road_map,
            ego,
            roads=args.roads,
            seed=args.seed,
            spare=args.spare_sites,
            baseline=baseline,
            out_dir=out,
        )
        report[name] = table.to_json()
        if not args.json:
            title = f"Ego failures of {ego.model_name} on {name}: {len(scenarios)} scenario(s) x {args.roads} site(s)"
            print(table.render(title))
    if args.json:
        print(json.dumps(report, indent=2, ensure_ascii=False))
    if args.output:
        print(f"verdicts written to {args.output}/", file=sys.stderr)
    return EXIT_OK


def tests_table(
    scenarios: list[Scenario],
    road_map: RoadMap,
    ego: EgoFmu,
    *,
    roads: int,
    seed: int = 0,
    spare: int | None = None,
    baseline: bool = True,
    out_dir: Path | None = None,
) -> TestsTable:
    """Plan every scenario on `roads` sites of the map and run its tests (writing them under out_dir, if
    given); a scenario-site that cannot be planned is counted, with its reason, and has no tests."""
    from sovarc.targets.fmu import TestsTable

    table = TestsTable()
    for scenario in progress(scenarios, len(scenarios), label=f"tests {road_map.name}"):
        kind = scenario.road.kind.value if isinstance(scenario.road.kind, RoadKind) else "unknown"
        try:
            results = plans_for(scenario, road_map, roads, seed, spare)
        except SovarcError as exc:  # facts no road can reconcile, or no site of its kind
            why = "unsat" if isinstance(exc, UnsatError) else "no fitting site"
            for _ in range(roads):
                table.add_unplanned(scenario.name, kind, "-", why, first_message(exc))
            continue
        for r in results:
            if r.plan is None:
                table.add_unplanned(scenario.name, kind, r.site, _why(r.error), first_message(r.error))
            else:
                table.add_plan(r.plan, ego, seed, baseline=baseline, out_dir=out_dir)
        for _ in range(roads - len(results)):
            table.add_unplanned(scenario.name, kind, "-", "no fitting site", "fewer fitting sites than asked")
    return table


def _scenario_files(names: list[str]) -> list[Path]:
    files: list[Path] = []
    for name in names:
        path = Path(name)
        if path.is_dir():
            found = sorted(path.glob("*.sov"))
            if not found:
                raise InputError(f"{name}: no .sov scenarios in this folder")
            files += found
        else:
            files.append(path)  # a missing or unreadable file is load_scenario's clear error
    return files


def _why(error: SovarcError | None) -> str:
    if isinstance(error, UnsatError):
        return "unsat"
    if isinstance(error, SynthesisError):
        return "synthesis"
    return "lowering" if error is not None and error.stage == "lower" else "other"


def _positive(value: str) -> int:
    number = int(value)
    if number < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, not {number}")
    return number
