"""A plan with a three-point turn: the car faces one way and moves both, stands at every change of
gear, keeps its body on the street, and is struck on its last leg, driving forward."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from sovarc.compiler.geometry.angles import heading_vector
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.lower.kturn import KERB_OVERHANG
from sovarc.compiler.lower.route import MANOEUVRE_SPEED
from sovarc.compiler.plan import Sample

from tests.compiler.synth.street import k_turn_plan, street

pytestmark = pytest.mark.slow  # netconvert builds the street

SPEED_SLACK = 0.05  # m/s


def _turner() -> tuple[Sample, ...]:
    return k_turn_plan().trajectory("V1").samples


def test_the_turn_reverses_at_walking_pace_and_stands_between_legs() -> None:
    samples = _turner()
    speeds = np.array([s.speed for s in samples])
    assert speeds.min() < 0.0  # a reverse leg
    assert speeds.min() >= -(MANOEUVRE_SPEED + SPEED_SLACK)
    for a, b in itertools.pairwise(samples):
        assert a.speed * b.speed >= 0.0, f"changes gear between {a.t:.1f} s and {b.t:.1f} s without standing"
    gears = [np.sign(v) for v in speeds if abs(v) > 1e-9]
    changes = sum(1 for a, b in itertools.pairwise(gears) if a != b)
    assert changes == 2  # forward, reverse, forward


def test_the_heading_is_the_way_the_body_faces_whichever_way_it_moves() -> None:
    samples = _turner()
    for a, b in itertools.pairwise(samples):
        turn = abs((b.heading - a.heading + 180.0) % 360.0 - 180.0)
        assert turn < 15.0, f"the heading jumps {turn:.0f} degrees at {b.t:.1f} s"
        moved = (b.x - a.x, b.y - a.y)
        if math.hypot(*moved) < 0.02:
            continue
        f = heading_vector(a.heading)
        along = (moved[0] * f[0] + moved[1] * f[1]) / math.hypot(*moved)
        assert along * a.speed >= -0.05, f"at {a.t:.1f} s it moves {'back' if along < 0 else 'ahead'} at {a.speed}"


def test_the_body_stays_on_the_street() -> None:
    from sumolib.net import readNet

    plan = k_turn_plan()
    net = readNet(str(street()))
    lanes = [net.getLane(lane) for lane in ("street_1", "-street_1")]
    worst = 0.0
    trajectory = plan.trajectory("V1")
    for s in trajectory.samples:
        f = heading_vector(s.heading)
        left = (-f[1], f[0])
        for back in (0.0, trajectory.body.length):
            for side in (-trajectory.body.width / 2.0, trajectory.body.width / 2.0):
                corner = (s.x - back * f[0] + side * left[0], s.y - back * f[1] + side * left[1])
                out = min(Polyline(lane.getShape()).project(corner)[1] - lane.getWidth() / 2.0 for lane in lanes)
                worst = max(worst, out)
    assert worst <= KERB_OVERHANG + 0.01


def test_the_turner_is_struck_on_its_last_leg_driving_forward() -> None:
    plan = k_turn_plan()
    samples = _turner()
    at = plan.trajectory("V1").at(plan.impact.time)
    last_reverse = max(s.t for s in samples if s.speed < 0.0)
    assert plan.impact.time > last_reverse
    assert at.speed > 0.0
    assert plan.impact.striker == "V2" and plan.impact.victim == "V1"
