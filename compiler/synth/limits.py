"""The fastest a vehicle can drive along its path, with TOPP-RA.

TOPP-RA's reachability analysis gives, at each point of the path, the speeds reachable from
a start no faster than the planned one, and the speeds from which the path can still be left
no faster than planned; the highest speed in both is the envelope. A planned profile is
drivable when it stays under it, and where it does not, the ratio says by how much, also at
an end driven faster than the path there allows. The acceleration limits bound the x and y
components of the acceleration, so the longitudinal and the lateral (v^2 / radius in a
curve) parts are both bounded.
"""

from __future__ import annotations

import functools
import logging
from typing import Any

import numpy as np
from sovarc.compiler.vehicles import PLANNED

ACCEL_LIMIT = PLANNED.plan_accel  # m/s^2 per axis, a car's: firm braking, and a sharp but possible turn
GRID = 60  # gridpoints along the path
SAME_POINT = 1e-3  # m; closer points are one (the spline needs increasing arc lengths)


@functools.cache
def _toppra() -> tuple[Any, type]:
    """toppra and the spline it judges, imported on first use: toppra imports scipy's interpolation and
    matplotlib's pyplot (1.5 s), which a process that only hands plans to workers never needs."""
    import toppra
    import toppra.algorithm
    import toppra.constraint

    logging.getLogger("toppra").setLevel(logging.ERROR)

    class Window(toppra.SplineInterpolator):  # type: ignore[misc]
        """A spline through all the points, of which TOPP-RA sees only `lo`..`hi`.

        A cubic spline cut off where a path is cut bends there as its last few points happen to
        lie, not as the path does: cut inside a turn, its end can curve twice as tight as the
        turn. Points past the judged stretch keep its ends true to the path.
        """

        def __init__(self, s: np.ndarray, points: np.ndarray, lo: float, hi: float) -> None:
            super().__init__(s, points)
            self._interval = np.array([lo, hi])

        @property
        def path_interval(self) -> np.ndarray:
            return self._interval

    return toppra, Window


def arc_lengths(points: np.ndarray) -> np.ndarray:
    return np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(points, axis=0).T))))


def envelope(
    points: np.ndarray,
    speed_limit: float,
    v_start: float,
    v_end: float,
    within: tuple[float, float] | None = None,
    accel_limit: float = ACCEL_LIMIT,
) -> tuple[np.ndarray, np.ndarray]:
    """(arc lengths, highest drivable speed at each) along the polyline `points` (N x 2), of the
    profiles that start no faster than `v_start` and end no faster than `v_end`, judged between
    the arc lengths `within` (default: all of it). NaN only when TOPP-RA's solver fails."""
    s = arc_lengths(points)
    keep = np.concatenate(([True], np.diff(s) > SAME_POINT))
    s, points = s[keep], points[keep]
    lo, hi = within if within is not None else (float(s[0]), float(s[-1]))
    if len(s) < 3 or hi - lo < 1.0:
        return np.array([lo, hi]), np.full(2, speed_limit)
    vlim = np.array([[-speed_limit, speed_limit]] * 2)
    alim = np.array([[-accel_limit, accel_limit]] * 2)
    toppra, window = _toppra()
    constraints = [toppra.constraint.JointVelocityConstraint(vlim), toppra.constraint.JointAccelerationConstraint(alim)]
    grid = np.linspace(lo, hi, GRID)
    instance = toppra.algorithm.TOPPRA(constraints, window(s, points, lo, hi), gridpoints=grid)
    # Squared speeds, point by point: the time-optimal profile is just one profile, and on a
    # coarse grid it can dip below speeds other profiles drive there. Ends bounded above only
    # (standing still is always possible), so a start or end too fast for the path shows as
    # a ratio over 1 there rather than as no envelope at all.
    reach = instance.compute_reachable_sets(0.0, min(v_start, speed_limit))
    control = instance.compute_controllable_sets(0.0, min(v_end, speed_limit))
    top = np.minimum(reach[:, 1], control[:, 1])
    return grid, np.sqrt(np.maximum(top, 0.0))  # NaN stays NaN


def worst_ratio(
    points: np.ndarray, speeds: np.ndarray, speed_limit: float, first: int = 0, accel_limit: float = ACCEL_LIMIT
) -> float:
    """The largest planned speed over the envelope's speed along a driven polyline (1.0 = at the limit).

    `speeds` are those at points[first : first + len(speeds)]; any points around them are the
    path before and after the driven stretch, which only shape its ends."""
    s = arc_lengths(points)
    driven = s[first : first + len(speeds)]
    grid, top = envelope(points, speed_limit, float(speeds[0]), float(speeds[-1]), (driven[0], driven[-1]), accel_limit)
    if np.isnan(top).any():
        return float("inf")
    planned = np.interp(grid, driven, speeds)
    return float(np.max(planned / np.maximum(top, 0.5)))
