"""Time to collision between moving bodies, approximated by discs (the FMU oracle's near misses).

A pose is (x, y, compass heading) of the map's reference point: the front-bumper centre of a
vehicle, the centre of a pedestrian. Whether two bodies overlap, and their corners, are the
geometry kernel's (compiler/geometry/bodies.py); the discs here only estimate how soon they may.
"""

from __future__ import annotations

import math

import numpy as np
from sovarc.compiler.vehicles import Body

TTC_HORIZON = 5.0  # s: beyond this, no collision is imminent
TICK = 0.1  # s between predicted poses


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
