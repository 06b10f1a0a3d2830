"""The path of a route that may turn in legs: Dubins paths between its three-point turns.

A three-point turn (compiler/lower/kturn.py) is laid out exactly in lowering, with the heading
the body faces at each point: its legs are driven as laid out. The stretches before, between and
after such turns are smoothed with OMPL's Dubins curves (paths.py), each on its own: a Dubins
curve drives forward only, and the turn's first stop has a corner where the wheels turn at rest.
A route without such a turn is one Dubins path, exactly as before.
"""

from __future__ import annotations

import itertools

import numpy as np
from sovarc.compiler.lower.route import Route
from sovarc.compiler.synth.paths import Path, plan_path
from sovarc.compiler.vehicles import model


class RoutePath:
    """Pose along a route, addressed by its arc length, and the direction it drives there."""

    def __init__(self, route: Route, *, vehicle: bool) -> None:
        self.route = route
        self.parts: list[tuple[float, float, Path | None]] = []  # (from, to, its Dubins path; None: a turn's legs)
        self.chords = 0
        radius = model(route.body).limits.path_radius
        cuts = [0.0, *(x for m in route.manoeuvres for x in (m.lo, m.hi)), route.line.length]
        for k, (a, b) in enumerate(itertools.pairwise(cuts)):
            if k % 2:
                self.parts.append((a, b, None))
            elif b - a > 1e-6:
                line = route.line if not route.manoeuvres else route.line.sub(a, b)
                path, chords = plan_path(line, vehicle=vehicle, min_radius=radius)
                self.parts.append((a, b, path))
                self.chords += chords

    def pose(self, s: float) -> tuple[float, float, float, float]:
        """(x, y, compass heading the body faces, path metres per route metre) at arc length s."""
        part = next((p for p in self.parts if s <= p[1] + 1e-9), self.parts[-1])
        lo, _, path = part
        if path is not None:
            return path.pose(s - lo)
        x, y = self.route.line.point(s)
        return x, y, float(self.route.facing(np.array([s]))[0]), 1.0

    def gear(self, s: float) -> int:
        """+1 where the route drives forward, -1 where it reverses."""
        return self.route.gear(s)

    def legs(self, lo: float, hi: float) -> list[tuple[float, float]]:
        """[lo, hi] cut at the places a three-point turn stands: stretches driven without a stop or
        a change of gear, each drivable on its own."""
        cuts = [lo, *(r for r in self.route.rests() if lo < r < hi), hi]
        return [(a, b) for a, b in itertools.pairwise(cuts) if b > a]
