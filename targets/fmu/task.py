"""One ego task: a participant's start, its route and goal, and the speeds its route asks for.

The ego starts at its trajectory's first sample, at that sample's speed. Its route is the path its
trajectory drives, then on along the lane of its last edge that runs its way (else straight on). The
goal is `GOAL_MARGIN` past the end of the planned path. The speed the route asks for at arc length s
is the fastest the participant drove there (a participant that waited does not make the ego wait),
and never below `MIN_CRUISE`, so that every ego has somewhere to go.

A participant that never moves (a parked car, traffic stopped at a light; its path is shorter than
HOLD_PATH) gives a task to HOLD: the route points the way it faces, the speed asked for is zero, and
the goal is to stay within HOLD_RADIUS of the start for the whole budget.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from sovarc.compiler.geometry.angles import angle_diff, heading_vector
from sovarc.compiler.geometry.polyline import Point, Polyline
from sovarc.compiler.plan import Plan, Sample, Trajectory
from sovarc.targets.fmu.interface import PATH_POINTS, PATH_SPACING

GOAL_MARGIN = 10.0  # m past the planned path's end
MIN_CRUISE = 3.0  # m/s: the slowest speed a route asks for
HOLD_PATH = 1.0  # m: a participant whose path is shorter holds its position
HOLD_RADIUS = 2.0  # m a holding ego may creep
BUDGET_SLACK = 8.0  # s the ego may take beyond the plan's own time to reach the goal
MAX_BUDGET = 120.0  # s: no test runs longer (the longest plans of the 90 reports last about 60 s)
BIN = 1.0  # m: resolution of the speed profile
JOIN_REACH = 15.0  # m: the route goes on along a lane of its last edge only this near the path's end (it may
# end inside the junction, short of the lane's start)
JOIN_TURN = 60.0  # deg: ... and only one that runs within this of the path's final heading
JOIN_AHEAD = 4.0  # m along that lane from the path's end to where the route joins it
PATH_GAP = 0.05  # m: a route or an NPC's path drops each point this near the last one it kept

LaneShapes = Callable[[str], Sequence[tuple[str, Sequence[Point]]]]  # edge id -> (lane id, centre line) per lane


@dataclass(frozen=True)
class EgoTask:
    participant: str
    trajectory: Trajectory
    start: Sample
    route: Polyline
    path_end: float  # m along the route where the planned path ends
    goal: float  # m along the route
    profile: np.ndarray  # m/s asked for in each BIN-metre bin of the planned path
    cruise: float  # m/s asked for past the planned path
    budget: float  # s to reach the goal (to hold: the length of the test)
    hold: bool = False  # the task is to stay put

    def target_speed(self, s: float) -> float:
        if self.hold:
            return 0.0
        if s >= self.path_end:
            return self.cruise
        k = min(max(int(s / BIN), 0), len(self.profile) - 1)
        return max(MIN_CRUISE, float(self.profile[k]))

    def path_points(self, s: float, x: float, y: float, heading: float) -> list[Point]:
        """The route points k·PATH_SPACING ahead of arc length s, in the ego frame at (x, y, heading)."""
        ahead = self.route.points_at(s + PATH_SPACING * np.arange(1, PATH_POINTS + 1))
        return [to_ego_frame(p[0], p[1], x, y, heading) for p in ahead]


def to_ego_frame(px: float, py: float, x: float, y: float, heading: float) -> Point:
    """A map point in the frame of a vehicle at (x, y) with a compass heading: (forward, left)."""
    rad = math.radians(heading)
    fx, fy = math.sin(rad), math.cos(rad)  # forward
    dx, dy = px - x, py - y
    return (dx * fx + dy * fy, -dx * fy + dy * fx)


def make_task(plan: Plan, participant: str, lane_shapes: LaneShapes | None = None) -> EgoTask:
    trajectory = plan.trajectory(participant)
    samples = trajectory.samples
    start = samples[0]
    if start.speed < 0.0:  # the ego does not reverse: it starts at rest
        start = Sample(start.t, start.x, start.y, start.heading, 0.0)
    extra = GOAL_MARGIN + PATH_POINTS * PATH_SPACING + 20.0
    try:
        planned: Polyline | None = Polyline([(s.x, s.y) for s in samples], min_gap=PATH_GAP)
    except ValueError:  # it never moves
        planned = None
    if planned is None or planned.length < HOLD_PATH:
        rad = math.radians(start.heading)
        route = Polyline([(start.x, start.y), (start.x + extra * math.sin(rad), start.y + extra * math.cos(rad))])
        budget = min(MAX_BUDGET, plan.duration + BUDGET_SLACK)
        return EgoTask(participant, trajectory, start, route, 0.0, HOLD_RADIUS, np.zeros(1), 0.0, budget, hold=True)
    towards = _continuation(trajectory, planned, lane_shapes) if lane_shapes else []
    route = extended(planned, extra, towards)
    path_end = planned.length
    profile, cruise = _speed_profile(samples, path_end)
    budget = min(MAX_BUDGET, plan.duration + GOAL_MARGIN / cruise + BUDGET_SLACK)
    return EgoTask(participant, trajectory, start, route, path_end, path_end + GOAL_MARGIN, profile, cruise, budget)


def extended(line: Polyline, extra: float, towards: Sequence[Point] = ()) -> Polyline:
    """The line, then `towards` (points beyond its end, e.g. a lane's centre line), then `extra` m straight on."""
    points = [tuple(p) for p in line.points] + [tuple(p) for p in towards]
    tail = Polyline(points, min_gap=PATH_GAP)
    end, (dx, dy) = tail.point_at(tail.length), heading_vector(tail.heading(tail.length))
    points.append((end[0] + extra * dx, end[1] + extra * dy))
    return Polyline(points, min_gap=PATH_GAP)


def _speed_profile(samples: Sequence[Sample], path_end: float) -> tuple[np.ndarray, float]:
    """The fastest speed driven in each BIN of the path (bins no sample fell in are interpolated)."""
    bins = np.zeros(max(int(path_end / BIN) + 1, 1))
    hit = np.zeros(len(bins), dtype=bool)
    s = 0.0
    for k, sample in enumerate(samples):
        if k:
            s += math.dist((samples[k - 1].x, samples[k - 1].y), (sample.x, sample.y))
        at = min(int(s / BIN), len(bins) - 1)
        bins[at] = max(bins[at], abs(sample.speed)) if hit[at] else abs(sample.speed)
        hit[at] = True
    where = np.flatnonzero(hit)
    bins = np.interp(np.arange(len(bins)), where, bins[where])
    cruise = max(MIN_CRUISE, float(bins.max()), abs(samples[-1].speed))
    return bins, cruise


def _continuation(trajectory: Trajectory, planned: Polyline, lane_shapes: LaneShapes) -> list[Point]:
    """The centre line of the lane of the last edge the trajectory drives, from where its path ends.

    Only a lane near the path's end that runs the way the path was heading counts: a wrong-way driver's
    lane runs against it, and a turn off the road (into a driveway) ends across the lanes, and following
    either would turn the route back on itself and put the goal out of reach. Those go straight on.
    """
    edges = [e for e in trajectory.edges if not e.startswith(":")]
    if not edges:
        return []
    end = planned.point_at(planned.length)
    heading = planned.heading(planned.length)
    lanes = list(lane_shapes(edges[-1]))
    allowed = [(lane, shape) for lane, shape in lanes if lane in trajectory.lanes] or lanes
    best: tuple[float, Polyline, float] | None = None
    for _lane, shape in allowed:
        if len(shape) < 2:
            continue
        line = Polyline(shape, min_gap=PATH_GAP)
        s, dist = line.project_within(end, 0.0, line.length)
        turn = abs(angle_diff(line.heading(s), heading))
        if dist <= JOIN_REACH and turn <= JOIN_TURN and (best is None or dist < best[0]):
            best = (dist, line, s)
    if best is None:
        return []
    _, line, s = best
    join = s + JOIN_AHEAD  # a little ahead, so that a path ending mid-turn bends onto the lane
    later = [tuple(p) for p, at in zip(line.points, line.s, strict=True) if at > join]
    return [line.point_at(join), *later] if later or join < line.length else []
