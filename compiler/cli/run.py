"""The main job (`sovarc run`, the default command) and `sovarc lower`: the pipeline, and what it prints."""

from __future__ import annotations

import argparse
import sys
from dataclasses import replace
from pathlib import Path
from typing import Any

import sovarc.targets.registry as registry
from sovarc.compiler.cli.common import front_end_options
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.pipeline import PIPELINE, STAGE_NAMES, Options, Sites, Slots, Stage, entry_stage, run_pipeline
from sovarc.compiler.report import write_run_report
from sovarc.compiler.scenario_io import load_scenario
from sovarc.compiler.slots import passed
from sovarc.dsl import read_source
from sovarc.dsl.errors import EXIT_INPUT, EXIT_OK, SovarcError

FIRST_PER_SITE = next(s.name for s in PIPELINE if s.per_site)


def cmd_run(args: argparse.Namespace) -> int:
    """Run the pipeline from the input's entry stage to --stop-after (default: check with -t, else
    verify or the last stage dumped), dumping the stages asked for; then print the last one."""
    start = entry_stage(args.input)
    source = read_source(args.input, "report or scenario file")
    stop = _last_stage(args)
    per_site = STAGE_NAMES.index(stop) >= STAGE_NAMES.index(FIRST_PER_SITE)
    options = replace(
        front_end_options(args),
        map=args.map,
        roads=args.roads,
        spare=args.spare_sites,
        targets=args.target or (),
        target_values={f.dest: getattr(args, f.dest) for f in registry.all_flags() if not f.shared},
    )

    def after(stage: Stage, value: Any) -> None:
        if stage.name in args.dump_ir_after:
            print(f"// ----- IR after {stage.name} -----")
            print(stage.render(value), end="")

    try:
        whole_stop = STAGE_NAMES[STAGE_NAMES.index(FIRST_PER_SITE) - 1] if per_site else stop
        value, log = run_pipeline(source, start=start, stop=whole_stop, options=options, after_stage=after)
        for warning in log.warnings:
            print(warning.render({source.name: source}), file=sys.stderr)
        if per_site:
            assert isinstance(value, Sites)
            # emit and check write one folder per site: -o, else sovarc-out/<scenario>
            out = Path(args.output) if args.output else Path("sovarc-out") / value.assumed.scenario.name
            writes = STAGE_NAMES.index(stop) >= STAGE_NAMES.index("emit")
            options = replace(options, out_dir=out if writes else None)
            value, _ = run_pipeline(value, start=FIRST_PER_SITE, stop=stop, options=options, after_stage=after)
    except SovarcError as exc:
        print(exc.render({source.name: source}), file=sys.stderr)
        return EXIT_INPUT
    last = PIPELINE[STAGE_NAMES.index(stop)]
    if options.out_dir is not None:
        _print_record(last.render(value), options.out_dir)
        if options.targets and isinstance(value, Slots):
            write_run_report(options.out_dir, value.results, options.targets, args.input)
        print(f"written to {options.out_dir}/", file=sys.stderr)
        return _exit_code(value)
    if isinstance(value, Slots):
        _print_errors(value)
    text = last.render(value)
    if args.output and not per_site:
        write_atomic(args.output, text)
    elif not args.dump_ir_after:
        print(text, end="")
    return _exit_code(value) if isinstance(value, Slots) else EXIT_OK


def _last_stage(args: argparse.Namespace) -> str:
    if args.stop_after:
        return str(args.stop_after)
    if args.target:
        return STAGE_NAMES[-1]
    return max(["verify", *args.dump_ir_after], key=STAGE_NAMES.index)


def cmd_lower(args: argparse.Namespace) -> int:
    """Stage a scenario on the map's sites and write each site's plan files (the pipeline up to emit)."""
    scenario, _ = load_scenario(args.input)
    options = Options(seed=args.seed, map=args.map, roads=args.roads, spare=args.spare_sites, out_dir=Path(args.output))
    slots, _ = run_pipeline(scenario, start="verify", stop="emit", options=options)
    _print_errors(slots)
    _print_record(PIPELINE[STAGE_NAMES.index("emit")].render(slots), Path(args.output))
    return _exit_code(slots)


def _print_errors(slots: Slots) -> None:
    for r in slots.results:
        if r.error is not None:
            print(r.error.render(), file=sys.stderr)


def _print_record(table: str, out: Path) -> None:
    """Print the table and keep it as out/summary.txt: the sites given up, and why, are in no site's folder."""
    write_atomic(out / "summary.txt", table)
    print(table, end="")


def _exit_code(slots: Slots) -> int:
    """Input error when a slot has no plan or a target's check failed; a failed ego test (fmu) is a
    finding about the driving system, not a failure of the run."""
    ok = all(r.plan is not None and all(passed(v) for t, v in r.verdicts.items() if t != "fmu") for r in slots.results)
    return EXIT_OK if ok else EXIT_INPUT
