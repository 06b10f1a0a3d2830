"""A polyline with arc length: the ego's route, and the paths of random NPCs.

Headings are compass degrees (0 = north, +y; 90 = east, +x), as everywhere in sovarc.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

Point = tuple[float, float]


def compass(dx: float, dy: float) -> float:
    """The compass heading of a direction vector."""
    return math.degrees(math.atan2(dx, dy)) % 360.0


class Polyline:
    """Points joined by straight segments, parametrised by arc length s from the first point."""

    def __init__(self, points: Sequence[Point], *, min_gap: float = 0.05) -> None:
        kept: list[Point] = []
        for p in points:
            if not kept or math.dist(kept[-1], p) > min_gap:
                kept.append((float(p[0]), float(p[1])))
        if len(kept) < 2:
            raise ValueError("a polyline needs two distinct points")
        self.xy = np.array(kept)
        seg = np.diff(self.xy, axis=0)
        self.seg_len = np.hypot(seg[:, 0], seg[:, 1])
        self.s = np.concatenate(([0.0], np.cumsum(self.seg_len)))
        self.dir = seg / self.seg_len[:, None]

    @property
    def length(self) -> float:
        return float(self.s[-1])

    def _index(self, s: float) -> int:
        return int(min(max(np.searchsorted(self.s, s, side="right") - 1, 0), len(self.seg_len) - 1))

    def point_at(self, s: float) -> Point:
        """The point at arc length s; past either end the line goes on straight."""
        k = self._index(s)
        u = s - self.s[k]
        return (float(self.xy[k, 0] + u * self.dir[k, 0]), float(self.xy[k, 1] + u * self.dir[k, 1]))

    def points_at(self, s: np.ndarray) -> np.ndarray:
        k = np.clip(np.searchsorted(self.s, s, side="right") - 1, 0, len(self.seg_len) - 1)
        u = s - self.s[k]
        return self.xy[k] + u[:, None] * self.dir[k]

    def headings_at(self, s: np.ndarray) -> np.ndarray:
        """Compass headings at arc lengths s (any shape)."""
        k = np.clip(np.searchsorted(self.s, s, side="right") - 1, 0, len(self.seg_len) - 1)
        return np.degrees(np.arctan2(self.dir[k, 0], self.dir[k, 1])) % 360.0

    def heading_at(self, s: float) -> float:
        k = self._index(s)
        return compass(float(self.dir[k, 0]), float(self.dir[k, 1]))

    def project(self, p: Point, lo: float = -math.inf, hi: float = math.inf) -> tuple[float, float]:
        """(s, distance) of the point of the line nearest to p, among arc lengths in [lo, hi]."""
        first, last = self._index(lo) if lo > 0 else 0, self._index(hi) if hi < self.length else len(self.seg_len) - 1
        a, d, n = self.xy[first : last + 1], self.dir[first : last + 1], self.seg_len[first : last + 1]
        rel = np.array(p) - a
        u = np.clip(np.einsum("ij,ij->i", rel, d), 0.0, n)
        if first == 0:  # before the start, the line goes on straight
            u[0] = min(float(rel[0] @ d[0]), float(n[0]))
        if last == len(self.seg_len) - 1:  # and past the end
            u[-1] = max(float(rel[-1] @ d[-1]), 0.0)
        dist = np.hypot(*(rel - u[:, None] * d).T)
        best = int(np.argmin(dist))
        s = float(self.s[first + best] + u[best])
        return min(max(s, lo), hi), float(dist[best])

    def extended(self, extra: float, towards: Sequence[Point] = ()) -> Polyline:
        """This line, then `towards` (points beyond the end, e.g. a lane's centre line), then straight on."""
        points = [tuple(p) for p in self.xy] + [tuple(p) for p in towards]
        tail = Polyline(points)
        end, heading = tail.point_at(tail.length), tail.heading_at(tail.length)
        rad = math.radians(heading)
        points.append((end[0] + extra * math.sin(rad), end[1] + extra * math.cos(rad)))
        return Polyline(points)
