"""The one error tree of sovarc, and how diagnostics are rendered.

Every problem the compiler finds in its input is a `Diagnostic` with a span.
Stages collect diagnostics and raise them together as one `SovarcError`
subclass, so the user sees every mistake of a file at once.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from enum import StrEnum

from sovarc.dsl.span import Source, Span

# Exit codes of the `sovarc` command, documented in its --help.
EXIT_OK = 0
EXIT_INPUT = 1  # the input is wrong (syntax, semantics, unreadable file, oracle failed)
EXIT_USAGE = 2  # the command line is wrong


class Severity(StrEnum):
    ERROR = "error"
    WARNING = "warning"
    NOTE = "note"


@dataclass(frozen=True)
class Diagnostic:
    message: str
    span: Span | None = None
    severity: Severity = Severity.ERROR
    hint: str | None = None

    def render(self, sources: Mapping[str, Source] | None = None) -> str:
        """`file:line:col: error: message`, then the line and a caret under the span."""
        if self.span is None:
            return f"{self.severity}: {self.message}" + (f"\n  hint: {self.hint}" if self.hint else "")
        if self.span.line == 0:  # a whole-file problem: no line to quote
            return f"{self.span.file}: {self.severity}: {self.message}"
        head = f"{self.span}: {self.severity}: {self.message}"
        source = (sources or {}).get(self.span.file)
        lines = [head]
        if source is not None:
            text = source.line_text(self.span.line).expandtabs(1)
            if text:
                width = (
                    max(1, self.span.end_col - self.span.col)
                    if self.span.end_line == self.span.line
                    else max(1, len(text) - self.span.col + 1)
                )
                gutter = f"{self.span.line:>4} | "
                lines.append(gutter + text)
                lines.append(" " * (len(gutter) - 2) + "| " + " " * (self.span.col - 1) + "^" + "~" * (width - 1))
        if self.hint:
            lines.append(f"  hint: {self.hint}")
        return "\n".join(lines)


class SovarcError(Exception):
    """Base of every error sovarc reports to a user; carries one or more diagnostics."""

    stage = "sovarc"

    def __init__(self, diagnostics: Diagnostic | Iterable[Diagnostic] | str) -> None:
        if isinstance(diagnostics, str):
            diagnostics = Diagnostic(diagnostics)
        if isinstance(diagnostics, Diagnostic):
            diagnostics = [diagnostics]
        self.diagnostics: tuple[Diagnostic, ...] = tuple(diagnostics)
        super().__init__("\n".join(d.render() for d in self.diagnostics))

    def render(self, sources: Mapping[str, Source] | None = None) -> str:
        return "\n".join(d.render(sources) for d in self.diagnostics)


class InputError(SovarcError):
    """A file cannot be read as input at all: missing, a directory, binary, not UTF-8, empty."""

    stage = "input"


class ParseError(SovarcError):
    stage = "parse"


class VerifyError(SovarcError):
    stage = "verify"


class LoweringError(SovarcError):
    stage = "lower"


class UnsatError(LoweringError):
    """The constraints of a scenario cannot all hold; the diagnostics name the conflicting facts."""


class SynthesisError(SovarcError):
    stage = "synthesize"


class UnsupportedError(SovarcError):
    """A target cannot express something in the IR; never dropped silently."""

    stage = "emit"


class OracleError(SovarcError):
    stage = "check"
