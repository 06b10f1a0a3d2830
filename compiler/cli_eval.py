"""`sovarc eval`: dispatch to srr and tests, and the extraction accuracy (the paper's Table 3)."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from sovarc.compiler.cli_backend import cmd_eval_srr
from sovarc.compiler.cli_common import Reporter, UsageError, make_front_end
from sovarc.compiler.cli_eval_tests import cmd_eval_tests
from sovarc.dsl import SovarcError
from sovarc.dsl.errors import EXIT_INPUT, EXIT_OK


def cmd_eval(args: argparse.Namespace) -> int:
    if args.evaluation == "srr":
        return cmd_eval_srr(args)
    if args.evaluation == "tests":
        return cmd_eval_tests(args)
    return cmd_eval_extraction(args)


def cmd_eval_extraction(args: argparse.Namespace) -> int:
    from sovarc.compiler.evaluation.extraction import Report
    from sovarc.compiler.frontend.truth import import_truth_file
    from sovarc.compiler.progress import progress
    from sovarc.dsl import read_source

    truths = sorted(Path(args.truth).glob("*/*.json"))
    if not truths:
        raise UsageError(f"no ground truth found: expected {args.truth}/<category>/<n>.json")
    report = Report()
    reporter = Reporter()
    front_end = make_front_end(args)
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
