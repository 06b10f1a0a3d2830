"""`sovarc batch`: many reports and scenarios on several maps, spread over cores or a Ray cluster."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

import sovarc.targets.registry as registry
from sovarc.compiler.batch import BatchOptions, run_batch
from sovarc.compiler.batch.executors import EXECUTORS, Executor, make_executor
from sovarc.compiler.cli.common import UsageError, add_llm_options, make_front_end, target_names
from sovarc.compiler.frontend import scenario_name
from sovarc.compiler.pipeline import default_map
from sovarc.dsl.errors import EXIT_INPUT, EXIT_OK

DESCRIPTION = """\
Compile many inputs on several maps. Each report is extracted once (the model's answers are cached)
and kept as OUT/scenarios/NAME.sov; then every scenario x map is an independent task, staged on
--roads sites, emitted for the targets and checked, in its own folder OUT/SCENARIO/MAP-KEY/, whose
KEY is the hash of its inputs and options. A rerun skips the tasks already finished, so a batch that
was stopped resumes where it was; a task that fails records its error and the others go on.

OUT/manifest.csv and OUT/manifest.json list one row per scenario-site: input, map, site, the
verdict of each target, timings and error.

examples:
  sovarc batch examples/reports/*.txt -m examples/maps/town.net.xml -t sumo --roads 3 -o out
  sovarc batch truth/*.sov -m town.net.xml -m city.xodr -t all -j 8 -o out
  sovarc batch truth/ -m town.net.xml --executor ray --address auto -o out   (a running Ray cluster)"""


def add_executor_options(parser: argparse.ArgumentParser) -> None:
    """-j, --executor and --address: where independent tasks run."""
    parser.add_argument(
        "-j", "--jobs", type=positive, metavar="N", help="tasks run at once (default: every core; 1 runs in-process)"
    )
    parser.add_argument(
        "--executor",
        choices=EXECUTORS,
        default="local",
        help="local: a process pool on this machine (default); ray: a Ray cluster (pip install 'sovarc[ray]')",
    )
    parser.add_argument(
        "--address", metavar="ADDR", help="with --executor ray: the cluster ('auto', 'ray://host:10001'); "
        "default: a local cluster of -j CPUs started for this run"
    )  # fmt: skip


def executor_of(args: argparse.Namespace) -> Executor:
    return make_executor(args.executor, args.jobs, args.address)


def add_batch_parser(sub: Any, summary: str, formatter: Any, add_target_options: Any) -> None:
    batch = sub.add_parser("batch", help=summary, formatter_class=formatter, description=DESCRIPTION)
    batch.add_argument("inputs", nargs="+", metavar="INPUT", help="crash reports (.txt), scenarios (.sov), or folders")
    batch.add_argument("-m", "--map", action="append", help="a map (repeatable; default: the bundled town)")
    batch.add_argument("-t", "--target", action="append", metavar="TARGET", type=target_names,
                       help=f"a target (repeatable): {', '.join(registry.names())} or all (default sumo)")  # fmt: skip
    batch.add_argument("--roads", type=positive, default=1, metavar="N", help="sites per scenario and map (default 1)")
    batch.add_argument("--spare-sites", type=int, metavar="K", help="extra sites tried in place of failed ones")
    batch.add_argument("--seed", type=int, default=0, help="seed for every random choice (default 0)")
    batch.add_argument("-o", "--output", required=True, metavar="OUT", help="the batch's folder")
    add_executor_options(batch)
    add_target_options(batch)
    add_llm_options(batch)


def positive(value: str) -> int:
    """An argparse type: a whole number of at least 1 (sites, jobs)."""
    number = int(value)
    if number < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, not {number}")
    return number


def expand_inputs(names: list[str]) -> list[str]:
    """Files as given; a folder's .txt and .sov files, sorted; each input once."""
    found: list[str] = []
    for name in names:
        path = Path(name)
        if path.is_dir():
            found += sorted(str(p) for p in path.rglob("*") if p.suffix.lower() in (".txt", ".sov"))
        elif path.suffix.lower() in (".txt", ".sov"):
            found.append(name)
        else:
            raise UsageError(f"{name}: not a crash report (.txt), a scenario (.sov) or a folder of them")
    return list(dict.fromkeys(found))


def _targets(given: list[tuple[str, ...]] | None) -> tuple[str, ...]:
    """The targets of every `-t` (each already a tuple of names: see `target_names`), once each, in order."""
    return tuple(dict.fromkeys(name for names in given or [("sumo",)] for name in names))


def _refuse_shared_names(inputs: list[str]) -> None:
    """Two reports whose scenarios would get one name would share OUT/scenarios/NAME.sov."""
    first: dict[str, str] = {}
    for name in inputs:
        if Path(name).suffix.lower() != ".txt":
            continue
        key = scenario_name(name)
        if key in first:
            raise UsageError(f"{first[key]} and {name} would both be extracted to scenarios/{key}.sov; "
                             "give the reports distinct file names")  # fmt: skip
        first[key] = name


def cmd_batch(args: argparse.Namespace) -> int:
    inputs = expand_inputs(args.inputs)
    if not inputs:
        raise UsageError("no crash reports (.txt) or scenarios (.sov) among the inputs")
    _refuse_shared_names(inputs)
    options = BatchOptions(
        maps=tuple(args.map or [str(default_map())]),
        out=Path(args.output),
        roads=args.roads,
        seed=args.seed,
        spare=args.spare_sites,
        targets=_targets(args.target),
        target_values={f.dest: getattr(args, f.dest) for f in registry.all_flags() if not f.shared},
    )
    executor = executor_of(args)
    try:
        result = run_batch(inputs, options, executor, lambda: make_front_end(args))
    finally:
        executor.close()
    planned = sum(1 for r in result.rows if r["planned"])
    failed = sum(1 for r in result.rows if r["error"] or any(r.get(t) == "fail" for t in options.targets))
    print(
        f"{len(result.rows)} scenario-site(s): {planned} planned, {failed} failed or unplanned; "
        f"{result.ran} task(s) run, {result.reused} reused from an earlier run; "
        f"manifest: {result.manifest[0]}",
        file=sys.stderr,
    )
    return EXIT_INPUT if result.failed_inputs else EXIT_OK
