"""The oracle on runs built by hand: who is to blame for a collision, near misses, harsh braking."""

from __future__ import annotations

import numpy as np
import pytest
from sovarc.compiler.plan import CAR
from sovarc.targets.fmu.harness import Contact, Run, Track
from sovarc.targets.fmu.oracle import judge
from sovarc.targets.fmu.task import make_task

from tests.targets.fmu.plans import car_following

STEPS = 41  # 2 s at 0.05 s


def _run(ego_speed: np.ndarray, other_x: np.ndarray, *, contact: bool) -> Run:
    """V1 (the ego) sits with its front bumper at x = 50 (moving as ego_speed says); V2 comes from behind."""
    plan = car_following()
    times = np.arange(STEPS) * 0.05
    ego_x = 50.0 + np.concatenate(([0.0], np.cumsum(ego_speed[:-1] * 0.05)))
    lane = np.full(STEPS, -8.25)
    east = np.full(STEPS, 90.0)
    tracks = {
        "V1": Track("V1", CAR, ego_x, lane, east, ego_speed),
        "V2": Track("V2", CAR, other_x, lane, east, np.full(STEPS, 10.0)),
    }
    return Run(
        "V1",
        make_task(plan, "V1"),
        times,
        tracks,
        ego_x - 20.0,
        np.zeros((STEPS, 2)),
        "collision" if contact else "budget",
        Contact(float(times[-1]), "V2") if contact else None,
        (),
        0.0,
    )


def test_an_ego_hit_while_standing_still_has_not_failed() -> None:
    run = _run(np.zeros(STEPS), 30.0 + 10.0 * np.arange(STEPS) * 0.05, contact=True)
    verdict = judge(run, car_following())
    assert verdict.passed, verdict.dumps()
    collision = verdict.findings[0]
    assert collision.check == "collision" and collision.passed and "not the ego's failure" in collision.message
    assert verdict.facts["collision"]["kind"] == "struck_from_behind"
    assert verdict.facts["min_ttc"] is None  # measured only while the ego moves
    assert [f.check for f in verdict.findings] == ["collision", "min_ttc", "harsh_braking"]  # goal not judged


def test_a_moving_ego_struck_from_behind_has_failed() -> None:
    run = _run(np.full(STEPS, 2.0), 30.0 + 12.0 * np.arange(STEPS) * 0.05, contact=True)
    verdict = judge(run, car_following())
    assert not verdict.findings[0].passed
    assert verdict.facts["failure"] == "struck_from_behind"


def test_harsh_braking_and_a_short_goal_are_failures() -> None:
    speed = np.concatenate((np.full(20, 10.0), np.linspace(10.0, 0.0, 7), np.zeros(STEPS - 27)))
    verdict = judge(_run(speed, np.full(STEPS, -100.0), contact=False), car_following())
    by_check = {f.check: f for f in verdict.findings}
    assert not by_check["goal"].passed and "did not reach its goal" in by_check["goal"].message
    assert not by_check["harsh_braking"].passed
    assert verdict.facts["peak_braking"] == pytest.approx((10.0 / 6) / 0.05, rel=1e-3)  # 10 m/s shed in 0.3 s
    assert verdict.facts["failure"] == "goal"  # the more serious failure names the test
