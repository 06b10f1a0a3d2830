"""Drivable paths through a route's waypoints, with OMPL's Dubins state space.

Waypoints (x, y, heading) are taken along the route's line (a vehicle's is smoothed once, in
lowering) every WAYPOINT_STEP metres. Between two waypoints the path is the shortest Dubins
curve (forward driving). Its turning radius is just under the route's own radius of curvature
there: a Dubins curve turns at its radius, so a smaller one would make wiggles tighter than
the road. Each curve is checked against the route's corridor (the front bumper stays within
CORRIDOR of the route's line, a SpaceInformation validity checker); where it leaves it, tighter
radius classes are tried that must hug the line (TIGHT_CORRIDOR), and only when none fits is
the piece the straight chord between its waypoints, whose kink TOPP-RA will likely reject.
Pedestrians walk the route's line itself.
"""

from __future__ import annotations

import bisect
import functools
import math
from dataclasses import dataclass, field

import numpy as np
from ompl import base as ob
from sovarc.compiler.geometry.angles import compass
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.vehicles import PLANNED

WAYPOINT_STEP = 4.0  # m
MIN_RADIUS = PLANNED.path_radius  # m; a tight junction corner for a car (each body has its own)
RADIUS_STEP = 1.08  # turning radii come in classes this far apart (a space per class)
TIGHTER_STEPS = 4  # classes skipped per retry when a curve does not fit
MAX_RADIUS = 2000.0
CORRIDOR = 1.2  # m the path may stray from the route's line
TIGHT_CORRIDOR = 0.3  # m, for curves tighter than the road's: they must hug its line
CHECK_STEP = 0.5  # m between checked states
PLANNED_KEPT = 64  # paths kept for lines asked for again
EXTENSION = 60.0  # m of straight road added past the route's end, so that nobody runs out of path


_PLANNED: dict[tuple[bytes, tuple[int, ...], bool, float], tuple[Path, int]] = {}


@dataclass
class Path:
    """Position and heading along a path, addressed by the ROUTE's arc length."""

    route_s: np.ndarray  # arc length of each waypoint along the route
    states: list[tuple[float, float, float]]  # waypoint (x, y, yaw in radians, counter-clockwise from +x)
    lengths: np.ndarray  # length of the path piece after each waypoint
    spaces: list[ob.DubinsStateSpace | None]  # each piece's Dubins space (None: a chord)
    _s: list[float] = field(init=False, repr=False)  # route_s, for bisect

    def __post_init__(self) -> None:
        self._s = self.route_s.tolist()  # a pose is asked for at every sample: plain floats are quicker

    def pose(self, s: float) -> tuple[float, float, float, float]:
        """(x, y, compass heading, path metres per route metre) at route arc length s."""
        route_s = self._s
        # the segment holding s, and the share of it (np.searchsorted and np.clip, in plain Python)
        k = min(max(bisect.bisect_right(route_s, s) - 1, 0), len(route_s) - 2)
        span = route_s[k + 1] - route_s[k]
        u = min(max((s - route_s[k]) / span, 0.0), 1.0) if span > 0 else 0.0
        if s > route_s[-1]:  # past the end: straight on
            x, y, yaw = self.states[-1]
            extra = s - self.route_s[-1]  # a numpy number, as before
            return x + extra * math.cos(yaw), y + extra * math.sin(yaw), _compass(yaw), 1.0
        a, b = self.states[k], self.states[k + 1]
        scale = self.lengths[k] / span if span > 0 else 1.0
        space = self.spaces[k]
        if space is not None:
            x, y, yaw = _interpolate(space, a, b, u)
            return x, y, _compass(yaw), scale
        x, y = a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])
        yaw = math.atan2(b[1] - a[1], b[0] - a[0])
        return x, y, _compass(yaw), scale


def plan_path(line: Polyline, *, vehicle: bool, min_radius: float = MIN_RADIUS) -> tuple[Path, int]:
    """The path along `line` (extended straight past its end); also the number of chords used.
    `min_radius`: the tightest bend of the body that drives it (its planned limits').

    Kept for the lines last asked for, by their points: the same route on the same site comes
    back for every staging of a scenario and for other scenarios; a Path is only read."""
    key = (line.points.tobytes(), line.points.shape, vehicle, min_radius)
    found = _PLANNED.get(key)
    if found is None:
        found = _PLANNED[key] = _plan_path(line, vehicle=vehicle, min_radius=min_radius)
        while len(_PLANNED) > PLANNED_KEPT:
            del _PLANNED[next(iter(_PLANNED))]
    return found


def _plan_path(line: Polyline, *, vehicle: bool, min_radius: float) -> tuple[Path, int]:
    end = line.point(line.length)
    heading = line.heading(line.length)
    rad = math.radians(heading)
    extended = Polyline(
        np.vstack([line.points, [end[0] + EXTENSION * math.sin(rad), end[1] + EXTENSION * math.cos(rad)]])
    )
    count = max(2, math.ceil(extended.length / WAYPOINT_STEP) + 1)
    at = np.linspace(0.0, extended.length, count)
    states = _states(extended, at)
    if not vehicle:
        return Path(at, states, np.diff(at), [None] * (count - 1)), 0
    radii = extended.curvature_radius(window=2.0 * WAYPOINT_STEP)
    local = np.interp(at, extended.s, np.minimum(radii, 1e6))
    xs, ys = extended.points[:, 0], extended.points[:, 1]
    box = (float(xs.min()) - 50.0, float(xs.max()) + 50.0, float(ys.min()) - 50.0, float(ys.max()) + 50.0)
    checkers = {True: _Corridor(extended, CORRIDOR), False: _Corridor(extended, TIGHT_CORRIDOR)}
    lengths = np.empty(count - 1)
    spaces: list[ob.DubinsStateSpace | None] = []
    chords = 0
    made: dict[tuple[float, bool], tuple[ob.DubinsStateSpace, ob.SpaceInformation]] = {}
    for k in range(count - 1):
        found = None
        for n, radius in enumerate(_radius_classes(0.9 * min(local[k], local[k + 1]), min_radius)):
            key = (radius, n == 0)
            if key not in made:
                made[key] = _space(radius, box, checkers[n == 0])
            found = _fit(*made[key], states[k], states[k + 1], at[k + 1] - at[k])
            if found is not None:
                break
        if found is None:
            chords += 1
            lengths[k] = math.dist(states[k][:2], states[k + 1][:2])
            spaces.append(None)
        else:
            lengths[k] = found[1]
            spaces.append(found[0])
    return Path(at, states, lengths, spaces), chords


def _radius_class(radius: float, floor: float = MIN_RADIUS) -> float:
    if radius <= floor:
        return floor
    steps = math.floor(math.log(min(radius, MAX_RADIUS) / floor, RADIUS_STEP))
    return round(floor * RADIUS_STEP**steps, 6)


def _radius_classes(radius: float, floor: float = MIN_RADIUS) -> list[float]:
    """The class of `radius`, then tighter ones down to `floor`, the body's tightest (a few classes apart).

    The local radius is measured over a window; where the waypoints' headings ask for a
    sharper bend than it, a tighter curve still beats a chord, whose kink no car can drive.
    """
    return _classes_from(_radius_class(radius, floor), floor)


@functools.cache
def _classes_from(first: float, floor: float) -> list[float]:
    """The classes tried from `first` on (a few dozen firsts exist): made once each."""
    out = [first]
    while out[-1] > floor:
        out.append(_radius_class(out[-1] / RADIUS_STEP**TIGHTER_STEPS, floor))
    return out


def _fit(
    space: ob.DubinsStateSpace,
    info: ob.SpaceInformation,
    a: tuple[float, float, float],
    b: tuple[float, float, float],
    step: float,
) -> tuple[ob.DubinsStateSpace, float] | None:
    """The Dubins curve from a to b and its length, when it is short and stays in the corridor."""
    a_state, b_state = space.allocState(), space.allocState()
    _set(a_state, a)
    _set(b_state, b)
    length = space.distance(a_state, b_state)
    if length <= 1.5 * step + 0.5 and info.checkMotion(a_state, b_state):
        return space, length
    return None


class _Corridor:
    """OMPL state validity: the front bumper within `width` metres of the route's line."""

    def __init__(self, line: Polyline, width: float) -> None:
        self.line = line
        self.width = width

    def __call__(self, state: ob.State) -> bool:
        return self.line.project((state.getX(), state.getY()))[1] <= self.width


def _space(
    radius: float, box: tuple[float, float, float, float], checker: _Corridor
) -> tuple[ob.DubinsStateSpace, ob.SpaceInformation]:
    space = ob.DubinsStateSpace(radius)
    bounds = ob.RealVectorBounds(2)
    bounds.setLow(0, box[0])
    bounds.setHigh(0, box[1])
    bounds.setLow(1, box[2])
    bounds.setHigh(1, box[3])
    space.setBounds(bounds)
    info = ob.SpaceInformation(space)
    info.setStateValidityChecker(checker)
    info.setStateValidityCheckingResolution(0.02)
    info.setup()
    return space, info


def _set(state: ob.State, values: tuple[float, float, float]) -> None:
    state.setX(values[0])
    state.setY(values[1])
    state.setYaw(values[2])


def _interpolate(
    space: ob.DubinsStateSpace, a: tuple[float, float, float], b: tuple[float, float, float], u: float
) -> tuple[float, float, float]:
    sa, sb, out = space.allocState(), space.allocState(), space.allocState()
    _set(sa, a)
    _set(sb, b)
    space.interpolate(sa, sb, u, out)
    return out.getX(), out.getY(), out.getYaw()


def _states(line: Polyline, at: np.ndarray) -> list[tuple[float, float, float]]:
    """The waypoints at arc lengths `at` (0..length): the point, and the yaw of the chord over
    +-1 m, smoother than a single segment's. Each is `line.point` done for all at once (np.interp
    gives the same numbers for an array as for each of its values)."""
    x, y = _points(line, at)
    ax, ay = _points(line, np.maximum(at - 1.0, 0.0))
    bx, by = _points(line, np.minimum(at + 1.0, line.length))
    yaws = [_yaw(compass(dx, dy)) for dx, dy in zip((bx - ax).tolist(), (by - ay).tolist(), strict=True)]
    return list(zip(x.tolist(), y.tolist(), yaws, strict=True))


def _points(line: Polyline, at: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    at = np.minimum(np.maximum(at, 0.0), line.length)
    return np.interp(at, line.s, line.points[:, 0]), np.interp(at, line.s, line.points[:, 1])


def _yaw(compass: float) -> float:
    return math.radians(90.0 - compass)


def _compass(yaw: float) -> float:
    return (90.0 - math.degrees(yaw)) % 360.0
