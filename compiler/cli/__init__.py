"""The `sovarc` command line: `main`, which parses the command line and hands it to a command's handler.

parser.py builds the parser; files.py handles the commands on scenario files; run.py the main job
(the pipeline) and `lower`; eval.py `sovarc eval`.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable, Sequence

from sovarc.compiler.cli.batch import cmd_batch
from sovarc.compiler.cli.common import UsageError
from sovarc.compiler.cli.eval import cmd_eval
from sovarc.compiler.cli.files import (
    cmd_check,
    cmd_convert,
    cmd_diff,
    cmd_explain,
    cmd_extract,
    cmd_fmt,
    cmd_import_truth,
    cmd_schema,
)
from sovarc.compiler.cli.parser import COMMANDS, build_parser
from sovarc.compiler.cli.run import cmd_lower, cmd_run
from sovarc.compiler.cli.sites import cmd_sites
from sovarc.dsl import SovarcError
from sovarc.dsl.errors import EXIT_INPUT, EXIT_OK, EXIT_USAGE

__all__ = ["main"]

HANDLERS: dict[str, Callable[[argparse.Namespace], int]] = {
    "extract": cmd_extract,
    "eval": cmd_eval,
    "import-truth": cmd_import_truth,
    "run": cmd_run,
    "lower": cmd_lower,
    "check": cmd_check,
    "fmt": cmd_fmt,
    "diff": cmd_diff,
    "explain": cmd_explain,
    "convert": cmd_convert,
    "schema": cmd_schema,
    "sites": cmd_sites,
    "batch": cmd_batch,
}


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    # `sovarc REPORT -t TARGET` is the main job: a first word that is no command means `run`.
    if argv and argv[0] not in COMMANDS and not argv[0].startswith("-"):
        argv.insert(0, "run")
    parser = build_parser()
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
