"""The road frame (s, d): s along a base line (the right-most lane of a road, in the direction
of travel), d metres to the left of it. Manoeuvres across a road (U-turns, turns in legs) are
laid out in it, and a body's reach across the road is measured in it.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

from sovarc.compiler.geometry.angles import compass, heading_vector
from sovarc.compiler.geometry.polyline import Point, Polyline

TANGENT = 5.0  # m either side over which the band's direction is measured (curved roads)


class Lane(Protocol):
    """What a band needs of a lane: its centre line and its width (maps.LaneInfo has both)."""

    @property
    def shape(self) -> Sequence[Point]: ...

    @property
    def width(self) -> float: ...


@dataclass(frozen=True)
class Band:
    """A road across: `base` runs along its right-most lane (in the car's first direction of
    travel), d is metres to the left of that lane's centre, from `right` to `left` (its edges)."""

    base: Polyline
    right: float
    left: float

    @classmethod
    def across(cls, own: Sequence[Lane], other: Sequence[Lane], median: float = 0.0) -> Band:
        """The road whose lanes in the car's direction are `own` (right-most first), `other` the rest,
        with `median` metres of open ground between the two (0: their lanes lie side by side)."""
        right = -own[0].width / 2.0
        width = sum(lane.width for lane in own) + median + sum(lane.width for lane in other)
        return cls(Polyline(own[0].shape), right, right + width)

    def _axes(self, s: float) -> tuple[Point, Point, Point]:
        """The base's point at s (clamped), its direction and its left normal there."""
        a = self.base.point(s - TANGENT)
        b = self.base.point(s + TANGENT)
        h = math.degrees(math.atan2(b[0] - a[0], b[1] - a[1]))
        return self.base.point(s), heading_vector(h), heading_vector(h - 90.0)

    def at(self, s: float, d: float) -> Point:
        """The point d to the left of the base at arc length s (straight on past its ends)."""
        inside = min(max(s, 0.0), self.base.length)
        q, f, n = self._axes(inside)
        extra = s - inside
        return (q[0] + extra * f[0] + d * n[0], q[1] + extra * f[1] + d * n[1])

    def heading(self, s: float) -> float:
        """The compass heading of the band's direction at arc length s (clamped to the base)."""
        _, f, _ = self._axes(min(max(s, 0.0), self.base.length))
        return compass(f[0], f[1])

    def place(self, p: Point) -> tuple[float, float]:
        """(s, d) of a point."""
        s, _ = self.base.project(p)
        q, f, n = self._axes(s)
        v = (p[0] - q[0], p[1] - q[1])
        along = v[0] * f[0] + v[1] * f[1]
        return s + (along if s <= 1e-9 or s >= self.base.length - 1e-9 else 0.0), v[0] * n[0] + v[1] * n[1]

    def d_abreast(self, line: Polyline, p: Point) -> float:
        """The d of `line` (a lane's centre) where it is abreast of the point p."""
        return self.place(line.point(line.project(p)[0]))[1]
