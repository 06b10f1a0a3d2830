"""A three-point turn replayed in SUMO: the body placed from the heading, reversing included, stays
off the sidewalks, and the car turning in legs is struck on its last leg as planned."""

from __future__ import annotations

import pytest
from sovarc.targets.sumo import check

from tests.compiler.synth.street import k_turn_plan

pytestmark = pytest.mark.slow


def test_the_turner_replays_and_is_struck_where_planned() -> None:
    plan = k_turn_plan()
    verdict = check(plan)
    assert verdict.passed, verdict.dumps()
    checks = ["xsd", "replay", "collision", "pair", "impact_angle", "lane_lines", "on_road"]
    assert [f.check for f in verdict.findings] == checks  # on_road: it reverses, and its body stays on the road
    impact = verdict.facts["impact"]
    assert impact["striker_face"].startswith("front") and "left" in impact["victim_face"]
    assert abs(impact["time"] - plan.impact.time) <= 0.3
    # it stood still and reversed before: the replay followed it there too (the 'replay' finding)
    assert min(s.speed for s in plan.trajectory("V1").samples) < 0.0
