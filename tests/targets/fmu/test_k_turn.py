"""A vehicle whose plan reverses is no ego: the ego interface drives forward only."""

from __future__ import annotations

import pytest
from sovarc.targets.fmu import egos

from tests.compiler.synth.street import k_turn_plan

pytestmark = pytest.mark.slow  # netconvert builds the street


def test_a_three_point_turner_replays_as_an_npc_but_is_not_an_ego() -> None:
    plan = k_turn_plan()
    assert min(s.speed for s in plan.trajectory("V1").samples) < 0.0
    assert egos(plan) == ["V2"]
