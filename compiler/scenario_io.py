"""Loading and saving scenarios in either of their forms: .sov text or .json."""

from __future__ import annotations

import json
import os
from pathlib import Path

from sovarc.dsl import (
    Diagnostic,
    ParseError,
    Scenario,
    from_json,
    parse_source,
    read_source,
    to_json,
    to_text,
)
from sovarc.dsl.span import Source, Span


def load_scenario(path: str | os.PathLike[str]) -> tuple[Scenario, Source]:
    """Read a .sov or .json scenario file (by its extension; anything else is read as .sov)."""
    source = read_source(path, "scenario file")
    if Path(source.name).suffix.lower() == ".json":
        try:
            data = json.loads(source.text)
        except json.JSONDecodeError as exc:
            span = Span(source.name, exc.lineno, exc.colno, exc.lineno, exc.colno + 1)
            raise ParseError(Diagnostic(f"invalid JSON: {exc.msg}", span)) from None
        return from_json(data, source.name), source
    return parse_source(source), source


def dump_scenario(scenario: Scenario, as_json: bool) -> str:
    if as_json:
        return json.dumps(to_json(scenario), indent=2, ensure_ascii=False) + "\n"
    return to_text(scenario)
