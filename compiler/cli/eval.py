"""`sovarc eval extraction | srr | tests`: read the arguments, run the evaluation, print its tables.

The evaluations themselves are in sovarc.compiler.evaluation.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
from pathlib import Path
from typing import Any

from sovarc.compiler.batch.executors import run_all
from sovarc.compiler.batch.tasks import worker_map
from sovarc.compiler.cli.batch import executor_of
from sovarc.compiler.cli.common import UsageError, resolve_llm
from sovarc.compiler.evaluation import sgo
from sovarc.compiler.evaluation.extraction import Report, extraction_tasks, run_extraction_task
from sovarc.compiler.evaluation.reading import FrontEndSpec
from sovarc.compiler.evaluation.srr import SrrTask, map_key, run_srr_task, sov_files, srr_table
from sovarc.compiler.evaluation.tests import TestsTable, TestsTask, load_ego, merged, run_tests_task, scenario_files
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.pipeline import default_map
from sovarc.compiler.scenario_io import load_scenario
from sovarc.compiler.slots import folder_name
from sovarc.dsl import verify_or_raise
from sovarc.dsl.errors import EXIT_INPUT, EXIT_OK


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
    failed = False
    report = Report()
    executor = executor_of(args)
    try:
        tasks = extraction_tasks(truths, Path(args.reports), _spec(args))
        for name, scores, error in run_all(executor, run_extraction_task, tasks, "eval extraction"):
            if error is not None:
                print(error, file=sys.stderr)
                failed = True
            else:
                report.cases[name] = scores
    finally:
        executor.close()
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
    return EXIT_INPUT if failed else EXIT_OK


def _spec(args: argparse.Namespace) -> FrontEndSpec:
    """The front end the --llm options name, as plain data for the executor's workers (see `reading`)."""
    llm = resolve_llm(args)
    return FrontEndSpec(llm, str(args.model) if args.model else None, args.llm_base_url)


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
    spec = _spec(args)
    scores = {}
    executor = executor_of(args)
    try:
        for name, rows in halves.items():
            tasks = [sgo.SgoTask(spec, row["Report ID"], row["Narrative"]) for row in rows]
            scores[name] = sgo.score_rows(rows, run_all(executor, sgo.run_sgo_task, tasks, f"sgo {name}"))
    finally:
        executor.close()
    if args.json:
        print(json.dumps(sgo.to_json(scores), indent=2, ensure_ascii=False))
        return EXIT_OK
    sizes = ", ".join(f"{name} {s.reports}" for name, s in scores.items())
    print(f"SGO two-party narratives scored on NHTSA's coded fields ({sizes}), front end --llm {args.llm}\n")
    print(sgo.table(scores))
    return EXIT_OK


def cmd_eval_srr(args: argparse.Namespace) -> int:
    """The scenario reconstruction rate of the SUMO oracle, per road kind (the paper's Tables 4 and 5).
    Every scenario x map is a task on the executor (-j, --executor); the rows are kept in file order,
    so the figures and the JSON are the same however many workers ran them."""
    files = sorted(p for name in args.scenarios for p in sov_files(Path(name)))
    maps = args.map or [str(default_map())]
    for map_path in maps:
        worker_map(map_path)  # a bad map is said before any task runs (and an .xodr is converted once)
    tasks = [SrrTask(str(path), str(m), args.roads, args.seed, args.spare_sites) for m in maps for path in files]
    executor = executor_of(args)
    try:
        done: list[list[dict[str, Any]]] = run_all(executor, run_srr_task, tasks, "srr")
    finally:
        executor.close()
    report: dict[str, dict[str, object]] = {}
    for number, map_path in enumerate(maps):
        rows = [row for chunk in done[number * len(files) : (number + 1) * len(files)] for row in chunk]
        key = map_key(map_path, maps)
        report[key] = {"rows": rows}
        print(srr_table(key, rows))
    if args.json:
        write_atomic(args.json, json.dumps(report, indent=2) + "\n")
    return EXIT_OK


def cmd_eval_tests(args: argparse.Namespace) -> int:
    """Ego failures of report-derived tests against random ones, per map (the paper's Table 6). Every
    scenario x map is a task on the executor; the tables are merged in task order."""
    files = scenario_files(args.scenarios)
    for path in files:  # every input is read and checked before the long run starts
        scenario, _ = load_scenario(path)
        verify_or_raise(scenario)
    ego = load_ego(args.ego)
    maps = args.map or [str(default_map())]
    tasks = []
    for map_path in maps:
        worker_map(map_path)  # a bad map is said before any task runs
        out = str(Path(args.output) / folder_name(Path(map_path).name)) if args.output else None
        tasks += [
            TestsTask(
                str(path),
                str(map_path),
                str(ego.path),
                args.roads,
                args.seed,
                args.spare_sites,
                args.baseline == "random",
                out,
            )
            for path in files
        ]
    executor = executor_of(args)
    try:
        done: list[TestsTable] = run_all(executor, run_tests_task, tasks, "tests")
    finally:
        executor.close()
    report: dict[str, Any] = {}
    for number, map_path in enumerate(maps):
        name = Path(map_path).name
        table = merged(done[number * len(files) : (number + 1) * len(files)])
        report[name] = table.to_json()
        if not args.json:
            title = f"Ego failures of {ego.model_name} on {name}: {len(files)} scenario(s) x {args.roads} site(s)"
            print(table.render(title))
    if args.json:
        print(json.dumps(report, indent=2, ensure_ascii=False))
    if args.output:
        print(f"verdicts written to {args.output}/", file=sys.stderr)
    return EXIT_OK
