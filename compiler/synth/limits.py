"""The fastest a vehicle can drive along its path, with TOPP-RA.

TOPP-RA's time-optimal parametrization under a speed limit and acceleration limits gives,
at each point of the path, the highest speed reachable from the start speed that still
lets the vehicle end at its end speed. A planned profile is drivable when it stays under
that envelope. The acceleration limits bound the x and y components of the acceleration,
so the longitudinal and the lateral (v^2 / radius in a curve) parts are both bounded.
"""

from __future__ import annotations

import logging

import numpy as np
import toppra
import toppra.algorithm
import toppra.constraint

ACCEL_LIMIT = 4.5  # m/s^2 per axis: firm braking, and a sharp but possible turn
GRID = 60  # gridpoints along the path

logging.getLogger("toppra").setLevel(logging.ERROR)


def envelope(points: np.ndarray, speed_limit: float, v_start: float, v_end: float) -> tuple[np.ndarray, np.ndarray]:
    """(arc lengths, highest drivable speed at each) along the polyline `points` (N x 2)."""
    s = np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(points, axis=0).T))))
    if len(s) < 3 or s[-1] < 1.0:
        return s, np.full(len(s), speed_limit)
    path = toppra.SplineInterpolator(s, points)
    vlim = np.array([[-speed_limit, speed_limit]] * 2)
    alim = np.array([[-ACCEL_LIMIT, ACCEL_LIMIT]] * 2)
    constraints = [toppra.constraint.JointVelocityConstraint(vlim), toppra.constraint.JointAccelerationConstraint(alim)]
    grid = np.linspace(0.0, s[-1], GRID)
    instance = toppra.algorithm.TOPPRA(constraints, path, gridpoints=grid, parametrizer="ParametrizeConstAccel")
    result = instance.compute_parameterization(min(v_start, speed_limit), min(v_end, speed_limit))
    sd = result[1]
    if sd is None or len(sd) != len(grid):
        return grid, np.full(len(grid), np.nan)  # infeasible: no profile reaches the end speed
    return grid, np.asarray(sd)


def worst_ratio(points: np.ndarray, speeds: np.ndarray, speed_limit: float) -> float:
    """The largest planned speed over the envelope's speed along a driven polyline (1.0 = at the limit)."""
    keep = np.concatenate(([True], np.hypot(*np.diff(points, axis=0).T) > 1e-3))
    points, speeds = points[keep], speeds[keep]
    grid, top = envelope(points, speed_limit, float(speeds[0]), float(speeds[-1]))
    if np.isnan(top).any():
        return float("inf")
    s = np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(points, axis=0).T))))
    planned = np.interp(grid, s, speeds)
    return float(np.max(planned / np.maximum(top, 0.5)))
