"""The IR's JSON form and its JSON Schema, both derived from the node definitions.

Nothing here names a node field by hand: the schema, `to_json` and `from_json`
walk the dataclasses' type hints, so a new field appears in all three at once.
The schema is what an LLM's structured output is constrained to.
"""

from __future__ import annotations

import copy
import functools
import types
import typing
from dataclasses import MISSING, fields, is_dataclass
from enum import Enum
from typing import Any

from sovarc.dsl.errors import Diagnostic, ParseError
from sovarc.dsl.ir import ACTION_SPECS, Meta, Scenario, Unknown

SCHEMA_ID = "https://sovarc.dev/schema/scenario-1.json"
_NONE = type(None)


@functools.cache
def _hints(cls: type) -> dict[str, Any]:
    return {k: v for k, v in typing.get_type_hints(cls).items() if v is not Meta}


def _fields(cls: type) -> list[Any]:
    return [f for f in fields(cls) if f.name in _hints(cls)]


# --- IR -> JSON --------------------------------------------------------------------
def to_json(node: Any) -> Any:
    """Plain JSON data (dicts, lists, strings, numbers) for an IR node."""
    if is_dataclass(node):
        return {f.name: to_json(getattr(node, f.name)) for f in _fields(type(node))}
    if isinstance(node, Enum):
        return node.value
    if isinstance(node, tuple):
        return [to_json(v) for v in node]
    return node


# --- JSON -> IR -----------------------------------------------------------------------
class _Reader:
    def __init__(self, origin: str) -> None:
        self.origin = origin
        self.errors: list[Diagnostic] = []

    def fail(self, where: str, message: str) -> None:
        self.errors.append(Diagnostic(f"{self.origin}: {where or '(top)'}: {message}"))

    def read(self, tp: Any, data: Any, where: str) -> Any:
        origin = typing.get_origin(tp)
        if origin in (typing.Union, types.UnionType):
            return self._union(typing.get_args(tp), data, where)
        if origin is tuple:
            if not isinstance(data, list):
                self.fail(where, f"expected a list, got {_kind(data)}")
                return ()
            item = typing.get_args(tp)[0]
            return tuple(self.read(item, v, f"{where}[{i}]") for i, v in enumerate(data))
        if isinstance(tp, type) and is_dataclass(tp):
            return self._node(tp, data, where)
        if isinstance(tp, type) and issubclass(tp, Enum):
            try:
                return tp(data)
            except ValueError:
                self.fail(where, f"expected one of {[m.value for m in tp]}, got {data!r}")
                return next(iter(tp))
        if tp is float and isinstance(data, int | float) and not isinstance(data, bool):
            return data
        if tp is _NONE and data is None:
            return None
        if isinstance(tp, type) and isinstance(data, tp) and not isinstance(data, bool):
            return data
        self.fail(where, f"expected {getattr(tp, '__name__', tp)}, got {_kind(data)}")
        return None

    def _union(self, options: tuple[Any, ...], data: Any, where: str) -> Any:
        for tp in sorted(options, key=lambda t: t is not Unknown and t is not _NONE):
            probe = _Reader(self.origin)
            value = probe.read(tp, data, where)
            if not probe.errors:
                return value
        names = " or ".join(_name(t) for t in options)
        self.fail(where, f"expected {names}, got {data!r}")
        return None

    def _node(self, cls: type, data: Any, where: str) -> Any:
        if not isinstance(data, dict):
            self.fail(where, f"expected an object, got {_kind(data)}")
            return None
        hints = _hints(cls)
        for extra in sorted(set(data) - set(hints)):
            self.fail(f"{where}.{extra}".lstrip("."), "is not a field of " + cls.__name__)
        values: dict[str, Any] = {}
        for f in _fields(cls):
            path = f"{where}.{f.name}".lstrip(".")
            if f.name in data:
                values[f.name] = self.read(hints[f.name], data[f.name], path)
            elif f.default is MISSING and f.default_factory is MISSING:
                self.fail(path, "is missing")
        if self.errors:
            return None
        return cls(**values)


def _kind(data: Any) -> str:
    return {dict: "an object", list: "a list", str: "a string", bool: "a boolean", type(None): "null"}.get(
        type(data), type(data).__name__
    )


def _name(tp: Any) -> str:
    if tp is Unknown:
        return '"unknown"'
    if tp is _NONE:
        return "null"
    if isinstance(tp, type) and issubclass(tp, Enum):
        return ", ".join(m.value for m in tp)
    return getattr(tp, "__name__", str(tp))


def from_json(data: Any, origin: str = "<json>") -> Scenario:
    """Build a Scenario from its JSON form; raise ParseError naming every bad field."""
    reader = _Reader(origin)
    scenario = reader.read(Scenario, data, "")
    if reader.errors:
        raise ParseError(reader.errors)
    return scenario


# --- JSON Schema ---------------------------------------------------------------------------
def _schema_of(tp: Any, defs: dict[str, Any]) -> dict[str, Any]:
    origin = typing.get_origin(tp)
    if origin in (typing.Union, types.UnionType):
        return {"anyOf": [_schema_of(t, defs) for t in typing.get_args(tp)]}
    if origin is tuple:
        return {"type": "array", "items": _schema_of(typing.get_args(tp)[0], defs)}
    if tp is Unknown:
        return {"const": "unknown"}
    if tp is _NONE:
        return {"type": "null"}
    if isinstance(tp, type) and issubclass(tp, Enum):
        if tp.__name__ not in defs:
            defs[tp.__name__] = {"enum": [m.value for m in tp]}
            if tp.__name__ == "ActionKind":
                defs[tp.__name__]["description"] = "; ".join(f"{k.value}: {s.meaning}" for k, s in ACTION_SPECS.items())
        return {"$ref": f"#/$defs/{tp.__name__}"}
    if isinstance(tp, type) and is_dataclass(tp):
        if tp.__name__ not in defs:
            defs[tp.__name__] = {}  # reserve the name before recursing
            hints = _hints(tp)
            defs[tp.__name__] = {
                "type": "object",
                "description": (tp.__doc__ or tp.__name__).strip().splitlines()[0],
                "properties": {f.name: _schema_of(hints[f.name], defs) for f in _fields(tp)},
                "required": [f.name for f in _fields(tp)],
                "additionalProperties": False,
            }
        return {"$ref": f"#/$defs/{tp.__name__}"}
    return {"type": {int: "integer", float: "number", str: "string", bool: "boolean"}[tp]}


@functools.cache
def _cached_schema() -> tuple[tuple[str, Any], ...]:
    defs: dict[str, Any] = {}
    root = _schema_of(Scenario, defs)
    schema = {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": SCHEMA_ID,
        "title": "sovarc scenario IR",
        **root,
        "$defs": dict(sorted(defs.items())),
    }
    return tuple(schema.items())


def json_schema() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of the IR's JSON form."""
    return copy.deepcopy(dict(_cached_schema()))
