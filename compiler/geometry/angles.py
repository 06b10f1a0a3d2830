"""Angles, with one convention and unit for all of sovarc: compass degrees.

0 = north (+y), 90 = east (+x), clockwise, in [0, 360). A target whose own frame is another
(OpenSCENARIO: radians counter-clockwise from +x) converts at its boundary and still calls these.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np


def compass(dx: float, dy: float) -> float:
    """The compass heading of the direction (dx, dy)."""
    return math.degrees(math.atan2(dx, dy)) % 360.0


def angle_diff(a: float, b: float) -> float:
    """Signed smallest difference a - b, in (-180, 180]."""
    d = (a - b) % 360.0
    return d - 360.0 if d > 180.0 else d


def angle_diffs(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """`angle_diff` element-wise: signed a - b in (-180, 180]."""
    d = (a - b) % 360.0
    return np.where(d > 180.0, d - 360.0, d)


def circular_mean(angles: Sequence[float]) -> float:
    x = sum(math.sin(math.radians(a)) for a in angles)
    y = sum(math.cos(math.radians(a)) for a in angles)
    return compass(x, y)


def heading_vector(heading: float) -> tuple[float, float]:
    """The unit vector of a compass heading."""
    rad = math.radians(heading)
    return (math.sin(rad), math.cos(rad))
