"""A lane change whose side the report does not give: `change_lane` with no target. It is valid, canonical and
round-trips through text and JSON; `to: unknown` is not a second spelling of it."""

from __future__ import annotations

import pytest
from sovarc.dsl import from_json, parse, to_json, to_text, verify
from sovarc.dsl.errors import ParseError, Severity
from sovarc.dsl.ir import ActionKind, Side

SIDELESS = """scenario sideless {
  environment {
    weather unknown
    lighting unknown
  }
  road {
    kind straight
    lanes 4
    speed_limit unknown
  }
  vehicle V1 {
    heading north
    lane unknown
    speed unknown
    actions {
      follow_lane
    }
  }
  vehicle V2 {
    heading north
    lane unknown
    speed unknown
    actions {
      follow_lane
      change_lane
    }
  }
  crash {
    type side
    striker V2
    victim V1
  }
}
"""


def test_a_side_less_lane_change_prints_back_byte_for_byte() -> None:
    s = parse(SIDELESS)
    v2 = s.participant("V2")
    assert v2 is not None and v2.known_actions[-1].kind is ActionKind.CHANGE_LANE
    assert v2.known_actions[-1].to is None
    assert to_text(s) == SIDELESS
    assert from_json(to_json(s)) == s


def test_a_side_less_lane_change_verifies() -> None:
    assert not [d for d in verify(parse(SIDELESS)) if d.severity is Severity.ERROR]


def test_sides_and_lane_numbers_are_still_written_as_before() -> None:
    for to, want in (("left", Side.LEFT), ("2", 2)):
        s = parse(SIDELESS.replace("      change_lane\n", f"      change_lane(to: {to})\n"))
        v2 = s.participant("V2")
        assert v2 is not None and v2.known_actions[-1].to == want


def test_unknown_is_not_a_target() -> None:
    with pytest.raises(ParseError, match="not written 'unknown'") as err:
        parse(SIDELESS.replace("      change_lane\n", "      change_lane(to: unknown)\n"))
    assert "leave out (to: ...)" in str(err.value.diagnostics[0].hint)
