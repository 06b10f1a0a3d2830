"""IR to canonical text: one layout, so that a one-fact change is a one-line diff.

Fixed section and field order, two-space indent, every field printed
(`unknown` included), sets sorted, integers without a decimal point.
`to_text(parse(s)) == s` for every canonical file.
"""

from __future__ import annotations

import json
from collections.abc import Iterator

from sovarc.dsl.ir import (
    Action,
    Crash,
    Environment,
    Evidence,
    Participant,
    Provenance,
    Road,
    Scenario,
    Speed,
    Trivia,
    Unknown,
)
from sovarc.dsl.parser import is_plain_name

INDENT = "  "


def format_number(value: float) -> str:
    """50 -> '50', 40.5 -> '40.5': the shortest text that reads back to the same float."""
    return str(int(value)) if float(value).is_integer() else repr(float(value))


def format_speed(value: Speed | Unknown) -> str:
    return str(value) if isinstance(value, Unknown) else f"{format_number(value.value)} {value.unit}"


def _word(value: object) -> str:
    return str(value)


def _text(value: str | Unknown) -> str:
    return "unknown" if isinstance(value, Unknown) else json.dumps(value, ensure_ascii=False)


def format_words(values: tuple[object, ...] | Unknown) -> str:
    return "unknown" if isinstance(values, Unknown) else ", ".join(str(v) for v in values)


def format_action(action: Action) -> str:
    return str(action.kind) if action.to is None else f"{action.kind}(to: {action.to})"


class _Writer:
    def __init__(self) -> None:
        self.lines: list[str] = []

    def line(self, depth: int, text: str, trivia: Trivia | None = None) -> None:
        pad = INDENT * depth
        if trivia:
            self.lines += [pad + c for c in trivia.leading]
        self.lines.append(pad + text + (f"  {trivia.trailing}" if trivia and trivia.trailing else ""))

    def close(self, depth: int, opened: Trivia | None, after: Trivia | None) -> None:
        if opened:
            self.lines += [INDENT * (depth + 1) + c for c in opened.closing]
        self.line(depth, "}", Trivia(trailing=after.trailing) if after else None)


def _fields(node: object, rows: list[tuple[str, str]]) -> Iterator[tuple[str, str, Trivia | None]]:
    comments = node.meta.comments  # type: ignore[attr-defined]
    for key, text in rows:
        yield key, text, comments.get(key)


def _block(w: _Writer, depth: int, header: str, node: object, rows: list[tuple[str, str]]) -> None:
    comments = node.meta.comments  # type: ignore[attr-defined]
    w.line(depth, header + " {", comments.get(""))
    for key, text, trivia in _fields(node, rows):
        w.line(depth + 1, f"{key} {text}", trivia)
    w.close(depth, comments.get(""), comments.get("}"))


def format_evidence(e: Evidence) -> str:
    return f"{e.fact} {e.reader} {e.start}..{e.end} {_text(e.quote)}"


def _provenance(w: _Writer, p: Provenance, order: dict[str, int]) -> None:
    rows = [
        ("report", _text(p.report)),
        ("sha256", _text(p.sha256)),
        ("frontend", _bare(p.frontend)),
        ("model", _text(p.model)),
    ]
    if p.assumed:
        rows.append(("assumed", ", ".join(p.assumed)))
    comments = p.meta.comments
    w.line(1, "provenance {", comments.get(""))
    for key, text, trivia in _fields(p, rows):
        w.line(2, f"{key} {text}", trivia)
    if p.evidence:  # in the order the facts are printed, so that a fact's evidence is one line of a diff
        w.line(2, "evidence {", comments.get("evidence"))
        for e in sorted(p.evidence, key=lambda e: e.sort_key(order)):
            w.line(3, format_evidence(e), e.meta.comments.get(""))
        w.close(2, comments.get("evidence"), comments.get("evidence}"))
    w.close(1, comments.get(""), comments.get("}"))


def _bare(value: str | Unknown) -> str:
    """A word if it is one, else a quoted string."""
    if isinstance(value, Unknown):
        return "unknown"
    return value if is_plain_name(value) else _text(value)


def _environment(w: _Writer, e: Environment) -> None:
    _block(w, 1, "environment", e, [("weather", format_words(e.weather)), ("lighting", format_words(e.lighting))])


def _road(w: _Writer, r: Road) -> None:
    _block(
        w,
        1,
        "road",
        r,
        [("kind", _word(r.kind)), ("lanes", _word(r.lanes)), ("speed_limit", format_speed(r.speed_limit))],
    )


def _participant(w: _Writer, p: Participant) -> None:
    comments = p.meta.comments
    w.line(1, f"{p.role} {p.id} {{", comments.get(""))
    for key, text, trivia in _fields(
        p,
        # An unknown kind is not written: most reports do not say it, and files from before kinds stay canonical.
        [("kind", _word(p.kind))] * (not isinstance(p.kind, Unknown))
        + [("heading", _word(p.heading)), ("lane", _word(p.lane)), ("speed", format_speed(p.speed))],
    ):
        w.line(2, f"{key} {text}", trivia)
    if isinstance(p.actions, Unknown):
        w.line(2, "actions unknown", comments.get("actions"))
        w.close(1, comments.get(""), comments.get("}"))
        return
    w.line(2, "actions {", comments.get("actions"))
    for action in p.actions:
        w.line(3, format_action(action), action.meta.comments.get(""))
    w.close(2, comments.get("actions"), comments.get("actions}"))
    w.close(1, comments.get(""), comments.get("}"))


def _crash(w: _Writer, c: Crash) -> None:
    _block(w, 1, "crash", c, [("type", _word(c.type)), ("striker", _word(c.striker)), ("victim", _word(c.victim))])


def to_text(scenario: Scenario) -> str:
    """The canonical text of a scenario, ending in one newline."""
    w = _Writer()
    comments = scenario.meta.comments
    w.line(0, f"scenario {scenario.name} {{", comments.get(""))
    if scenario.provenance is not None:
        order = {p.id: i for i, p in enumerate(scenario.participants)}
        _provenance(w, scenario.provenance, order)
    _environment(w, scenario.environment)
    _road(w, scenario.road)
    for participant in scenario.participants:
        _participant(w, participant)
    _crash(w, scenario.crash)
    w.close(0, comments.get(""), comments.get("}"))
    if "eof" in comments:
        w.lines += list(comments["eof"].leading)
    return "\n".join(w.lines) + "\n"
