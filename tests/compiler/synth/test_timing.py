"""Jerk-limited timing through the solved schedule's knots: exact at the knots, really stopped in a stop."""

from __future__ import annotations

import numpy as np
import pytest
from sovarc.compiler.lower.solve import A_UP, B_DOWN, LegValues
from sovarc.compiler.synth.timing import Knot, knots, sample
from sovarc.dsl.errors import SovarcError

from tests.compiler.lower.staging import staged


def _stop_and_go() -> tuple[tuple[LegValues, ...], float]:
    """Wait 1 s, drive 60 m at 8 m/s to a stop, wait 2 s, then drive on at 5 m/s."""
    v = 8.0
    duration = v / A_UP + (60.0 - v * v / (2 * A_UP) - v * v / (2 * B_DOWN)) / v + v / B_DOWN
    first = LegValues(0.0, 60.0, True, True, v, 1.0, duration, 2.0)
    second = LegValues(60.0, None, True, False, 5.0, 1.0 + duration + 2.0, None, 0.0)
    return (first, second), 1.0 + duration


def test_knots_are_the_corners_of_the_trapezoid() -> None:
    legs, stopped_at = _stop_and_go()
    points = knots(legs, 0.0, 1.0, 30.0)
    assert points[:3] == [Knot(0.0, 0.0, 0.0), Knot(1.0, 0.0, 0.0), Knot(5.0, 16.0, 8.0)]  # wait, then ramp up
    assert points[3].v == 8.0 and points[3].s == pytest.approx(60.0 - 64.0 / 6.0)  # braking starts
    assert points[4] == Knot(pytest.approx(stopped_at), 60.0, 0.0)
    assert points[5] == Knot(pytest.approx(stopped_at + 2.0), 60.0, 0.0)
    assert points[-1].t == 30.0 and points[-1].v == 5.0
    assert [k.t for k in points] == sorted(k.t for k in points)


def test_sampling_passes_every_knot_exactly() -> None:
    legs, _ = _stop_and_go()
    points = knots(legs, 0.0, 1.0, 30.0)
    s, v, fallbacks = sample(points, np.array([k.t for k in points]))
    assert fallbacks == 0
    assert s == pytest.approx([k.s for k in points], abs=1e-6)
    assert v == pytest.approx([k.v for k in points], abs=1e-6)


def test_a_stop_really_stops() -> None:
    legs, stopped_at = _stop_and_go()
    times = np.round(np.arange(0.0, 30.0 + 0.05, 0.1), 6)
    s, v, _ = sample(knots(legs, 0.0, 1.0, 30.0), times)
    waiting = (times <= 1.0) | ((times >= stopped_at) & (times <= stopped_at + 2.0))
    assert waiting.sum() >= 25
    assert np.all(v[waiting] == 0.0)
    assert np.all(s[times <= 1.0] == 0.0)
    assert s[(times >= stopped_at) & (times <= stopped_at + 2.0)] == pytest.approx(60.0, abs=1e-6)
    assert np.all(np.diff(s) >= -1e-9)  # never backwards
    assert v.max() <= 8.0 * 1.1 + 0.5


def test_a_participant_without_legs_stands_still() -> None:
    points = knots((), 12.5, 0.0, 10.0)
    assert points == [Knot(0.0, 12.5, 0.0), Knot(10.0, 12.5, 0.0)]
    s, v, _ = sample(points, np.linspace(0.0, 10.0, 101))
    assert np.all(s == 12.5) and np.all(v == 0.0)


@pytest.mark.parametrize(
    "name",
    ["straight_rear_end_stopped_traffic", "t_junction_right_turn_stop_rear_end", "straight_double_yellow_pass_frontal"],
)
def test_striker_and_victim_are_at_their_impact_points_at_the_exact_impact_time(name: str) -> None:
    result = staged(name)
    assert not isinstance(result, SovarcError)
    for item in result:
        solution = item.lowered.solution
        end = solution.impact_time + 2.0
        for pid, impact_s in solution.impact.items():
            profile = knots(solution.legs.get(pid, ()), solution.starts[pid], solution.initial_dwell.get(pid, 0.0), end)
            s, _, _ = sample(profile, np.array([solution.impact_time]))
            assert s[0] == pytest.approx(impact_s, abs=1e-3), f"{item.lowered.match.site.id} {pid}"


def test_a_stop_before_a_turn_is_a_real_stop_in_the_plan() -> None:
    result = staged("t_junction_right_turn_stop_rear_end")
    assert not isinstance(result, SovarcError)
    for item in result:
        assert item.plan is not None
        stop = next(seg for seg in item.plan.trajectory("V1").segments if seg.action.endswith(":stop"))
        dwell = item.lowered.solution.legs["V1"][0].dwell
        assert dwell > 0.0
        during = [s for s in item.plan.trajectory("V1").samples if stop.end_t <= s.t <= stop.end_t + dwell]
        assert during and all(s.speed == 0.0 for s in during)
        assert max(s.x for s in during) - min(s.x for s in during) < 1e-6
        assert max(s.y for s in during) - min(s.y for s in during) < 1e-6
