"""Hand-made plans on examples/maps/town.net.xml, standing in for synthesis.

Each case drives constant-speed straight lines (one also a quarter-circle turn) that are
placed so that the striker's front touches the named face of the victim exactly at the
impact time, as synthesis promises.
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

from sovarc.compiler.geometry.angles import heading_vector
from sovarc.compiler.maps import with_opendrive
from sovarc.compiler.plan import Impact, Network, Plan, Sample, Trajectory
from sovarc.compiler.vehicles import CAR, PEDESTRIAN, Body
from sovarc.dsl import parse
from sovarc.dsl.ir import Role
from sovarc.targets import openscenario

from tests.conftest import EXAMPLES

TOWN = EXAMPLES / "maps" / "town.net.xml"
STEP = 0.1
AFTER = 1.0  # s the trajectories go on past the impact


def on_opendrive(plan: Plan) -> Plan:
    """The plan with its network's OpenDRIVE file, as the compiler provides it before this target runs."""
    return replace(plan, network=with_opendrive(plan.network))


def emit_files(plan: Plan, out_dir: str | Path, version: str = openscenario.DEFAULT_VERSION) -> openscenario.Emitted:
    """The target's emit_files, on the plan with its OpenDRIVE file (netconvert's, cached, for the town)."""
    return openscenario.emit_files(on_opendrive(plan), out_dir, version)


Pose = tuple[float, float, float, float]  # x, y, compass heading, speed
Motion = Callable[[float], Pose]


def straight(x: float, y: float, heading: float, speed: float, t_at: float = 0.0) -> Motion:
    """Constant speed along a compass heading, at (x, y) at time t_at."""
    dx, dy = heading_vector(heading)
    return lambda t: (x + dx * speed * (t - t_at), y + dy * speed * (t - t_at), heading, speed)


def left_turn(x: float, y: float, speed: float, straight_m: float, radius: float) -> Motion:
    """North from (x, y), after straight_m a quarter circle to the left, then west."""
    t1 = straight_m / speed
    arc = math.pi / 2 * radius / speed
    cx, cy = x - radius, y + straight_m

    def pose(t: float) -> Pose:
        if t <= t1:
            return x, y + speed * t, 0.0, speed
        if t <= t1 + arc:
            a = speed * (t - t1) / radius  # angle turned so far
            return cx + radius * math.cos(a), cy + radius * math.sin(a), (360.0 - math.degrees(a)) % 360.0, speed
        return cx - speed * (t - t1 - arc), cy + radius, 270.0, speed

    return pose


def _samples(motion: Motion, end: float) -> tuple[Sample, ...]:
    n = round(end / STEP)
    return tuple(Sample(round(k * STEP, 6), *motion(k * STEP)) for k in range(n + 1))


def make_plan(
    example: str,
    site: str,
    impact_time: float,
    point: tuple[float, float],
    motions: dict[str, Motion],
    radius: float = 2.0,
) -> Plan:
    scenario = parse((EXAMPLES / "scenarios" / f"{example}.sov").read_text(encoding="utf-8"), f"{example}.sov")
    crash = scenario.crash
    end = impact_time + AFTER
    trajectories = []
    for p in scenario.participants:
        body: Body = PEDESTRIAN if p.role is Role.PEDESTRIAN else CAR
        samples = _samples(motions[p.id], end)
        trajectories.append(Trajectory(p.id, p.role, body, samples, (), (), (), None))
    return Plan(
        scenario=scenario,
        network=Network(str(TOWN), hashlib.sha256(TOWN.read_bytes()).hexdigest(), str(TOWN)),
        site=site,
        kind=scenario.road.kind,  # type: ignore[arg-type]
        rotation=0,
        seed=0,
        step=STEP,
        impact=Impact(impact_time, point, radius, str(crash.striker), str(crash.victim), crash.type),  # type: ignore[arg-type]
        trajectories=tuple(trajectories),
        notes=("hand-made test plan",),
    )


def t_bone() -> Plan:
    """Northbound V1 runs the light at x_main; its front strikes the right (south) side of eastbound V2."""
    t_hit, half_w, half_l = 4.0, CAR.width / 2, CAR.length / 2
    y2 = -8.25
    point = (4.5, y2 - half_w)
    motions = {"V1": straight(4.5, point[1], 0.0, 15.0, t_hit), "V2": straight(4.5 + half_l, y2, 90.0, 35 / 3.6, t_hit)}
    return make_plan("intersection_red_light_runner_side", "junction:x_main", t_hit, point, motions)


def rear_end() -> Plan:
    """Eastbound V1 strikes the back of V2, stopped in the same lane of the avenue."""
    t_hit, y = 3.0, -11.55
    point = (200.0 - CAR.length, y)
    motions = {"V1": straight(point[0], y, 90.0, 50 * 0.44704, t_hit), "V2": straight(200.0, y, 90.0, 0.0)}
    return make_plan("straight_rear_end_stopped_traffic", "edge:ave2", t_hit, point, motions, radius=1.5)


def head_on() -> Plan:
    """Westbound V1 passes over the double yellow line and meets eastbound V2 head on."""
    t_hit, y = 3.0, -1.65
    motions = {
        "V1": straight(250.0, y, 270.0, 60 * 0.44704, t_hit),
        "V2": straight(250.0, y, 90.0, 45 * 0.44704, t_hit),
    }
    return make_plan("straight_double_yellow_pass_frontal", "edge:ave2", t_hit, (250.0, y), motions)


def pedestrian() -> Plan:
    """Northbound V1 on Main Street strikes P1, who crosses westward mid-block."""
    t_hit, x = 3.0, 4.8
    front_y = 200.0 - PEDESTRIAN.width / 2
    motions = {"V1": straight(x, front_y, 0.0, 38 / 3.6, t_hit), "P1": straight(x, 200.0, 270.0, 5.5 / 3.6, t_hit)}
    return make_plan("straight_midblock_pedestrian_cross_side", "edge:main2", t_hit, (x, front_y), motions, radius=1.0)


def left_turn_across_path() -> Plan:
    """V1 turns left at x_main; southbound V2 strikes its right side just after the turn."""
    speed1, speed2, t_hit = 15 * 0.44704, 40 * 0.44704, 6.5
    v1 = left_turn(1.5, -40.0, speed1, 24.0, 10.0)
    x1, y1, _, _ = v1(t_hit)  # V1 heads west here: its right side faces north
    point = (x1 + CAR.length / 2, y1 + CAR.width / 2)
    motions = {"V1": v1, "V2": straight(point[0], point[1], 180.0, speed2, t_hit)}
    return make_plan("intersection_left_turn_across_path_side", "junction:x_main", t_hit, point, motions)


CASES: dict[str, Callable[[], Plan]] = {
    "t_bone": t_bone,
    "rear_end": rear_end,
    "head_on": head_on,
    "pedestrian": pedestrian,
    "left_turn": left_turn_across_path,
}


def clipped_rear_corner() -> Plan:
    """A failing plan, the shape of the ground truth's shallow merges: the T-bone with V2 creeping east
    at 4 m/s and V1 closing on it from behind at 12 m/s, 8 degrees off its heading, its bumper centre
    planned at the middle of V2's right side at the impact time. V1's front-left corner meets V2's
    rear-right corner 0.28 s earlier, more than 3 m short of C_A: an offset rear-end, not the side hit."""
    plan = CASES["t_bone"]()
    t_hit, (x, y) = plan.impact.time, plan.impact.point
    victim = straight(x + CAR.length / 2, y + CAR.width / 2, 90.0, 4.0, t_hit)
    plan = with_samples(plan, "V2", lambda s: Sample(s.t, *victim(s.t)))
    return with_samples(plan, "V1", lambda s: Sample(s.t, *straight(x, y, 82.0, 12.0, t_hit)(s.t)))


def with_samples(plan: Plan, participant: str, change: Callable[[Sample], Sample]) -> Plan:
    """The plan with one participant's samples changed (for negative tests)."""
    trajectories = tuple(
        replace(t, samples=tuple(change(s) for s in t.samples)) if t.participant == participant else t
        for t in plan.trajectories
    )
    return replace(plan, trajectories=trajectories)
