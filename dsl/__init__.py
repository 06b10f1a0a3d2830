"""The scenario IR of sovarc: nodes, parser, canonical printer, verifier, diff, JSON form."""

from sovarc.dsl.diff import Change, diff
from sovarc.dsl.errors import (
    Diagnostic,
    InputError,
    ParseError,
    Severity,
    SovarcError,
    VerifyError,
)
from sovarc.dsl.ir import UNKNOWN, Scenario
from sovarc.dsl.jsonform import from_json, json_schema, to_json
from sovarc.dsl.parser import parse, parse_source
from sovarc.dsl.printer import to_text
from sovarc.dsl.source import read_source
from sovarc.dsl.verifier import verify, verify_or_raise

__all__ = [
    "UNKNOWN",
    "Change",
    "Diagnostic",
    "InputError",
    "ParseError",
    "Scenario",
    "Severity",
    "SovarcError",
    "VerifyError",
    "diff",
    "from_json",
    "json_schema",
    "parse",
    "parse_source",
    "read_source",
    "to_json",
    "to_text",
    "verify",
    "verify_or_raise",
]
