"""Polylines with arc length (the geometry routes, contact search, synthesis and the oracles
share), and helpers on plain shapes (sequences of points, as maps give lane shapes).

Headings are compass degrees (0 = north, clockwise), as everywhere in sovarc (angles.py).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Sequence

import numpy as np
from sovarc.compiler.geometry.angles import angle_diff, angle_diffs, compass, heading_vector

Point = tuple[float, float]
Shape = tuple[Point, ...]

# How far along a lane its direction at a junction is measured: long enough to skip
# the rounded corner netconvert adds, short enough for a curved road.
TAIL_M = 20.0


class Polyline:
    """An immutable polyline; `s` is the arc length at each vertex, from 0."""

    __slots__ = ("points", "s")

    def __init__(self, points: Sequence[Point] | np.ndarray, *, min_gap: float | None = None) -> None:
        """With `min_gap`, a point within that distance of the last one kept is dropped too (the FMU
        harness's paths through the samples of a slow car, whose tiny steps have no reliable direction)."""
        array = np.asarray(points, dtype=float).reshape(-1, 2)
        if min_gap is not None:
            array = array[_spaced(array, min_gap)]
        elif len(array) >= 2:  # drop repeated vertices: they have no direction
            keep = np.concatenate(([True], np.hypot(*np.diff(array, axis=0).T) > 1e-9))
            array = array[keep]
        if len(array) < 2:
            raise ValueError("a polyline needs two distinct points")
        self.points = array
        self.s = np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(array, axis=0).T))))

    @property
    def length(self) -> float:
        return float(self.s[-1])

    def point(self, s: float) -> Point:
        """The point at arc length s, clamped to the ends (`point_at` goes on past them)."""
        s = min(max(s, 0.0), self.length)
        return (float(np.interp(s, self.s, self.points[:, 0])), float(np.interp(s, self.s, self.points[:, 1])))

    def heading(self, s: float) -> float:
        """Direction of travel at arc length s (of the segment containing it)."""
        return float(self.headings(np.array([s]))[0])

    def point_at(self, s: float) -> Point:
        """The point at arc length s; past either end the line goes on straight."""
        x, y = self.points_at(np.array([s]))[0]
        return (float(x), float(y))

    def points_at(self, s: np.ndarray) -> np.ndarray:
        """`point_at` for many arc lengths (a 1-D array): n x 2."""
        k = self._segments(s)
        d = self.points[k + 1] - self.points[k]
        return self.points[k] + (s - self.s[k])[:, None] * (d / np.hypot(d[:, 0], d[:, 1])[:, None])

    def sub(self, start: float, end: float) -> Polyline:
        """The part between two arc lengths (start < end)."""
        start, end = max(start, 0.0), min(end, self.length)
        inner = self.points[(self.s > start) & (self.s < end)]
        return Polyline(np.vstack([self.point(start), inner, self.point(end)]))

    def reversed(self) -> Polyline:
        return Polyline(self.points[::-1])

    def resample(self, step: float) -> np.ndarray:
        """Points every `step` metres (and the last point)."""
        count = max(2, math.ceil(self.length / step) + 1)
        at = np.linspace(0.0, self.length, count)
        return np.column_stack((np.interp(at, self.s, self.points[:, 0]), np.interp(at, self.s, self.points[:, 1])))

    def smoothing(self, window: float = 6.0) -> tuple[Polyline, np.ndarray]:
        """The line resampled every metre and averaged over `window` metres (kinks where two lane
        shapes meet are rounded off, curves wider than the window keep their shape, ends stay
        put), and for each of its points the arc length on this line it comes from:
        np.interp(s, from_s, smooth.s) carries an arc length over (curves get shorter)."""
        points = self.resample(1.0)
        half = int(window // 2)
        if len(points) <= 2 * half + 1:
            return self, self.s
        from_s = np.linspace(0.0, self.length, len(points))
        kernel = np.ones(2 * half + 1) / (2 * half + 1)
        padded = np.vstack([np.repeat(points[:1], half, axis=0), points, np.repeat(points[-1:], half, axis=0)])
        smooth = np.column_stack([np.convolve(padded[:, i], kernel, mode="valid") for i in (0, 1)])
        smooth[0], smooth[-1] = points[0], points[-1]
        line = Polyline(smooth)
        if len(line.s) != len(from_s):  # a repeated point was dropped: carry over by proportion
            from_s = line.s * (self.length / line.length)
        return line, from_s

    def smoothing_except(self, keep: Sequence[tuple[float, float]], window: float = 6.0) -> tuple[Polyline, np.ndarray]:
        """`smoothing`, but the stretches `keep` (arc-length ranges, in order) stay as they are:
        the legs of a three-point turn are laid out exactly, corners at their stops and all."""
        if not keep:
            return self.smoothing(window)
        cuts = [0.0, *(x for stretch in keep for x in stretch), self.length]
        points: list[np.ndarray] = []
        from_s: list[np.ndarray] = []
        for k, (a, b) in enumerate(itertools.pairwise(cuts)):
            if b - a < 1e-6:
                continue
            part = self.sub(a, b)
            line, at = part.smoothing(window) if k % 2 == 0 else (part, part.s)
            first = 1 if points else 0  # each part begins where the one before ends
            points.append(line.points[first:])
            from_s.append(at[first:] + a)
        joined, carried = np.vstack(points), np.concatenate(from_s)
        keep_mask = np.concatenate(([True], np.hypot(*np.diff(joined, axis=0).T) > 1e-9))
        return Polyline(joined[keep_mask]), carried[keep_mask]

    def project(self, p: Point) -> tuple[float, float]:
        """(arc length of the closest point, distance to it)."""
        a, b = self.points[:-1], self.points[1:]
        ab = b - a
        lengths2 = np.maximum((ab**2).sum(axis=1), 1e-12)
        u = np.clip(((np.asarray(p) - a) * ab).sum(axis=1) / lengths2, 0.0, 1.0)
        closest = a + ab * u[:, None]
        d = np.hypot(*(closest - np.asarray(p)).T)
        k = int(np.argmin(d))
        return float(self.s[k] + u[k] * math.sqrt(lengths2[k])), float(d[k])

    def project_within(self, p: Point, lo: float = -math.inf, hi: float = math.inf) -> tuple[float, float]:
        """(s, distance) of the point nearest p among arc lengths in [lo, hi], the line going on straight
        past either end (`project` keeps to the line): the FMU harness follows a car along its route."""
        last_segment = len(self.s) - 2
        first = int(self._segments(lo)) if lo > 0 else 0
        last = int(self._segments(hi)) if hi < self.length else last_segment
        a = self.points[first : last + 1]
        step = self.points[first + 1 : last + 2] - a
        n = np.hypot(step[:, 0], step[:, 1])
        d = step / n[:, None]
        rel = np.array(p) - a
        u = np.clip(np.einsum("ij,ij->i", rel, d), 0.0, n)
        if first == 0:  # before the start, the line goes on straight
            u[0] = min(float(rel[0] @ d[0]), float(n[0]))
        if last == last_segment:  # and past the end
            u[-1] = max(float(rel[-1] @ d[-1]), 0.0)
        dist = np.hypot(*(rel - u[:, None] * d).T)
        best = int(np.argmin(dist))
        s = float(self.s[first + best] + u[best])
        return min(max(s, lo), hi), float(dist[best])

    def distances(self, points: np.ndarray) -> np.ndarray:
        """For each of `points` (n x 2), its distance to the line: `project` for many points at once."""
        return distances_to(self.points, points)

    def offset(self, lateral: float) -> Polyline:
        """The polyline shifted sideways, to the right of travel for positive `lateral`."""
        normals = _vertex_normals(self.points)
        return Polyline(self.points + lateral * normals)

    def curvature_radius(self, window: float = 6.0) -> np.ndarray:
        """Radius of curvature at each vertex, over a window of +-window/2 metres (inf if straight):
        the window's length over the turn between the headings at its two ends."""
        a = np.maximum(0.0, self.s - window / 2)
        b = np.minimum(self.length, self.s + window / 2)
        turn = np.abs(angle_diffs(self.headings(b - 1e-6), self.headings(a)))
        radii = np.full(len(self.s), np.inf)
        bent = (b - a >= 1.0) & (turn > 1e-3)
        radii[bent] = (b - a)[bent] / np.radians(turn[bent])
        return radii

    def headings(self, at: np.ndarray) -> np.ndarray:
        """`heading` at many arc lengths (an array of any shape): compass degrees of the segments containing them."""
        k = self._segments(at)
        d = self.points[k + 1] - self.points[k]
        return np.degrees(np.arctan2(d[..., 0], d[..., 1])) % 360.0

    def _segments(self, at: np.ndarray | float) -> np.ndarray:
        """The index of the segment containing each arc length (the first or last past the ends)."""
        return np.clip(np.searchsorted(self.s, at, side="right") - 1, 0, len(self.s) - 2)


def concat(parts: Iterable[Polyline]) -> Polyline:
    return Polyline(np.vstack([p.points for p in parts]))


def blend(first: Polyline, second: Polyline, start: float, end: float) -> Polyline:
    """Follow `first` until `start`, move smoothly across to `second` by `end`, then follow it.

    Both polylines run side by side (two lanes of one road); arc lengths are `first`'s.
    The sideways move follows a smoothstep, as a lane change does.
    """
    before = first.sub(0.0, start).points if start > 0.5 else first.points[:1]
    steps = np.linspace(start, end, max(3, math.ceil((end - start) / 2.0) + 1))
    middle = []
    for s in steps:
        w = (s - start) / (end - start)
        w = w * w * (3.0 - 2.0 * w)
        a = np.asarray(first.point(s))
        b = np.asarray(second.point(second.project(first.point(s))[0]))
        middle.append((1.0 - w) * a + w * b)
    tail_start = second.project(first.point(end))[0]
    after = second.sub(tail_start, second.length).points if second.length - tail_start > 0.5 else second.points[-1:]
    return Polyline(np.vstack([before, np.asarray(middle), after]))


def bezier(p0: Point, h0: float, p1: Point, h1: float, samples: int = 16, reach: float | None = None) -> Polyline:
    """A cubic curve leaving p0 in compass heading h0 and arriving at p1 in heading h1.

    `reach` is how far the control points lie along the two headings (default: a third of
    the chord); a U-turn, whose ends are close together, needs it longer to be round.
    """
    reach = math.dist(p0, p1) / 3.0 if reach is None else reach
    d0, d1 = heading_vector(h0), heading_vector(h1)
    c0 = (p0[0] + reach * d0[0], p0[1] + reach * d0[1])
    c1 = (p1[0] - reach * d1[0], p1[1] - reach * d1[1])
    u = np.linspace(0.0, 1.0, samples)[:, None]
    pts = (
        (1 - u) ** 3 * np.asarray(p0)
        + 3 * (1 - u) ** 2 * u * np.asarray(c0)
        + 3 * (1 - u) * u**2 * np.asarray(c1)
        + u**3 * np.asarray(p1)
    )
    return Polyline(pts)


def _spaced(points: np.ndarray, gap: float) -> list[int]:
    """The indices of the points kept when each one within `gap` of the last one kept is dropped."""
    rows = points.tolist()
    kept = [0] if rows else []
    for k in range(1, len(rows)):
        if math.dist(rows[kept[-1]], rows[k]) > gap:
            kept.append(k)
    return kept


def _vertex_normals(points: np.ndarray) -> np.ndarray:
    """Unit normals pointing to the right of travel, averaged at inner vertices."""
    d = np.diff(points, axis=0)
    d /= np.maximum(np.hypot(*d.T), 1e-12)[:, None]
    right = np.column_stack((d[:, 1], -d[:, 0]))
    normals = np.vstack([right[:1], (right[:-1] + right[1:]) / 2.0, right[-1:]])
    return normals / np.maximum(np.hypot(*normals.T), 1e-12)[:, None]


def shape_length(shape: Sequence[Point]) -> float:
    return sum(math.dist(p, q) for p, q in itertools.pairwise(shape))


def point_at(shape: Sequence[Point], s: float) -> Point:
    """The point at distance `s` along the polyline (clamped to its ends)."""
    if s <= 0.0:
        return shape[0]
    for p, q in itertools.pairwise(shape):
        step = math.dist(p, q)
        if step > 0.0 and s <= step:
            t = s / step
            return (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))
        s -= step
    return shape[-1]


def distances_to(shape: np.ndarray, points: np.ndarray) -> np.ndarray:
    """For each of `points` (n x 2), its shortest distance to the polyline `shape` (m x 2)."""
    a, ab = shape[:-1], shape[1:] - shape[:-1]
    lengths2 = np.maximum((ab**2).sum(axis=1), 1e-12)
    rel = points[:, None, :] - a[None, :, :]  # n x segments x 2
    u = np.clip((rel * ab[None, :, :]).sum(axis=2) / lengths2, 0.0, 1.0)
    gap = rel - ab[None, :, :] * u[:, :, None]
    return np.hypot(gap[:, :, 0], gap[:, :, 1]).min(axis=1)


def heading_between(p: Point, q: Point) -> float:
    return compass(q[0] - p[0], q[1] - p[1])


def end_heading(shape: Sequence[Point], tail: float = TAIL_M) -> float:
    """Direction of travel over the last `tail` metres of a polyline."""
    length = shape_length(shape)
    return heading_between(point_at(shape, max(0.0, length - tail)), shape[-1])


def start_heading(shape: Sequence[Point], tail: float = TAIL_M) -> float:
    """Direction of travel over the first `tail` metres of a polyline."""
    return heading_between(shape[0], point_at(shape, tail))


def max_offset_from_chord(shape: Sequence[Point]) -> float:
    """The largest distance of a shape point from the straight line through its ends."""
    (x0, y0), (x1, y1) = shape[0], shape[-1]
    chord = math.hypot(x1 - x0, y1 - y0)
    if chord == 0.0:
        return max((math.dist(shape[0], p) for p in shape), default=0.0)
    return max(abs((x1 - x0) * (y0 - y) - (x0 - x) * (y1 - y0)) / chord for x, y in shape)


def max_kink(shape: Sequence[Point]) -> float:
    """The sharpest change of direction between two successive segments, in degrees."""
    steps = [heading_between(p, q) for p, q in itertools.pairwise(shape) if math.dist(p, q) > 1e-6]
    return max((abs(angle_diff(b, a)) for a, b in itertools.pairwise(steps)), default=0.0)
