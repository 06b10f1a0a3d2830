"""Keeping `#` comments through a parse and print.

Comments are not facts, so they live in each node's `meta` (ignored by
equality). Each comment is attached to the printed line it belongs to: a
comment on its own line to the next line below it (or to the closing brace of
the block it ends), a comment after code to that line.
"""

from __future__ import annotations

import re
from collections import defaultdict
from dataclasses import dataclass, fields, is_dataclass, replace
from typing import Any

from sovarc.dsl.ir import Meta, Scenario, Trivia

# Strings are matched too, so that a '#' inside a string is not taken for a comment.
_STRING_OR_COMMENT = re.compile(r'"(?:[^"\\\n]|\\.)*"|#[^\n]*')

# Keys of the lines of a node: "" its header, a field name, "}" its closing
# brace, and "actions}" the closing brace of a participant's actions block.
HEADER, CLOSE = "", "}"

Path = tuple[Any, ...]


@dataclass(frozen=True)
class _Anchor:
    line: int
    col: int
    path: Path
    key: str
    closing: bool


def find_comments(text: str) -> list[tuple[int, int, str]]:
    """(line, col, text) of every comment in `text`, in order."""
    out = []
    for m in _STRING_OR_COMMENT.finditer(text):
        if m.group().startswith("#"):
            line = text.count("\n", 0, m.start()) + 1
            col = m.start() - (text.rfind("\n", 0, m.start()) + 1) + 1
            out.append((line, col, m.group().rstrip()))
    return out


def _anchors(node: Any, path: Path) -> list[_Anchor]:
    meta: Meta = node.meta
    out: list[_Anchor] = []
    if meta.span is not None:
        out.append(_Anchor(meta.span.line, meta.span.col, path, HEADER, False))
        if meta.span.end_line > meta.span.line:
            out.append(_Anchor(meta.span.end_line, meta.span.end_col - 1, path, CLOSE, True))
    for key, span in meta.fields.items():
        if hasattr(getattr(node, key, None), "meta"):
            continue  # a child node: it has anchors of its own
        if meta.span is None or span.line != meta.span.line:
            out.append(_Anchor(span.line, span.col, path, key, False))
        if span.end_line > span.line:
            out.append(_Anchor(span.end_line, span.end_col - 1, path, key + CLOSE, True))
    for f in fields(node):
        value = getattr(node, f.name)
        if is_dataclass(value) and hasattr(value, "meta"):
            out += _anchors(value, (*path, f.name))
        elif isinstance(value, tuple):
            for i, item in enumerate(value):
                if is_dataclass(item) and hasattr(item, "meta"):
                    out += _anchors(item, (*path, f.name, i))
    return out


def attach_comments(scenario: Scenario, text: str, filename: str) -> Scenario:
    found = find_comments(text)
    if not found:
        return scenario
    anchors = sorted(_anchors(scenario, ()), key=lambda a: (a.line, a.col))
    leading: dict[tuple[Path, str], list[str]] = defaultdict(list)
    trailing: dict[tuple[Path, str], str] = {}
    for line, col, comment in found:
        before = [a for a in anchors if a.line == line and a.col < col]
        if before:
            a = before[-1]
            trailing[(a.path, a.key)] = comment
            continue
        after = next((a for a in anchors if a.line > line), None)
        # Comments after the final brace stay at the end of the file.
        target = (after.path, after.key) if after else ((), "eof")
        leading[target].append(comment)
    return _rebuild(scenario, (), leading, trailing)


def _rebuild(node: Any, path: Path, leading: dict, trailing: dict) -> Any:
    changes: dict[str, Any] = {}
    for f in fields(node):
        value = getattr(node, f.name)
        if is_dataclass(value) and hasattr(value, "meta"):
            changes[f.name] = _rebuild(value, (*path, f.name), leading, trailing)
        elif isinstance(value, tuple) and any(hasattr(v, "meta") for v in value):
            changes[f.name] = tuple(_rebuild(v, (*path, f.name, i), leading, trailing) for i, v in enumerate(value))
    trivia: dict[str, Trivia] = {}
    keys = {k for (p, k) in [*leading, *trailing] if p == path}
    for key in keys:
        if key.endswith(CLOSE):
            base = key[: -len(CLOSE)]
            old = trivia.get(base, Trivia())
            trivia[base] = replace(old, closing=tuple(leading.get((path, key), ())))
            if (path, key) in trailing:  # a comment after a closing brace
                trivia[key] = Trivia(trailing=trailing[(path, key)])
        else:
            old = trivia.get(key, Trivia())
            trivia[key] = replace(old, leading=tuple(leading.get((path, key), ())), trailing=trailing.get((path, key)))
    if trivia:
        changes["meta"] = replace(node.meta, comments=trivia)
    return replace(node, **changes) if changes else node
