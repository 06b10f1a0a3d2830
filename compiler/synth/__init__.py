"""Trajectory synthesis: OMPL paths, Ruckig timing, TOPP-RA checks; a lowered scenario becomes a Plan.

plan = synthesize(lowered, step=0.1, seed=0)

Each participant's route becomes a Dubins path (paths.py; the legs of a three-point turn are
driven as lowering laid them out, legs.py), its solved schedule a jerk-limited arc-length
profile (timing.py), and sampling both at the plan's step gives (t, x, y, heading, speed):
the heading the body faces, the speed negative on a reverse leg. TOPP-RA then checks that every
vehicle's profile stays under the fastest drivable speed along its path (limits.py), leg by
leg; a profile over it is an error. So is a plan whose bodies would not first touch as
the crash type needs (impact.py).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from sovarc.compiler.geometry.trailing import trailing_headings
from sovarc.compiler.lower import Lowered
from sovarc.compiler.lower.route import Route
from sovarc.compiler.lower.solve import AFTER_CRASH
from sovarc.compiler.plan import Impact, Plan, Sample, Segment, Trajectory
from sovarc.compiler.synth.impact import check_impact
from sovarc.compiler.synth.legs import RoutePath
from sovarc.compiler.synth.limits import worst_ratio
from sovarc.compiler.synth.timing import knots, sample
from sovarc.compiler.vehicles import model
from sovarc.dsl.errors import Diagnostic, SynthesisError
from sovarc.dsl.ir import ActionKind, Role

STEP = 0.1  # s between samples: SUMO's usual step for replays
AFTER = 1.5  # s the trajectories go on after the impact
ENVELOPE_SLACK = 1.10  # planned speed may exceed TOPP-RA's by this factor (its grid is coarse)
CONTEXT = 6.0  # m of path either side of the judged stretch that shape its ends (see limits.py)


def synthesize(lowered: Lowered, *, step: float = STEP, seed: int = 0) -> Plan:
    solution = lowered.solution
    impact_time = solution.impact_time
    end_time = math.ceil((impact_time + AFTER) / step) * step
    times = np.round(np.arange(0.0, end_time + step / 2, step), 6)
    notes = list(lowered.notes)
    trajectories = []
    for pid, route in lowered.routes.items():
        trajectory, extra = _trajectory(lowered, pid, route, times, end_time)
        trajectories.append(trajectory)
        notes += extra
    striker = next(t for t in trajectories if t.participant == lowered.striker)
    point = _point_at(striker, impact_time, lowered.routes[lowered.striker].backs_at_end)
    plan = Plan(
        scenario=lowered.scenario,
        network=lowered.road_map.network,
        site=lowered.match.site.id,
        kind=lowered.match.site.kind,
        rotation=lowered.match.rotation,
        seed=seed,
        step=step,
        impact=Impact(impact_time, point, 2.0, lowered.striker, lowered.victim, lowered.crash),
        trajectories=tuple(trajectories),
        notes=tuple(notes),
    )
    check_impact(plan)
    return plan


def _trajectory(
    lowered: Lowered, pid: str, route: Route, times: np.ndarray, end_time: float
) -> tuple[Trajectory, list[str]]:
    solution = lowered.solution
    notes = []
    vehicle = route.participant.role is Role.VEHICLE
    path = RoutePath(route, vehicle=vehicle)
    if path.chords > 2:
        notes.append(f"{pid}: {path.chords} pieces of path tighter than a car turns; planned along the lane line")
    legs = solution.legs.get(pid, ())
    start = solution.starts[pid]
    limits = model(route.body).limits
    profile = knots(legs, start, solution.initial_dwell.get(pid, 0.0), end_time, limits.plan_accel)
    s, v, fallbacks = sample(profile, times)
    if route.ends_in_legs:  # cut where the leg it is met on ends (lower/midturn.py): it stands there
        s, v = _brakes_after(times, s, v, solution.impact_time, route.line.length, limits.stop_decel)
    if fallbacks:
        notes.append(f"{pid}: {fallbacks} timing pieces kept constant acceleration (no jerk-limited fit)")
    samples = []
    for t, si, vi in zip(times, s, v, strict=True):
        x, y, heading, scale = path.pose(float(si))
        samples.append(Sample(float(t), x, y, heading, float(vi) * scale * path.gear(float(si))))
    kind = model(route.body)
    if vehicle and kind.trails and all(sample_.speed >= 0.0 for sample_ in samples):
        # a long body faces the way its rear axle trails, not along its front's path (trailing.py)
        points = np.array([(sample_.x, sample_.y) for sample_ in samples])
        headings = trailing_headings(points, samples[0].heading, kind.axle_reach)
        samples = [replace(sample_, heading=float(h)) for sample_, h in zip(samples, headings, strict=True)]
    if vehicle:
        _check_drivable(pid, path, s, v, lowered)
        _check_backing(pid, route, times, s, v, lowered)
    return (
        Trajectory(
            participant=pid,
            role=route.participant.role,
            body=route.body,
            samples=tuple(samples),
            lanes=route.lanes,
            edges=route.edges,
            segments=_segments(route, profile_times=(times, s), legs=legs),
            impact_s=solution.impact.get(pid),
        ),
        notes,
    )


def _brakes_after(
    times: np.ndarray, s: np.ndarray, v: np.ndarray, t_hit: float, end: float, decel: float
) -> tuple[np.ndarray, np.ndarray]:
    """The profile from the impact on braking at `decel` (harder if it must) to stand by arc length
    `end`, where the leg of a turn it was met on ends: the crash, not a change of gear, stops it."""
    after = times > t_hit
    if not after.any():
        return s, v
    s0, v0 = float(np.interp(t_hit, times, s)), float(np.interp(t_hit, times, v))
    rate = max(decel, v0 * v0 / (2.0 * max(end - s0, 1e-6)))
    tau = np.minimum(times[after] - t_hit, v0 / rate)
    s, v = s.copy(), v.copy()
    s[after] = np.minimum(s0 + v0 * tau - rate * tau * tau / 2.0, end)
    v[after] = v0 - rate * tau
    return s, v


def _check_drivable(pid: str, path: RoutePath, s: np.ndarray, v: np.ndarray, lowered: Lowered) -> None:
    """TOPP-RA's envelope on the path, every metre of the driven stretch, over the planned speeds;
    leg by leg where a three-point turn stops (its path turns back on the spot there)."""
    upto = lowered.solution.impact.get(pid)
    if upto is not None:  # what it would drive after the crash is not driven: not judged
        # nor past it on a turn's leg cut there (lower/midturn.py): the crash, not the car, stops it
        keep = s <= upto + (0.0 if path.route.ends_in_legs else AFTER_CRASH)
        s, v = s[keep], v[keep]
    if len(s) < 2 or s[-1] - s[0] < 2.0:
        return  # it (almost) never moves
    unique, first = np.unique(np.round(s, 3), return_index=True)
    fastest = np.maximum.reduceat(v, first)
    ratio = 0.0
    turns = bool(path.route.manoeuvres)
    for lo, hi in path.legs(float(s[0]), float(s[-1])):
        # a leg of a turn is judged up to its stop, where it stands
        grid = np.append(np.arange(lo, hi, 1.0), hi) if turns else np.arange(lo, hi, 1.0)
        if len(grid) < 2 or hi - lo < 2.0:
            continue
        planned = np.interp(grid, unique, fastest)
        # The path around a stretch too (it runs on past the route's end), so that the stretch's
        # ends bend as the path does where it is cut, often inside a turn after the crash; not
        # around a leg of a turn in legs, whose path turns back on the spot where it stands.
        steps = np.zeros(0) if turns else np.arange(1.0, CONTEXT + 0.5)
        before = (grid[0] - steps)[::-1]
        before = before[before >= 0.0]  # the path begins where the route does
        after = grid[-1] + steps
        points = np.array([path.pose(float(g))[:2] for g in np.concatenate((before, grid, after))])
        limit = max(float(planned.max()) * 1.05, 1.0)
        ratio = max(ratio, worst_ratio(points, planned, limit, len(before), model(path.route.body).limits.plan_accel))
    if ratio > ENVELOPE_SLACK:
        raise SynthesisError(
            Diagnostic(
                f"{pid}'s planned speed on {lowered.match.site.id} is {ratio:.2f} times what its path allows "
                "under the acceleration limits (TOPP-RA)",
                lowered.scenario.participant(pid).meta.span,  # type: ignore[union-attr]
            )
        )


def _check_backing(pid: str, route: Route, times: np.ndarray, s: np.ndarray, v: np.ndarray, lowered: Lowered) -> None:
    """Backing along the road within the vehicle's reversing limits: its speed and its ramps (a car backs
    at a walking pace or two and eases in and out of it), up to the crash. The legs of a turn in legs
    are held to walking pace by lowering (route.MANOEUVRE_SPEED) and keep the usual ramps."""
    backing = np.array([route.backing(float(x)) for x in s])
    upto = lowered.solution.impact.get(pid)
    if upto is not None:
        backing &= s <= upto + 1e-6
    if not backing.any():
        return
    limits = model(route.body).limits
    accel = np.abs(np.gradient(v, times))
    fastest, hardest = float(v[backing].max()), float(accel[backing].max())
    if fastest <= limits.reverse_speed * ENVELOPE_SLACK and hardest <= limits.reverse_accel * ENVELOPE_SLACK:
        return
    message = (
        f"{pid} backs on {lowered.match.site.id} at up to {fastest:.2f} m/s and {hardest:.2f} m/s^2; "
        f"it may back at {limits.reverse_speed:.1f} m/s and {limits.reverse_accel:.1f} m/s^2"
    )
    raise SynthesisError(Diagnostic(message, lowered.scenario.participant(pid).meta.span))  # type: ignore[union-attr]


def _segments(route: Route, profile_times: tuple[np.ndarray, np.ndarray], legs: tuple) -> tuple[Segment, ...]:
    times, s = profile_times

    def time_at(x: float) -> float:
        reached = np.flatnonzero(s >= x - 1e-6)
        return float(times[reached[0]]) if len(reached) else float(times[-1])

    speed = max((leg.v for leg in legs), default=0.0)
    out = []
    for event in route.events:
        if event.gear_stop:
            continue  # within the U-turn's own segment
        label = f"{event.index + 1}:{event.kind.value}"
        cruise = 0.0 if event.kind is ActionKind.STOP else speed
        out.append(Segment(label, event.lo, event.hi, time_at(event.lo), time_at(event.hi), cruise))
    return tuple(out)


def _point_at(trajectory: Trajectory, t: float, backing: bool) -> tuple[float, float]:
    """The striker's leading point at t: its front bumper, or backing, its rear bumper."""
    sample_ = trajectory.at(t)
    if not backing:
        return (sample_.x, sample_.y)
    rad = math.radians(sample_.heading)
    length = trajectory.body.length
    return (sample_.x - length * math.sin(rad), sample_.y - length * math.cos(rad))
