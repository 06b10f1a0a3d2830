"""Each participant planned with its own kind's body and limits: lane changes long enough for a long
body, a cyclist in the kerb lane at a cyclist's pace, a heavy vehicle's gentle ramps and wide bends."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from sovarc.compiler.lower.route import MIN_CHANGE, swept_change_length
from sovarc.compiler.lower.solve import LegValues, ramps
from sovarc.compiler.synth.timing import knots
from sovarc.compiler.vehicles import BICYCLE_MODEL, CAR, CAR_MODEL, MODELS, PEDESTRIAN_MODEL, participant_model
from sovarc.dsl.errors import SovarcError
from sovarc.dsl.ir import UNKNOWN, VehicleKind

from tests.compiler.lower.staging import Staged, scenario, staged

LANE = 3.25  # m, a town lane
ROOM = LANE / 2.0 + 0.25 - 0.15  # the oracle's tolerance less the margin (corridor.py)


def _swing(length: float, body_length: float, shift: float) -> float:
    """How far the rear swings out over a smoothstep lane change of `length`, measured densely."""
    u = np.linspace(0.0, 1.0, 5001)
    return shift * float(np.max(body_length * 6 * u * (1 - u) / length - u * u * (3 - 2 * u)))


@pytest.mark.parametrize("kind", ["car", "van", "pickup", "bus", "truck", "motorcycle", "bicycle"])
def test_a_lane_change_is_long_enough_for_the_body_to_keep_its_rear_in(kind: str) -> None:
    body = MODELS[kind].body
    room = ROOM - body.width / 2.0
    length = swept_change_length(body, LANE, room)
    assert _swing(length, body.length, LANE) <= room + 1e-3  # its rear stays in at that length
    assert _swing(0.9 * length, body.length, LANE) > room  # and not much shorter
    if body.length <= CAR.length + 1.0:
        assert length < MIN_CHANGE  # a car-sized body's change between two lanes needs no more than the shortest
    else:
        assert length > MIN_CHANGE  # a bus's or truck's is (about 40 m)


def test_no_sideways_move_needs_no_length() -> None:
    assert swept_change_length(CAR, 0.0, 1.0) == 0.0


def test_each_participant_has_its_kinds_model_and_an_unstated_kind_is_a_car() -> None:
    sov = scenario("intersection_bus_left_turn_cyclist_side")
    bus, cyclist = sov.participants
    assert participant_model(bus) is MODELS["bus"] and participant_model(cyclist) is BICYCLE_MODEL
    assert participant_model(replace(bus, kind=UNKNOWN)) is CAR_MODEL
    assert participant_model(replace(bus, kind=VehicleKind.CAR)) is CAR_MODEL
    walker = scenario("straight_midblock_pedestrian_cross_side").participant("P1")
    assert participant_model(walker) is PEDESTRIAN_MODEL


def test_the_trapezoid_ramps_are_the_bodys() -> None:
    """A bus takes twice a car's time to reach a speed from rest; the knots follow the solver."""
    heavy = MODELS["bus"].limits
    assert heavy.start_accel < CAR_MODEL.limits.start_accel
    leg = LegValues(0.0, None, True, False, 6.0, 0.0, None, 0.0)  # from rest at 0 s, on at 6 m/s
    car = knots((leg,), 0.0, 0.0, 20.0)
    bus = knots((replace(leg, up=heavy.start_accel, down=heavy.stop_decel),), 0.0, 0.0, 20.0, heavy.plan_accel)
    assert car[1].t == pytest.approx(6.0 / CAR_MODEL.limits.start_accel)
    assert bus[1].t == pytest.approx(6.0 / heavy.start_accel) and bus[1].s == pytest.approx(36.0 / 2.0)


def _plans(name: str) -> list[Staged]:
    result = staged(name)
    assert not isinstance(result, SovarcError), result
    return [s for s in result if s.plan is not None]


@pytest.mark.slow
def test_a_cyclist_rides_the_kerb_lane_at_a_cyclists_pace() -> None:
    for item in _plans("intersection_cyclist_go_across_side"):
        route = item.lowered.routes["V1"]
        assert route.body == BICYCLE_MODEL.body
        placement = item.lowered.match.placement("V1")
        arm = next(a for a in item.lowered.match.site.arms if a.id == placement.arm)
        assert arm.incoming[0].id in route.lanes  # the right-most lane of its direction
        assert all(leg.v <= BICYCLE_MODEL.limits.top_speed for leg in item.lowered.solution.legs["V1"])
        speeds = [s.speed for s in item.plan.trajectory("V1").samples]
        assert max(speeds) < 8.0


@pytest.mark.slow
def test_a_heavy_vehicle_ramps_gently_and_bends_no_tighter_than_it_can() -> None:
    for item in _plans("intersection_truck_left_turn_side"):
        route = item.lowered.routes["V1"]
        assert ramps(route) == (MODELS["truck"].limits.start_accel, MODELS["truck"].limits.stop_decel)
        line = route.line
        radii = line.curvature_radius(window=8.0)
        assert radii.min() >= 0.9 * MODELS["truck"].limits.path_radius
        trajectory = item.plan.trajectory("V1")
        assert trajectory.body == MODELS["truck"].body
        times = np.array([s.t for s in trajectory.samples])
        speed = np.array([s.speed for s in trajectory.samples])
        accel = np.diff(speed) / np.diff(times)
        assert accel.max() <= MODELS["truck"].limits.plan_accel + 0.1
        assert math.isfinite(float(speed.max()))
