"""Path synthesis: the waypoints made for all arc lengths at once are those made one by one,
a path asked for again is the one made first, and poses are those of numpy's look-ups."""

from __future__ import annotations

import math

import numpy as np
from sovarc.compiler.geometry.angles import compass
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.synth import paths


def _curvy_line(seed: int) -> Polyline:
    rng = np.random.default_rng(seed)
    heading = np.cumsum(rng.normal(0.0, 0.08, 120))
    steps = rng.uniform(0.3, 2.5, 120)
    points = np.cumsum(np.column_stack((steps * np.sin(heading), steps * np.cos(heading))), axis=0)
    return Polyline(points + rng.uniform(-500.0, 500.0, 2))


def _one_by_one(line: Polyline, at: np.ndarray) -> list[tuple[float, float, float]]:
    out = []
    for s in at:
        a, b = line.point(max(0.0, s - 1.0)), line.point(min(line.length, s + 1.0))
        out.append((*line.point(s), math.radians(90.0 - compass(b[0] - a[0], b[1] - a[1]))))
    return out


def _bits(rows: list[tuple[float, ...]]) -> list[tuple[str, ...]]:
    return [tuple(float(v).hex() for v in row) for row in rows]


def test_waypoints_at_once_are_the_waypoints_one_by_one() -> None:
    for seed in range(5):
        line = _curvy_line(seed)
        at = np.linspace(0.0, line.length, max(2, math.ceil(line.length / paths.WAYPOINT_STEP) + 1))
        assert _bits(paths._states(line, at)) == _bits(_one_by_one(line, at))


def test_a_line_asked_for_again_gets_the_path_made_first() -> None:
    line = _curvy_line(9)
    first = paths.plan_path(line, vehicle=True)
    again = paths.plan_path(Polyline(line.points.copy()), vehicle=True)
    assert again is first
    assert paths.plan_path(line, vehicle=False) is not first


def test_pose_finds_the_segment_as_numpy_does() -> None:
    line = _curvy_line(3)
    path, _ = paths.plan_path(line, vehicle=True)
    for s in [-1.0, -0.0, 0.0, *np.linspace(0.0, path.route_s[-1], 97).tolist(), *path.route_s[:5], 1e9]:
        k = int(np.clip(np.searchsorted(path.route_s, s, side="right") - 1, 0, len(path.route_s) - 2))
        span = path.route_s[k + 1] - path.route_s[k]
        u = float(np.clip((s - path.route_s[k]) / span, 0.0, 1.0))
        x, y, _heading, scale = path.pose(s)
        if s <= path.route_s[-1]:
            a, b, space = path.states[k], path.states[k + 1], path.spaces[k]
            if space is None:
                expected = (a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]))
            else:
                expected = paths._interpolate(space, a, b, u)[:2]
            assert (x, y) == expected
            assert scale == path.lengths[k] / span
