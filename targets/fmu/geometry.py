"""Bodies on the ground: overlap of two oriented rectangles, and time to collision between moving bodies.

A pose is (x, y, compass heading) of the map's reference point: the front-bumper centre of a
vehicle, the centre of a pedestrian.
"""

from __future__ import annotations

import math

import numpy as np
from sovarc.compiler.plan import Body

TTC_HORIZON = 10.0  # s: beyond this, no collision is imminent


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


def time_to_collision(
    a: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray],
    body_a: Body,
    b: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray],
    body_b: Body,
) -> np.ndarray:
    """Per step, the time until bodies a and b touch if both keep their velocity (inf: not within TTC_HORIZON).

    Each of a, b is (x, y, heading, speed) arrays of the reference point, one entry per step.
    """
    ax, ay, ah, av = a
    bx, by, bh, bv = b
    acx, acy = _centres(ax, ay, ah, body_a)
    bcx, bcy = _centres(bx, by, bh, body_b)
    pax, pay, ra = _discs(acx, acy, ah, body_a)
    pbx, pby, rb = _discs(bcx, bcy, bh, body_b)
    # relative position of every disc pair (steps, 3, 3) and relative velocity (steps, 1, 1)
    px = pax[:, :, None] - pbx[:, None, :]
    py = pay[:, :, None] - pby[:, None, :]
    vx = (av * np.sin(np.radians(ah)) - bv * np.sin(np.radians(bh)))[:, None, None]
    vy = (av * np.cos(np.radians(ah)) - bv * np.cos(np.radians(bh)))[:, None, None]
    reach = ra + rb
    qa = vx * vx + vy * vy
    qb = 2.0 * (px * vx + py * vy)
    qc = px * px + py * py - reach * reach
    disc = qb * qb - 4.0 * qa * qc
    with np.errstate(divide="ignore", invalid="ignore"):
        first = (-qb - np.sqrt(np.maximum(disc, 0.0))) / (2.0 * qa)
    ttc = np.where((disc >= 0.0) & (qa > 1e-9) & (first >= 0.0), first, np.inf)
    ttc = np.where(qc <= 0.0, 0.0, ttc)  # already touching
    ttc = ttc.min(axis=(1, 2))
    return np.where(ttc <= TTC_HORIZON, ttc, np.inf)


def _centres(x: np.ndarray, y: np.ndarray, heading: np.ndarray, body: Body) -> tuple[np.ndarray, np.ndarray]:
    if body.vclass == "pedestrian":
        return x, y
    rad = np.radians(heading)
    back = body.length / 2.0
    return x - back * np.sin(rad), y - back * np.cos(rad)
