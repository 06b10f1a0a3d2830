"""Roads as a person sees them in a network netconvert built (from OpenDRIVE, OSM or plain XML).

netconvert splits one road into many edges: at every OpenDRIVE lane section, at every OSM way
end, wherever a lane begins or ends. Such a node joins two arms and nothing else; it is no
junction. Here the map's nodes are sorted into junctions (three or more arms) and pass-through
nodes (two arms), and each edge is continued through pass-through nodes, so that a road is a
chain of edges and a lane of it a chain of SUMO lanes (with the internal lanes between them).

An arm of a node: its incoming and outgoing car edges that leave the node in about the same
direction, paired into one two-way road (see `node_arms`).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.geometry.polyline import Shape, end_heading, shape_length, start_heading

CAR = "passenger"  # the SUMO vehicle class a site's lanes must allow
TINY = 2.0  # m: an edge this short (netconvert leaves some between lane sections) does not split a road
PAIR_TOLERANCE = 40.0  # an incoming and an outgoing edge this close in direction form one arm
THROUGH_TYPES = frozenset({"priority", "priority_stop"})  # junctions where a main road has the right of way
THROUGH_TOLERANCE = 20.0  # degrees a main road may bend going through a junction


@dataclass(frozen=True)
class LaneInfo:
    """One car lane of a road: one SUMO lane, or a chain of them through pass-through nodes.

    `id`, `edge` and `index` name the SUMO lane at the site's junction (the last of an incoming
    chain, the first of an outgoing one) or, on a straight site, its lane on its longest edge.
    `lanes` and `edges` are every SUMO lane (internal lanes between edges included) and every
    edge the chain runs on, in the direction of travel; `shape` is the chain's centre line.
    """

    id: str  # SUMO lane id
    edge: str  # SUMO edge id
    index: int  # SUMO's index on the edge: 0 is the right-most lane (maybe a sidewalk)
    number: int  # counted from the right-most car lane of the edge as 1, as in the IR
    width: float  # m; the narrowest along a chain
    length: float  # m
    speed: float  # m/s, the lane's speed limit (the lowest along a chain)
    shape: Shape  # centre line, in the direction of travel
    lanes: tuple[str, ...] = ()  # every SUMO lane it runs on, in order; (id,) for one lane
    edges: tuple[str, ...] = ()  # every SUMO edge it runs on, in order; (edge,) for one lane

    def __post_init__(self) -> None:
        if not self.lanes:
            object.__setattr__(self, "lanes", (self.id,))
        if not self.edges:
            object.__setattr__(self, "edges", (self.edge,))


@dataclass(frozen=True)
class NodeArm:
    """One road at a node: the edge entering the node along it and the edge leaving by it."""

    heading: float  # compass degrees of traffic entering the node along it
    incoming: Any | None  # sumolib edge
    outgoing: Any | None


def is_road(edge: Any) -> bool:
    return not edge.isSpecial() and edge.allows(CAR)


class RoadNet:
    """A map's car lanes, node arms and edge chains, computed once per map."""

    def __init__(self, net: Any) -> None:
        self.net = net
        self._lanes: dict[str, tuple[LaneInfo, ...]] = {}
        self.arms: dict[str, tuple[NodeArm, ...]] = {}
        for node in net.getNodes():
            self.arms[node.getID()] = self._node_arms(node)
        self._next: dict[str, Any] = {}
        self._prev: dict[str, Any] = {}
        self._reverse: dict[str, Any] = {}
        self._through_next: dict[str, Any] = {}  # a main road on through a priority junction
        self._through_prev: dict[str, Any] = {}
        for node in net.getNodes():
            arms = self.arms[node.getID()]
            for arm in arms:
                if arm.incoming is not None and arm.outgoing is not None:
                    self._reverse.setdefault(arm.incoming.getID(), arm.outgoing)
                    self._reverse.setdefault(arm.outgoing.getID(), arm.incoming)
            if len(arms) == 2:
                for here, there in (arms, arms[::-1]):
                    if (
                        here.incoming is not None
                        and there.outgoing is not None
                        and _linked(here.incoming, there.outgoing)
                    ):
                        self._next[here.incoming.getID()] = there.outgoing
                        self._prev[there.outgoing.getID()] = here.incoming
            elif len(arms) == 3 and node.getType() in THROUGH_TYPES:
                self._through_road(arms)

    def _through_road(self, arms: tuple[NodeArm, ...]) -> None:
        """A junction where one road runs straight on with the right of way and the others give way
        to it: that road goes on through the junction (a straight site may span it)."""
        pairs = []
        for here, there in itertools.combinations(arms, 2):
            if abs(angle_diff(here.heading, there.heading)) < 180.0 - THROUGH_TOLERANCE:
                continue
            links = [(a.incoming, b.outgoing) for a, b in ((here, there), (there, here)) if a.incoming and b.outgoing]
            if links and all(_major_straight(a, b) for a, b in links):
                pairs.append(links)
        if len(pairs) != 1:
            return  # no road through, or two (a crossing of equals)
        for a, b in pairs[0]:
            self._through_next[a.getID()] = b
            self._through_prev[b.getID()] = a

    # --- nodes ---

    def is_junction(self, node: Any) -> bool:
        """Three or more arms meet here (a pass-through node has two, a dead end one)."""
        return len(self.arms[node.getID()]) >= 3

    def _node_arms(self, node: Any) -> tuple[NodeArm, ...]:
        """Group a node's car edges into arms: an incoming and an outgoing edge that leave the
        node in about the same direction are one two-way road (same far node preferred)."""
        incoming = sorted((e for e in node.getIncoming() if is_road(e) and e.getFromNode() is not node), key=_eid)
        outgoing = sorted((e for e in node.getOutgoing() if is_road(e) and e.getToNode() is not node), key=_eid)
        out_dir = {e.getID(): start_heading(axis(self.lanes(e))) for e in outgoing}
        in_dir = {e.getID(): (end_heading(axis(self.lanes(e))) + 180.0) % 360.0 for e in incoming}
        candidates = []
        for i in incoming:
            for o in outgoing:
                diff = abs(angle_diff(in_dir[i.getID()], out_dir[o.getID()]))
                if diff <= PAIR_TOLERANCE:
                    candidates.append(
                        (o.getToNode() is not i.getFromNode(), round(diff, 6), i.getID(), o.getID(), i, o)
                    )
        paired: dict[str, Any] = {}
        taken: set[str] = set()
        for *_, i, o in sorted(candidates, key=lambda c: c[:4]):
            if i.getID() not in paired and o.getID() not in taken:
                paired[i.getID()] = o
                taken.add(o.getID())
        arms = [NodeArm(round((in_dir[i.getID()] + 180.0) % 360.0, 6), i, paired.get(i.getID())) for i in incoming]
        arms += [
            NodeArm(round((out_dir[o.getID()] + 180.0) % 360.0, 6), None, o) for o in outgoing if o.getID() not in taken
        ]
        return tuple(arms)

    # --- edges ---

    def lanes(self, edge: Any) -> tuple[LaneInfo, ...]:
        """The car lanes of one edge, right-most first."""
        eid = edge.getID()
        if eid not in self._lanes:
            cars = sorted((lane for lane in edge.getLanes() if lane.allows(CAR)), key=lambda lane: lane.getIndex())
            self._lanes[eid] = tuple(
                LaneInfo(
                    id=lane.getID(),
                    edge=eid,
                    index=lane.getIndex(),
                    number=number,
                    width=round(lane.getWidth(), 3),
                    length=round(lane.getLength(), 3),
                    speed=round(lane.getSpeed(), 3),
                    shape=_shape(lane.getShape()),
                )
                for number, lane in enumerate(cars, start=1)
            )
        return self._lanes[eid]

    def next_edge(self, edge: Any) -> Any | None:
        """The edge this one continues as through a pass-through node, if its end is one."""
        return self._next.get(edge.getID())

    def prev_edge(self, edge: Any) -> Any | None:
        return self._prev.get(edge.getID())

    def reverse(self, edge: Any) -> Any | None:
        """The edge of the other direction of the same road (paired in an arm at either end)."""
        return self._reverse.get(edge.getID())

    def chain(self, edge: Any, *, through: bool = False) -> list[Any]:
        """The whole road `edge` is on, in its direction: back and on through pass-through nodes
        (and, with `through`, through the junctions where it is the main road), never into its
        own other direction."""
        seen = {edge.getID()}
        edges = [edge]

        def before(e: Any) -> Any | None:
            found = self.prev_edge(e)
            return found if found is not None or not through else self._through_prev.get(e.getID())

        def after(e: Any) -> Any | None:
            found = self.next_edge(e)
            return found if found is not None or not through else self._through_next.get(e.getID())

        def other_way(e: Any) -> bool:
            # a road that runs on into its own other direction (a turning loop, a cul-de-sac's
            # bulb) ends there: its two directions are partners, not one chain
            back = self.reverse(e)
            return back is not None and back.getID() in seen

        while (back := before(edges[0])) is not None and back.getID() not in seen and not other_way(back):
            seen.add(back.getID())
            edges.insert(0, back)
        while (on := after(edges[-1])) is not None and on.getID() not in seen and not other_way(on):
            seen.add(on.getID())
            edges.append(on)
        if (on := after(edges[-1])) is not None and on.getID() == edges[0].getID():
            # a ring (a block's perimeter, a ring road) has no first edge: start it at its least id,
            # so that its walk is the same from wherever it was found and its two directions agree
            # which of them stages the road (straights.py)
            start = min(range(len(edges)), key=lambda k: edges[k].getID())
            edges = edges[start:] + edges[:start]
        return edges

    def reach(self, edge: Any, forward: bool, length: float) -> list[Any]:
        """`edge` and the edges it continues as (forward) or continues (backward), in the direction
        of travel, while the road keeps its car lane count, until `length` metres are covered.
        Backward, it also runs on through a node where lanes open (a turn pocket, an added lane):
        a car reaches such a lane from the one it branches off, so the road behind is its approach
        too; the count is the narrower road's from there."""
        edges = [edge]
        count = len(self.lanes(edge))
        total = self.lanes(edge)[0].length
        seen = {edge.getID()}
        while total < length:
            step = self.next_edge(edges[-1]) if forward else self.prev_edge(edges[0])
            if step is None or step.getID() in seen or not self.lanes(step):
                break
            if len(self.lanes(step)) != count and self.lanes(step)[0].length > TINY:
                if forward or len(self.lanes(step)) > count:
                    break
                count = len(self.lanes(step))
            seen.add(step.getID())
            total += self.lanes(step)[0].length
            if forward:
                edges.append(step)
            else:
                edges.insert(0, step)
        return edges

    def chained(self, edges: Sequence[Any], at: int) -> tuple[LaneInfo, ...]:
        """The car lanes of `edges[at]`, each chained along the consecutive `edges` (back and on
        through the lanes it is linked with, else the nearest lane), and named by its lane there."""
        per_edge = [self.lanes(e) for e in edges]
        if len(edges) == 1:
            return per_edge[0]
        chains = []
        for named in per_edge[at]:
            parts = [named]
            for j in range(at - 1, -1, -1):
                parts.insert(0, self._linked_lane(per_edge[j], parts[0], before=True))
            for j in range(at + 1, len(edges)):
                parts.append(self._linked_lane(per_edge[j], parts[-1], before=False))
            ids: list[str] = []
            points: list[tuple[float, float]] = []
            for a, b in itertools.pairwise([*parts, None]):
                ids.append(a.id)
                points += a.shape if not points or a.shape[0] != points[-1] else a.shape[1:]
                if b is not None:
                    ids += self._vias(a.id, b.id)
            chains.append(
                replace(
                    named,
                    width=min((p.width for p in parts if p.length > TINY), default=named.width),
                    length=round(sum(p.length for p in parts), 3),
                    speed=min(p.speed for p in parts),
                    shape=tuple(points),
                    lanes=tuple(ids),
                    edges=tuple(p.edge for p in parts),
                )
            )
        return tuple(chains)

    def _linked_lane(self, candidates: tuple[LaneInfo, ...], lane: LaneInfo, before: bool) -> LaneInfo:
        """The lane of a neighbouring edge that `lane` continues (before) or continues as: the one
        a connection links it with, else the one whose end lies nearest."""
        ids = {c.id for c in candidates}
        if before:
            linked = [c for c in candidates if lane.id in self._successors(c.id)]
        else:
            linked = [c for c in candidates if c.id in self._successors(lane.id) and c.id in ids]
        pool = linked or list(candidates)
        here = lane.shape[0] if before else lane.shape[-1]
        return min(pool, key=lambda c: math.dist(c.shape[-1] if before else c.shape[0], here))

    def _successors(self, lane_id: str) -> set[str]:
        return {link.getToLane().getID() for link in self.net.getLane(lane_id).getOutgoing()}

    def _vias(self, from_lane: str, to_lane: str) -> list[str]:
        """The internal lanes from one lane to the next across a pass-through node."""
        lane = self.net.getLane(from_lane)
        found: list[str] = []
        for link in lane.getOutgoing():
            if link.getToLane().getID() == to_lane and link.getViaLaneID():
                via = link.getViaLaneID()
                while via and len(found) < 4:
                    found.append(via)
                    via = next((c.getViaLaneID() for c in self.net.getLane(via).getOutgoing() if c.getViaLaneID()), "")
                break
        return found


def axis(lanes: tuple[LaneInfo, ...]) -> Shape:
    """The shape that stands for a direction's lanes: its middle car lane."""
    return lanes[len(lanes) // 2].shape


def _major_straight(a: Any, b: Any) -> bool:
    """Whether edge `a` leads straight on into `b` with the right of way (SUMO's link state 'M')."""
    links = a.getOutgoing().get(b, [])
    return bool(links) and all(c.getDirection() == "s" and c.getState() == "M" for c in links)


def _linked(a: Any, b: Any) -> bool:
    return b in a.getOutgoing()


def _shape(points: Sequence[Sequence[float]]) -> Shape:
    out: list[tuple[float, float]] = []
    for p in points:
        q = (round(p[0], 3), round(p[1], 3))
        if not out or q != out[-1]:  # repeated vertices have no direction
            out.append(q)
    if len(out) == 1:
        out.append(out[0])
    return tuple(out)


def _eid(edge: Any) -> str:
    return edge.getID()


# --- plain polyline helpers on numpy arrays (the maps layer has no Polyline class) ---


def cumulative(points: np.ndarray) -> np.ndarray:
    return np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(points, axis=0).T))))


def project(points: np.ndarray, p: Sequence[float]) -> tuple[float, float]:
    """Arc length along `points` of the nearest point to `p`, and the distance to it."""
    a, ab = points[:-1], points[1:] - points[:-1]
    lengths2 = np.maximum((ab**2).sum(axis=1), 1e-12)
    rel = np.asarray(p, dtype=float) - a
    u = np.clip((rel * ab).sum(axis=1) / lengths2, 0.0, 1.0)
    gaps = np.hypot(*(rel - ab * u[:, None]).T)
    k = int(np.argmin(gaps))
    s = cumulative(points)
    return float(s[k] + u[k] * math.sqrt(lengths2[k])), float(gaps[k])


def project_many(
    line: np.ndarray, points: np.ndarray, chunk: int = 256, near: float | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """`project` for many points (n x 2): arc lengths and distances, n each. With `near`, only the
    segments that come that close to the points' bounding box are tried (a point further from
    every one of them gets a distance over `near`, not the true one)."""
    a, ab = line[:-1], line[1:] - line[:-1]
    lengths2 = np.maximum((ab**2).sum(axis=1), 1e-12)
    s = cumulative(line)
    if near is not None:
        low, high = points.min(axis=0) - near, points.max(axis=0) + near
        keep = ~(
            (np.minimum(line[:-1], line[1:]) > high).any(axis=1) | (np.maximum(line[:-1], line[1:]) < low).any(axis=1)
        )
        if not keep.any():
            return np.zeros(len(points)), np.full(len(points), np.inf)
        a, ab, lengths2, s = a[keep], ab[keep], lengths2[keep], s[:-1][keep]
    along, gaps = [], []
    for k in range(0, len(points), chunk):
        rel = points[k : k + chunk, None, :] - a[None, :, :]
        u = np.clip((rel * ab[None]).sum(axis=2) / lengths2, 0.0, 1.0)
        d = np.hypot(*(rel - ab[None] * u[:, :, None]).transpose(2, 0, 1))
        best = d.argmin(axis=1)
        rows = np.arange(len(best))
        along.append(s[best] + u[rows, best] * np.sqrt(lengths2[best]))
        gaps.append(d[rows, best])
    return np.concatenate(along), np.concatenate(gaps)


def cut(shape: Shape, lo: float, hi: float) -> Shape:
    """The part of a polyline from arc length `lo` to `hi`."""
    points = np.asarray(shape, dtype=float)
    s = cumulative(points)
    lo, hi = max(0.0, lo), min(float(s[-1]), hi)
    inside = [tuple(map(float, q)) for q, t in zip(points, s, strict=True) if lo < t < hi]
    ends = [tuple(float(np.interp(t, s, points[:, i])) for i in (0, 1)) for t in (lo, hi)]
    out = [ends[0], *inside, ends[1]]
    return tuple((round(x, 3), round(y, 3)) for x, y in out)


def length_of(shape: Shape) -> float:
    return shape_length(shape)
