"""`sovarc eval extraction | srr | tests`: read the arguments, run the evaluation, print its tables.

The evaluations themselves are in sovarc.compiler.evaluation.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

from sovarc.compiler.cli.common import Reporter, UsageError, make_front_end
from sovarc.compiler.evaluation import sgo
from sovarc.compiler.evaluation.extraction import evaluate_extraction
from sovarc.compiler.evaluation.srr import map_key, reconstruct, sov_files, srr_table
from sovarc.compiler.evaluation.tests import load_ego, scenario_files, tests_table
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.maps import load_map
from sovarc.compiler.pipeline import default_map
from sovarc.compiler.progress import progress
from sovarc.compiler.scenario_io import load_scenario
from sovarc.compiler.slots import folder_name
from sovarc.dsl import verify_or_raise
from sovarc.dsl.errors import EXIT_INPUT, EXIT_OK
from sovarc.dsl.ir import Scenario
from sovarc.dsl.span import Source


def cmd_eval(args: argparse.Namespace) -> int:
    if args.evaluation == "srr":
        return cmd_eval_srr(args)
    if args.evaluation == "tests":
        return cmd_eval_tests(args)
    return cmd_eval_extraction(args)


def cmd_eval_extraction(args: argparse.Namespace) -> int:
    """Extraction accuracy per attribute (the paper's Table 3), then the failing cases and fields."""
    if args.format == "sgo":
        return cmd_eval_sgo(args)
    if args.csv or not args.reports or not args.truth:
        raise UsageError("eval extraction needs --reports DIR and --truth DIR (or --format sgo CSV)")
    truths = sorted(Path(args.truth).glob("*/*.json"))
    if not truths:
        raise UsageError(f"no ground truth found: expected {args.truth}/<category>/<n>.json")
    reporter = Reporter()
    front_end = make_front_end(args)
    report = evaluate_extraction(
        progress(truths, len(truths), "eval extraction"),
        Path(args.reports),
        front_end,
        on_error=lambda path, exc: reporter.error(exc, None, str(path)),
    )
    front_end.close()
    if args.json:
        print(json.dumps(report.to_json(), indent=2, ensure_ascii=False))
    else:
        print(f"extraction accuracy (%) on {len(report.cases)} reports, front end --llm {args.llm}\n")
        print(report.table())
        failures = report.failures()
        if failures:
            print(f"\n{len(failures)} failing fields:")
            for case, attribute, why in failures:
                print(f"  {case:<14} {attribute:<18} {why}")
    return EXIT_INPUT if reporter.failed else EXIT_OK


def cmd_eval_sgo(args: argparse.Namespace) -> int:
    """SGO narratives scored on NHTSA's coded fields, the development half beside the held-out half."""
    if not args.csv or args.reports or args.truth:
        raise UsageError("eval extraction --format sgo takes the SGO incident CSV, and no --reports or --truth")
    path = Path(args.csv)
    if not path.is_file():
        raise UsageError(f"{path}: no such file")
    halves = sgo.halves(sgo.read_pool(path))
    if args.sample is not None:  # a slow front end reads a sample of the held-out half only
        by_hash = sorted(halves["held-out"], key=lambda r: hashlib.sha256(r["Report ID"].encode()).hexdigest())
        halves = {"held-out": by_hash[: args.sample]}
    front_end = make_front_end(args)

    def read(front: FrontEnd) -> Callable[[str, str], Scenario]:
        return lambda report_id, text: front.extract(Source(f"sgo_{report_id}.txt", text)).scenario

    scores = {}
    for name, rows in halves.items():
        scores[name] = sgo.score_rows(progress(rows, len(rows), f"sgo {name}"), read(front_end))
    front_end.close()
    if args.json:
        print(json.dumps(sgo.to_json(scores), indent=2, ensure_ascii=False))
        return EXIT_OK
    sizes = ", ".join(f"{name} {s.reports}" for name, s in scores.items())
    print(f"SGO two-party narratives scored on NHTSA's coded fields ({sizes}), front end --llm {args.llm}\n")
    print(sgo.table(scores))
    return EXIT_OK


def cmd_eval_srr(args: argparse.Namespace) -> int:
    """The scenario reconstruction rate of the SUMO oracle, per road kind (the paper's Tables 4 and 5)."""
    files = sorted(p for name in args.scenarios for p in sov_files(Path(name)))
    maps = args.map or [str(default_map())]
    report: dict[str, dict[str, object]] = {}
    for map_path in maps:
        road_map = load_map(map_path)
        rows: list[dict[str, Any]] = []
        for path in progress(files, len(files), label=f"srr {Path(map_path).name}"):
            scenario, _ = load_scenario(path)
            rows += reconstruct(scenario, path, road_map, roads=args.roads, seed=args.seed, spare=args.spare_sites)
        key = map_key(map_path, maps)
        report[key] = {"rows": rows}
        print(srr_table(key, rows))
    if args.json:
        write_atomic(args.json, json.dumps(report, indent=2) + "\n")
    return EXIT_OK


def cmd_eval_tests(args: argparse.Namespace) -> int:
    """Ego failures of report-derived tests against random ones, per map (the paper's Table 6)."""
    scenarios: list[Scenario] = []
    for path in scenario_files(args.scenarios):  # every input is read and checked before the long run starts
        scenario, _ = load_scenario(path)
        verify_or_raise(scenario)
        scenarios.append(scenario)
    ego = load_ego(args.ego)
    report: dict[str, Any] = {}
    for map_path in args.map or [str(default_map())]:
        name = Path(map_path).name
        out = Path(args.output) / folder_name(name) if args.output else None
        table = tests_table(
            scenarios,
            load_map(map_path),
            ego,
            roads=args.roads,
            seed=args.seed,
            spare=args.spare_sites,
            baseline=args.baseline == "random",
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
