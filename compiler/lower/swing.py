"""A car's body kept between its lane's lines up to the stop line of a junction move.

A plan's body trails its front bumper along the heading (compiler/plan.py). SUMO's junction
lanes start up to ~20 degrees off the approach lane (and some approach lanes bend in their last
metres), and smoothing a route (Polyline.smoothing) rounds that bend from a few metres BEFORE
the stop line: a car whose front is still on its approach lane then points into the turn, and
its rear swings over the lane's far line, into the neighbour lane or onto the sidewalk.

An `Approach` says where the stop line is and which lanes the car may use up to it, and
`overreach` measures the swing of a line (or a path) against them. `keep_in_lane` reshapes the
bend of a line that swings out: the stretch around the stop line becomes a quintic curve that
meets the line at both ends in position, heading and curvature, chosen among a few lengths
and tangents as the one that keeps the body in and bends least tightly. A line that keeps its
body in is left as it is.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np
from sovarc.compiler.crashes import LINE_TOLERANCE  # the SUMO oracle's: corners are moved in by it
from sovarc.compiler.geometry.angles import heading_vector
from sovarc.compiler.geometry.bodies import corner_array
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.vehicles import Body, model

MARGIN = 0.15  # m kept in hand, for the synthesized path's small departures from the line
STEP = 0.25  # m between checked front positions
AHEAD = (3.0, 4.0, 6.0, 8.0, 10.0, 12.0)  # m before the stop line where a reshaped bend may begin
PAST = (1.0, 2.0, 3.0, 4.0, 6.0, 8.0)  # m after it where it may rejoin the line
REACH = (0.8, 1.0, 1.2, 1.4)  # its end tangents' length, as a share of its chord
SAMPLES = 40  # points on a reshaped bend
MAX_SHIFT = 1.0  # m a reshaped bend may lie from the line it replaces
BEHIND = 10.0  # m an approach lane is extended back before its start


@dataclass(frozen=True)
class Approach:
    """The lanes a vehicle may use up to the stop line, where its junction move begins."""

    stop: float  # arc length of the stop line on the route's line
    lanes: tuple[tuple[Polyline, float], ...]  # centre line (ending at the stop line) and half width

    @classmethod
    def of(cls, stop: float, lanes: Iterable[tuple[Sequence[tuple[float, float]], float]]) -> Approach:
        """From lane shapes and widths; each shape is extended straight back by BEHIND, so that a body
        whose rear is still on the lane before it is measured across, not from the shape's start."""
        made = []
        for shape, width in lanes:
            line = Polyline(shape)
            (x0, y0), (x1, y1) = line.points[0], line.point(min(1.0, line.length))
            d = math.hypot(x1 - x0, y1 - y0)
            back = (x0 - BEHIND * (x1 - x0) / d, y0 - BEHIND * (y1 - y0) / d)
            made.append((Polyline(np.vstack([back, line.points])), width / 2.0))
        return cls(stop, tuple(made))

    def before_stop(self, points: np.ndarray) -> np.ndarray:
        """For each point (n x 2), whether it lies before the stop line (the end of some approach lane)."""
        before = np.zeros(len(points), dtype=bool)
        for line, _ in self.lanes:
            end, last = line.points[-1], line.points[-1] - line.points[-2]
            before |= (points - end) @ last < 0.0
        return before

    def overreach(self, poses: np.ndarray, body: Body) -> float:
        """The most a corner of the body (moved in by LINE_TOLERANCE) lies beyond the approach lanes'
        outer lines, over the poses (n x 3: front x, y, compass heading) whose front is before
        the stop line; negative when every corner stays in by that much (-inf: no such pose)."""
        poses = np.asarray(poses, dtype=float).reshape(-1, 3)
        poses = poses[self.before_stop(poses[:, :2])]
        if not len(poses):
            return -math.inf
        corners = corner_array(poses, body.length, body.width, shrink=LINE_TOLERANCE)
        outside = np.min([line.distances(corners) - half for line, half in self.lanes], axis=0)
        return float(outside.max())

    def line_overreach(self, line: Polyline, body: Body, since: float | None = None) -> float:
        """`overreach` of a body whose front follows `line` in its heading, up to the stop line, from
        a body length (and 2 m) before it, or from `since` when that is earlier."""
        start = self.stop - body.length - 2.0
        return self.overreach(line_poses(line, start if since is None else min(start, since), self.stop + 1.0), body)


def keep_in_lane(
    line: Polyline, from_s: np.ndarray, approach: Approach, body: Body
) -> tuple[Polyline, np.ndarray, Approach]:
    """`line` (smoothed, with `from_s` from Polyline.smoothing) with its bend into the junction
    reshaped when its body would swing over the approach lanes' lines; returns the line, its
    `from_s` and the approach with the stop line where the line crosses it. A line that keeps
    its body in (by MARGIN), or for which no reshaped bend does, is returned as it is."""
    if approach.line_overreach(line, body) <= -MARGIN:
        return line, from_s, approach
    # Candidates are tried on the stretch around the stop line alone (the same geometry, shorter).
    lo = max(0.0, approach.stop - max(AHEAD) - body.length - 3.0)
    piece = line.sub(lo, min(line.length, approach.stop + max(PAST) + 3.0))
    here = Approach(approach.stop - lo, approach.lanes)
    span = (here.stop - max(AHEAD) - 1.0, here.stop + max(PAST) + 1.0)
    # a reshaped bend may be tighter only down to the body's tightest
    floor = min(tightest_radius(piece, *span), model(body).limits.path_radius)
    ends = {s: end_pose(piece, s) for s in [here.stop - a for a in AHEAD] + [here.stop + p for p in PAST]}
    best: tuple[float, float, float, float] | None = None
    for ahead, past, reach in itertools.product(AHEAD, PAST, REACH):
        made = bend(piece, here, ahead, past, reach, ends)
        if made is None:
            continue
        new, crossing = made
        radius = tightest_radius(new, span[0], crossing + max(PAST) + 1.0)
        if radius < floor or (best is not None and radius <= best[0]):
            continue
        if largest_shift(piece, new, here.stop - ahead, here.stop + past) > MAX_SHIFT:
            continue
        if Approach(crossing, here.lanes).line_overreach(new, body, since=here.stop - ahead) > -MARGIN:
            continue
        best = (radius, ahead, past, reach)
    if best is None:
        return line, from_s, approach
    _, ahead, past, reach = best
    made = bend(line, approach, ahead, past, reach)
    if made is None:  # not expected: the same geometry as the stretch it was tried on
        return line, from_s, approach
    new, crossing = made
    start, end = approach.stop - ahead, approach.stop + past
    head, tail = int((line.s < start - 1e-6).sum()), int((line.s > end + 1e-6).sum())
    middle = new.s[head : len(new.s) - tail]
    raw = np.interp([start, approach.stop, end], line.s, from_s)  # the stop line carries over onto itself
    carried = np.interp(middle, [middle[0], crossing, middle[-1]], raw)
    carried = np.concatenate([from_s[:head], carried, from_s[len(from_s) - tail :]])
    return new, carried, Approach(crossing, approach.lanes)


def bend(
    line: Polyline, approach: Approach, ahead: float, past: float, reach: float, ends: dict[float, End] | None = None
) -> tuple[Polyline, float] | None:
    """`line` with its stretch from `ahead` metres before the stop line to `past` metres after it
    replaced by a quintic curve that meets the line there in position, heading and curvature
    (`reach`: the length of its end tangents, as a share of its chord), and the arc length
    where it crosses the stop line. None when the stretch does not fit on the line. `ends`: the
    line's `end_pose` at arc lengths already measured."""
    start, end = approach.stop - ahead, approach.stop + past
    if start < 1.0 or end > line.length - 1.0:
        return None
    (p0, h0, k0), (p1, h1, k1) = (ends[s] if ends and s in ends else end_pose(line, s) for s in (start, end))
    curve = quintic(p0, h0, k0, p1, h1, k1, reach * math.dist(p0, p1))
    head, tail = line.points[line.s < start - 1e-6], line.points[line.s > end + 1e-6]
    new = Polyline(np.vstack([head, curve, tail]))
    if len(new.s) != len(head) + len(curve) + len(tail):
        return None  # a repeated point: arc lengths would not carry over vertex by vertex
    at = np.arange(start + 0.05, end + new.length - line.length - 0.05, 0.05)  # on the curve
    after = np.flatnonzero(~approach.before_stop(_points(new, at)))
    return (new, float(at[after[0]])) if len(after) else None


def line_poses(line: Polyline, start: float, end: float) -> np.ndarray:
    """Front poses (x, y, compass heading) along `line` every STEP metres from `start` to `end`,
    heading along the chord over +-0.5 m."""
    at = np.arange(max(0.0, start), min(end, line.length) + 1e-9, STEP)
    here, behind, ahead = _points(line, at), _points(line, at - 0.5), _points(line, at + 0.5)
    d = ahead - behind
    return np.column_stack([here, np.degrees(np.arctan2(d[:, 0], d[:, 1])) % 360.0])


def _points(line: Polyline, at: np.ndarray) -> np.ndarray:
    at = np.clip(at, 0.0, line.length)
    return np.column_stack([np.interp(at, line.s, line.points[:, 0]), np.interp(at, line.s, line.points[:, 1])])


def largest_shift(line: Polyline, new: Polyline, start: float, end: float) -> float:
    """How far `new` (which replaces `line` from `start` to `end`) lies from it there."""
    return float(line.sub(start, end).distances(new.sub(start, end + new.length - line.length).points).max())


def tightest_radius(line: Polyline, start: float, end: float) -> float:
    """The smallest radius of curvature (over 2 m) between two arc lengths."""
    inside = (line.s >= start) & (line.s <= end)
    return float(line.curvature_radius(window=2.0)[inside].min()) if inside.any() else math.inf


End = tuple[tuple[float, float], float, float]  # a point of a line, its heading and its curvature


def end_pose(line: Polyline, s: float) -> End:
    return line.point(s), line.heading(s - 1e-6), _curvature(line, s)


def _curvature(line: Polyline, s: float, half: float = 1.0) -> float:
    """Signed curvature (1/m, positive turning clockwise) over +-`half` metres."""
    a, b = line.heading(max(s - half, 0.0)), line.heading(min(s + half, line.length - 1e-6))
    return math.radians((b - a + 180.0) % 360.0 - 180.0) / (2.0 * half)


def quintic(
    p0: tuple[float, float],
    h0: float,
    k0: float,
    p1: tuple[float, float],
    h1: float,
    k1: float,
    tangent: float,
) -> np.ndarray:
    """SAMPLES points of the quintic Hermite curve from p0 (compass heading h0, curvature k0) to
    p1 (h1, k1), with end tangents `tangent` long."""
    u = np.linspace(0.0, 1.0, SAMPLES)[:, None]
    basis = (
        1 - 10 * u**3 + 15 * u**4 - 6 * u**5,
        u - 6 * u**3 + 8 * u**4 - 3 * u**5,
        (u**2 - 3 * u**3 + 3 * u**4 - u**5) / 2.0,
        (u**3 - 2 * u**4 + u**5) / 2.0,
        -4 * u**3 + 7 * u**4 - 3 * u**5,
        10 * u**3 - 15 * u**4 + 6 * u**5,
    )
    terms = (
        np.asarray(p0),
        tangent * np.asarray(heading_vector(h0)),
        k0 * tangent**2 * np.asarray(heading_vector(h0 + 90.0)),
        k1 * tangent**2 * np.asarray(heading_vector(h1 + 90.0)),
        tangent * np.asarray(heading_vector(h1)),
        np.asarray(p1),
    )
    return sum((b * t for b, t in zip(basis, terms, strict=True)), np.zeros((SAMPLES, 2)))
