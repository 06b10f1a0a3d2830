"""Plane geometry for maps: compass headings of polylines, and fitting arms to a compass cross.

Compass degrees: 0 = north (+y), 90 = east (+x), clockwise, in [0, 360).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

Point = tuple[float, float]
Shape = tuple[Point, ...]

# How far along a lane its direction at a junction is measured: long enough to skip
# the rounded corner netconvert adds, short enough for a curved road.
TAIL_M = 20.0


def compass(dx: float, dy: float) -> float:
    return math.degrees(math.atan2(dx, dy)) % 360.0


def angle_diff(a: float, b: float) -> float:
    """Signed smallest difference a - b, in (-180, 180]."""
    d = (a - b) % 360.0
    return d - 360.0 if d > 180.0 else d


def angle_diffs(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """`angle_diff` element-wise: signed a - b in (-180, 180]."""
    d = (a - b) % 360.0
    return np.where(d > 180.0, d - 360.0, d)


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


def circular_mean(angles: Sequence[float]) -> float:
    x = sum(math.sin(math.radians(a)) for a in angles)
    y = sum(math.cos(math.radians(a)) for a in angles)
    return compass(x, y)


@dataclass(frozen=True)
class Frame:
    """A compass cross laid over a site: arm i sits in `slots[i]` (0..3), whose ideal
    heading is `orientation + 90 * slot`; `error` is the worst arm's distance from it."""

    orientation: float  # in [-45, 45)
    slots: tuple[int, ...]
    error: float


def fit_frame(headings: Sequence[float]) -> Frame:
    """The cross (up to four arms, each in its own slot, clockwise order kept) that fits best.

    Keeping the clockwise order means left stays left and right stays right; the best fit is
    the one with the least squared angular error, ties broken by enumeration order.
    """
    count = len(headings)
    if not 1 <= count <= 4:
        raise ValueError(f"a compass cross has 1 to 4 arms, not {count}")
    order = sorted(range(count), key=lambda i: (headings[i], i))
    best: tuple[float, Frame] | None = None
    for chosen in itertools.combinations(range(4), count):
        for shift in range(count):
            slots = [0] * count
            for rank, arm in enumerate(order):
                slots[arm] = chosen[(rank + shift) % count]
            offsets = [headings[i] - 90.0 * slots[i] for i in range(count)]
            centre = circular_mean(offsets)
            errors = [abs(angle_diff(o, centre)) for o in offsets]
            score = sum(e * e for e in errors)
            if best is None or score < best[0] - 1e-9:
                best = (score, _normalized(centre, slots, max(errors)))
    assert best is not None
    return best[1]


def _normalized(orientation: float, slots: list[int], error: float) -> Frame:
    # Pick the multiple of 90 that brings the orientation into [-45, 45) and renumber the slots.
    turns = math.floor((orientation + 45.0) / 90.0)
    orientation -= 90.0 * turns
    return Frame(round(orientation, 6), tuple((s + turns) % 4 for s in slots), round(error, 6))
