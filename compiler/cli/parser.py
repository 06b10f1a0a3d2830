"""The `sovarc` command line's parser: its commands, options and help text."""

from __future__ import annotations

import argparse
from importlib.metadata import PackageNotFoundError, version
from typing import Any

import sovarc.targets.registry as registry
from sovarc.compiler.cli.batch import add_batch_parser, add_executor_options, positive
from sovarc.compiler.cli.common import add_llm_options, target_names
from sovarc.compiler.cli.sites import add_sites_parser
from sovarc.compiler.pipeline import STAGE_NAMES

try:
    __version__ = version("sovarc")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"

# The OpenSCENARIO versions the target writes, as its --osc-version option declares them.

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
  sovarc batch reports/ -m MAP -m MAP2 -t all -o out     many inputs x maps, on every core, resumable

Tools for the scenario IR:
  sovarc check examples/scenarios/*.sov     report every error and warning, compiler style
  sovarc fmt --check examples/scenarios/*.sov
  sovarc diff old.sov new.sov               what changed, by meaning
  sovarc explain FILE.sov                   each fact beside the report's words it was read from
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
    "explain": "show each fact of a scenario with the words of the report it was read from",
    "convert": "convert a scenario between .sov text and its JSON form",
    "schema": "print the JSON Schema of the scenario IR's JSON form",
    "import-truth": "convert SoVAR-style ground-truth JSON into .sov scenarios",
    "extract": "read crash reports into .sov scenarios (the front end alone)",
    "eval": "measure the compiler against ground truth (extraction, srr, tests)",
    "lower": "stage a scenario on a map's sites and write the timed plan",
    "sites": "list (and draw) the sites a map offers, per road kind",
    "batch": "compile many reports or scenarios on several maps, in parallel, resumable",
}


EXPLAIN_DESCRIPTION = """\
Show why each fact of a scenario was read. The front end records, for every fact it
reads, the characters of the report it read it from (the `evidence` block of the
scenario's provenance). explain prints the facts layer by layer (environment, road,
each participant, the crash), each with the reader that read it (rules or model) and
the report's line with a caret under the words, as the compiler shows an error.
A fact with no evidence says why: "assumed" (filled in by the defaults pass, listed
under provenance.assumed), "not stated" (unknown: the report does not say), or
"no evidence" (known, but no reader recorded where: a hand-written scenario, say).

The report must be the one the scenario was read from: explain refuses a report
whose sha256 differs from the provenance's, and one whose text at a span is not the
quoted text. Without the report, the quotes are shown alone.

examples:
  sovarc extract examples/reports/evidence_left_turn_signal.txt -o out/
  sovarc explain out/evidence_left_turn_signal.sov
  sovarc explain scenario.sov --report ../reports/30.txt
  sovarc diff --evidence old.sov new.sov      what changed in the evidence too"""


TESTS_DESCRIPTION = """\
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
            "  sovarc scenario.sov --dump-ir-after=stage -m city.net.xml"
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
        choices=STAGE_NAMES,
        metavar="STAGE",
        action="append",
        default=[],
        help="print the IR after STAGE (repeatable)",
    )
    run.add_argument("--seed", type=int, default=0, help="seed for every random choice (default 0)")
    add_llm_options(run)

    _add_lower_parser(sub, COMMANDS["lower"], _formatter)
    add_sites_parser(sub, COMMANDS["sites"], _formatter)
    add_batch_parser(sub, COMMANDS["batch"], _formatter, add_target_options)

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
    dif.add_argument(
        "--evidence", action="store_true", help="also list changed evidence (why a fact was read), which is no fact"
    )

    exp = sub.add_parser(
        "explain",
        help=COMMANDS["explain"],
        formatter_class=_formatter,
        description=EXPLAIN_DESCRIPTION,
    )
    exp.add_argument("file", metavar="FILE.sov", help="a scenario (.sov or .json), usually written by `sovarc extract`")
    exp.add_argument(
        "--report",
        metavar="REPORT.txt",
        help="the crash report it was read from (default: the report its provenance names, if that file exists)",
    )

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
        "in the form of the paper's Table 3, then the failing cases and fields.\n"
        "With --format sgo CSV: the SGO narratives' reading, scored on NHTSA's coded fields.",
    )
    exv.add_argument(
        "--format",
        choices=("nmvccs", "sgo"),
        default="nmvccs",
        help="nmvccs: --reports and --truth folders (default); sgo: NHTSA's SGO incident CSV, scored on its "
        "coded fields, development half beside held-out half",
    )
    exv.add_argument("csv", nargs="?", help="the SGO incident CSV (with --format sgo)")
    exv.add_argument("--reports", help="folder of <category>/<n>.txt reports")
    exv.add_argument("--truth", help="folder of <category>/<n>.json ground truth")
    exv.add_argument(
        "--sample",
        type=_not_negative,
        metavar="N",
        help="with --format sgo: score only N held-out reports (the first by sha256 of the Report ID), for a "
        "slow front end",
    )
    exv.add_argument("--json", action="store_true", help="print the figures and failures as JSON")
    add_llm_options(exv)
    add_executor_options(exv)
    _add_srr_parser(which, _formatter)
    _add_tests_parser(which, _formatter)
    return parser


def add_site_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-m", "--map", help="road network, .net.xml or .xodr (default: the bundled example town)")
    parser.add_argument("--roads", type=int, default=1, metavar="N", help="stage on N distinct sites (default 1)")
    add_spare_option(parser)


def add_spare_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--spare-sites",
        type=_not_negative,
        metavar="K",
        help="when a chosen site cannot host the crash, try up to K more sites in its place, each one noted "
        "with its reason (default: three times --roads; 0 keeps the first choice, failures and all)",
    )


def _not_negative(value: str) -> int:
    number = int(value)
    if number < 0:
        raise argparse.ArgumentTypeError(f"must be 0 or more, not {number}")
    return number


def add_target_options(parser: argparse.ArgumentParser) -> None:
    """Each registered target's options as flags (a shared one, like --seed, the parser has already)."""
    for flag in registry.all_flags():
        if flag.shared:
            continue
        parser.add_argument(flag.flag, type=flag.type, choices=flag.choices, default=flag.default, help=flag.help)


def _add_lower_parser(sub: Any, summary: str, formatter: Any) -> None:
    low = sub.add_parser(
        "lower",
        help=summary,
        formatter_class=formatter,
        description=(
            "Stage a scenario on sites of a map: routes, the collision area, Z3 constraints (Groups 1-5),\n"
            "OMPL paths and Ruckig timing. Writes, per site, plan.txt (readable), plan.json and plan.png.\n\n"
            "examples:\n"
            "  sovarc lower examples/scenarios/intersection_left_turn_across_path_side.sov -o out\n"
            "  sovarc lower scenario.sov -m city.net.xml --roads 3 --seed 7 -o out"
        ),
    )
    low.add_argument("input", help="a scenario (.sov or .json)")
    add_site_options(low)
    low.add_argument("--seed", type=int, default=0, help="seed for the choice of sites (default 0)")
    low.add_argument("-o", "--output", required=True, help="folder for one sub-folder per site")


def _add_srr_parser(which: Any, formatter: Any) -> None:
    srr = which.add_parser(
        "srr",
        formatter_class=formatter,
        help="scenario reconstruction rate in SUMO, per road kind",
        description="Stage every scenario on --roads sites of each map, replay it in SUMO and print the\n"
        "reconstruction rate per road kind (the paper's Table 4) and the failures by class\n"
        "(Table 5: planning failed, crash type mismatch, line crossing; and no site of its shape,\n"
        "where fewer of the map's sites have the lanes and arms a scenario needs than --roads),\n"
        "the rate also over the scenario-sites the map has a site of the needed shape for.\n\n"
        "example:\n"
        "  sovarc import-truth ../shared/data/nmvccs/truth -o truth\n"
        "  sovarc eval srr truth --roads 3 -m examples/maps/town.net.xml --json srr.json",
    )
    srr.add_argument("scenarios", nargs="+", help=".sov files, or folders of them")
    srr.add_argument("-m", "--map", action="append", help="a map (repeatable; default: the bundled town)")
    srr.add_argument("--roads", type=int, default=3, metavar="N", help="sites per scenario (default 3)")
    add_spare_option(srr)
    srr.add_argument("--seed", type=int, default=0, help="seed for the choice of sites (default 0)")
    srr.add_argument("--json", help="also write every scenario-site's result here")
    add_executor_options(srr)


def _add_tests_parser(which: Any, formatter: Any) -> None:
    tests = which.add_parser(
        "tests",
        formatter_class=formatter,
        help="ego failures: report-derived tests against random ones (Table 6)",
        description=TESTS_DESCRIPTION,
    )
    tests.add_argument("scenarios", nargs="+", help=".sov files, or folders of them")
    tests.add_argument("-m", "--map", action="append", help="a map (repeatable; default: the bundled town)")
    tests.add_argument("--roads", type=positive, default=3, metavar="N", help="sites per scenario (default 3)")
    add_spare_option(tests)
    tests.add_argument(
        "--baseline", choices=("random", "none"), default="random", help="the baseline to compare with (default random)"
    )
    tests.add_argument("--ego", metavar="FMU", help="the driving system under test (default: the reference ego)")
    tests.add_argument("--seed", type=int, default=0, help="seed for the sites and the random NPCs (default 0)")
    tests.add_argument("--json", action="store_true", help="print the figures and every verdict as JSON")
    tests.add_argument("-o", "--output", help="write each test's verdict, and a PNG of each failed test, under here")
    add_executor_options(tests)
