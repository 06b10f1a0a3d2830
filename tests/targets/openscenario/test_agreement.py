"""The OpenSCENARIO oracle judges a crash as the SUMO oracle does: the same first touch, the same
faces (a corner that leads is a corner on both), the same angle, the same verdict."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from sovarc.compiler.plan import Plan, Sample
from sovarc.targets import sumo
from sovarc.targets.openscenario import check

from tests.targets.openscenario.plans import CASES, clipped_rear_corner, emit_files, straight, with_samples

pytestmark = pytest.mark.slow  # SUMO replays the plan; netconvert writes the .xodr


def skewed_t_bone(heading: float, speed: float, late: float = 0.0) -> Callable[[], Plan]:
    """The T-bone with the striker `heading` degrees off square, its bumper centre meeting the
    victim's side `late` seconds after the impact: one front corner leads and touches first."""

    def make() -> Plan:
        plan = CASES["t_bone"]()
        t_hit, (x, y) = plan.impact.time + late, plan.impact.point
        return with_samples(plan, "V1", lambda s: Sample(s.t, *straight(x, y, heading, speed, t_hit)(s.t)))

    return make


PLANS: dict[str, Callable[[], Plan]] = {
    **CASES,
    # One corner leads the other by 1.6 cm; the touch falls between two of the oracle's scan steps.
    "t_bone_half_deg": skewed_t_bone(0.5, 15.0, late=0.013),
    "t_bone_20deg_slow": skewed_t_bone(20.0, 1.0),  # the corner leads by 0.3 m, 0.33 s
}


@pytest.mark.parametrize("name", sorted(PLANS))
def test_both_oracles_see_the_same_crash(name: str, tmp_path: Path) -> None:
    plan = PLANS[name]()
    by_sumo = sumo.check(plan)
    by_osc = check(emit_files(plan, tmp_path).xosc, plan)
    assert by_osc.passed == by_sumo.passed, (by_sumo.dumps(), by_osc.dumps())
    impact = by_sumo.facts["impact"]
    assert (by_osc.facts["striker_face"], by_osc.facts["victim_face"]) == (
        impact["striker_face"],
        impact["victim_face"],
    )
    assert by_osc.facts["relative_heading"] == pytest.approx(impact["angle"], abs=1.0)
    assert by_osc.facts["first_contact_time"] == pytest.approx(impact["time"], abs=0.05)


def test_a_leading_corner_is_named_a_corner(tmp_path: Path) -> None:
    plan = PLANS["t_bone_half_deg"]()
    verdict = check(emit_files(plan, tmp_path).xosc, plan)
    assert verdict.passed
    assert (verdict.facts["striker_face"], verdict.facts["victim_face"]) == ("front-left", "right")


def test_a_rear_corner_clipped_before_the_collision_area_is_the_same_touch_for_both(tmp_path: Path) -> None:
    """Where the verdicts part (the OSC oracle wants the first touch in C_A, SUMO's does not look at
    C_A), the two still see the same touch: time, faces and angle."""
    plan = clipped_rear_corner()
    impact = sumo.check(plan).facts["impact"]
    by_osc = check(emit_files(plan, tmp_path).xosc, plan)
    # an offset rear-end: the corner V1's front meets is V2's rear (crashes.struck_face), so no side crash either
    assert [f.check for f in by_osc.failures] == ["first_contact", "impact_faces"]
    assert not next(f for f in sumo.check(plan).findings if f.check == "impact_angle").passed
    assert by_osc.facts["first_contact_time"] == pytest.approx(impact["time"], abs=0.03)
    assert (by_osc.facts["striker_face"], by_osc.facts["victim_face"]) == (
        impact["striker_face"],
        impact["victim_face"],
    )
    assert by_osc.facts["relative_heading"] == pytest.approx(impact["angle"], abs=1.0)
