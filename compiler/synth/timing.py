"""Jerk-limited timing with Ruckig, through the knots of the solved schedule.

The solver's schedule is a trapezoid speed profile per leg: ramp up from rest, cruise,
brake to rest, wait. Its corners are knots (t, s, v). Between two knots Ruckig computes a
jerk-limited profile that starts and ends at the knots' positions and speeds and lasts
exactly as long (its minimum-duration synchronization), so the impact knot is reached at
the solved instant by striker and victim alike. A piece Ruckig cannot fit in its time
keeps the trapezoid's constant acceleration, and the plan notes it.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
from ruckig import InputParameter, Result, Ruckig, RuckigError, Trajectory
from sovarc.compiler.lower.solve import LegValues
from sovarc.compiler.vehicles import PLANNED

MAX_ACCEL = PLANNED.plan_accel  # m/s^2 Ruckig may use inside a car's piece (the legs' own ramps shape the trapezoid)
MAX_JERK = 12.0  # m/s^3
RAMP_SLACK = 1.05  # of a reverse leg's ramp rate, the most Ruckig may use on it


@dataclass(frozen=True)
class Knot:
    t: float
    s: float
    v: float
    accel: float = MAX_ACCEL  # m/s^2 the piece that reaches it may use (a reverse leg's: its ramps')


def knots(
    legs: tuple[LegValues, ...], start: float, initial_dwell: float, end_time: float, max_accel: float = MAX_ACCEL
) -> list[Knot]:
    """The corners of the trapezoid profile, from t = 0 to end_time. Each leg ramps as the solver planned it
    (the body's own rates, or its reversing rate); `max_accel` is the most Ruckig may use, the body's."""
    if not legs:  # stationary throughout
        return [Knot(0.0, start, 0.0), Knot(end_time, start, 0.0)]
    first = legs[0]
    out = [Knot(0.0, start, 0.0 if first.from_rest else first.v)]
    if initial_dwell > 0.0:
        out.append(Knot(initial_dwell, start, 0.0))
    for leg in legs:
        t, s, v = leg.begin, leg.start, leg.v
        # Ruckig keeps a little above the ramps' own rate on a reverse leg (its jerk limit needs it)
        a = min(max_accel, RAMP_SLACK * max(leg.up, leg.down)) if leg.backing else max_accel
        if leg.from_rest:
            t, s = t + v / leg.up, s + v * v / (2 * leg.up)
            out.append(Knot(t, s, v, a))
        if leg.end is None:
            out.append(Knot(end_time, s + v * (end_time - t), v, a))
            break
        assert leg.duration is not None
        brake_at = leg.begin + leg.duration - v / leg.down
        out.append(Knot(brake_at, leg.end - v * v / (2 * leg.down), v, a))
        out.append(Knot(leg.begin + leg.duration, leg.end, 0.0, a))
        rest_until = leg.begin + leg.duration + leg.dwell
        if leg is legs[-1]:
            rest_until = end_time
        out.append(Knot(min(rest_until, end_time), leg.end, 0.0))
    clipped = [k for k in out if k.t <= end_time + 1e-9]
    if clipped[-1].t < end_time - 1e-9:
        last = clipped[-1]
        clipped.append(Knot(end_time, last.s + last.v * (end_time - last.t), last.v))
    return _merged(clipped)


def _merged(points: list[Knot]) -> list[Knot]:
    out: list[Knot] = []
    for k in points:
        if out and k.t - out[-1].t < 1e-6:
            out[-1] = k
        else:
            out.append(k)
    return out


def sample(points: list[Knot], times: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
    """Arc length and speed at each time; also how many pieces kept constant acceleration
    (each piece may accelerate at most as its end knot says: the body's, or a reverse leg's)."""
    s_out = np.empty(len(times))
    v_out = np.empty(len(times))
    fallbacks = 0
    otg = Ruckig(1)
    for a, b in itertools.pairwise(points):
        inside = (times >= a.t - 1e-9) & (times <= b.t + 1e-9)
        if not inside.any():
            continue
        local = times[inside] - a.t
        piece = _ruckig(otg, a, b)
        if piece is None:
            fallbacks += 1
            duration = b.t - a.t
            accel = (b.v - a.v) / duration if duration > 0 else 0.0
            s_out[inside] = a.s + a.v * local + 0.5 * accel * local**2
            v_out[inside] = a.v + accel * local
        else:
            for i, t in zip(np.flatnonzero(inside), local, strict=True):
                pos, vel, _ = piece.at_time(float(t))
                s_out[i], v_out[i] = pos[0], vel[0]
    return s_out, np.maximum(v_out, 0.0), fallbacks


def _ruckig(otg: Ruckig, a: Knot, b: Knot) -> Trajectory | None:
    duration = b.t - a.t
    if duration <= 1e-6:
        return None
    if abs(a.v - b.v) < 1e-9 and abs((b.s - a.s) - a.v * duration) < 1e-6:
        return _constant(a, duration)
    inp = InputParameter(1)
    inp.current_position, inp.current_velocity, inp.current_acceleration = [a.s], [a.v], [0.0]
    inp.target_position, inp.target_velocity, inp.target_acceleration = [b.s], [b.v], [0.0]
    inp.max_velocity = [max(a.v, b.v) * 1.1 + 0.5]
    inp.min_velocity = [0.0]
    inp.max_acceleration = [b.accel]
    inp.max_jerk = [MAX_JERK]
    inp.minimum_duration = duration
    trajectory = Trajectory(1)
    try:
        result = otg.calculate(inp, trajectory)
    except RuckigError:  # no jerk-limited profile lasts exactly this long
        return None
    if result not in (Result.Working, Result.Finished) or abs(trajectory.duration - duration) > 1e-6:
        return None
    return trajectory


class _Constant:
    """A constant-speed piece, in Ruckig's Trajectory interface."""

    def __init__(self, s: float, v: float) -> None:
        self.s, self.v = s, v

    def at_time(self, t: float) -> tuple[list[float], list[float], list[float]]:
        return [self.s + self.v * t], [self.v], [0.0]


def _constant(a: Knot, duration: float) -> _Constant:  # type: ignore[return-value]
    return _Constant(a.s, a.v)
