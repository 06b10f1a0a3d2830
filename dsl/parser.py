"""Text to IR: the Lark parser of grammar/sov.lark and a mechanical transformer.

The transformer maps each grammar rule onto one IR node or field and records
the span of everything it builds. It checks only what the text alone decides
(an enum word exists, a field is not written twice); meaning is the verifier's.
"""

from __future__ import annotations

import difflib
import functools
import json
import re
from collections.abc import Iterable
from dataclasses import fields as dc_fields
from enum import Enum
from importlib import resources
from typing import Any, TypeVar

from lark import Lark, Token, Transformer, Tree, v_args
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken
from sovarc.dsl.comments import attach_comments
from sovarc.dsl.errors import Diagnostic, ParseError
from sovarc.dsl.ir import (
    UNKNOWN,
    Action,
    ActionKind,
    Crash,
    CrashType,
    Environment,
    Evidence,
    Heading,
    Lighting,
    Meta,
    Participant,
    Provenance,
    Reader,
    Road,
    RoadKind,
    Role,
    Scenario,
    Side,
    Speed,
    SpeedUnit,
    Unknown,
    VehicleKind,
    Weather,
)
from sovarc.dsl.span import Source, Span

E = TypeVar("E", bound=Enum)

# How Lark's terminal names read in an error message.
_TERMINAL_WORDS = {
    "NAME": "a name",
    "NUMBER": "a number",
    "STRING": "a quoted string",
    "PATH": "a dotted path like V1.lane",
    "CHARS": "a character span like 120..131",
    "LBRACE": "'{'",
    "RBRACE": "'}'",
    "LPAR": "'('",
    "RPAR": "')'",
    "COMMA": "','",
    "COLON": "':'",
    "SLASH": "'/'",
    "ROLE": "'vehicle' or 'pedestrian'",
    "$END": "end of file",
}

# Unit spellings accepted on input; the printer always writes the canonical one.
_UNITS = {"km/h": SpeedUnit.KMH, "mph": SpeedUnit.MPH}


@functools.cache
def _lark() -> Lark:
    grammar = resources.files("sovarc.grammar").joinpath("sov.lark").read_text("utf-8")
    return Lark(grammar, parser="lalr", propagate_positions=True, maybe_placeholders=False)


NAME_PATTERN = re.compile(r"[A-Za-z_][A-Za-z0-9_\-]*")


@functools.cache
def keywords() -> frozenset[str]:
    """Words the grammar reserves; they cannot serve as names."""
    words: set[str] = set()
    for term in _lark().terminals:
        if term.pattern.type == "str":
            words.add(term.pattern.value)
        elif term.name == "ROLE":
            words.update(("vehicle", "pedestrian"))
    return frozenset(w for w in words if NAME_PATTERN.fullmatch(w))


def is_plain_name(word: str) -> bool:
    """True if `word` can be written unquoted where the grammar takes a NAME."""
    return bool(NAME_PATTERN.fullmatch(word)) and word not in keywords() and word != "unknown"


def parse(text: str, filename: str = "<string>") -> Scenario:
    """Parse .sov text into a Scenario; raise ParseError with every problem found."""
    try:
        tree = _lark().parse(text)
    except UnexpectedInput as exc:
        raise ParseError(_syntax_diagnostic(exc, filename)) from None
    builder = _Builder(filename)
    scenario = builder.transform(tree)
    if builder.errors:
        raise ParseError(builder.errors)
    return attach_comments(scenario, text, filename)


def parse_source(source: Source) -> Scenario:
    return parse(source.text, source.name)


def _describe(terminal: str) -> str:
    if terminal in _TERMINAL_WORDS:
        return _TERMINAL_WORDS[terminal]
    pattern = _lark().get_terminal(terminal).pattern
    return f"'{pattern.value}'" if pattern.type == "str" else terminal.lower()


def _syntax_diagnostic(exc: UnexpectedInput, filename: str) -> Diagnostic:
    line, col = max(exc.line, 1), max(exc.column, 1)
    if isinstance(exc, UnexpectedCharacters):
        char = exc.char if exc.char.isprintable() else repr(exc.char)
        return Diagnostic(f"unexpected character '{char}'", Span(filename, line, col, line, col + 1))
    expected: Iterable[str] = getattr(exc, "expected", None) or getattr(exc, "accepts", None) or ()
    # '/' is only ever the middle of km/h: offering it after every speed misleads.
    wanted = sorted({_describe(t) for t in expected if not t.startswith("__") and t != "SLASH"})
    missing_brace = "RBRACE" in expected
    hint = "expected " + (", ".join(wanted[:-1]) + " or " + wanted[-1] if len(wanted) > 1 else "".join(wanted))
    if isinstance(exc, UnexpectedToken) and exc.token.type != "$END":
        tok = exc.token
        span = Span(filename, tok.line, tok.column, tok.end_line or tok.line, tok.end_column or tok.column + 1)
        brace_hint = "is a '}' missing before this?" if missing_brace and tok.type != "RBRACE" else None
        return Diagnostic(f"unexpected '{tok}'; {hint}", span, hint=brace_hint)
    if isinstance(exc, UnexpectedEOF | UnexpectedToken):
        return Diagnostic(
            f"unexpected end of file; {hint}",
            Span(filename, line, col, line, col + 1),
            hint="the file ends inside a block: is a '}' missing?" if missing_brace else None,
        )
    return Diagnostic(str(exc).splitlines()[0], Span(filename, line, col, line, col + 1))


class _Field:
    """One `keyword value` line of a block, before it is placed into its node."""

    __slots__ = ("name", "span", "value")

    def __init__(self, name: str, value: Any, span: Span) -> None:
        self.name, self.value, self.span = name, value, span


@v_args(meta=True)
class _Builder(Transformer[Token, Any]):
    """One method per grammar rule; collects errors instead of stopping at the first."""

    def __init__(self, filename: str) -> None:
        super().__init__()
        self.filename = filename
        self.errors: list[Diagnostic] = []

    # --- helpers -------------------------------------------------------------
    def _span(self, meta: Any) -> Span:
        return Span(self.filename, meta.line, meta.column, meta.end_line, meta.end_column)

    def _tok_span(self, tok: Token) -> Span:
        return Span(self.filename, tok.line, tok.column, tok.end_line, tok.end_column)

    def _error(self, message: str, span: Span, hint: str | None = None) -> None:
        self.errors.append(Diagnostic(message, span, hint=hint))

    def _enum(self, cls: type[E], tok: Token, what: str, unknown_ok: bool = True) -> E | Unknown:
        word = str(tok)
        if unknown_ok and word == "unknown":
            return UNKNOWN
        try:
            return cls(word)
        except ValueError:
            choices = [m.value for m in cls] + (["unknown"] if unknown_ok else [])
            close = difflib.get_close_matches(word, choices, n=1)
            hint = f"did you mean '{close[0]}'?" if close else None
            self._error(f"unknown {what} '{word}'; expected one of: {', '.join(choices)}", self._tok_span(tok), hint)
            return UNKNOWN

    def _block(self, cls: type, meta: Any, items: list[Any], **fixed: Any) -> Any:
        values: dict[str, Any] = {}
        spans: dict[str, Span] = {}
        for item in items:
            if not isinstance(item, _Field):
                continue
            if item.name in values:
                self._error(
                    f"'{item.name}' is written twice in this block",
                    item.span,
                    f"first written at line {spans[item.name].line}",
                )
                continue
            values[item.name] = item.value
            spans[item.name] = item.span
        known = {f.name for f in dc_fields(cls)}
        values = {k: v for k, v in values.items() if k in known}
        return cls(**fixed, **values, meta=Meta(self._span(meta), spans))

    def _field(self, name: str, meta: Any, value: Any) -> _Field:
        return _Field(name, value, self._span(meta))

    # --- values --------------------------------------------------------------
    def count(self, meta: Any, children: list[Token]) -> int | Unknown:
        tok = children[0]
        if tok.type == "NAME":
            if str(tok) != "unknown":
                self._error(f"expected a whole number or 'unknown', got '{tok}'", self._tok_span(tok))
            return UNKNOWN
        if "." in tok or int(tok) < 1:
            self._error(f"expected a whole number of at least 1, got {tok}", self._tok_span(tok))
            return UNKNOWN
        return int(tok)

    def unit(self, meta: Any, children: list[Token]) -> SpeedUnit | Unknown:
        word = "/".join(str(c) for c in children)
        if word in _UNITS:
            return _UNITS[word]
        self._error(f"unknown speed unit '{word}'; expected km/h or mph", self._span(meta))
        return UNKNOWN

    def speed_value(self, meta: Any, children: list[Any]) -> Speed | Unknown:
        if len(children) == 1:
            tok = children[0]
            if str(tok) != "unknown":
                self._error(f"expected a speed like '50 km/h' or 'unknown', got '{tok}'", self._tok_span(tok))
            return UNKNOWN
        number, unit = children
        if isinstance(unit, Unknown):
            return UNKNOWN
        value = float(number)
        return Speed(int(value) if value.is_integer() else value, unit)

    def words(self, meta: Any, children: list[Token]) -> list[Token]:
        return children

    def _word_list(self, cls: type[E], toks: list[Token], what: str) -> tuple[E, ...] | Unknown:
        if [str(t) for t in toks] == ["unknown"]:
            return UNKNOWN
        out: list[E] = []
        for tok in toks:
            if str(tok) == "unknown":
                self._error(f"'unknown' cannot be listed with other {what} words", self._tok_span(tok))
                continue
            value = self._enum(cls, tok, what, unknown_ok=False)
            if not isinstance(value, Unknown):
                out.append(value)
        return tuple(out)

    @staticmethod
    def _text(tok: Token) -> str | Unknown:
        if tok.type == "STRING":
            return str(json.loads(tok))
        return UNKNOWN if str(tok) == "unknown" else str(tok)

    # --- provenance ------------------------------------------------------------
    def report(self, meta: Any, c: list[Token]) -> _Field:
        return self._field("report", meta, self._text(c[1]))

    def sha256(self, meta: Any, c: list[Token]) -> _Field:
        return self._field("sha256", meta, self._text(c[1]))

    def frontend(self, meta: Any, c: list[Token]) -> _Field:
        return self._field("frontend", meta, self._text(c[1]))

    def model(self, meta: Any, c: list[Token]) -> _Field:
        return self._field("model", meta, self._text(c[1]))

    def assumed(self, meta: Any, c: list[Token]) -> _Field:
        return self._field("assumed", meta, tuple(str(t) for t in c[1:]))

    def evidence_item(self, meta: Any, c: list[Token]) -> Evidence | None:
        path, reader, chars, quote = c
        kind = self._enum(Reader, reader, "reader", unknown_ok=False)
        start, end = (int(n) for n in str(chars).split(".."))
        if end < start:
            self._error(f"the span {chars} ends before it starts", self._tok_span(chars))
            return None
        text = self._text(quote)
        if isinstance(kind, Unknown) or isinstance(text, Unknown):
            return None
        return Evidence(str(path), kind, start, end, text, meta=Meta(self._span(meta)))

    def evidence(self, meta: Any, c: list[Any]) -> _Field:
        return self._field("evidence", meta, tuple(e for e in c[1:] if e is not None))

    def provenance(self, meta: Any, c: list[Any]) -> Provenance:
        return self._block(Provenance, meta, c)

    # --- environment -----------------------------------------------------------
    def weather(self, meta: Any, c: list[Any]) -> _Field:
        return self._field("weather", meta, self._word_list(Weather, c[1], "weather"))

    def lighting(self, meta: Any, c: list[Any]) -> _Field:
        return self._field("lighting", meta, self._word_list(Lighting, c[1], "lighting"))

    def environment(self, meta: Any, c: list[Any]) -> Environment:
        return self._block(Environment, meta, c)

    # --- road ------------------------------------------------------------------
    def kind(self, meta: Any, c: list[Token]) -> _Field:
        return self._field("kind", meta, self._enum(RoadKind, c[1], "road kind"))

    def lanes(self, meta: Any, c: list[Any]) -> _Field:
        return self._field("lanes", meta, c[1])

    def speed_limit(self, meta: Any, c: list[Any]) -> _Field:
        return self._field("speed_limit", meta, c[1])

    def road(self, meta: Any, c: list[Any]) -> Road:
        return self._block(Road, meta, c)

    # --- participants -------------------------------------------------------------
    def vehicle_kind(self, meta: Any, c: list[Token]) -> _Field:
        return self._field("kind", meta, self._enum(VehicleKind, c[1], "vehicle kind"))

    def heading(self, meta: Any, c: list[Token]) -> _Field:
        return self._field("heading", meta, self._enum(Heading, c[1], "heading"))

    def lane(self, meta: Any, c: list[Any]) -> _Field:
        return self._field("lane", meta, c[1])

    def speed(self, meta: Any, c: list[Any]) -> _Field:
        return self._field("speed", meta, c[1])

    def arg(self, meta: Any, c: list[Token]) -> _Field:
        key, tok = c
        value: int | Side | Unknown
        if tok.type == "NUMBER":
            value = int(float(tok))
            if "." in tok or value < 1:
                self._error(f"a lane number is a whole number of at least 1, got {tok}", self._tok_span(tok))
        elif tok == "unknown":  # one spelling of "not said": the action without its argument, as a turn's lane
            value = UNKNOWN
            self._error(
                "a target not said is not written 'unknown'",
                self._tok_span(tok),
                "leave out (to: ...): an action without it is one whose target lane or side the report does not give",
            )
        else:
            value = self._enum(Side, tok, "side", unknown_ok=False)
        return _Field(str(key), value, self._span(meta))

    def action(self, meta: Any, c: list[Any]) -> Action | None:
        kind = self._enum(ActionKind, c[0], "action", unknown_ok=False)
        to: int | Side | None = None
        seen: set[str] = set()
        for arg in c[1:]:
            if arg.name in seen:
                self._error(f"argument '{arg.name}' is written twice", arg.span)
            elif arg.name != "to":
                self._error(f"unknown argument '{arg.name}'; actions take only 'to'", arg.span)
            elif not isinstance(arg.value, Unknown):
                to = arg.value
            seen.add(arg.name)
        if isinstance(kind, Unknown):
            return None
        spans = {"to": next(a.span for a in c[1:] if a.name == "to")} if to is not None else {}
        return Action(kind, to, meta=Meta(self._span(meta), spans))

    def actions(self, meta: Any, c: list[Any]) -> _Field:
        if len(c) == 2 and isinstance(c[1], Token):
            if str(c[1]) != "unknown":
                self._error(f"expected '{{' or 'unknown' after actions, got '{c[1]}'", self._tok_span(c[1]))
            return self._field("actions", meta, UNKNOWN)
        return self._field("actions", meta, tuple(a for a in c[1:] if a is not None))

    def participant(self, meta: Any, c: list[Any]) -> Participant:
        role, pid = c[0], c[1]
        return self._block(Participant, meta, c[2:], id=str(pid), role=Role(str(role)))

    # --- crash ---------------------------------------------------------------------
    def crash_type(self, meta: Any, c: list[Token]) -> _Field:
        return self._field("type", meta, self._enum(CrashType, c[1], "crash type"))

    def striker(self, meta: Any, c: list[Token]) -> _Field:
        return self._field("striker", meta, self._text(c[1]))

    def victim(self, meta: Any, c: list[Token]) -> _Field:
        return self._field("victim", meta, self._text(c[1]))

    def crash(self, meta: Any, c: list[Any]) -> Crash:
        return self._block(Crash, meta, c)

    # --- the whole scenario --------------------------------------------------------------
    def scenario(self, meta: Any, c: list[Any]) -> Scenario:
        name = str(c[1])
        sections: dict[str, Any] = {}
        spans: dict[str, Span] = {}
        participants: list[Participant] = []
        for node in c[2:]:
            if isinstance(node, Participant):
                participants.append(node)
                continue
            key = type(node).__name__.lower()
            if key in sections:
                self._error(
                    f"'{key}' block is written twice", node.meta.span, f"first written at line {spans[key].line}"
                )
                continue
            sections[key] = node
            spans[key] = node.meta.span
        return Scenario(name, participants=tuple(participants), **sections, meta=Meta(self._span(meta), spans))

    def start(self, meta: Any, c: list[Any]) -> Scenario:
        return c[0]

    def __default__(self, data: str, children: list[Any], meta: Any) -> Tree[Any]:
        raise AssertionError(f"grammar rule '{data}' has no transformer method")
