"""One test: a participant of a plan becomes the ego, driven by the FMU; the others replay their trajectories.

Each step of STEP seconds at time t:
1. read every actor's pose back from SUMO (the ground truth); speeds are the bicycle model's for the
   ego and the replayed trajectory's for an NPC (SUMO's own speed of a moved vehicle is not exact);
2. stop at the first contact between the ego and another body, or when the ego reaches its goal,
   or when its time budget is spent;
3. give the FMU the ego's state, its route ahead and the objects it can see; step it;
4. move the ego by the bicycle model under the FMU's commands, the NPCs to their trajectories at
   t + STEP (straight on at their last speed once a trajectory ends), and step SUMO.
Nothing here is random: the same plan and FMU give the same run.
"""

from __future__ import annotations

import math
import time as clock
from dataclasses import dataclass

import numpy as np
from sovarc.compiler.geometry.bodies import Box, overlap
from sovarc.compiler.geometry.polyline import Point
from sovarc.compiler.plan import Plan, Sample, Trajectory
from sovarc.compiler.vehicles import Body
from sovarc.targets.fmu.bicycle import Geometry, State, advance
from sovarc.targets.fmu.driver import Driver
from sovarc.targets.fmu.interface import MAX_OBJECTS, PERCEPTION_RANGE, STEP
from sovarc.targets.fmu.task import EgoTask, make_task, to_ego_frame
from sovarc.targets.fmu.world import World

BACKGROUND_MARGIN = 40.0  # m around the run whose lanes are kept for its picture


@dataclass(frozen=True)
class Track:
    """The poses of one actor at each step of a run, as SUMO had them."""

    actor: str
    body: Body
    x: np.ndarray
    y: np.ndarray
    heading: np.ndarray  # compass degrees
    speed: np.ndarray  # m/s


@dataclass(frozen=True)
class Contact:
    time: float
    other: str


@dataclass(frozen=True)
class Run:
    ego: str
    task: EgoTask
    times: np.ndarray
    tracks: dict[str, Track]  # the ego's first
    progress: np.ndarray  # m along the ego's route, per step
    commands: np.ndarray  # (steps, 2): the FMU's accel and steer, per step (the last is zeros)
    ended: str  # 'goal', 'collision' or 'budget'
    contact: Contact | None
    lanes: tuple[tuple[Point, ...], ...]  # lane centre lines around the run, for its picture
    wall: float  # s of wall time the run took

    @property
    def ego_track(self) -> Track:
        return self.tracks[self.ego]


def npc_pose(trajectory: Trajectory, t: float) -> Sample:
    """Where an NPC is at time t: its trajectory, then straight on at its last speed."""
    last = trajectory.samples[-1]
    if t <= last.t:
        return trajectory.at(t)
    ahead = last.speed * (t - last.t)
    rad = math.radians(last.heading)
    return Sample(t, last.x + ahead * math.sin(rad), last.y + ahead * math.cos(rad), last.heading, last.speed)


def run_test(plan: Plan, ego: str, driver: Driver, world: World) -> Run:
    """Run one test in a started world with a loaded driver (see `run_tests` for the usual way in)."""
    started = clock.perf_counter()
    own = plan.trajectory(ego)
    npcs = [t for t in plan.trajectories if t.participant != ego]
    task = make_task(plan, ego, world.lane_shapes)
    geometry = Geometry.of(own.body)
    bodies = {ego: own.body} | {t.participant: t.body for t in npcs}
    state = State(task.start.x, task.start.y, task.start.heading, task.start.speed)
    world.add(ego, own.body, state.x, state.y, state.heading)
    for npc in npcs:
        first = npc_pose(npc, 0.0)
        world.add(npc.participant, npc.body, first.x, first.y, first.heading)
    world.advance()

    rows: dict[str, list[tuple[float, float, float, float]]] = {name: [] for name in bodies}
    times: list[float] = []
    progress: list[float] = []
    commands: list[tuple[float, float]] = []
    s, ended, contact = 0.0, "budget", None
    with driver.session(geometry) as session:
        for k in range(math.ceil(task.budget / STEP) + 1):
            t = round(k * STEP, 6)
            poses = {name: world.read(name) for name in bodies}
            ex, ey, eh, _ = poses[ego]
            poses[ego] = (ex, ey, eh, state.speed)
            for npc in npcs:
                x, y, h, _ = poses[npc.participant]
                poses[npc.participant] = (x, y, h, npc_pose(npc, t).speed)
            times.append(t)
            for name, pose in poses.items():
                rows[name].append(pose)
            s = task.route.project_within((ex, ey), s - 2.0, s + 25.0)[0]
            progress.append(s)
            hit = _first_contact(ego, poses, bodies)
            if hit is not None:
                ended, contact = "collision", Contact(t, hit)
                break
            if s >= task.goal and not task.hold:
                ended = "goal"
                break
            if t >= task.budget:
                break
            inputs, count = _inputs(task, s, ego, poses, bodies)
            accel, steer = session.step(t, inputs, count)
            commands.append((accel, steer))
            state = advance(state, accel, steer, STEP, geometry)
            world.move(ego, state.x, state.y, state.heading)
            for npc in npcs:
                pose = npc_pose(npc, t + STEP)
                world.move(npc.participant, pose.x, pose.y, pose.heading)
            world.advance()
    commands.append((0.0, 0.0))
    tracks = {name: _track(name, bodies[name], rows[name]) for name in bodies}
    lanes = _background(world, tracks)
    return Run(
        ego,
        task,
        np.array(times),
        tracks,
        np.array(progress),
        np.array(commands),
        ended,
        contact,
        lanes,
        clock.perf_counter() - started,
    )


def _track(name: str, body: Body, rows: list[tuple[float, float, float, float]]) -> Track:
    data = np.array(rows, dtype=float).reshape(-1, 4)
    return Track(name, body, data[:, 0], data[:, 1], data[:, 2], data[:, 3])


def _first_contact(
    ego: str, poses: dict[str, tuple[float, float, float, float]], bodies: dict[str, Body]
) -> str | None:
    ex, ey, eh, _ = poses[ego]
    mine = Box.of(bodies[ego], ex, ey, eh)
    for name in sorted(poses):
        if name == ego:
            continue
        x, y, h, _ = poses[name]
        if overlap(mine, Box.of(bodies[name], x, y, h)):
            return name
    return None


def _inputs(
    task: EgoTask,
    s: float,
    ego: str,
    poses: dict[str, tuple[float, float, float, float]],
    bodies: dict[str, Body],
) -> tuple[list[float], int]:
    """The FMU's inputs in driver.INPUTS order, and the object count."""
    ex, ey, eh, ev = poses[ego]
    values = [ex, ey, eh, ev, task.target_speed(s), task.goal - s]
    for px, py in task.path_points(s, ex, ey, eh):
        values += [px, py]
    ecx, ecy = Box.of(bodies[ego], ex, ey, eh).centre
    seen = []
    for name, (x, y, h, v) in poses.items():
        if name == ego:
            continue
        cx, cy = Box.of(bodies[name], x, y, h).centre
        distance = math.hypot(cx - ecx, cy - ecy)
        if distance <= PERCEPTION_RANGE:
            seen.append((distance, name, cx, cy, h, v))
    seen.sort()
    for _, name, cx, cy, h, v in seen[:MAX_OBJECTS]:
        fx, fy = to_ego_frame(cx, cy, ex, ey, eh)
        relative = ((eh - h + 180.0) % 360.0) - 180.0  # compass turns clockwise; the ego frame counts left
        values += [fx, fy, relative, v, bodies[name].length, bodies[name].width]
    values += [0.0] * (6 * (MAX_OBJECTS - min(len(seen), MAX_OBJECTS)))
    return values, min(len(seen), MAX_OBJECTS)


def _background(world: World, tracks: dict[str, Track]) -> tuple[tuple[Point, ...], ...]:
    xs = np.concatenate([t.x for t in tracks.values()])
    ys = np.concatenate([t.y for t in tracks.values()])
    lo_x, hi_x = xs.min() - BACKGROUND_MARGIN, xs.max() + BACKGROUND_MARGIN
    lo_y, hi_y = ys.min() - BACKGROUND_MARGIN, ys.max() + BACKGROUND_MARGIN
    kept = []
    for lane in world.all_lane_shapes():
        if any(lo_x <= x <= hi_x and lo_y <= y <= hi_y for x, y in lane):
            kept.append(tuple((float(x), float(y)) for x, y in lane))
    return tuple(kept)
