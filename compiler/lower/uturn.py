"""U-turns that fit the road: one forward half circle, as round as the road's width allows.

In the plan's body model a vehicle's heading is the tangent of its front bumper's path and
its body trails behind it, so a car turning left on a circle of radius R swings its rear
out to the right: its rear outer corner reaches sqrt((R + w/2)^2 + L^2) from the circle's
centre on the side the car comes from, and its front outer corner R + w/2 on the far side.
A U-turn therefore needs R + w/2 + sqrt((R + w/2)^2 + L^2) of road across (11.6 m for a
4.6 x 1.8 m car at R = 4 m), and begins far enough from the kerb for the rear to stay on it.

The turn is laid out across the road, in a `Band`: s along the right-most lane of the
direction the car comes from, d to the left of it. The car moves over from its lane to d0,
turns on a half circle to d1 = d0 + 2R, facing back, and moves over to the lane it ends
in. R is the natural radius (half the way from its lane to that lane) unless that is
tighter than MIN_RADIUS or wider than the road holds. A road narrower than the tightest
turn needs a three-point turn, which plans do not carry (they drive forward only): the
layout says it does not fit, and the caller decides.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from sovarc.compiler.lower.polyline import Point, Polyline, unit
from sovarc.compiler.maps import LaneInfo
from sovarc.compiler.plan import Body

MIN_RADIUS = 4.0  # m, the front bumper's path at full lock (a car's 10-11 m kerb-to-kerb turning circle)
MARGIN = 0.2  # m the body keeps from the road's edges
SHIFT = 4.0  # m of road per metre moved across before and after the half circle
MIN_SHIFT = 8.0  # m: the shortest move across
TANGENT = 5.0  # m either side over which the band's direction is measured (curved roads)


@dataclass(frozen=True)
class Band:
    """A road across: `base` runs along its right-most lane (in the car's first direction of
    travel), d is metres to the left of that lane's centre, from `right` to `left` (its edges)."""

    base: Polyline
    right: float
    left: float

    @classmethod
    def across(cls, own: Sequence[LaneInfo], other: Sequence[LaneInfo]) -> Band:
        """The road whose lanes in the car's direction are `own` (right-most first), `other` the rest."""
        right = -own[0].width / 2.0
        width = sum(lane.width for lane in own) + sum(lane.width for lane in other)
        return cls(Polyline(own[0].shape), right, right + width)

    def _axes(self, s: float) -> tuple[Point, Point, Point]:
        """The base's point at s (clamped), its direction and its left normal there."""
        a = self.base.point(s - TANGENT)
        b = self.base.point(s + TANGENT)
        h = math.degrees(math.atan2(b[0] - a[0], b[1] - a[1]))
        return self.base.point(s), unit(h), unit(h - 90.0)

    def at(self, s: float, d: float) -> Point:
        """The point d to the left of the base at arc length s (straight on past its ends)."""
        inside = min(max(s, 0.0), self.base.length)
        q, f, n = self._axes(inside)
        extra = s - inside
        return (q[0] + extra * f[0] + d * n[0], q[1] + extra * f[1] + d * n[1])

    def place(self, p: Point) -> tuple[float, float]:
        """(s, d) of a point."""
        s, _ = self.base.project(p)
        q, f, n = self._axes(s)
        v = (p[0] - q[0], p[1] - q[1])
        along = v[0] * f[0] + v[1] * f[1]
        return s + (along if s <= 1e-9 or s >= self.base.length - 1e-9 else 0.0), v[0] * n[0] + v[1] * n[1]


@dataclass(frozen=True)
class Layout:
    radius: float
    d0: float  # across the road, where the half circle begins
    d1: float  # where it ends, facing back
    fits: bool  # the body stays on the road with MARGIN to spare


def _start_range(band: Band, radius: float, body: Body) -> tuple[float, float]:
    """Where across the road a half circle of `radius` may begin: its rear swing keeps off the
    right edge, its far side off the left edge."""
    half = body.width / 2.0
    low = band.right + MARGIN - radius + math.hypot(radius + half, body.length)
    high = band.left - MARGIN - half - 2.0 * radius
    return low, high


def layout(band: Band, d_from: float, d_to: float, body: Body) -> Layout:
    """The roundest half circle from lane position `d_from` towards `d_to` that fits the road."""
    natural = max(abs(d_to - d_from) / 2.0, MIN_RADIUS)
    low, high = _start_range(band, MIN_RADIUS, body)
    if low > high:  # too narrow even at the tightest: overhang both edges alike
        d0 = (low + high) / 2.0
        return Layout(MIN_RADIUS, d0, d0 + 2.0 * MIN_RADIUS, False)
    lo, hi = MIN_RADIUS, natural
    if _fits(band, hi, body):
        lo = hi
    for _ in range(30):  # the widest radius up to the natural one whose start range is not empty
        mid = (lo + hi) / 2.0
        lo, hi = (mid, hi) if _fits(band, mid, body) else (lo, mid)
    low, high = _start_range(band, lo, body)
    d0 = min(max(d_from, low), high)
    return Layout(lo, d0, d0 + 2.0 * lo, True)


def _fits(band: Band, radius: float, body: Body) -> bool:
    low, high = _start_range(band, radius, body)
    return low <= high


def u_turn_line(
    band: Band, line: Polyline, at: float, target: Polyline, d_to: float, plan: Layout
) -> tuple[Polyline, float]:
    """The turn from `line` at arc length `at` onto `target` (a lane running the new way, at
    `d_to` across the band): the move across, the half circle, the move to the lane. Also the
    arc length within the turn where the half circle ends."""
    s_a, d_a = band.place(line.point(at))
    before = _move(band, s_a, d_a, plan.d0, forward=True)
    centre, d0 = (before[-1][0], plan.d0) if before else (s_a, d_a)
    theta = np.linspace(0.0, math.pi, 25)
    middle = (centre + plan.radius * np.sin(theta), d0 + plan.radius * (1.0 - np.cos(theta)))
    arc = [band.at(float(s), float(d)) for s, d in zip(*middle, strict=True)]
    after = _move(band, centre, d0 + 2.0 * plan.radius, d_to, forward=False)
    head = [band.at(s, d) for s, d in before[1:-1]]
    turn = Polyline([line.point(at), *head, *arc[0 if before else 1 :]])
    arc_end = turn.length
    tail = [band.at(s, d) for s, d in after[1:]]
    joined = tail[-1] if tail else arc[-1]
    s_t = target.project(joined)[0]
    rest = target.sub(s_t, target.length).points if target.length - s_t > 0.5 else target.points[-1:]
    return Polyline(np.vstack([turn.points, np.asarray(tail).reshape(-1, 2), rest])), arc_end


def _move(band: Band, s: float, d_from: float, d_to: float, *, forward: bool) -> list[tuple[float, float]]:
    """(s, d) points of a smooth move across from d_from to d_to, going forward or back along
    the band from s (empty when there is nothing to move)."""
    gap = abs(d_to - d_from)
    if gap < 0.05:
        return []
    length = max(MIN_SHIFT, SHIFT * gap)
    count = max(3, math.ceil(length) + 1)
    out = []
    for w in np.linspace(0.0, 1.0, count):
        smooth = w * w * (3.0 - 2.0 * w)
        out.append((s + (length if forward else -length) * w, d_from + (d_to - d_from) * smooth))
    return out


def footprint(line: Polyline, band: Band, body: Body, step: float = 0.5) -> tuple[float, float]:
    """The least and the greatest d any corner of the body reaches while its front bumper
    follows `line` (heading along it): the road is [band.right, band.left]."""
    low, high = math.inf, -math.inf
    for s in np.arange(0.0, line.length, step):
        front = line.point(float(s))
        f = unit(line.heading(float(s)))
        left = (-f[1], f[0])
        for back in (0.0, body.length):
            for side in (-body.width / 2.0, body.width / 2.0):
                corner = (front[0] - back * f[0] + side * left[0], front[1] - back * f[1] + side * left[1])
                d = band.place(corner)[1]
                low, high = min(low, d), max(high, d)
    return low, high
