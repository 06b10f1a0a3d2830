"""The `sovarc` command line's parser: its commands, options and help text."""

from __future__ import annotations

import argparse
from importlib.metadata import PackageNotFoundError, version

from sovarc.compiler.cli_backend import (
    add_lower_parser,
    add_site_options,
    add_srr_parser,
    add_target_options,
    target_names,
)
from sovarc.compiler.cli_common import add_llm_options
from sovarc.compiler.cli_eval_tests import add_tests_parser
from sovarc.compiler.pipeline import STAGE_NAMES
from sovarc.targets import registry

try:
    __version__ = version("sovarc")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"

DESCRIPTION = """\
sovarc compiles a police crash report into executable driving-test scenarios.

  report.txt --extract--> scenario IR (.sov) --lower--> plan --synthesize--> trajectories --emit--> targets

The main job takes a report (or a .sov scenario) and a target:
  sovarc examples/reports/left_turn_oncoming_pickup.txt -t sumo --roads 3 -o out
                                     stage on 3 sites of the bundled town, replay each in SUMO
  sovarc examples/reports/left_turn_oncoming_pickup.txt       extract, verify, print the IR
  sovarc examples/scenarios/straight_rear_end_stopped_traffic.sov --dump-ir-after=read

Front end and evaluation:
  sovarc extract examples/reports/*.txt -o out/          one .sov per report
  sovarc eval extraction --reports DIR --truth DIR       accuracy per attribute (the paper's Table 3)
  sovarc eval srr truth/ -m MAP --roads 3                reconstruction rate in SUMO (Tables 4 and 5)

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


def _formatter(prog: str) -> argparse.HelpFormatter:
    return argparse.RawDescriptionHelpFormatter(prog, max_help_position=32)


def build_parser() -> argparse.ArgumentParser:
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
        help=f"stage the crash on the map and emit and check: {', '.join(registry.names())} or all",
    )
    run.add_argument("-o", "--output", help="the final IR (no -t), or the output folder (with -t)")
    add_site_options(run)
    add_target_options(run)
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
    add_llm_options(run)

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
    add_llm_options(ext)

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
    add_llm_options(exv)
    add_srr_parser(which, _formatter)
    add_tests_parser(which, _formatter)
    return parser
