"""The way a long body faces as its front follows a path: its rear axle trails behind.

A vehicle's rear axle moves along its body's axis (its wheels do not slide sideways), so as the
front bumper follows a path, the rear axle, a fixed `reach` behind it on the axis, follows the
path's tractrix: at each step it moves straight towards where the front now is, staying `reach`
from it. The body faces from the rear axle to the front. In a turn the rear cuts inside the front's
path (a 12 m bus on a 9 m bend faces tens of degrees less far round than the path), where a body
laid along the path's own direction would swing its rear out over the outside of the bend.
"""

from __future__ import annotations

import math

import numpy as np

STEP = 0.05  # m: the most the front moves in one step of the tractrix


def trailing_headings(points: np.ndarray, first: float, reach: float) -> np.ndarray:
    """The compass heading of the body at each of `points` (n x 2, its front bumper moving forwards
    through them), the body facing `first` at the first point, its rear axle `reach` metres behind."""
    rad = math.radians(first)
    rear = np.asarray(points[0], dtype=float) - reach * np.array([math.sin(rad), math.cos(rad)])
    headings = np.empty(len(points))
    headings[0] = first % 360.0
    for k in range(1, len(points)):
        a, b = np.asarray(points[k - 1], dtype=float), np.asarray(points[k], dtype=float)
        steps = max(1, math.ceil(math.dist(a, b) / STEP))
        for u in np.linspace(1.0 / steps, 1.0, steps):
            front = a + u * (b - a)
            d = front - rear
            rear = front - reach * d / max(math.hypot(d[0], d[1]), 1e-9)
        d = points[k] - rear
        headings[k] = math.degrees(math.atan2(d[0], d[1])) % 360.0
    return headings
