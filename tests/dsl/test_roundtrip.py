"""Canonical printing: print(parse(s)) == s for canonical text, and parse(print(ir)) == ir."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.dsl import parse, to_text

from tests.conftest import EXAMPLES

FIXTURES = Path(__file__).parent / "fixtures"


def _identity_cases() -> list[str]:
    text = (FIXTURES / "identity.sov").read_text(encoding="utf-8")
    return [case.lstrip("\n") for case in text.split("%%\n")]


@pytest.mark.parametrize("case", _identity_cases(), ids=lambda c: c.split("scenario ")[1].split()[0])
def test_identity_fixture_prints_back_byte_for_byte(case: str) -> None:
    assert to_text(parse(case)) == case


EXAMPLE_FILES = sorted(EXAMPLES.glob("**/*.sov"))


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.stem)
def test_every_example_is_canonical(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    assert to_text(parse(text, str(path))) == text


def test_there_are_enough_examples() -> None:
    assert len(list((EXAMPLES / "scenarios").glob("*.sov"))) >= 12
    assert len(list((EXAMPLES / "reports").glob("*.txt"))) >= 6


def test_layout_is_normalised() -> None:
    messy = (
        "scenario  m{road{lanes 2 kind straight speed_limit 30.0 mph}"
        "vehicle V1{actions{follow_lane}}environment{lighting daylight weather rainy,clear,rainy}}"
    )
    assert to_text(parse(messy)) == (
        "scenario m {\n"
        "  environment {\n    weather clear, rainy\n    lighting daylight\n  }\n"
        "  road {\n    kind straight\n    lanes 2\n    speed_limit 30 mph\n  }\n"
        "  vehicle V1 {\n    heading unknown\n    lane unknown\n    speed unknown\n"
        "    actions {\n      follow_lane\n    }\n  }\n"
        "  crash {\n    type unknown\n    striker unknown\n    victim unknown\n  }\n"
        "}\n"
    )


def test_comments_do_not_change_meaning() -> None:
    case = _identity_cases()[1]
    stripped = "\n".join(line.split("#")[0].rstrip() for line in case.splitlines() if not line.lstrip().startswith("#"))
    assert parse(stripped) == parse(case)
    assert to_text(parse(stripped)) != case


def test_hash_inside_a_string_is_not_a_comment() -> None:
    text = _identity_cases()[0].replace(
        "scenario minimal {",
        'scenario s {\n  provenance {\n    report "a#b.txt"\n    sha256 unknown\n'
        "    frontend unknown\n    model unknown\n  }",
        1,
    )
    assert to_text(parse(text)) == text
