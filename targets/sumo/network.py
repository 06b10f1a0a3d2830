"""The lanes of a SUMO network, read once, and which lane a point of a trajectory is on.

Only what the SUMO target needs: each lane's centre line, width and edge, and which lane
follows an internal (junction) lane. A plain ElementTree pass is several times faster than
sumolib's full network and keeps big city networks cheap.
"""

from __future__ import annotations

import functools
import io
import itertools
import math
from collections import defaultdict
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from xml.etree import ElementTree

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
    internal: bool
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


class Network:
    """A SUMO network's lanes with a grid index for point look-ups."""

    def __init__(self, lanes: Iterable[Lane], successors: dict[str, str], predecessors: dict[str, str]) -> None:
        self.lanes = {lane.id: lane for lane in lanes}
        self.successors = successors  # internal lane id -> the lane it leads into
        self.predecessors = predecessors  # internal lane id -> the lane that leads into it
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
        by_ends: dict[tuple[str, str], list[Lane]] = defaultdict(list)
        for lane in sorted(self.lanes.values(), key=lambda lane: lane.id):
            if not lane.internal:
                by_ends[lane.ends].append(lane)
        self._by_ends = {ends: tuple(lanes) for ends, lanes in by_ends.items()}
        self._segments: dict[str, _Segments] = {}  # lane id -> its segments, made when first asked for

    def alongside(self, lane: Lane) -> list[Lane]:
        """The lanes beside `lane`: the others of its edge and those of the edge the other way."""
        if lane.internal:
            return []
        reverse = (lane.ends[1], lane.ends[0])
        return [other for other in self._by_ends.get(lane.ends, ()) + self._by_ends.get(reverse, ()) if other != lane]

    def near(self, x: float, y: float, radius: float) -> list[Lane]:
        """Lanes with some part within about `radius` of the point, sorted by id."""
        ids: set[str] = set()
        for i in range(_cell(x - radius), _cell(x + radius) + 1):
            for j in range(_cell(y - radius), _cell(y + radius) + 1):
                ids.update(self._grid.get((i, j), ()))
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

    def _segments_of(self, lane: Lane) -> _Segments:
        found = self._segments.get(lane.id)
        if found is None:
            found = self._segments[lane.id] = _Segments.of(lane.shape)
        return found

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
                spot, distance = self.spot(lane, x, y)
                inside = distance <= lane.width / 2.0 + 1e-6
                along = abs(angle_diff(spot.heading, heading)) <= HEADING_MATCH
                key = (0 if inside else 1, 0 if lane.id in prefer else 1, 0 if along else 1, distance, lane.id)
                ranked.append((key, spot))
            if ranked and (radius > 0.0 or min(ranked)[0][0] == 0):
                return min(ranked, key=lambda item: item[0])[1]
        raise ValueError(f"no lane within {5 * CELL:.0f} m of ({x:.2f}, {y:.2f})")

    def _may_hold(self, lane: Lane, x: float, y: float) -> bool:
        """False when the point is surely outside the lane (`locate`'s inside): far from its box."""
        x0, y0, x1, y1 = self._segments_of(lane).box
        margin = lane.width / 2.0 + 1e-6 + 1e-6
        return x0 - margin <= x <= x1 + margin and y0 - margin <= y <= y1 + margin

    def next_normal_lane(self, lane: Lane) -> Lane | None:
        """The first non-internal lane reached from an internal one."""
        return self._walk(lane, self.successors)

    def previous_normal_lane(self, lane: Lane) -> Lane | None:
        """The non-internal lane an internal one is entered from."""
        return self._walk(lane, self.predecessors)

    def _walk(self, lane: Lane, links: dict[str, str]) -> Lane | None:
        seen = set()
        current: str | None = lane.id
        while current is not None and current not in seen:
            seen.add(current)
            found = self.lanes.get(current)
            if found is not None and not found.internal:
                return found
            current = links.get(current)
        return None


def _cell(v: float) -> int:
    return math.floor(v / CELL)


def _shape(text: str) -> tuple[Point, ...]:
    return tuple((float(x), float(y)) for x, y, *_ in (p.split(",") for p in text.split()))


@functools.lru_cache(maxsize=8)
def _read(data: bytes) -> Network:
    lanes: list[Lane] = []
    successors: dict[str, str] = {}
    predecessors: dict[str, str] = {}
    edge_id, internal, ends = "", False, ("", "")
    for event, element in ElementTree.iterparse(io.BytesIO(data), events=("start", "end")):
        if event == "start":
            if element.tag == "edge":
                edge_id, internal = element.get("id", ""), element.get("function") == "internal"
                ends = (element.get("from", ""), element.get("to", ""))
            continue
        if element.tag == "lane":
            allow = element.get("allow", "")
            lanes.append(
                Lane(
                    id=element.get("id", ""),
                    edge=edge_id,
                    index=int(element.get("index", "0")),
                    width=float(element.get("width", "3.2")),
                    length=float(element.get("length", "0")),
                    shape=_shape(element.get("shape", "")),
                    internal=internal,
                    pedestrian_only=allow.split() == ["pedestrian"],
                    ends=ends,
                )
            )
        elif element.tag == "connection":
            source = f"{element.get('from', '')}_{element.get('fromLane')}"
            via = element.get("via")
            if source.startswith(":"):
                successors[source] = via or f"{element.get('to')}_{element.get('toLane')}"
            if via:
                predecessors[via] = source
        elif element.tag in {"edge", "junction", "tlLogic"}:
            element.clear()
    return Network(lanes, successors, predecessors)


def read_network(path: Path) -> Network:
    """The network at `path`, cached by its bytes: every site's scenario folder holds a copy of
    the same map (or of one crop of it), which is read and indexed once."""
    return _read(path.read_bytes())
