"""Candidate sites of a road map: four-way intersections, T-junctions and straight roads.

A site is what a scenario can be placed on. Its arms carry the lanes, their widths,
lengths and shapes, and the compass heading of the traffic on them; a junction site also
carries its connections. Only car lanes count (lanes that allow SUMO's `passenger` class):
sidewalks, bike lanes and rails are left out, and lane numbers count from the right-most
car lane as 1, as the scenario IR does.

Headings are compass degrees, 0 = north (+y), 90 = east (+x). An arm's heading is the
direction of travel of traffic ENTERING the junction along it; for an exit-only arm, the
direction traffic would enter by. A straight site has one arm per direction of travel:
its `incoming` lanes travel in `heading`, its `outgoing` lanes the other way.

Each site lays a compass cross over its arms (`Site.orientation`, `Arm.slot`): arm slot k
ideally has heading `orientation + 90 * k`. The site search rotates reports on this cross.
"""

from __future__ import annotations

import statistics
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.geometry.polyline import (
    Point,
    Shape,
    distances_to,
    end_heading,
    heading_between,
    max_kink,
    max_offset_from_chord,
    point_at,
    shape_length,
    start_heading,
)
from sovarc.compiler.maps.geometry import fit_frame
from sovarc.dsl.ir import RoadKind

if TYPE_CHECKING:
    from sovarc.compiler.maps.load import RoadMap

CAR = "passenger"  # the SUMO vehicle class a site's lanes must allow
DEFAULT_MIN_LENGTH = 80.0  # m; a straight site must be at least this long
CROSS_TOLERANCE = 35.0  # degrees an intersection's arm may stray from its place in the cross
PAIR_TOLERANCE = 40.0  # an incoming and an outgoing edge this close in direction form one arm
# A straight road: bends no tighter than this radius over its length (its bulge from the chord
# is at most L^2 / 8R, about 3 m over 100 m) and has no kink sharper than STRAIGHT_KINK degrees.
STRAIGHT_RADIUS = 400.0
STRAIGHT_KINK = 15.0
# Inner lane edges of the two directions further apart than this: a divided road. Its halves
# are staged as one-way roads, because a median (often with paths or rails on it) is no lane
# line a wrong-way or overtaking car can cross.
MEDIAN_MAX = 1.0  # m


@dataclass(frozen=True)
class LaneInfo:
    """One car lane of a SUMO edge."""

    id: str  # SUMO lane id
    edge: str  # SUMO edge id
    index: int  # SUMO's index on the edge: 0 is the right-most lane (maybe a sidewalk)
    number: int  # counted from the right-most car lane of the edge as 1, as in the IR
    width: float  # m
    length: float  # m
    speed: float  # m/s, the lane's speed limit
    shape: Shape  # centre line, in the direction of travel


@dataclass(frozen=True)
class Connection:
    """A link through a junction, from the end of one lane to the start of another."""

    from_lane: str
    to_lane: str
    direction: str  # SUMO: s straight, l/L left/partly left, r/R right/partly right, t turnaround
    via: str | None  # the internal lane that carries it, if the network has one


@dataclass(frozen=True)
class Arm:
    """One road at a site. Lanes are ordered right-most first."""

    id: str  # the incoming edge's id, or the outgoing edge's for an exit-only arm
    heading: float  # compass degrees of the traffic on `incoming` (see the module docstring)
    slot: int  # place in the site's compass cross, 0..3
    incoming: tuple[LaneInfo, ...]  # towards the junction (straight site: travelling in `heading`)
    outgoing: tuple[LaneInfo, ...]  # away from the junction (straight site: the other direction)
    length: float  # m, of the incoming lanes (of the outgoing ones for an exit-only arm)

    @property
    def two_way(self) -> bool:
        return bool(self.incoming and self.outgoing)


@dataclass(frozen=True)
class Site:
    """A place of one road kind where a scenario can happen."""

    id: str  # 'junction:<SUMO junction id>' or 'road:<edge id>[|<reverse edge id>]'
    kind: RoadKind
    centre: Point  # the junction's point, or the middle of the road
    orientation: float  # degrees in [-45, 45): the compass cross's offset from true north
    arms: tuple[Arm, ...]  # sorted by slot
    connections: tuple[Connection, ...] = ()  # sorted by (from_lane, to_lane); none on a straight road
    junction: str | None = None  # SUMO junction id
    control: str | None = None  # SUMO junction type: priority, traffic_light, right_before_left, ...

    def arm_in_slot(self, slot: int) -> Arm | None:
        return next((arm for arm in self.arms if arm.slot == slot % 4), None)

    def arm_of_lane(self, lane_id: str) -> Arm | None:
        return next((a for a in self.arms if any(lane.id == lane_id for lane in a.incoming + a.outgoing)), None)

    def connections_from(self, arm: Arm) -> tuple[Connection, ...]:
        ids = {lane.id for lane in arm.incoming}
        return tuple(c for c in self.connections if c.from_lane in ids)

    @property
    def lanes(self) -> int:
        """The most lanes any arm has in one direction."""
        return max(max(len(a.incoming), len(a.outgoing)) for a in self.arms)

    @property
    def mean_width(self) -> float:
        return statistics.fmean(lane.width for a in self.arms for lane in a.incoming + a.outgoing)

    @property
    def min_length(self) -> float:
        return min(a.length for a in self.arms)


def find_sites(
    road_map: RoadMap, kind: RoadKind | str | None = None, *, min_length: float = DEFAULT_MIN_LENGTH
) -> list[Site]:
    """Every site of the map, or those of one kind, sorted by id. Computed once per map and min_length."""
    sites = road_map.cache.get(min_length)
    if sites is None:
        found = _junction_sites(road_map.net) + _straight_sites(road_map.net, min_length)
        sites = road_map.cache[min_length] = tuple(sorted(found, key=lambda s: s.id))
    wanted = RoadKind(kind) if kind is not None else None
    return [s for s in sites if wanted is None or s.kind is wanted]


# --- building sites from sumolib objects (typed Any: sumolib has no type hints) ---


class _Lanes:
    """Car lanes per edge, built once."""

    def __init__(self) -> None:
        self._memo: dict[str, tuple[LaneInfo, ...]] = {}

    def __call__(self, edge: Any) -> tuple[LaneInfo, ...]:
        eid = edge.getID()
        if eid not in self._memo:
            cars = [lane for lane in edge.getLanes() if lane.allows(CAR)]
            self._memo[eid] = tuple(
                LaneInfo(
                    id=lane.getID(),
                    edge=eid,
                    index=lane.getIndex(),
                    number=number,
                    width=round(lane.getWidth(), 3),
                    length=round(lane.getLength(), 3),
                    speed=round(lane.getSpeed(), 3),
                    shape=tuple((round(p[0], 3), round(p[1], 3)) for p in lane.getShape()),
                )
                for number, lane in enumerate(sorted(cars, key=lambda lane: lane.getIndex()), start=1)
            )
        return self._memo[eid]


def _is_road(edge: Any) -> bool:
    return not edge.isSpecial() and edge.allows(CAR)


def _axis(lanes: tuple[LaneInfo, ...]) -> Shape:
    """The shape that stands for a direction's lanes: its middle car lane."""
    return lanes[len(lanes) // 2].shape


@dataclass(frozen=True)
class _RawArm:
    id: str
    heading: float
    incoming: tuple[LaneInfo, ...]
    outgoing: tuple[LaneInfo, ...]


def _junction_sites(net: Any) -> list[Site]:
    lanes = _Lanes()
    sites = []
    for node in net.getNodes():
        incoming = sorted((e for e in node.getIncoming() if _is_road(e) and e.getFromNode() is not node), key=_eid)
        outgoing = sorted((e for e in node.getOutgoing() if _is_road(e) and e.getToNode() is not node), key=_eid)
        if len(incoming) + len(outgoing) < 3:
            continue  # a dead end or a bend
        raw = _pair_arms(incoming, outgoing, lanes)
        if len(raw) not in (3, 4):
            continue
        frame = fit_frame([a.heading for a in raw])
        if len(raw) == 4 and frame.error > CROSS_TOLERANCE:
            continue  # four roads, but not a cross
        arms = sorted(
            (
                Arm(a.id, a.heading, slot, a.incoming, a.outgoing, (a.incoming or a.outgoing)[0].length)
                for a, slot in zip(raw, frame.slots, strict=True)
            ),
            key=lambda arm: arm.slot,
        )
        kind = RoadKind.INTERSECTION if len(raw) == 4 else RoadKind.T_JUNCTION
        centre = node.getCoord()
        sites.append(
            Site(
                id=f"junction:{node.getID()}",
                kind=kind,
                centre=(round(centre[0], 3), round(centre[1], 3)),
                orientation=frame.orientation,
                arms=tuple(arms),
                connections=_connections(incoming, {e.getID() for e in outgoing}),
                junction=node.getID(),
                control=node.getType(),
            )
        )
    return sites


def _pair_arms(incoming: list[Any], outgoing: list[Any], lanes: _Lanes) -> list[_RawArm]:
    """Group a junction's edges into arms: an incoming and an outgoing edge that leave the
    junction in about the same direction are one two-way road (same far node preferred)."""
    out_dir = {e.getID(): start_heading(_axis(lanes(e))) for e in outgoing}
    in_dir = {e.getID(): (end_heading(_axis(lanes(e))) + 180.0) % 360.0 for e in incoming}
    candidates = []
    for i in incoming:
        for o in outgoing:
            diff = abs(angle_diff(in_dir[i.getID()], out_dir[o.getID()]))
            if diff <= PAIR_TOLERANCE:
                candidates.append((o.getToNode() is not i.getFromNode(), round(diff, 6), i.getID(), o.getID(), i, o))
    paired: dict[str, Any] = {}
    taken: set[str] = set()
    for *_, i, o in sorted(candidates, key=lambda c: c[:4]):
        if i.getID() not in paired and o.getID() not in taken:
            paired[i.getID()] = o
            taken.add(o.getID())
    arms = []
    for i in incoming:
        o = paired.get(i.getID())
        heading = (in_dir[i.getID()] + 180.0) % 360.0
        arms.append(_RawArm(i.getID(), round(heading, 6), lanes(i), lanes(o) if o is not None else ()))
    for o in outgoing:
        if o.getID() not in taken:
            arms.append(_RawArm(o.getID(), round((out_dir[o.getID()] + 180.0) % 360.0, 6), (), lanes(o)))
    return arms


def _connections(incoming: list[Any], outgoing_ids: set[str]) -> tuple[Connection, ...]:
    found = []
    for edge in incoming:
        for to_edge, links in edge.getOutgoing().items():
            if to_edge.getID() not in outgoing_ids:
                continue
            for link in links:
                src, dst = link.getFromLane(), link.getToLane()
                if src.allows(CAR) and dst.allows(CAR):
                    found.append(Connection(src.getID(), dst.getID(), link.getDirection(), link.getViaLaneID() or None))
    return tuple(sorted(found, key=lambda c: (c.from_lane, c.to_lane, c.direction)))


def _straight_sites(net: Any, min_length: float) -> list[Site]:
    lanes = _Lanes()
    roads = sorted((e for e in net.getEdges() if _is_road(e)), key=_eid)
    used: set[str] = set()
    sites = []
    for edge in roads:
        if edge.getID() in used:
            continue
        used.add(edge.getID())
        reverse = _reverse_of(edge, used, lanes)
        if reverse is not None:
            used.add(reverse.getID())
            if _median(lanes(edge), lanes(reverse)) <= MEDIAN_MAX:
                if all(_is_straight(lanes(e), min_length) for e in (edge, reverse)):
                    sites.append(_straight_site([edge, reverse], lanes))
                continue
        for one_way in (edge, reverse):
            # a one-way single lane is not a road to stage a crash on
            if one_way is not None and len(lanes(one_way)) >= 2 and _is_straight(lanes(one_way), min_length):
                sites.append(_straight_site([one_way], lanes))
    return sites


def _median(there: tuple[LaneInfo, ...], back: tuple[LaneInfo, ...]) -> float:
    """The gap between the two directions' inner (left-most) car lanes, at the middle of the road."""
    inner, other = there[-1], back[-1]
    middle = point_at(inner.shape, shape_length(inner.shape) / 2.0)
    gap = distances_to(np.asarray(other.shape), np.asarray([middle]))[0]
    return float(gap) - (inner.width + other.width) / 2.0


def _reverse_of(edge: Any, used: set[str], lanes: _Lanes) -> Any | None:
    """The edge running the other way between the same two nodes, if any (the closest in length)."""
    heading = heading_between(_axis(lanes(edge))[0], _axis(lanes(edge))[-1])
    back = [
        e
        for e in edge.getToNode().getOutgoing()
        if e.getToNode() is edge.getFromNode()
        and e.getID() not in used
        and _is_road(e)
        and abs(angle_diff(heading_between(_axis(lanes(e))[0], _axis(lanes(e))[-1]), heading + 180.0)) <= 30.0
    ]
    length = _axis(lanes(edge))
    return min(back, key=lambda e: (abs(shape_length(_axis(lanes(e))) - shape_length(length)), e.getID()), default=None)


def _is_straight(lanes: tuple[LaneInfo, ...], min_length: float) -> bool:
    shape = _axis(lanes)
    length = shape_length(shape)
    if length < min_length or max_offset_from_chord(shape) > length * length / (8.0 * STRAIGHT_RADIUS):
        return False
    return max_kink(shape) <= STRAIGHT_KINK


def _straight_site(directions: list[Any], lanes: _Lanes) -> Site:
    headings = [heading_between(_axis(lanes(e))[0], _axis(lanes(e))[-1]) for e in directions]
    frame = fit_frame(headings)
    arms = []
    for k, edge in enumerate(directions):
        other = directions[1 - k] if len(directions) == 2 else None
        own = lanes(edge)
        arms.append(
            Arm(edge.getID(), round(headings[k], 6), frame.slots[k], own, lanes(other) if other else (), own[0].length)
        )
    middles = [point_at(_axis(lanes(e)), shape_length(_axis(lanes(e))) / 2.0) for e in directions]
    centre = (sum(p[0] for p in middles) / len(middles), sum(p[1] for p in middles) / len(middles))
    return Site(
        id="road:" + "|".join(e.getID() for e in directions),
        kind=RoadKind.STRAIGHT,
        centre=(round(centre[0], 3), round(centre[1], 3)),
        orientation=frame.orientation,
        arms=tuple(sorted(arms, key=lambda arm: arm.slot)),
    )


def _eid(edge: Any) -> str:
    return edge.getID()
