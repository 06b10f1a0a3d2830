"""A long body's heading as its front follows a path: the rear axle trails, cutting inside a bend."""

from __future__ import annotations

import math

import numpy as np
import pytest
from sovarc.compiler.geometry.trailing import trailing_headings


def _circle(radius: float, degrees: float, step: float = 0.2) -> np.ndarray:
    """A right-hand circle from (0, 0) facing north, about the centre (radius, 0)."""
    angles = np.radians(np.arange(0.0, degrees, math.degrees(step / radius)))
    return np.column_stack([radius - radius * np.cos(angles), radius * np.sin(angles)])


def test_on_a_straight_path_the_body_faces_along_it() -> None:
    points = np.column_stack([np.zeros(50), np.arange(50.0)])
    assert np.allclose(trailing_headings(points, 0.0, 8.0), 0.0)


@pytest.mark.parametrize(("radius", "reach"), [(9.0, 6.0), (11.5, 8.9), (20.0, 3.6)])
def test_on_a_long_circle_it_settles_where_the_rear_axle_runs_inside(radius: float, reach: float) -> None:
    """Steady turning: the rear axle circles the same centre at sqrt(R^2 - reach^2), so the body
    faces atan(reach / that) less far round than the front's path."""
    points = _circle(radius, 720.0)
    headings = trailing_headings(points, 0.0, reach)
    x, y = points[-1]
    tangent = (math.degrees(math.atan2(x - radius, y)) + 90.0) % 360.0  # clockwise: the outward radius turned right
    lag = math.degrees(math.atan2(reach, math.sqrt(radius**2 - reach**2)))
    assert (tangent - headings[-1]) % 360.0 == pytest.approx(lag, abs=0.5)


def test_the_rear_axle_cuts_inside_the_front_path_and_never_outside() -> None:
    radius, reach = 11.5, 8.9
    points = _circle(radius, 90.0)
    headings = np.radians(trailing_headings(points, 0.0, reach))
    rear = points - reach * np.column_stack([np.sin(headings), np.cos(headings)])
    from_centre = np.hypot(rear[:, 0] - radius, rear[:, 1])
    assert from_centre.max() <= math.hypot(radius, reach) + 1e-6  # it starts straight behind the front
    assert from_centre[-1] < radius - 2.0  # by the end of a quarter turn it runs metres inside
