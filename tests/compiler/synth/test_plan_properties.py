"""Properties of every plan synthesized from the example scenarios on the example town (3 sites, a few seeds).

Each property is checked per scenario over all of its plans: vehicles stay in the lanes their
actions allow, speeds stay within the limits lowering promised (negative only on the reverse
legs of a three-point turn and while backing), striker and victim touch at the faces the crash type names and
arrive together, samples are regular, and the output is deterministic.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np
import pytest
from sovarc.compiler.crashes import backing_at
from sovarc.compiler.geometry.angles import heading_vector
from sovarc.compiler.lower import DEFAULT_LIMIT_KMH, lower
from sovarc.compiler.lower.route import MANOEUVRE_SPEED
from sovarc.compiler.lower.solve import V_PED_MAX
from sovarc.compiler.plan import Plan, Sample, Trajectory, dump_plan
from sovarc.compiler.synth import synthesize
from sovarc.compiler.synth.timing import knots, sample
from sovarc.compiler.vehicles import model
from sovarc.dsl.errors import SovarcError
from sovarc.dsl.ir import ActionKind, CrashType, RoadKind, Role, Speed

from tests.compiler.lower.staging import NAMES, ROADS, Staged, plans, scenario, seeds_for, staged, town

pytestmark = pytest.mark.slow  # the first test pays for lowering every example (about 20 s)

LANE_MARGIN = 0.5  # m beyond half a lane width a front bumper may be
SPEED_SLACK = 0.05  # m/s
TOUCH = 1.0  # m between the faces that meet at impact
OFF_ROAD = ("drive_into", "drive_off")  # actions that leave or enter the lanes (driveways)


def _angle(a: float, b: float) -> float:
    return abs((a - b + 180.0) % 360.0 - 180.0)


def _distance_to_polyline(points: np.ndarray, shape: Iterable[tuple[float, ...]]) -> np.ndarray:
    """Distance of each of N points (N x 2) to a polyline."""
    line = np.array([p[:2] for p in shape], dtype=float)
    a, b = line[:-1], line[1:]
    d = b - a
    length2 = np.maximum((d**2).sum(axis=1), 1e-12)
    rel = points[:, None, :] - a[None, :, :]
    u = np.clip((rel * d[None, :, :]).sum(axis=2) / length2[None, :], 0.0, 1.0)
    nearest = a[None, :, :] + u[..., None] * d[None, :, :]
    return np.hypot(*(points[:, None, :] - nearest).transpose(2, 0, 1)).min(axis=1)


def _backs(plan: Plan, participant: str) -> bool:
    p = plan.scenario.participant(participant)
    return p is not None and any(a.kind is ActionKind.REVERSE for a in p.known_actions)


def _allowed_lanes(plan: Plan, trajectory: Trajectory) -> list[object]:
    net = town().net
    lanes = [net.getLane(lane_id) for lane_id in trajectory.lanes]
    if plan.site.startswith("junction:"):
        junction = plan.site.split(":", 1)[1]
        lanes += [lane for lane in net.getNode(junction).getInternal() for lane in [net.getLane(lane)]]
    return lanes


def _on_road_samples(trajectory: Trajectory) -> list[Sample]:
    """The samples not in a driveway: before a drive_into ends, or after a drive_off begins."""
    into = [s.end_t for s in trajectory.segments if s.action.endswith(":drive_into")]
    off = [s.start_t for s in trajectory.segments if s.action.endswith(":drive_off")]
    return [s for s in trajectory.samples if all(s.t > t + 1e-9 for t in into) and all(s.t < t - 1e-9 for t in off)]


def _speed_cap(plan: Plan, participant: str) -> float:
    p = plan.scenario.participant(participant)
    assert p is not None
    reported = p.speed.to_mps() if isinstance(p.speed, Speed) else None
    if p.role is Role.PEDESTRIAN:
        return max(V_PED_MAX, reported or 0.0)
    road = plan.scenario.road
    if isinstance(road.speed_limit, Speed):
        limit = road.speed_limit.to_mps()
    else:
        kind = road.kind if isinstance(road.kind, RoadKind) else RoadKind.STRAIGHT
        limit = DEFAULT_LIMIT_KMH[kind] / 3.6
    return max(limit, 1.25 * reported) if reported else limit


def _face(sample_: Sample, length: float, k: float) -> tuple[float, float]:
    """The point k body lengths behind a front-bumper sample (0: front, 1: rear)."""
    hx, hy = heading_vector(sample_.heading)
    return (sample_.x - k * length * hx, sample_.y - k * length * hy)


@pytest.mark.parametrize("name", NAMES)
def test_vehicles_stay_in_their_allowed_lanes(name: str) -> None:
    bad = []
    for plan in plans(name):
        for trajectory in plan.trajectories:
            if trajectory.role is not Role.VEHICLE:
                continue
            lanes = _allowed_lanes(plan, trajectory)
            samples = _on_road_samples(trajectory)
            if not samples:
                continue
            points = np.array([(s.x, s.y) for s in samples])
            outside = np.min(
                [_distance_to_polyline(points, lane.getShape()) - lane.getWidth() / 2.0 for lane in lanes], axis=0
            )
            worst = int(np.argmax(outside))
            if outside[worst] > LANE_MARGIN:
                bad.append(
                    f"{plan.site} seed {plan.seed} {trajectory.participant} at t={samples[worst].t:.1f}: "
                    f"{outside[worst]:.2f} m outside its lanes"
                )
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("name", NAMES)
def test_speeds_are_within_the_limit_and_negative_only_reversing(name: str) -> None:
    bad = []
    for plan in plans(name):
        for trajectory in plan.trajectories:
            cap = _speed_cap(plan, trajectory.participant)
            speeds = [s.speed for s in trajectory.samples]
            turns = any(n.startswith(f"{trajectory.participant} ") and " legs (a " in n for n in plan.notes)
            floor = -(MANOEUVRE_SPEED + SPEED_SLACK) if turns else 0.0  # its legs at walking pace
            if _backs(plan, trajectory.participant):  # backing along the road: at its reversing speed
                floor = -(model(trajectory.body).limits.reverse_speed + SPEED_SLACK)
            if min(speeds) < floor or max(speeds) > cap + SPEED_SLACK:
                bad.append(
                    f"{plan.site} {trajectory.participant}: speeds {min(speeds):.2f}..{max(speeds):.2f} m/s, "
                    f"cap {cap:.2f}"
                )
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("name", NAMES)
def test_striker_and_victim_touch_at_the_faces_the_crash_type_names(name: str) -> None:
    bad = []
    for plan in plans(name):
        impact = plan.impact
        striker = plan.trajectory(impact.striker).at(impact.time)
        victim_trajectory = plan.trajectory(impact.victim)
        victim = victim_trajectory.at(impact.time)
        length, width = victim_trajectory.body.length, victim_trajectory.body.width
        # the striker's leading face: its front, or backing, its rear (which meets the victim's front in a
        # rear_end, its rear in a frontal crash: crash types read with front and rear swapped)
        backing = backing_at(plan, impact.striker, impact.time)
        hx, hy = heading_vector(striker.heading)
        behind = plan.trajectory(impact.striker).body.length if backing else 0.0
        front = (striker.x - behind * hx, striker.y - behind * hy)
        turn = _angle(striker.heading, victim.heading)
        where = f"{plan.site} seed {plan.seed} t={impact.time:.2f}"
        assert math.dist(impact.point, front) < 1e-6, f"{where}: the impact point is not the striker's leading face"
        if impact.type is CrashType.REAR_END:
            gap = math.dist(front, _face(victim, length, 0.0 if backing else 1.0))
            if gap > TOUCH or turn > 45.0:
                bad.append(f"{where}: rear_end with the striker {gap:.2f} m from the victim's rear, {turn:.0f} deg")
        elif impact.type is CrashType.FRONTAL:
            gap = math.dist(front, _face(victim, length, 1.0 if backing else 0.0))
            if gap > TOUCH or turn < 120.0:
                bad.append(f"{where}: frontal with fronts {gap:.2f} m apart, headings {turn:.0f} deg apart")
        else:
            hx, hy = heading_vector(victim.heading)
            back = (victim.x - front[0]) * hx + (victim.y - front[1]) * hy  # m behind the victim's front
            lateral = abs((front[0] - victim.x) * hy - (front[1] - victim.y) * hx)
            # the front bumper (half the striker's width each side of its centre) reaches the side
            reach = width / 2.0 + plan.trajectory(impact.striker).body.width / 2.0
            if not (-0.1 <= back <= length + 0.1) or lateral > reach:
                bad.append(f"{where}: side: striker {back:.2f} m behind the victim's front, {lateral:.2f} m aside")
    assert not bad, "\n".join(bad)


def _staged(name: str) -> list[Staged]:
    out: list[Staged] = []
    for seed in seeds_for(name):
        result = staged(name, seed)
        if not isinstance(result, SovarcError):
            out += [s for s in result if s.plan is not None]
    return out


@pytest.mark.parametrize("name", NAMES)
def test_striker_and_victim_reach_the_contact_within_one_step(name: str) -> None:
    bad = []
    for item in _staged(name):
        plan, solution = item.plan, item.lowered.solution
        assert plan is not None
        times = np.array([s.t for s in plan.trajectories[0].samples])
        for pid in (plan.impact.striker, plan.impact.victim):
            profile = knots(
                solution.legs.get(pid, ()), solution.starts[pid], solution.initial_dwell.get(pid, 0.0), times[-1]
            )
            s, v, _ = sample(profile, times)
            target = plan.trajectory(pid).impact_s
            assert target is not None
            reached = np.flatnonzero(s >= target - 1e-3)
            arrival = float(times[reached[0]]) if len(reached) else math.inf
            at_impact = float(np.interp(plan.impact.time, times, v))
            late = arrival - plan.impact.time
            # a moving participant arrives with the impact; a stopped one may have been there all along
            if late > plan.step + 1e-6 or (at_impact > 0.1 and late < -plan.step - 1e-6):
                bad.append(f"{plan.site} {pid}: at its contact at {arrival:.2f} s, impact at {plan.impact.time:.2f}")
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("name", NAMES)
def test_samples_every_step_and_all_trajectories_the_same_length(name: str) -> None:
    for plan in plans(name):
        lengths = {len(t.samples) for t in plan.trajectories}
        assert len(lengths) == 1, f"{plan.site}: trajectories of {sorted(lengths)} samples"
        for trajectory in plan.trajectories:
            times = [s.t for s in trajectory.samples]
            assert times == [round(k * plan.step, 6) for k in range(len(times))]
        assert plan.duration >= plan.impact.time, "the plan ends before the impact"


@pytest.mark.parametrize(
    ("name", "seed"), [("straight_freeway_lane_change_rear_end", 1), ("intersection_left_turn_across_path_side", 0)]
)
def test_same_input_and_seed_give_the_same_bytes(name: str, seed: int) -> None:
    cached = staged(name, seed)
    assert not isinstance(cached, SovarcError)
    again = [synthesize(item, seed=seed) for item in lower(scenario(name), town(), roads=ROADS, seed=seed)]
    assert [dump_plan(p) for p in again] == [dump_plan(s.plan) for s in cached if s.plan is not None]
