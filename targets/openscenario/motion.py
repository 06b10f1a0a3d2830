"""Kinematic findings on the trajectories as the file encodes them.

- teleports: each entity is placed once, in Init, where its trajectory starts; none later.
- timing: vertex times rise strictly.
- speed, acceleration: implied by positions and times, within each entity's limits; measured at
  the point the plan drives along (a vehicle's front-bumper centre, from the pose and the box).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator

from sovarc.targets.openscenario.kinematics import driven_point
from sovarc.targets.openscenario.readback import Entity, Pose, ScenarioFile
from sovarc.targets.verdict import Finding

START_POSITION_TOL = 0.05  # m between the Init teleport and the trajectory's first vertex
START_TIME_TOL = 1e-6  # s: a trajectory must start at t = 0
SPEED_TOL = 0.05  # m/s, for the file's millimetre rounding
ROUNDING = 0.0005  # m: half the last digit of a coordinate


def single_trajectories(scenario: ScenarioFile) -> tuple[list[Finding], dict[str, tuple[Pose, ...]]]:
    """One trajectory per entity, or a finding that says why not."""
    findings = [Finding("trajectories", False, p) for p in scenario.problems]
    found: dict[str, tuple[Pose, ...]] = {}
    for name in scenario.entities:
        paths = scenario.trajectories.get(name, [])
        if len(paths) != 1:
            what = "no FollowTrajectoryAction" if not paths else f"{len(paths)} FollowTrajectoryActions"
            findings.append(Finding("trajectories", False, f"{name} has {what}; the oracle expects exactly one"))
        else:
            found[name] = paths[0]
    unknown = sorted(set(scenario.trajectories) - set(scenario.entities))
    if unknown:
        findings.append(Finding("trajectories", False, f"trajectories for undeclared entities: {', '.join(unknown)}"))
    if not findings:
        findings.append(Finding("trajectories", True, f"one timed trajectory for each of {len(found)} entities"))
    return findings, found


def teleport_findings(scenario: ScenarioFile, paths: dict[str, tuple[Pose, ...]]) -> Iterator[Finding]:
    bad = False
    if scenario.story_teleports:
        bad = True
        names = ", ".join(sorted(set(scenario.story_teleports)))
        yield Finding("teleports", False, f"TeleportAction after the start (in the Story) for {names}")
    for name in scenario.entities:
        placed = scenario.init_teleports.get(name, [])
        if len(placed) != 1:
            bad = True
            yield Finding("teleports", False, f"{name} is teleported {len(placed)} times in Init; expected once")
            continue
        path = paths.get(name)
        if path is None:
            continue
        start, first = placed[0], path[0]
        if first.t > START_TIME_TOL:
            bad = True
            yield Finding("teleports", False, f"{name}'s trajectory starts at t={first.t:g} s, not at 0", first.t)
        jump = math.hypot(first.x - start.x, first.y - start.y)
        if jump > START_POSITION_TOL:
            bad = True
            message = f"{name} jumps {jump:.2f} m from its Init position to its trajectory"
            yield Finding("teleports", False, message, 0.0)
    if not bad:
        yield Finding("teleports", True, "every entity is placed once in Init, where its trajectory starts")


def timing_findings(paths: dict[str, tuple[Pose, ...]]) -> Iterator[Finding]:
    bad = False
    for name, path in paths.items():
        for a, b in itertools.pairwise(path):
            if b.t <= a.t:
                bad = True
                yield Finding("timing", False, f"{name}'s vertex times do not rise: {a.t:g} s then {b.t:g} s", b.t)
                break
    if not bad:
        yield Finding("timing", True, "vertex times rise strictly along every trajectory")


def _speeds(entity: Entity, path: tuple[Pose, ...]) -> list[tuple[float, float, float]]:
    """(mid time, speed, duration) of each step between vertices, at the point the vehicle drives along."""
    points = [driven_point(entity, pose) for pose in path]
    return [
        ((a.t + b.t) / 2, math.dist(p, q) / (b.t - a.t), b.t - a.t)
        for (a, p), (b, q) in itertools.pairwise(zip(path, points, strict=True))
        if b.t > a.t
    ]


def speed_findings(
    scenario: ScenarioFile, paths: dict[str, tuple[Pose, ...]]
) -> tuple[list[Finding], dict[str, float]]:
    findings: list[Finding] = []
    peaks: dict[str, float] = {}
    for name, path in paths.items():
        entity = scenario.entities[name]
        steps = _speeds(entity, path)
        if not steps:
            continue
        t_peak, peak, _ = max(steps, key=lambda s: s[1])
        peaks[name] = round(peak, 3)
        if entity.max_speed is not None and peak > entity.max_speed + SPEED_TOL:
            message = f"{name} moves at {peak:.2f} m/s at t={t_peak:.2f} s, above its limit {entity.max_speed:g} m/s"
            findings.append(Finding("speed", False, message, t_peak))
        findings.extend(_acceleration(name, entity.max_acceleration, entity.max_deceleration, steps))
    if not any(f.check == "speed" for f in findings):
        findings.insert(0, Finding("speed", True, "speeds implied by the timing are within every entity's limit"))
    if not any(f.check == "acceleration" for f in findings):
        findings.append(Finding("acceleration", True, "accelerations implied by the timing are within the limits"))
    return findings, peaks


def _acceleration(
    name: str, max_acc: float | None, max_dec: float | None, steps: list[tuple[float, float, float]]
) -> Iterator[Finding]:
    for (t1, v1, d1), (t2, v2, d2) in itertools.pairwise(steps):
        dt = (d1 + d2) / 2
        accel = (v2 - v1) / dt
        noise = 4 * ROUNDING / (min(d1, d2) * dt) + 0.1
        limit = max_acc if accel > 0 else max_dec
        if limit is not None and abs(accel) > limit + noise:
            word = "accelerates" if accel > 0 else "decelerates"
            yield Finding(
                "acceleration", False, f"{name} {word} at {abs(accel):.1f} m/s² near t={t2:.2f} s, above {limit:g}", t1
            )
            return
