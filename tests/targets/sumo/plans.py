"""Hand-made plans on the example town, for the SUMO target's tests (synthesis is not needed).

Each participant drives a chain of SUMO lanes at constant speed, placed so that the
striker and the victim touch at the faces the crash type names at `IMPACT_T`; the
trajectories go on for `AFTER_S` past it, as synthesis does.
"""

from __future__ import annotations

import functools
import hashlib
import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import replace

import sumolib
from sovarc.compiler.geometry.angles import compass
from sovarc.compiler.geometry.polyline import point_at, shape_length
from sovarc.compiler.plan import Impact, Network, Plan, Sample, Segment, Trajectory
from sovarc.compiler.vehicles import CAR, PEDESTRIAN, Body
from sovarc.dsl import parse
from sovarc.dsl.ir import CrashType, RoadKind, Role

from tests.conftest import EXAMPLES

TOWN = EXAMPLES / "maps" / "town.net.xml"
STEP = 0.1
IMPACT_T = 3.0
AFTER_S = 0.5

Point = tuple[float, float]


@functools.cache
def town() -> sumolib.net.Net:
    return sumolib.net.readNet(str(TOWN), withInternal=True)


def lane_chain(*lanes: str) -> tuple[str, ...]:
    """The lanes driven from each given lane to the next, junction lanes included."""
    net = town()
    chain = [lanes[0]]
    for a, b in itertools.pairwise(lanes):
        conn = next(c for c in net.getLane(a).getOutgoing() if c.getToLane().getID() == b)
        via = conn.getViaLaneID()
        while via and via != b:  # an internal lane may continue into another one
            chain.append(via)
            nxt = net.getLane(via).getOutgoing()
            via = nxt[0].getViaLaneID() or nxt[0].getToLane().getID()
        chain.append(b)
    return tuple(chain)


def shape_of(lanes: Sequence[str], reverse: bool = False, offset: float = 0.0) -> list[Point]:
    """The centre line of the lanes, end to end (reversed for a wrong-way driver), shifted
    `offset` metres to the left of the direction of travel."""
    points: list[Point] = []
    for lane in lanes:
        for p in town().getLane(lane).getShape():
            if not points or math.dist(points[-1], p) > 1e-6:
                points.append((float(p[0]), float(p[1])))
    if reverse:
        points.reverse()
    if offset:
        points = [_shifted(points, i, offset) for i in range(len(points))]
    return points


def _shifted(points: list[Point], i: int, offset: float) -> Point:
    a, b = points[max(i - 1, 0)], points[min(i + 1, len(points) - 1)]
    h = math.radians(compass(b[0] - a[0], b[1] - a[1]))
    return (points[i][0] - offset * math.cos(h), points[i][1] + offset * math.sin(h))


def s_of(shape: Sequence[Point], point: Point) -> float:
    """Distance along the shape of its point nearest to `point`."""
    best, best_s, s = math.inf, 0.0, 0.0
    for p, q in itertools.pairwise(shape):
        seg = math.dist(p, q)
        u = max(0.0, min(1.0, ((point[0] - p[0]) * (q[0] - p[0]) + (point[1] - p[1]) * (q[1] - p[1])) / seg**2))
        d = math.dist(point, (p[0] + u * (q[0] - p[0]), p[1] + u * (q[1] - p[1])))
        if d < best:
            best, best_s = d, s + u * seg
        s += seg
    return best_s


def pose(shape: Sequence[Point], s: float) -> tuple[float, float, float]:
    """x, y and compass heading at distance s along the shape (extended straight past its ends)."""
    length = shape_length(shape)
    if s < 0.0:
        (x, y), h = shape[0], _heading(shape, 0.0)
        r = math.radians(h)
        return x + s * math.sin(r), y + s * math.cos(r), h
    if s > length:
        (x, y), h = shape[-1], _heading(shape, length)
        r = math.radians(h)
        return x + (s - length) * math.sin(r), y + (s - length) * math.cos(r), h
    x, y = point_at(shape, s)
    return x, y, _heading(shape, s)


def _heading(shape: Sequence[Point], s: float) -> float:
    for p, q in itertools.pairwise(shape):
        seg = math.dist(p, q)
        if s <= seg or q == shape[-1]:
            return compass(q[0] - p[0], q[1] - p[1])
        s -= seg
    raise AssertionError("empty shape")


def drive(
    participant: str,
    role: Role,
    lanes: Sequence[str],
    speed: float,
    s_at_impact: float,
    *,
    body: Body = CAR,
    shape: Sequence[Point] | None = None,
    allowed: Sequence[str] | None = None,
    impact_s: float | None = 0.0,
) -> Trajectory:
    """Constant speed along `shape` (default: the lanes' centre line), front at s_at_impact at IMPACT_T."""
    path = list(shape) if shape is not None else shape_of(lanes)
    count = round((IMPACT_T + AFTER_S) / STEP) + 1
    samples = []
    for k in range(count):
        t = round(k * STEP, 6)
        x, y, h = pose(path, s_at_impact + speed * (t - IMPACT_T))
        samples.append(Sample(t, round(x, 3), round(y, 3), round(h, 2), speed))
    s0 = s_at_impact - speed * IMPACT_T
    edges = tuple(dict.fromkeys(lane.rsplit("_", 1)[0] for lane in lanes if not lane.startswith(":")))
    return Trajectory(
        participant=participant,
        role=role,
        body=body,
        samples=tuple(samples),
        lanes=tuple(allowed if allowed is not None else lanes),
        edges=edges,
        segments=(Segment("follow_lane", s0, s0 + speed * (IMPACT_T + AFTER_S), 0.0, IMPACT_T + AFTER_S, speed),),
        impact_s=None if impact_s is None else s_at_impact,
    )


def make_plan(example: str, site: str, kind: RoadKind, *trajectories: Trajectory, point: Point) -> Plan:
    scenario = parse((EXAMPLES / "scenarios" / f"{example}.sov").read_text(encoding="utf-8"))
    crash = scenario.crash
    assert isinstance(crash.type, CrashType) and isinstance(crash.striker, str) and isinstance(crash.victim, str)
    return Plan(
        scenario=scenario,
        network=Network(str(TOWN), hashlib.sha256(TOWN.read_bytes()).hexdigest(), str(TOWN)),
        site=site,
        kind=kind,
        rotation=0,
        seed=0,
        step=STEP,
        impact=Impact(IMPACT_T, point, 1.5, crash.striker, crash.victim, crash.type),
        trajectories=trajectories,
        notes=("hand-made test plan",),
    )


def crossing(a: Sequence[Point], b: Sequence[Point]) -> Point:
    """Where two polylines cross."""
    for (p, q), (r, s) in itertools.product(itertools.pairwise(a), itertools.pairwise(b)):
        d = (q[0] - p[0]) * (s[1] - r[1]) - (q[1] - p[1]) * (s[0] - r[0])
        if abs(d) < 1e-12:
            continue
        u = ((r[0] - p[0]) * (s[1] - r[1]) - (r[1] - p[1]) * (s[0] - r[0])) / d
        v = ((r[0] - p[0]) * (q[1] - p[1]) - (r[1] - p[1]) * (q[0] - p[0])) / d
        if 0.0 <= u <= 1.0 and 0.0 <= v <= 1.0:
            return (p[0] + u * (q[0] - p[0]), p[1] + u * (q[1] - p[1]))
    raise AssertionError("the paths do not cross")


# --- the three scenes -----------------------------------------------------------------


def t_bone() -> Plan:
    """x_oak: northbound V1 runs across and its front strikes the right side of eastbound V2."""
    v1_lanes = lane_chain("oak1_0", "oak2_0")
    v2_lanes = lane_chain("ave2_1", "ave3_1")
    s1, s2 = shape_of(v1_lanes), shape_of(v2_lanes)
    c = crossing(s1, s2)
    v1 = drive("V1", Role.VEHICLE, v1_lanes, 12.0, s_of(s1, c) - CAR.width / 2, shape=s1)
    v2 = drive("V2", Role.VEHICLE, v2_lanes, 9.7, s_of(s2, c) + CAR.length / 2, shape=s2)
    return make_plan("intersection_red_light_runner_side", "junction:x_oak", RoadKind.INTERSECTION, v1, v2, point=c)


def rear_end() -> Plan:
    """ave2, lane 1: V1 at 22 m/s strikes the back of V2, stopped 150 m along."""
    lanes = ("ave2_0",)
    shape = shape_of(lanes)
    v2 = drive("V2", Role.VEHICLE, lanes, 0.0, 150.0)
    v1 = drive("V1", Role.VEHICLE, lanes, 22.0, 150.0 - CAR.length)
    point = pose(shape, 150.0 - CAR.length)[:2]
    return make_plan("straight_rear_end_stopped_traffic", "road:-ave2|ave2", RoadKind.STRAIGHT, v1, v2, point=point)


def head_on() -> Plan:
    """south1: westbound V1 drives on the eastbound lane (retrograde) into eastbound V2's front."""
    v2 = drive("V2", Role.VEHICLE, ("south1_0",), 20.0, 200.0)
    wrong_way = shape_of(("south1_0",), reverse=True)
    meet = pose(shape_of(("south1_0",)), 200.0)[:2]
    v1 = drive(
        "V1",
        Role.VEHICLE,
        ("-south1_0",),
        26.0,
        s_of(wrong_way, meet),
        shape=wrong_way,
        allowed=("-south1_0", "south1_0"),
    )
    site = "road:-south1|south1"
    return make_plan("straight_double_yellow_pass_frontal", site, RoadKind.STRAIGHT, v1, v2, point=meet)


def line(point: Point, heading: float, back: float = 200.0, ahead: float = 100.0) -> list[Point]:
    """A straight path through `point` in compass `heading`."""
    r = math.radians(heading)
    dx, dy = math.sin(r), math.cos(r)
    return [(point[0] - back * dx, point[1] - back * dy), (point[0] + ahead * dx, point[1] + ahead * dy)]


def sideswipe() -> Plan:
    """ave2: V2 drifts left from lane 2 into lane 3 and its front strikes the right side of V1 there."""
    v1 = drive("V1", Role.VEHICLE, ("ave2_2",), 14.0, s_of(shape_of(("ave2_2",)), (152.3, -4.95)))
    contact = (150.0, -4.95 - CAR.width / 2)
    r = math.radians(80.0)
    drift = (-8.25 - contact[1]) * math.sin(r) / math.cos(r)  # where the 80-degree line leaves lane 2
    path = [(10.4, -8.25), (contact[0] + drift, -8.25), *line(contact, 80.0, back=0.0)]
    v2 = drive("V2", Role.VEHICLE, ("ave2_1",), 12.0, s_of(path, contact), shape=path, allowed=("ave2_1", "ave2_2"))
    site = "road:-ave2|ave2"
    return make_plan("straight_driveway_left_drive_off_side", site, RoadKind.STRAIGHT, v1, v2, point=contact)


def pedestrian() -> Plan:
    """main1, mid-block: P1 walks west across; northbound V1 in lane 2 strikes P1's left side."""
    centre = (1.5, -150.0)
    p1 = drive(
        "P1",
        Role.PEDESTRIAN,
        ("main1_0", "-main1_0"),
        1.5,
        20.0,
        body=PEDESTRIAN,
        shape=line(centre, 270.0, back=20.0, ahead=20.0),
        allowed=("main1_0", "main1_1", "main1_2", "-main1_2", "-main1_1", "-main1_0"),
    )
    v1 = drive("V1", Role.VEHICLE, ("main1_2",), 10.5, 150.0 - 6.0 - PEDESTRIAN.width / 2)
    site = "road:-main1|main1"
    return make_plan("straight_midblock_pedestrian_cross_side", site, RoadKind.STRAIGHT, v1, p1, point=centre)


SCENES: dict[str, Callable[[], Plan]] = {
    "t_bone": t_bone,
    "rear_end": rear_end,
    "head_on": head_on,
    "sideswipe": sideswipe,
    "pedestrian": pedestrian,
}


def with_trajectory(plan: Plan, trajectory: Trajectory) -> Plan:
    """The plan with one participant's trajectory replaced."""
    return replace(
        plan,
        trajectories=tuple(trajectory if t.participant == trajectory.participant else t for t in plan.trajectories),
    )


# --- deliberately broken plans ----------------------------------------------------------


def no_collision() -> Plan:
    """The rear-end, but V1 is 15 m further back: it never reaches V2 before the end."""
    plan = rear_end()
    return with_trajectory(plan, drive("V1", Role.VEHICLE, ("ave2_0",), 22.0, 150.0 - CAR.length - 15.0))


def wrong_pair() -> Plan:
    """The rear-end with V3 stopped between them: V1 strikes V3 first."""
    plan = rear_end()
    v3 = drive("V3", Role.VEHICLE, ("ave2_0",), 0.0, 120.0, impact_s=None)
    return replace(plan, trajectories=(*plan.trajectories, v3))


def wrong_angle() -> Plan:
    """The T-bone with V2 6 m late: V2's front strikes V1's left side instead."""
    plan = t_bone()
    late = plan.trajectory("V2")
    shape = shape_of(late.lanes)
    s_at_impact = s_of(shape, (late.at(IMPACT_T).x, late.at(IMPACT_T).y)) - 6.0
    return with_trajectory(plan, drive("V2", Role.VEHICLE, late.lanes, 9.7, s_at_impact, shape=shape))


def lane_crossing() -> Plan:
    """The rear-end with V1 driving 1.5 m left of its lane's centre, over the line into lane 2."""
    plan = rear_end()
    shape = shape_of(("ave2_0",), offset=1.5)
    return with_trajectory(plan, drive("V1", Role.VEHICLE, ("ave2_0",), 22.0, 150.0 - CAR.length, shape=shape))


BROKEN: dict[str, Callable[[], Plan]] = {
    "no_collision": no_collision,
    "wrong_pair": wrong_pair,
    "wrong_angle": wrong_angle,
    "lane_crossing": lane_crossing,
}


def wrong_way_near_miss() -> Plan:
    """Both stopped on south1_0, fronts 3 m apart, V1 the wrong way: SUMO's lane check takes V1's
    body to lie behind its front along the lane, over V2, and reports a collision that is not one."""
    plan = head_on()
    wrong_way = shape_of(("south1_0",), reverse=True)
    meet = pose(shape_of(("south1_0",)), 200.0)[:2]
    v1 = drive("V1", Role.VEHICLE, ("-south1_0",), 0.0, s_of(wrong_way, meet) - 3.0, shape=wrong_way)
    v1 = replace(v1, lanes=("-south1_0", "south1_0"))
    return with_trajectory(with_trajectory(plan, v1), drive("V2", Role.VEHICLE, ("south1_0",), 0.0, 200.0))
