"""The oracle on runs built by hand: who is to blame for a collision, near misses, harsh braking."""

from __future__ import annotations

import numpy as np
import pytest
from sovarc.compiler.geometry.bodies import Box, overlap
from sovarc.compiler.vehicles import CAR
from sovarc.targets.fmu.harness import Contact, Run, Track
from sovarc.targets.fmu.oracle import FAILURE_CLASSES, VIOLATIONS, judge
from sovarc.targets.fmu.task import make_task

from tests.targets.fmu.plans import car_following

STEPS = 41  # 2 s at 0.05 s


def _run(ego_speed: np.ndarray, other_x: np.ndarray, *, contact: bool, other_speed: float = 10.0) -> Run:
    """V1 (the ego) starts with its front bumper at x = 50 and moves as ego_speed says; V2, in the same
    lane, is where other_x says, driving east at other_speed."""
    plan = car_following()
    steps = len(ego_speed)
    times = np.arange(steps) * 0.05
    ego_x = 50.0 + np.concatenate(([0.0], np.cumsum(ego_speed[:-1] * 0.05)))
    lane = np.full(steps, -8.25)
    east = np.full(steps, 90.0)
    tracks = {
        "V1": Track("V1", CAR, ego_x, lane, east, ego_speed),
        "V2": Track("V2", CAR, other_x, lane, east, np.full(steps, other_speed)),
    }
    return Run(
        "V1",
        make_task(plan, "V1"),
        times,
        tracks,
        ego_x - 20.0,
        np.zeros((steps, 2)),
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


def test_a_moving_ego_run_into_from_behind_has_not_failed() -> None:
    """The NPCs replay and never react: one driving into the back of a slower ego is its own doing."""
    run = _run(np.full(STEPS, 2.0), 30.0 + 12.0 * np.arange(STEPS) * 0.05, contact=True)
    verdict = judge(run, car_following())
    assert verdict.passed, verdict.dumps()
    assert "ran into the back of the ego" in verdict.findings[0].message
    assert verdict.facts["collision"]["kind"] == "struck_from_behind"
    assert verdict.facts["min_ttc"] is not None and verdict.facts["min_ttc"] < 1.0  # close, but coming at the ego
    assert verdict.facts["min_own_ttc"] is None and verdict.facts["failure"] is None


def test_running_up_on_a_standing_car_is_a_near_miss_of_its_own_making() -> None:
    """The ego comes at 10 m/s, brakes at 8 m/s² after 1.5 s and stops 0.75 m behind a standing car."""
    speed = np.concatenate((np.full(30, 10.0), np.maximum(10.0 - 8.0 * 0.05 * np.arange(1, 34), 0.0)))
    ego_x = 50.0 + np.concatenate(([0.0], np.cumsum(speed[:-1] * 0.05)))
    standing = np.full(len(speed), ego_x[-1] + CAR.length + 0.75)  # its front bumper
    run = _run(speed, standing, contact=False, other_speed=0.0)
    verdict = judge(run, car_following())
    by_check = {f.check: f for f in verdict.findings}
    assert not by_check["min_ttc"].passed and "of its own making" in by_check["min_ttc"].message
    assert not by_check["harsh_braking"].passed and "for V2" in by_check["harsh_braking"].message
    assert by_check["goal"].passed and "held up by V2" in by_check["goal"].message  # it has no way past
    assert verdict.facts["blocked_by"] == "V2"
    assert verdict.facts["failure"] == "near_miss" and verdict.facts["violation"] == "rear_end"


def test_harsh_braking_for_no_one_and_stalling_with_the_route_clear_are_failures() -> None:
    speed = np.concatenate((np.full(20, 10.0), np.linspace(10.0, 0.0, 7), np.zeros(STEPS - 27)))
    verdict = judge(_run(speed, np.full(STEPS, -100.0), contact=False), car_following())
    by_check = {f.check: f for f in verdict.findings}
    assert not by_check["goal"].passed and "stood still, its route clear" in by_check["goal"].message
    assert not by_check["harsh_braking"].passed and "no one on a collision course" in by_check["harsh_braking"].message
    assert verdict.facts["peak_braking"] == pytest.approx((10.0 / 6) / 0.05, rel=1e-3)  # 10 m/s shed in 0.3 s
    assert verdict.facts["failure"] == "goal"  # the more serious failure names the test
    assert verdict.facts["violation"] == "stalled"


def test_every_failure_class_and_violation_has_a_description() -> None:
    assert list(FAILURE_CLASSES) == ["collision", "goal", "near_miss", "harsh_braking"]
    assert {"crossing", "turn_across", "entering", "pedestrian", "oncoming", "stalled"} <= set(VIOLATIONS)


def test_harsh_braking_begun_at_the_start_answers_the_state_the_test_began_in() -> None:
    """A plan may start the ego a car length behind the car it strikes: braking then is not its choice."""
    early = np.concatenate((np.linspace(10.0, 0.0, 7), np.zeros(STEPS - 7)))
    late = np.concatenate((np.full(30, 10.0), np.linspace(10.0, 0.0, 7), np.zeros(STEPS - 37)))
    findings = {}
    for name, speed in (("early", early), ("late", late)):
        verdict = judge(_run(speed, np.full(STEPS, -100.0), contact=False), car_following())
        findings[name] = next(f for f in verdict.findings if f.check == "harsh_braking")
        assert verdict.facts["peak_braking"] > 30.0
    assert findings["early"].passed and "answering the state the test began in" in findings["early"].message
    assert not findings["late"].passed and findings["late"].time == pytest.approx(1.55, abs=0.06)


def _side_run(ego_speed: float, other_start: tuple[float, float], other_heading: float, other_speed: float) -> Run:
    """V1 (the ego) drives east from x = 50 at ego_speed for 2 s; V2 drives straight from other_start;
    the run ends at their first contact."""
    times = np.arange(STEPS) * 0.05
    ego_x = 50.0 + ego_speed * times
    rad = np.radians(other_heading)
    ox, oy = other_start[0] + other_speed * times * np.sin(rad), other_start[1] + other_speed * times * np.cos(rad)
    end = next(
        (
            k
            for k in range(STEPS)
            if overlap(Box.of(CAR, ego_x[k], -8.25, 90.0), Box.of(CAR, ox[k], oy[k], other_heading))
        ),
        None,
    )
    assert end is not None, "the hand-made bodies must meet"
    n = end + 1
    tracks = {
        "V1": Track("V1", CAR, ego_x[:n], np.full(n, -8.25), np.full(n, 90.0), np.full(n, ego_speed)),
        "V2": Track("V2", CAR, ox[:n], oy[:n], np.full(n, other_heading), np.full(n, other_speed)),
    }
    task = make_task(car_following(), "V1")
    contact = Contact(float(times[end]), "V2")
    return Run("V1", task, times[:n], tracks, ego_x[:n] - 20.0, np.zeros((n, 2)), "collision", contact, (), 0.0)


def test_a_collision_counts_only_when_the_ego_s_motion_brought_it_on() -> None:
    # V2 comes south at 10 m/s straight at the side of an ego creeping at 1 m/s: standing would not help
    rammed = judge(_side_run(1.0, (49.0, 5.0), 180.0, 10.0), car_following())
    assert rammed.passed, rammed.dumps()
    assert "drove into the ego" in rammed.findings[0].message and rammed.facts["collision"]["kind"] == "angle"
    # the ego drives at 10 m/s into V2 crossing slowly ahead of it: standing, it would have been passed by
    crossing = judge(_side_run(10.0, (66.0, -4.0), 180.0, 3.0), car_following())
    assert not crossing.findings[0].passed and crossing.facts["failure"] == "collision"
    assert crossing.facts["violation"] == "crossing"
