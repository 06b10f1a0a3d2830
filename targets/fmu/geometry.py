"""Bodies on the ground: overlap of two oriented rectangles, and time to collision between moving bodies.

A pose is (x, y, compass heading) of the map's reference point: the front-bumper centre of a
vehicle, the centre of a pedestrian.
"""

from __future__ import annotations

import math

import numpy as np
from sovarc.compiler.plan import Body

TTC_HORIZON = 5.0  # s: beyond this, no collision is imminent
TICK = 0.1  # s between predicted poses


def centre(x: float, y: float, heading: float, body: Body) -> tuple[float, float]:
    """The centre of a body whose reference point is at (x, y)."""
    if body.vclass == "pedestrian":
        return (x, y)
    rad = math.radians(heading)
    back = body.length / 2.0
    return (x - back * math.sin(rad), y - back * math.cos(rad))


def corners(x: float, y: float, heading: float, body: Body) -> list[tuple[float, float]]:
    cx, cy = centre(x, y, heading, body)
    rad = math.radians(heading)
    fx, fy = math.sin(rad), math.cos(rad)  # forward
    rx, ry = fy, -fx  # right
    hl, hw = body.length / 2.0, body.width / 2.0
    return [
        (cx + a * hl * fx + b * hw * rx, cy + a * hl * fy + b * hw * ry)
        for a, b in ((1, 1), (1, -1), (-1, -1), (-1, 1))
    ]


def overlap(a: list[tuple[float, float]], b: list[tuple[float, float]]) -> bool:
    """Two convex quadrilaterals overlap (separating-axis test; touching counts)."""
    for poly in (a, b):
        for k in range(4):
            (x1, y1), (x2, y2) = poly[k], poly[(k + 1) % 4]
            nx, ny = y2 - y1, x1 - x2
            pa = [nx * x + ny * y for x, y in a]
            pb = [nx * x + ny * y for x, y in b]
            if max(pa) < min(pb) or max(pb) < min(pa):
                return False
    return True


def _discs(cx: np.ndarray, cy: np.ndarray, heading: np.ndarray, body: Body) -> tuple[np.ndarray, np.ndarray, float]:
    """Three discs along a body that together cover it: centres (..., 3) and the radius."""
    rad = np.radians(heading)
    offsets = np.array([-1.0, 0.0, 1.0]) * body.length / 3.0
    radius = math.hypot(body.length / 6.0, body.width / 2.0)
    return cx[..., None] + offsets * np.sin(rad)[..., None], cy[..., None] + offsets * np.cos(rad)[..., None], radius


Future = tuple[np.ndarray, np.ndarray, np.ndarray]  # x, y, heading of a reference point: (steps, ticks)


def ticks() -> np.ndarray:
    """The times ahead at which bodies are predicted: 0, TICK, ... TTC_HORIZON."""
    return np.arange(0.0, TTC_HORIZON + TICK / 2.0, TICK)


def straight_on(x: np.ndarray, y: np.ndarray, heading: np.ndarray, speed: np.ndarray) -> Future:
    """Per step, where a body will be at each tick if it keeps its velocity."""
    ahead = speed[:, None] * ticks()[None, :]
    rad = np.radians(heading)[:, None]
    shape = ahead.shape
    return x[:, None] + ahead * np.sin(rad), y[:, None] + ahead * np.cos(rad), np.broadcast_to(heading[:, None], shape)


def time_to_collision(a: Future, body_a: Body, b: Future, body_b: Body) -> np.ndarray:
    """Per step, the first tick at which bodies a and b, moving as predicted, touch (inf: not within
    TTC_HORIZON). Each body is covered by three discs, so bodies "touch" a little before their boxes do."""
    pax, pay, ra = _discs(*_centres(a[0], a[1], a[2], body_a), a[2], body_a)
    pbx, pby, rb = _discs(*_centres(b[0], b[1], b[2], body_b), b[2], body_b)
    dx = pax[..., :, None] - pbx[..., None, :]
    dy = pay[..., :, None] - pby[..., None, :]
    touching = ((dx * dx + dy * dy) < (ra + rb) ** 2).any(axis=(2, 3))  # (steps, ticks)
    first = np.argmax(touching, axis=1)
    return np.where(touching.any(axis=1), ticks()[first], np.inf)


def _centres(x: np.ndarray, y: np.ndarray, heading: np.ndarray, body: Body) -> tuple[np.ndarray, np.ndarray]:
    if body.vclass == "pedestrian":
        return x, y
    rad = np.radians(heading)
    back = body.length / 2.0
    return x - back * np.sin(rad), y - back * np.cos(rad)
