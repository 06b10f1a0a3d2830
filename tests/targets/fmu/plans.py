"""Hand-made plans on the example town's avenue (edge ave2: four eastbound lanes, 10 m to 392 m along
x, lane centres at y = -11.55, -8.25, -4.95, -1.65), built the way synthesis will build them."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace

import numpy as np
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.plan import Impact, Network, Plan, Sample, Segment, Trajectory
from sovarc.compiler.vehicles import CAR, Body
from sovarc.dsl import parse
from sovarc.dsl.ir import CrashType, RoadKind, Role

from tests.conftest import EXAMPLES

TOWN = EXAMPLES / "maps" / "town.net.xml"
SITE = "road:-ave2|ave2"
STEP = 0.1  # s between plan samples
LANE_Y = {0: -11.55, 1: -8.25, 2: -4.95, 3: -1.65}  # ave2_k centre lines (eastbound)

Profile = Callable[[float], float]


def eastbound(
    name: str,
    x0: float,
    lane: int,
    speed: Profile,
    duration: float,
    lateral: Profile | None = None,
    body: Body = CAR,
) -> Trajectory:
    """A car (or another `body`) driving east on ave2 from x0 in a lane, at speed(t); lateral(t) moves it
    left (+y) by metres."""
    times = np.arange(0.0, duration + 1e-9, STEP)
    xs = x0 + np.concatenate(([0.0], np.cumsum([speed(t) * STEP for t in times[:-1]])))
    ys = np.array([LANE_Y[lane] + (lateral(t) if lateral else 0.0) for t in times])
    samples = []
    for k, t in enumerate(times):
        j = min(k, len(times) - 2)
        dx, dy = xs[j + 1] - xs[j], ys[j + 1] - ys[j]
        heading = math.degrees(math.atan2(dx, dy)) % 360.0 if dx or dy else 90.0
        samples.append(Sample(round(float(t), 3), float(xs[k]), float(ys[k]), heading, math.hypot(dx, dy) / STEP))
    last = lane + round((lateral(duration) if lateral else 0.0) / 3.3)
    lanes = tuple(f"ave2_{k}" for k in sorted({lane, last}))
    segment = Segment("follow_lane", 0.0, float(xs[-1] - x0), 0.0, duration, speed(0.0))
    return Trajectory(name, Role.VEHICLE, body, tuple(samples), lanes, ("ave2",), (segment,), None)


def smooth_step(start: float, end: float, height: float) -> Profile:
    """0 before start, `height` after end, a smooth (cosine) move between."""

    def f(t: float) -> float:
        if t <= start:
            return 0.0
        if t >= end:
            return height
        return height * (1.0 - math.cos(math.pi * (t - start) / (end - start))) / 2.0

    return f


def plan_of(*trajectories: Trajectory, striker: str = "V1", victim: str = "V2", impact_time: float = 5.0) -> Plan:
    scenario = parse((EXAMPLES / "scenarios" / "straight_rear_end_stopped_traffic.sov").read_text(encoding="utf-8"))
    return Plan(
        scenario=scenario,
        network=Network(str(TOWN), "0" * 64, str(TOWN)),
        site=SITE,
        kind=RoadKind.STRAIGHT,
        rotation=0,
        seed=0,
        step=STEP,
        impact=Impact(impact_time, (200.0, -8.25), 2.0, striker, victim, CrashType.REAR_END),
        trajectories=trajectories,
        notes=("hand-made for the FMU harness tests",),
    )


def car_following(duration: float = 12.0) -> Plan:
    """V2 drives at 9 m/s; V1 comes up behind it at 14 m/s and settles 30 m back at 9 m/s."""
    leader = eastbound("V2", 80.0, 1, lambda t: 9.0, duration)
    follower = eastbound("V1", 20.0, 1, lambda t: 14.0 - smooth_step(1.0, 6.0, 5.0)(t), duration)
    return plan_of(follower, leader)


def cut_in(duration: float = 10.0) -> Plan:
    """V2, just ahead of V1 in the lane to its left and much slower, swerves into V1's lane in 0.8 s."""
    ego = eastbound("V1", 30.0, 1, lambda t: 15.0, duration)
    cutter = eastbound("V2", 40.0, 2, lambda t: 9.0, duration, lateral=lambda t: -smooth_step(0.6, 1.4, 3.3)(t))
    return plan_of(ego, cutter, impact_time=1.5)


def along(
    name: str,
    points: list[tuple[float, float]],
    start: float,
    speed: float,
    duration: float,
    lanes: tuple[str, ...],
    edges: tuple[str, ...],
) -> Trajectory:
    """A car driving a polyline from arc length `start` at a steady speed."""
    line = Polyline(points)
    samples = []
    for t in np.arange(0.0, duration + 1e-9, STEP):
        s = start + speed * float(t)
        x, y = line.point_at(s)
        samples.append(Sample(round(float(t), 3), x, y, line.heading(s), speed))
    segment = Segment("go_across", start, start + speed * duration, 0.0, duration, speed)
    return Trajectory(name, Role.VEHICLE, CAR, tuple(samples), lanes, edges, (segment,), None)


def crossing(duration: float = 7.0) -> Plan:
    """At x_oak (priority junction at (400, 0)): V1 eastbound on ave2 lane 2 and V2 southbound on oak
    both reach the conflict point at t = 5 s: a side crash, V2 striking V1."""
    east = [
        (10.4, -8.25),
        (392.6, -8.25),
        (397.05, -7.72),
        (400.0, -6.56),
        (402.95, -5.4),
        (407.4, -4.88),
        (791.84, -4.88),
    ]
    south = [(398.3, 389.8), (398.3, -288.5)]
    v1 = along(
        "V1", east, 382.6 - 12.0 * 5.0 + 10.0, 12.0, duration, ("ave2_1", ":x_oak_16_1", "ave3_1"), ("ave2", "ave3")
    )
    v2 = along("V2", south, 389.8 - (-3.0) - 50.0, 10.0, duration, ("-oak2_0", "-oak1_0"), ("-oak2", "-oak1"))
    plan = plan_of(v1, v2, striker="V2", victim="V1")
    return replace(
        plan,
        site="junction:x_oak",
        kind=RoadKind.INTERSECTION,
        impact=replace(plan.impact, point=(398.3, -4.9), type=CrashType.SIDE),
    )


def stopped_ahead(duration: float = 10.0) -> Plan:
    """V2 stands at x = 80 in lane 2; V1 comes at 12 m/s and brakes to a stop 7 m behind it."""
    standing = eastbound("V2", 80.0, 1, lambda t: 0.0, duration)
    braking = eastbound("V1", 20.0, 1, lambda t: max(0.0, 12.0 - 1.5 * t), duration)
    return plan_of(braking, standing)


def slow_ahead(body: Body, duration: float = 14.0) -> Plan:
    """V2, of `body`, rides at 4 m/s from x = 80 in lane 2 (a cyclist's pace); V1 comes at 12 m/s and
    runs into it (the reported crash) after about 7 s."""
    ahead = eastbound("V2", 80.0, 1, lambda t: 4.0, duration, body=body)
    behind = eastbound("V1", 20.0, 1, lambda t: 12.0, duration)
    return plan_of(behind, ahead)
