"""Junctions as a person sees them: a cluster of nodes read as one junction.

netconvert often builds one junction as several nodes a few metres apart:
- from OpenDRIVE and OSM, a junction is split into nodes joined by short edges;
- a divided road meets a side road at one node per carriageway, the side road's two
  directions (or a crossing of the median) joining them.
Nodes with no road between them are no one junction, however close: no traffic goes from one
to another (side roads on both sides of a divided road with no gap in its median are two T's).
Read node by node, each such node is a one-way 'T' or a half of a cross. Here the junction
nodes of a map are grouped (from geometry alone: how far apart they are against the width of
their roads, and what joins them) and each group is read as one junction: its arms are the
roads that leave the group, an incoming and an outgoing carriageway on the same side paired
into one two-way arm, and its connections run across the group's nodes and the short edges
between them (`Connection.path`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.geometry.polyline import end_heading, start_heading
from sovarc.compiler.maps.roads import CAR, PAIR_TOLERANCE, NodeArm, RoadNet, axis, is_road

# Two junction nodes are one junction when their centres are no further apart than the widths of
# their widest roads together (the two nodes' junction areas then lie within one crossing of those
# roads) and something joins them: a car edge, or a road whose two directions end one at each.
JOIN_WIDTHS = 1.0
MAX_NODES = 6  # a group of more nodes than this is a stretch of town, not a junction
MAX_HOPS = 8  # SUMO lanes a connection may run on inside a group


@dataclass(frozen=True)
class Cluster:
    """One junction: its nodes (one for a plain junction), the edges inside it, its arms."""

    nodes: tuple[Any, ...]  # sumolib nodes, sorted by id
    inner: frozenset[str]  # ids of the car edges with both ends in it
    arms: tuple[NodeArm, ...]

    @property
    def id(self) -> str:
        return "+".join(node.getID() for node in self.nodes)


def junction_clusters(roads: RoadNet) -> list[Cluster]:
    """Every junction of the map (three or more arms), nodes that make one junction grouped."""
    junctions = [node for node in roads.net.getNodes() if roads.is_junction(node)]
    ids = {node.getID() for node in junctions}
    width = {node.getID(): _node_width(roads, node) for node in junctions}
    parent = {nid: nid for nid in ids}

    def root(nid: str) -> str:
        while parent[nid] != nid:
            parent[nid] = parent[parent[nid]]
            nid = parent[nid]
        return nid

    for a, b in sorted(_joined(roads, junctions, ids, width)):
        parent[max(root(a), root(b))] = min(root(a), root(b))
    groups: dict[str, list[Any]] = {}
    for node in junctions:
        groups.setdefault(root(node.getID()), []).append(node)
    found = []
    for members in groups.values():
        members.sort(key=lambda n: n.getID())
        if len(members) == 1 or len(members) > MAX_NODES:
            found += [Cluster((n,), frozenset(), roads.arms[n.getID()]) for n in members]
            continue
        cluster = _cluster(roads, members)
        if cluster is None:  # the group makes no T or cross: its nodes are read one by one
            found += [Cluster((n,), frozenset(), roads.arms[n.getID()]) for n in members]
        else:
            found.append(cluster)
    return sorted(found, key=lambda c: c.id)


def _node_width(roads: RoadNet, node: Any) -> float:
    """The width of the widest road at a node: its arm's car lanes, both directions."""
    widths = [0.0]
    for arm in roads.arms[node.getID()]:
        lanes = [lane for edge in (arm.incoming, arm.outgoing) if edge is not None for lane in roads.lanes(edge)]
        widths.append(sum(lane.width for lane in lanes))
    return max(widths)


def _joined(roads: RoadNet, junctions: list[Any], ids: set[str], width: dict[str, float]) -> set[tuple[str, str]]:
    """Pairs of junction nodes close enough, and joined, to be one junction."""

    def close(a: Any, b: Any) -> bool:
        return math.dist(a.getCoord()[:2], b.getCoord()[:2]) <= JOIN_WIDTHS * (width[a.getID()] + width[b.getID()])

    pairs: set[tuple[str, str]] = set()
    for node in junctions:
        for edge in node.getOutgoing():
            other = edge.getToNode()
            if is_road(edge) and other.getID() in ids and other is not node and close(node, other):
                pairs.add(tuple(sorted((node.getID(), other.getID()))))  # type: ignore[arg-type]
    # a road whose two directions end at two nodes (a divided road, a side road split at its mouth):
    # a one-way incoming arm at one node beside a one-way outgoing arm of the same heading at the other
    halves = {
        n.getID(): [a for a in roads.arms[n.getID()] if (a.incoming is None) != (a.outgoing is None)] for n in junctions
    }
    cell = 2.0 * JOIN_WIDTHS * max(width.values(), default=1.0) or 1.0
    grid: dict[tuple[int, int], list[Any]] = {}
    for node in junctions:
        if halves[node.getID()]:
            x, y = node.getCoord()[:2]
            grid.setdefault((int(x // cell), int(y // cell)), []).append(node)
    for (i, j), here in sorted(grid.items()):
        near = [n for di in (-1, 0, 1) for dj in (-1, 0, 1) for n in grid.get((i + di, j + dj), [])]
        for a in here:
            for b in near:
                if a.getID() < b.getID() and close(a, b) and _split_road(halves[a.getID()], halves[b.getID()]):
                    pairs.add((a.getID(), b.getID()))
    return pairs


def _split_road(at_a: list[NodeArm], at_b: list[NodeArm]) -> bool:
    """Whether one node's one-way arms and the other's hold the two directions of one road."""
    return any(
        (x.incoming is None) != (y.incoming is None) and abs(angle_diff(x.heading, y.heading)) <= PAIR_TOLERANCE
        for x in at_a
        for y in at_b
    )


def _cluster(roads: RoadNet, members: list[Any]) -> Cluster | None:
    """The group as one junction, or None when its roads make no T or cross."""
    inside = {n.getID() for n in members}
    inner = frozenset(
        e.getID()
        for n in members
        for e in n.getOutgoing()
        if is_road(e) and e.getToNode().getID() in inside and e.getFromNode() is not e.getToNode()
    )
    if not inner:
        # no road between its nodes, so no traffic goes from one to another: each node is a junction
        # of its own (side roads meeting a divided road's carriageways, with no gap in the median)
        return None
    halves: list[NodeArm] = []
    for node in members:
        for arm in roads.arms[node.getID()]:
            incoming = arm.incoming if arm.incoming is not None and arm.incoming.getID() not in inner else None
            outgoing = arm.outgoing if arm.outgoing is not None and arm.outgoing.getID() not in inner else None
            if incoming is None and outgoing is None:
                continue
            if incoming is not None and outgoing is not None:
                halves.append(NodeArm(arm.heading, incoming, outgoing))
            else:
                halves.append(_half(roads, incoming, outgoing))
    arms = _pair_halves(roads, halves)
    if len(arms) not in (3, 4):
        return None
    # One junction, as a person sees it, when its roads are two-way or when reading it whole pairs
    # carriageways that each node alone leaves one-way. A knot of one-way links (a ramp system, a
    # roundabout's entries) grouped only in part would make a junction of no more two-way roads.
    one_way = sum(_one_way(arm) for arm in arms)
    if one_way and one_way >= min(sum(_one_way(arm) for arm in roads.arms[n.getID()]) for n in members):
        return None
    return Cluster(tuple(members), inner, tuple(arms))


def _one_way(arm: NodeArm) -> bool:
    return arm.incoming is None or arm.outgoing is None


def _half(roads: RoadNet, incoming: Any | None, outgoing: Any | None) -> NodeArm:
    """A one-way arm: what is left of a node's arm when its other direction is inside the group."""
    if incoming is not None:
        return NodeArm(round(end_heading(axis(roads.lanes(incoming))) % 360.0, 6), incoming, None)
    return NodeArm(round((start_heading(axis(roads.lanes(outgoing))) + 180.0) % 360.0, 6), None, outgoing)


def _pair_halves(roads: RoadNet, halves: list[NodeArm]) -> list[NodeArm]:
    """One-way arms of the group on the same side (their traffic entering in about the same
    direction, their ends side by side) paired into two-way arms: a divided road's carriageways."""
    ins = [h for h in halves if h.incoming is not None and h.outgoing is None]
    outs = [h for h in halves if h.outgoing is not None and h.incoming is None]
    candidates = []
    for i in ins:
        end = roads.lanes(i.incoming)[-1].shape[-1]
        reach = sum(lane.width for lane in roads.lanes(i.incoming))
        for o in outs:
            diff = abs(angle_diff(i.heading, o.heading))
            start = roads.lanes(o.outgoing)[-1].shape[0]
            gap = math.dist(end, start)
            span = reach + sum(lane.width for lane in roads.lanes(o.outgoing))
            if diff <= PAIR_TOLERANCE and gap <= JOIN_WIDTHS * 2.0 * span:
                candidates.append((round(diff, 6), round(gap, 3), i.incoming.getID(), o.outgoing.getID(), i, o))
    used: set[int] = set()
    paired = []
    for *_, i, o in sorted(candidates, key=lambda c: c[:4]):
        if id(i) in used or id(o) in used:
            continue
        used |= {id(i), id(o)}
        paired.append(NodeArm(i.heading, i.incoming, o.outgoing))
    arms = paired + [h for h in halves if id(h) not in used]
    return sorted(arms, key=lambda a: (a.incoming or a.outgoing).getID())


Way = tuple[Any, tuple[str, ...], tuple[str, ...]]  # a SUMO lane, the lanes before it, the edges driven


def paths(roads: RoadNet, cluster: Cluster, from_lane: Any, exits: set[str]) -> list[Way]:
    """From an incoming SUMO lane, every way across the cluster to a lane of an exit edge (`exits`):
    (the exit lane, the SUMO lanes between, the inner edges driven), the shortest per exit lane."""
    found: dict[str, Way] = {}
    frontier: list[Way] = [(from_lane, (), ())]
    seen = {from_lane.getID()}
    while frontier:
        step = []
        for lane, between, edges in frontier:
            for link in lane.getOutgoing():
                to = link.getToLane()
                if not to.allows(CAR):
                    continue
                through = tuple(vias(roads, link))
                edge = to.getEdge().getID()
                if edge in exits:
                    found.setdefault(to.getID(), (to, between + through, edges))
                elif edge in cluster.inner and to.getID() not in seen and len(between) < MAX_HOPS:
                    seen.add(to.getID())
                    step.append((to, (*between, *through, to.getID()), (*edges, edge)))
        frontier = sorted(step, key=lambda s: s[0].getID())
    return [found[k] for k in sorted(found)]


def vias(roads: RoadNet, link: Any) -> list[str]:
    """The internal lanes a link runs on, in order (SUMO splits some turns in two)."""
    found: list[str] = []
    via = link.getViaLaneID()
    while via and len(found) < 5:
        found.append(via)
        via = next((c.getViaLaneID() for c in roads.net.getLane(via).getOutgoing() if c.getViaLaneID()), "")
    return found
