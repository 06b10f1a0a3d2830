"""TOPP-RA's envelope (limits.py) on hand-made paths: a drivable profile is under it, one too
fast for a turn or a stop is over it by a finite ratio, wherever the judged stretch is cut."""

from __future__ import annotations

import math

import numpy as np
import pytest
from sovarc.compiler.synth.limits import ACCEL_LIMIT, worst_ratio

FINE = 0.01  # m; the curve is integrated this finely, then sampled every metre as synth does
CONTEXT = 6  # points of path past the judged stretch


def _path(*pieces: tuple[float, float]) -> np.ndarray:
    """Points 1 m apart along (length, curvature) pieces, from the origin heading east."""
    curvature = np.concatenate([np.full(round(length / FINE), k) for length, k in pieces])
    yaw = np.concatenate(([0.0], np.cumsum(curvature) * FINE))
    steps = np.column_stack((np.cos(yaw[:-1]), np.sin(yaw[:-1]))) * FINE
    points = np.vstack(([0.0, 0.0], np.cumsum(steps, axis=0)))
    return points[:: round(1.0 / FINE)]


def _at_speed(fraction: float, radius: float) -> float:
    """The speed whose lateral acceleration in a turn of `radius` is `fraction` of the limit."""
    return math.sqrt(fraction * ACCEL_LIMIT * radius)


def test_a_stretch_cut_just_inside_a_turn_is_judged_by_the_turn() -> None:
    """An S-bend of 5 m radius cut 2 m into its second turn, driven at 3/4 of the lateral limit.
    Before, the spline through the stretch alone bent at its cut end twice as tight as the
    turn, so no profile could end at the planned speed: 'inf times what its path allows'. The
    points past the stretch (as synth passes them) keep its end true to the path."""
    radius = 5.0
    points = _path((30.0, 0.0), (3.0, 1.0 / radius), (20.0, -1.0 / radius))
    driven = 30 + 3 + 2 + 1
    v = _at_speed(0.75, radius)
    assert worst_ratio(points[: driven + CONTEXT], np.full(driven, v), 1.05 * v) <= 1.01


def test_a_speed_the_whole_path_allows_is_under_the_envelope_everywhere() -> None:
    """An S-bend of 4 m radius at 85% of the lateral limit: a constant speed is drivable. Before,
    the envelope was TOPP-RA's one time-optimal profile, which on its grid dipped to 1/1.14 of
    that speed between the turns."""
    radius = 4.0
    points = _path((30.0, 0.0), (8.0, 1.0 / radius), (20.0, -1.0 / radius))
    driven = 30 + 8 + 8 + 1
    v = _at_speed(0.85, radius)
    assert worst_ratio(points[:driven], np.full(driven, v), 1.05 * v) <= 1.01


def test_an_end_too_fast_for_its_turn_is_over_by_a_finite_ratio() -> None:
    """Ending inside a 5 m turn at 1.35 times the lateral limit: over the envelope by about
    the square root of that (the acceleration grows with the square of the speed), not 'inf'."""
    radius = 5.0
    points = _path((30.0, 0.0), (40.0, 1.0 / radius))
    v = _at_speed(1.35, radius)
    ratio = worst_ratio(points[:60], np.full(60, v), 1.05 * v)
    assert ratio == pytest.approx(math.sqrt(1.35), rel=0.05)


def test_a_stop_too_sudden_is_still_over_the_envelope() -> None:
    points = _path((70.0, 0.0))
    speeds = np.full(50, 10.0)
    speeds[-5:] = np.linspace(10.0, 0.0, 5)  # 10 m/s to rest in 4 m: 12.5 m/s^2
    assert worst_ratio(points[:50], speeds, 10.5) > 1.5
