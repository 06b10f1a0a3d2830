"""The lanes of a SUMO network, read once, and which lane a point of a trajectory is on.

Only what the SUMO target needs: each lane's centre line, width and edge, and which lane
follows an internal (junction) lane. A plain ElementTree pass is several times faster than
sumolib's full network and keeps big city networks cheap.
"""

from __future__ import annotations

import functools
import itertools
import math
from collections import defaultdict
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from xml.etree import ElementTree

from sovarc.compiler.geometry.angles import angle_diff, compass

Point = tuple[float, float]
CELL = 10.0  # m, side of a spatial index cell
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
        """The point's place on `lane`, and its distance from the lane's centre line."""
        best = (math.inf, 0.0, 0.0, 0.0, 0.0)
        s = 0.0
        for p, q in itertools.pairwise(lane.shape):
            seg = math.dist(p, q)
            if seg == 0.0:
                continue
            ux, uy = (q[0] - p[0]) / seg, (q[1] - p[1]) / seg
            along = (x - p[0]) * ux + (y - p[1]) * uy
            u = min(max(along, 0.0), seg)
            cx, cy = p[0] + u * ux, p[1] + u * uy
            distance = math.hypot(x - cx, y - cy)
            if distance < best[0] - 1e-9:
                side = ux * (y - p[1]) - uy * (x - p[0])  # > 0: left of the direction
                best = (distance, s + u, math.copysign(distance, side) if distance else 0.0, ux, uy)
            s += seg
        distance, pos, offset, ux, uy = best
        heading = compass(ux, uy)
        return Spot(lane, min(pos, lane.length), offset, heading), distance

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
                spot, distance = self.spot(lane, x, y)
                inside = distance <= lane.width / 2.0 + 1e-6
                along = abs(angle_diff(spot.heading, heading)) <= HEADING_MATCH
                key = (0 if inside else 1, 0 if lane.id in prefer else 1, 0 if along else 1, distance, lane.id)
                ranked.append((key, spot))
            if ranked and (radius > 0.0 or min(ranked)[0][0] == 0):
                return min(ranked, key=lambda item: item[0])[1]
        raise ValueError(f"no lane within {5 * CELL:.0f} m of ({x:.2f}, {y:.2f})")

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


@functools.lru_cache(maxsize=4)
def _read(path: str, _stamp: tuple[int, int]) -> Network:
    lanes: list[Lane] = []
    successors: dict[str, str] = {}
    predecessors: dict[str, str] = {}
    edge_id, internal, ends = "", False, ("", "")
    for event, element in ElementTree.iterparse(path, events=("start", "end")):
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
    """The network at `path` (cached while the file is unchanged)."""
    stat = path.stat()
    return _read(str(path.resolve()), (stat.st_mtime_ns, stat.st_size))
