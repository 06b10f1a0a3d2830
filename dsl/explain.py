"""Why each fact was read: every fact of a scenario beside the report's words it came from.

The evidence of a scenario (`provenance.evidence`) names characters of the report. Shown against the
report, each span is quoted as the compiler quotes an error: the report's line, and a caret under the
span. A report whose sha256 differs from the one the scenario was read from is refused: its characters
are not the ones the spans count.
"""

from __future__ import annotations

import hashlib
from collections.abc import Iterable, Iterator

from sovarc.dsl.errors import Diagnostic, InputError
from sovarc.dsl.ir import Evidence, Provenance, Role, Scenario, Unknown
from sovarc.dsl.printer import format_action, format_speed, format_words
from sovarc.dsl.span import Source, Span

WIDTH = 100  # characters of a report line shown around a span; report paragraphs are often one long line


def check_evidence(report: str, evidence: Iterable[Evidence]) -> list[str]:
    """Every way the evidence does not hold: a span outside the report, or a quote that is not the report's
    text at its span."""
    problems = []
    for e in evidence:
        if not 0 <= e.start < e.end <= len(report):
            problems.append(f"{e.fact}: span {e.start}..{e.end} is not inside the report ({len(report)} characters)")
        elif report[e.start : e.end] != e.quote:
            found = report[e.start : e.end]
            problems.append(f"{e.fact}: the report has {found!r} at {e.start}..{e.end}, not {e.quote!r}")
    return problems


def check_report(scenario: Scenario, report: Source) -> None:
    """Refuse a report that is not the one the scenario's evidence was read from."""
    p = scenario.provenance or Provenance()
    digest = hashlib.sha256(report.text.encode("utf-8")).hexdigest()
    if not isinstance(p.sha256, Unknown) and p.sha256 != digest:
        raise InputError(
            Diagnostic(
                f"{report.name} is not the report this scenario was read from (its sha256 is {digest[:12]}..., "
                f"the scenario's provenance has {p.sha256[:12]}...)",
                p.meta.where("sha256") or Span.whole_file(report.name),
                hint="give the report it was extracted from with --report, or extract it again",
            )
        )
    if problems := check_evidence(report.text, p.evidence):
        raise InputError([Diagnostic(f"evidence does not match {report.name}: {problem}") for problem in problems[:5]])


def _position(text: str, at: int) -> tuple[int, int]:
    """Line and column (from 1) of character `at`."""
    line = text.count("\n", 0, at) + 1
    return line, at - (text.rfind("\n", 0, at) + 1) + 1


def excerpt(report: Source, e: Evidence) -> list[str]:
    """The report's line with a caret under the span, cut to WIDTH characters around it."""
    line, col = _position(report.text, e.start)
    text = report.line_text(line).expandtabs(1)
    end_line, _ = _position(report.text, e.end)
    width = len(e.quote) if end_line == line else len(text) - col + 1
    left = max(0, min(col - 1 - 20, len(text) - WIDTH))
    right = left + WIDTH
    shown = ("…" if left else "") + text[left:right] + ("…" if right < len(text) else "")
    caret_at = col - 1 - left + (1 if left else 0)
    caret = min(width, WIDTH - (col - 1 - left))
    gutter = f"{line:>6} | "
    more = "…" if caret < width else ""  # the span goes on past what is shown
    more += f" (to line {end_line})" if end_line != line else ""
    return [gutter + shown, " " * (len(gutter) - 2) + "| " + " " * caret_at + "^" + "~" * max(0, caret - 1) + more]


def _facts(s: Scenario) -> Iterator[tuple[str, list[tuple[str, str, bool]]]]:
    """Each layer's name and its facts: (path, value shown, whether the value is unknown)."""

    def row(path: str, value: object, shown: str) -> tuple[str, str, bool]:
        return path, shown, isinstance(value, Unknown)

    env, road, crash = s.environment, s.road, s.crash
    yield (
        "environment",
        [
            row("environment.weather", env.weather, format_words(env.weather)),
            row("environment.lighting", env.lighting, format_words(env.lighting)),
        ],
    )
    yield (
        "road",
        [
            row("road.kind", road.kind, str(road.kind)),
            row("road.lanes", road.lanes, str(road.lanes)),
            row("road.speed_limit", road.speed_limit, format_speed(road.speed_limit)),
        ],
    )
    for p in s.participants:
        rows = [row(f"{p.id}.kind", p.kind, str(p.kind))] if p.role is Role.VEHICLE else []
        rows += [
            row(f"{p.id}.heading", p.heading, str(p.heading)),
            row(f"{p.id}.lane", p.lane, str(p.lane)),
            row(f"{p.id}.speed", p.speed, format_speed(p.speed)),
        ]
        if isinstance(p.actions, Unknown):
            rows.append(row(f"{p.id}.actions", p.actions, "unknown"))
        else:
            rows += [(f"{p.id}.actions[{n}]", format_action(a), False) for n, a in enumerate(p.actions, 1)]
        yield f"{p.role} {p.id}", rows
    yield (
        "crash",
        [
            row("crash.type", crash.type, str(crash.type)),
            row("crash.striker", crash.striker, str(crash.striker)),
            row("crash.victim", crash.victim, str(crash.victim)),
        ],
    )


def explain(scenario: Scenario, report: Source | None = None) -> str:
    """Every fact of the scenario, layer by layer, each with its evidence (against `report` when given:
    its line and a caret), or why it has none: assumed by the defaults, or not stated in the report."""
    p = scenario.provenance or Provenance()
    if report is not None:
        check_report(scenario, report)
    lines = [f"scenario {scenario.name}"]
    source = report.name if report is not None else p.report
    lines.append(f"  read from {source} by {p.frontend}" + ("" if report else " (report not given: quotes only)"))
    by_fact: dict[str, list[Evidence]] = {}
    for e in p.evidence:
        by_fact.setdefault(e.fact, []).append(e)
    for layer, rows in _facts(scenario):
        lines += ["", layer]
        for path, shown, unknown in rows:
            label = path.split(".", 1)[1]
            found = by_fact.get(path, [])
            if path in p.assumed:
                lines.append(f"  {label} {shown}: assumed (filled in by the defaults pass)")
            elif not found:
                lines.append(f"  {label} {shown}: " + ("not stated" if unknown else "no evidence"))
            for e in found:
                if report is None:
                    lines += [f"  {label} {shown}: {e.reader}, characters {e.start}..{e.end}", f'      "{e.quote}"']
                    continue
                line, col = _position(report.text, e.start)
                lines.append(f"  {label} {shown}: {e.reader}, line {line}:{col}")
                lines += excerpt(report, e)
    return "\n".join(lines) + "\n"
