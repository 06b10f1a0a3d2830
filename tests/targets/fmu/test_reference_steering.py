"""The reference ego's steering, run as plain Python (the class pythonfmu packs): every body it may
drive steers for a route that bends ahead, a bus and a truck too, whose front lies further from the
rear axle than its shortest look-ahead."""

from __future__ import annotations

import math

import pytest
from sovarc.compiler.vehicles import MODELS
from sovarc.targets.fmu.bicycle import Geometry
from sovarc.targets.fmu.interface import PATH_POINTS, PATH_SPACING
from sovarc.targets.fmu.reference.sovarc_ego import SovarcEgo


def _ego(kind: str, speed: float) -> SovarcEgo:
    geometry = Geometry.of(MODELS[kind].body)
    ego = SovarcEgo(instance_name="steering", resources=None)
    ego.ego_length, ego.ego_width = geometry.length, geometry.width
    ego.ego_wheelbase, ego.ego_rear_axle = geometry.wheelbase, geometry.rear_axle
    ego.ego_speed, ego.target_speed, ego.obj_count = speed, speed, 0
    return ego


def _right_bend(radius: float) -> list[list[float]]:
    """Route points ahead of the front bumper, (forward, left), on a right-hand circle from it."""
    points = []
    for k in range(1, PATH_POINTS + 1):
        angle = PATH_SPACING * k / radius
        points.append([radius * math.sin(angle), -radius * (1.0 - math.cos(angle))])
    return points


@pytest.mark.parametrize("kind", ["car", "van", "pickup", "bus", "truck", "motorcycle"])
@pytest.mark.parametrize("speed", [0.5, 3.0])
def test_every_body_steers_right_for_a_route_bending_right(kind: str, speed: float) -> None:
    ego = _ego(kind, speed)
    ego.path = _right_bend(12.0)
    ego.do_step(0.0, 0.1)
    assert ego.steer < -0.05, f"{kind} at {speed} m/s steers {ego.steer:.3f} rad"


def test_on_a_straight_route_nothing_steers() -> None:
    for kind in ("car", "bus"):
        ego = _ego(kind, 3.0)
        ego.path = [[PATH_SPACING * k, 0.0] for k in range(1, PATH_POINTS + 1)]
        ego.do_step(0.0, 0.1)
        assert ego.steer == pytest.approx(0.0, abs=1e-9)
