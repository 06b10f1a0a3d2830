"""The commands that work on scenario files: check, fmt, diff, explain, convert, schema, import-truth, extract."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from sovarc.compiler.cli.common import Reporter, UsageError, make_front_end, source_of
from sovarc.compiler.frontend import scenario_name
from sovarc.compiler.frontend.truth import import_truth_file
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.scenario_io import dump_scenario, load_scenario
from sovarc.dsl import Severity, SovarcError, diff, json_schema, read_source, to_text, verify, verify_or_raise
from sovarc.dsl.errors import EXIT_INPUT, EXIT_OK
from sovarc.dsl.explain import explain
from tqdm import tqdm


def cmd_check(args: argparse.Namespace) -> int:
    reporter = Reporter()
    ok = 0
    for name in args.files:
        try:
            scenario, source = load_scenario(name)
        except SovarcError as exc:
            reporter.error(exc, source_of(name))
            continue
        found = verify(scenario)
        reporter.diagnostics(found, source, args.strict)
        if not any(d.severity is Severity.ERROR for d in found):
            ok += 1
    print(f"{ok} of {len(args.files)} file(s) ok", file=sys.stderr)
    return EXIT_INPUT if reporter.failed else EXIT_OK


def cmd_fmt(args: argparse.Namespace) -> int:
    reporter = Reporter()
    changed = 0
    for name in args.files:
        try:
            scenario, source = load_scenario(name)
        except SovarcError as exc:
            reporter.error(exc, source_of(name))
            continue
        if Path(name).suffix.lower() == ".json":
            reporter.failed = True
            print(f"{name}: fmt rewrites .sov text; use `sovarc convert` for JSON", file=sys.stderr)
            continue
        text = to_text(scenario)
        if text == source.text:
            continue
        changed += 1
        if args.check:
            print(f"would reformat {name}", file=sys.stderr)
        else:
            write_atomic(name, text)
            print(f"reformatted {name}", file=sys.stderr)
    verb = "would be reformatted" if args.check else "reformatted"
    print(f"{changed} file(s) {verb}, {len(args.files) - changed} unchanged", file=sys.stderr)
    if args.check and changed:
        return EXIT_INPUT
    return EXIT_INPUT if reporter.failed else EXIT_OK


def cmd_diff(args: argparse.Namespace) -> int:
    reporter = Reporter()
    loaded = []
    for name in (args.old, args.new):
        try:
            loaded.append(load_scenario(name)[0])
        except SovarcError as exc:
            reporter.error(exc, source_of(name))
    if reporter.failed:
        return EXIT_INPUT
    changes = diff(loaded[0], loaded[1], evidence=args.evidence)
    if args.json:
        print(json.dumps([c.to_json() for c in changes], indent=2, ensure_ascii=False))
    elif changes:
        print("\n".join(c.message for c in changes))
    else:
        print("no semantic changes")
    return EXIT_INPUT if (args.exit_code and changes) else EXIT_OK


def cmd_convert(args: argparse.Namespace) -> int:
    form = args.to or (Path(args.output).suffix.lstrip(".").lower() if args.output else None)
    if form not in ("sov", "json"):
        raise UsageError("say which form to write: -o FILE.sov / -o FILE.json, or --to sov|json")
    try:
        scenario, _ = load_scenario(args.file)
    except SovarcError as exc:
        Reporter().error(exc, source_of(args.file))
        return EXIT_INPUT
    text = dump_scenario(scenario, as_json=form == "json")
    if args.output:
        write_atomic(args.output, text)
    else:
        print(text, end="")
    return EXIT_OK


def cmd_explain(args: argparse.Namespace) -> int:
    reporter = Reporter()
    try:
        scenario, source = load_scenario(args.file)
    except SovarcError as exc:
        reporter.error(exc, source_of(args.file))
        return EXIT_INPUT
    report = None
    p = scenario.provenance
    if args.report:
        report = read_source(args.report, "crash report")
    elif p is not None and isinstance(p.report, str):
        # The report as the provenance names it: from here, else beside the scenario file.
        for candidate in (Path(p.report), Path(source.name).parent / p.report):
            if candidate.is_file():
                report = read_source(candidate, "crash report")
                break
    try:
        print(explain(scenario, report), end="")
    except SovarcError as exc:
        reporter.error(exc, source)
        return EXIT_INPUT
    return EXIT_OK


def cmd_schema(args: argparse.Namespace) -> int:
    print(json.dumps(json_schema(), indent=2, ensure_ascii=False))
    return EXIT_OK


def cmd_import_truth(args: argparse.Namespace) -> int:
    files: list[Path] = []
    for name in args.inputs:
        path = Path(name)
        if path.is_dir():
            files += sorted(path.rglob("*.json"))
        else:
            files.append(path)
    if not files:
        raise UsageError("no ground-truth .json files found in " + ", ".join(args.inputs))
    _refuse_shared_outputs({str(path): f"{path.parent.name}_{path.stem}" for path in files}, args.output)
    reporter = Reporter()
    written = 0
    for path in tqdm(files, desc="import-truth", unit="file", disable=None):
        reports = Path(args.reports) if args.reports else path.parent.parent.parent / "reports"
        try:
            imported = import_truth_file(path, reports if reports.is_dir() else None)
            verify_or_raise(imported.scenario)
        except SovarcError as exc:
            reporter.error(exc, source_of(str(path)), str(path))
            continue
        for note in imported.notes:
            print(f"{path}: note: {note}", file=sys.stderr)
        write_atomic(Path(args.output) / f"{imported.scenario.name}.sov", to_text(imported.scenario))
        written += 1
    print(f"{written} of {len(files)} scenario(s) written to {args.output}", file=sys.stderr)
    return EXIT_INPUT if reporter.failed else EXIT_OK


def cmd_extract(args: argparse.Namespace) -> int:
    if len(args.reports) > 1 and not args.output:
        raise UsageError("give -o DIR to extract more than one report")
    if args.output:
        _refuse_shared_outputs({name: scenario_name(name) for name in args.reports}, args.output)
    reporter = Reporter()
    written = 0
    front_end = make_front_end(args)
    for name in tqdm(args.reports, desc="extract", unit="report", disable=None):
        try:
            source = read_source(name, "crash report")
            extraction = front_end.extract(source)
            scenario = extraction.scenario
            warnings = verify_or_raise(scenario)
        except SovarcError as exc:
            reporter.error(exc, None, name)
            continue
        for note in extraction.notes:
            print(f"{name}: note: {note}", file=sys.stderr)
        for w in warnings:
            reporter.show(w, None, name)
        if args.output:
            write_atomic(Path(args.output) / f"{scenario.name}.sov", to_text(scenario))
        else:
            print(to_text(scenario), end="")
        written += 1
    front_end.close()
    if args.output:
        print(f"{written} of {len(args.reports)} scenario(s) written to {args.output}", file=sys.stderr)
    return EXIT_INPUT if reporter.failed else EXIT_OK


def _refuse_shared_outputs(names: dict[str, str], folder: str) -> None:
    """Before anything is written: two inputs whose scenarios would get one name (a/30.txt and b/30.txt)
    would overwrite each other's file in `folder`. Named inputs, not a silent loss."""
    first: dict[str, str] = {}
    for given, name in names.items():
        if name in first and first[name] != given:
            target = Path(folder) / f"{name}.sov"
            raise UsageError(
                f"{first[name]} and {given} would both be written to {target} (scenario '{name}'); "
                "give the inputs distinct file names, or run them into separate folders"
            )
        first.setdefault(name, given)
