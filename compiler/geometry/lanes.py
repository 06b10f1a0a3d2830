"""A road network's lanes as shapes, and which lane a point is on, heading which way.

A lane is its centre line (a shape), its width, the edge (road) it belongs to and that edge's
end junctions, whether it is a junction's internal lane and whether only pedestrians use it.
The SUMO target reads them from a network file (targets/sumo/network.py), lowering from the map
it plans on (compiler/maps/lane_map.py); both ask the same questions of them here, and the
lane-line test (lane_lines.py) is made of these answers.

Distances walk a lane's segments (numpy on long lanes) and are exact to the last bit: the SUMO
target's FCD positions and the oracle's verdicts are made of them.
"""

from __future__ import annotations

import itertools
import math
from collections import defaultdict
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
from sovarc.compiler.geometry.angles import angle_diff, compass

Point = tuple[float, float]
CELL = 10.0  # m, side of a spatial index cell
LONG_LANE = 24  # segments: `spot` does a longer lane's arithmetic in numpy
HEADING_MATCH = 60.0  # degrees: a lane runs "the same way" as a participant within this


@dataclass(frozen=True)
class Lane:
    id: str
    edge: str
    index: int
    width: float
    length: float
    shape: tuple[Point, ...]
    internal: bool  # a junction's lane: no painted lines
    pedestrian_only: bool  # a sidewalk
    ends: tuple[str, str] = ("", "")  # the edge's from and to junctions


@dataclass(frozen=True)
class Spot:
    """Where on the network a point is: its lane, the distance along it, and how far off its centre."""

    lane: Lane
    pos: float  # m along the lane (clamped to the lane)
    offset: float  # m from the lane's centre line; positive = left of its direction
    heading: float  # compass degrees of the lane there


@dataclass(frozen=True)
class Fit:
    """A point against one lane: its spot there, its distance from the centre line, whether the
    lane's corridor holds it and whether the lane runs the point's way (within HEADING_MATCH)."""

    spot: Spot
    distance: float
    inside: bool
    along: bool


@dataclass(frozen=True)
class _Segments:
    """A lane's segments of positive length, as `spot` walks them: (start x, start y, unit
    direction x, y, length, arc length at the start) each, and the box around the shape."""

    rows: tuple[tuple[float, float, float, float, float, float], ...]
    box: tuple[float, float, float, float]  # min x, min y, max x, max y
    columns: np.ndarray  # the rows as columns, for `nearest`

    @classmethod
    def of(cls, shape: tuple[Point, ...]) -> _Segments:
        rows = []
        s = 0.0
        for p, q in itertools.pairwise(shape):
            seg = math.dist(p, q)
            if seg == 0.0:
                continue
            rows.append((p[0], p[1], (q[0] - p[0]) / seg, (q[1] - p[1]) / seg, seg, s))
            s += seg
        xs, ys = [p[0] for p in shape] or [math.nan], [p[1] for p in shape] or [math.nan]
        columns = np.array(rows, dtype=float).reshape(-1, 6).T.copy()
        return cls(tuple(rows), (min(xs), min(ys), max(xs), max(ys)), columns)

    def nearest(self, x: float, y: float) -> tuple[int, float, float]:
        """`spot`'s walk over a long lane, its arithmetic done by numpy on every segment at once
        (the same operations, so the same numbers; the distance by math.hypot, as in the walk)."""
        px, py, ux, uy, seg, _s = self.columns
        along = (x - px) * ux + (y - py) * uy
        at = np.where(along < 0.0, 0.0, along)
        at = np.where(seg < at, seg, at)
        dx, dy = x - (px + at * ux), y - (py + at * uy)
        k, distance = -1, math.inf
        for i, d in enumerate(map(math.hypot, dx.tolist(), dy.tolist())):
            if d < distance - 1e-9:
                k, distance = i, d
        return k, distance, float(at[k]) if k >= 0 else 0.0


class LaneMap:
    """A network's lanes by id, the lanes of each road, and a grid index for point look-ups
    (made when first asked for: the lane-line test looks up lanes by id and road alone)."""

    def __init__(self, lanes: Iterable[Lane]) -> None:
        self.lanes = {lane.id: lane for lane in lanes}
        by_ends: dict[tuple[str, str], list[Lane]] = defaultdict(list)
        for lane in sorted(self.lanes.values(), key=lambda lane: lane.id):
            if not lane.internal:
                by_ends[lane.ends].append(lane)
        self._by_ends = {ends: tuple(lanes) for ends, lanes in by_ends.items()}
        self._segments: dict[str, _Segments] = {}  # lane id -> its segments, made when first asked for
        self._grid: dict[tuple[int, int], tuple[str, ...]] | None = None

    def alongside(self, lane: Lane) -> list[Lane]:
        """The lanes beside `lane`: the others of its edge and those of the edge the other way."""
        if lane.internal:
            return []
        reverse = (lane.ends[1], lane.ends[0])
        return [other for other in self._by_ends.get(lane.ends, ()) + self._by_ends.get(reverse, ()) if other != lane]

    def near(self, x: float, y: float, radius: float) -> list[Lane]:
        """Lanes with some part within about `radius` of the point, sorted by id."""
        grid = self._index()
        ids: set[str] = set()
        for i in range(_cell(x - radius), _cell(x + radius) + 1):
            for j in range(_cell(y - radius), _cell(y + radius) + 1):
                ids.update(grid.get((i, j), ()))
        return [self.lanes[i] for i in sorted(ids)]

    def spot(self, lane: Lane, x: float, y: float) -> tuple[Spot, float]:
        """The point's place on `lane`, and its distance from the lane's centre line: the nearest
        point of its first segment that is closer than every earlier one by more than 1e-9 m."""
        segments = self._segments_of(lane)
        if len(segments.rows) > LONG_LANE:
            k, distance, u = segments.nearest(x, y)
        else:
            k, distance, u = -1, math.inf, 0.0
            for i, (px, py, ux, uy, seg, _s) in enumerate(segments.rows):
                along = (x - px) * ux + (y - py) * uy
                at = 0.0 if along < 0.0 else along  # = min(max(along, 0.0), seg), as written before
                if seg < at:
                    at = seg
                d = math.hypot(x - (px + at * ux), y - (py + at * uy))
                if d < distance - 1e-9:
                    k, distance, u = i, d, at
        if k < 0:  # no segment of positive length
            return Spot(lane, min(0.0, lane.length), 0.0, compass(0.0, 0.0)), math.inf
        px, py, ux, uy, _seg, s = segments.rows[k]
        side = ux * (y - py) - uy * (x - px)  # > 0: left of the direction
        offset = math.copysign(distance, side) if distance else 0.0
        return Spot(lane, min(s + u, lane.length), offset, compass(ux, uy)), distance

    def reaches(self, lane: Lane, x: float, y: float, reach: float) -> bool:
        """Whether the point is within `reach` of the lane's centre line (`spot`'s distance), its
        box first: a point farther than that from the box is farther from the line too."""
        x0, y0, x1, y1 = self._segments_of(lane).box
        margin = reach + 1e-6  # far above the rounding of a distance
        if x < x0 - margin or x > x1 + margin or y < y0 - margin or y > y1 + margin:
            return False
        return self.spot(lane, x, y)[1] <= reach

    def fit(self, lane: Lane, x: float, y: float, heading: float) -> Fit:
        """The point, going `heading`, against `lane` (the terms `locate` ranks lanes by)."""
        spot, distance = self.spot(lane, x, y)
        inside = distance <= lane.width / 2.0 + 1e-6
        return Fit(spot, distance, inside, abs(angle_diff(spot.heading, heading)) <= HEADING_MATCH)

    def locate(self, x: float, y: float, heading: float, prefer: frozenset[str], pedestrian: bool = False) -> Spot:
        """The lane a participant at (x, y) going `heading` is on.

        Among the lanes whose corridor holds the point (overlapping junction lanes, or none),
        the participant's own lanes (`prefer`) come first, then lanes running its way, then the
        nearest centre line. Vehicles are never placed on sidewalks, nor pedestrians on the
        vehicles' junction lanes (SUMO walks people along edges, not through junction lanes).
        """
        # a lane whose corridor holds the point is indexed in the point's own cell
        for radius in (0.0, CELL, 5 * CELL):
            ranked: list[tuple[tuple[int, int, int, float, str], Spot]] = []
            for lane in self.near(x, y, radius):
                if (lane.pedestrian_only and not pedestrian) or (lane.internal and pedestrian):
                    continue
                if radius == 0.0 and not self._may_hold(lane, x, y):
                    continue  # not inside it: at this radius only a lane that holds the point is taken
                fit = self.fit(lane, x, y, heading)
                key = (
                    0 if fit.inside else 1,
                    0 if lane.id in prefer else 1,
                    0 if fit.along else 1,
                    fit.distance,
                    lane.id,
                )
                ranked.append((key, fit.spot))
            if ranked and (radius > 0.0 or min(ranked)[0][0] == 0):
                return min(ranked, key=lambda item: item[0])[1]
        raise ValueError(f"no lane within {5 * CELL:.0f} m of ({x:.2f}, {y:.2f})")

    def holding(self, x: float, y: float, heading: float, among: Iterable[Lane]) -> Lane | None:
        """`locate` among the lanes `among` alone (a participant's own): the one whose corridor
        holds the point, running its way first, then the nearest centre line; None when none does."""
        ranked = []
        for lane in among:
            fit = self.fit(lane, x, y, heading)
            if fit.inside:
                ranked.append(((0 if fit.along else 1, fit.distance, lane.id), lane))
        return min(ranked, key=lambda item: item[0])[1] if ranked else None

    def _may_hold(self, lane: Lane, x: float, y: float) -> bool:
        """False when the point is surely outside the lane (`locate`'s inside): far from its box."""
        x0, y0, x1, y1 = self._segments_of(lane).box
        margin = lane.width / 2.0 + 1e-6 + 1e-6
        return x0 - margin <= x <= x1 + margin and y0 - margin <= y <= y1 + margin

    def _segments_of(self, lane: Lane) -> _Segments:
        found = self._segments.get(lane.id)
        if found is None:
            found = self._segments[lane.id] = _Segments.of(lane.shape)
        return found

    def _index(self) -> dict[tuple[int, int], tuple[str, ...]]:
        if self._grid is None:
            grid: dict[tuple[int, int], set[str]] = defaultdict(set)
            for lane in self.lanes.values():
                reach = lane.width / 2.0
                for p, q in itertools.pairwise(lane.shape):
                    x0, x1 = sorted((p[0], q[0]))
                    y0, y1 = sorted((p[1], q[1]))
                    for i in range(_cell(x0 - reach), _cell(x1 + reach) + 1):
                        for j in range(_cell(y0 - reach), _cell(y1 + reach) + 1):
                            grid[(i, j)].add(lane.id)
            self._grid = {key: tuple(sorted(ids)) for key, ids in grid.items()}
        return self._grid


def _cell(v: float) -> int:
    return math.floor(v / CELL)
