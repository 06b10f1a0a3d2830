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

Roads are read as a person sees them, not edge by edge (roads.py): a road runs on through the
nodes netconvert adds where lanes begin or end, so a junction's arm reaches back through them
(while its lane count stays, or back through where lanes open beside it, a turn pocket, up to
ARM_REACH) and a straight site is a stretch of bounded
curvature along a road, wherever its edges split (straights.py). Such a lane is a chain of SUMO
lanes (`LaneInfo.lanes`, `.edges`). A junction is a T or a cross by its arms' headings, and a
junction netconvert built as several nodes (a divided road's carriageways each meeting a side
road at a node of its own, a junction split by short edges) is one junction (clusters.py).
A junction is one of crossing traffic: where one-way roads only merge and diverge (ramps) or a
two-way road parts into its two directions, a person sees no T and no cross, and none is made.

Each site lays a compass cross over its arms (`Site.orientation`, `Arm.slot`): arm slot k
ideally has heading `orientation + 90 * k`. The site search rotates reports on this cross.
"""

from __future__ import annotations

import itertools
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from sovarc.compiler.geometry.polyline import end_heading, start_heading
from sovarc.compiler.maps.clusters import Cluster, junction_clusters, paths, vias
from sovarc.compiler.maps.geometry import fit_frame
from sovarc.compiler.maps.medians import open_medians
from sovarc.compiler.maps.roads import CAR, LaneInfo, NodeArm, RoadNet, axis
from sovarc.compiler.maps.site import Arm, Connection, Site
from sovarc.compiler.maps.straights import MEDIAN_MAX as MEDIAN_MAX  # lowering's median rule
from sovarc.compiler.maps.straights import straight_sites
from sovarc.compiler.vehicles import CAR_MODEL
from sovarc.dsl.ir import RoadKind

if TYPE_CHECKING:
    from sovarc.compiler.maps.load import RoadMap

# m: a straight site is at least this long; a shorter stretch (a city block) is a site of last resort
DEFAULT_MIN_LENGTH = 80.0
# The shortest straight stretch kept at all (`short_sites`): a straight crash puts two cars on the
# road, one closing on the other, and a driver follows another at the two-second gap at the least a
# town's streets are driven at, 30 km/h: two car bodies and that gap, 2 x 4.6 + 16.7 = 26 m. On less,
# no two cars are in traffic one behind the other, nor meet head on (the same gap closed from both
# ends); a city block of 50-70 m between junctions leaves more once the junctions are taken off.
FOLLOWING_GAP = 2.0  # s: the two-second rule of driving manuals
SLOWEST_STREET = 30.0 / 3.6  # m/s: the lowest urban speed limit (30 km/h zones)
SHORT_MIN_LENGTH = round(2 * CAR_MODEL.body.length + FOLLOWING_GAP * SLOWEST_STREET, 1)  # m
CROSS_TOLERANCE = 35.0  # degrees an intersection's or T's arm may stray from its place in the cross
# ... and where every arm is a two-way road: two roads crossing at 50 degrees or more are still a
# crossing a person sees (a ring road crossing the spokes of a town's radial streets meets them at
# 54), and the moves across it are planned and replayed as at a square one. One-way arms that close
# are how carriageways and ramps part and merge: a fork, no T.
SKEW_TOLERANCE = 40.0
# a turn by the exit arm's place in the cross, counted clockwise from the entry arm's (see search.py)
TURNS = {0: "t", 1: "l", 2: "s", 3: "r"}
ARM_REACH = 100.0  # m: a junction's arm reaches back this far through pass-through nodes (RoadNet.reach)


def find_sites(
    road_map: RoadMap, kind: RoadKind | str | None = None, *, min_length: float = DEFAULT_MIN_LENGTH
) -> list[Site]:
    """Every site of the map, or those of one kind, sorted by id. Computed once per map and min_length."""
    sites = road_map.cache.get(min_length)
    if sites is None:
        roads = road_net(road_map)
        junctions, road_map.cache["merges"] = _junction_sites(roads)
        straights, short = straight_sites(roads, min_length, _open_edges(road_map), floor=SHORT_MIN_LENGTH)
        sites = road_map.cache[min_length] = tuple(sorted(junctions + straights, key=lambda s: s.id))
        road_map.cache["short", min_length] = tuple(sorted(short, key=lambda s: s.id))
    return _of_kind(sites, kind)


def short_sites(
    road_map: RoadMap, kind: RoadKind | str | None = None, *, min_length: float = DEFAULT_MIN_LENGTH
) -> list[Site]:
    """The straight sites of last resort, sorted by id: stretches of a road between junctions shorter
    than `min_length` and at least SHORT_MIN_LENGTH long (a city block), which `find_sites` leaves out."""
    find_sites(road_map, min_length=min_length)
    return _of_kind(road_map.cache["short", min_length], kind)


def _of_kind(sites: tuple[Site, ...], kind: RoadKind | str | None) -> list[Site]:
    wanted = RoadKind(kind) if kind is not None else None
    return [s for s in sites if wanted is None or s.kind is wanted]


# --- building sites from sumolib objects (typed Any: sumolib has no type hints) ---


def road_net(road_map: RoadMap) -> RoadNet:
    """The map's roads (node arms, edge chains), built once per map."""
    roads = road_map.cache.get("roads")
    if roads is None:
        roads = road_map.cache["roads"] = RoadNet(road_map.net)
    return roads


def _open_edges(road_map: RoadMap) -> frozenset[str]:
    """The edges whose road has a median a car can drive across: only an OpenDRIVE map says so
    (medians.py); in a SUMO network the ground between two carriageways is not described."""
    if road_map.format != "opendrive":
        return frozenset()
    return open_medians(road_map.path, (e.getID() for e in road_map.net.getEdges()))


def merges(road_map: RoadMap) -> int:
    """How many junctions of the map are one-way roads merging or diverging, and so no site."""
    find_sites(road_map)
    return int(road_map.cache["merges"])


def _junction_sites(roads: RoadNet) -> tuple[list[Site], int]:
    """The T's and crosses of the map, and how many merges or diverges of one-way roads it has."""
    sites = []
    merging = 0
    for cluster in junction_clusters(roads):
        raw = [_arm_lanes(roads, arm) for arm in cluster.arms]
        if len(raw) not in (3, 4):
            continue
        frame = fit_frame([heading for _, heading, _, _ in raw])
        two_way = all(incoming and outgoing for _, _, incoming, outgoing in raw)
        if frame.error > (SKEW_TOLERANCE if two_way else CROSS_TOLERANCE):
            continue  # three or four roads, but not a T or a cross
        arms = sorted(
            (
                Arm(arm_id, heading, slot, incoming, outgoing, (incoming or outgoing)[0].length)
                for (arm_id, heading, incoming, outgoing), slot in zip(raw, frame.slots, strict=True)
            ),
            key=lambda arm: arm.slot,
        )
        kind = RoadKind.INTERSECTION if len(raw) == 4 else RoadKind.T_JUNCTION
        coords = [node.getCoord() for node in cluster.nodes]
        centre = (sum(c[0] for c in coords) / len(coords), sum(c[1] for c in coords) / len(coords))
        if len(cluster.nodes) == 1:
            incoming_edges = [a.incoming for a in cluster.arms if a.incoming is not None]
            outgoing_ids = {a.outgoing.getID() for a in cluster.arms if a.outgoing is not None}
            connections = _by_cross(_connections(roads, incoming_edges, outgoing_ids), arms)
        else:
            connections = _cluster_connections(roads, cluster, arms)
        if not any(arm.two_way for arm in arms) and not streams_cross(arms, connections):
            merging += 1  # one-way roads merging or diverging (a ramp, a carriageway's fork): no T, no cross
            continue
        if divides(arms, connections):
            continue  # a two-way road parting into its two directions: where a median or a loop begins
        sites.append(
            Site(
                id=f"junction:{cluster.id}",
                kind=kind,
                centre=(round(centre[0], 3), round(centre[1], 3)),
                orientation=frame.orientation,
                arms=tuple(arms),
                connections=connections,
                junction=cluster.id,
                control="/".join(sorted({node.getType() for node in cluster.nodes})),
            )
        )
    return sites, merging


def divides(arms: list[Arm], connections: tuple[Connection, ...]) -> bool:
    """Whether three arms are one two-way road parting into its two directions: the other two arms
    are one-way, one in and one out, and no traffic runs from the one into the other (a one-way
    road through the node would). A person sees a road dividing there, no T-junction."""
    if len(arms) != 3 or sum(arm.two_way for arm in arms) != 1:
        return False
    ins = [arm for arm in arms if arm.incoming and not arm.outgoing]
    outs = [arm for arm in arms if arm.outgoing and not arm.incoming]
    if len(ins) != 1 or len(outs) != 1:
        return False
    entering = {lane.id for lane in ins[0].incoming}
    leaving = {lane.id for lane in outs[0].outgoing}
    # a turnaround from the one into the other is a U-turn at the road's end, no road through
    return not any(c.from_lane in entering and c.to_lane in leaving and c.direction != "t" for c in connections)


def streams_cross(arms: list[Arm], connections: tuple[Connection, ...]) -> bool:
    """Whether two streams of traffic through a junction of one-way arms cross each other.

    Each arm is a point on a circle around the junction (where it lies: opposite its entering
    heading) and each stream a chord from the arm it enters by to the arm it leaves by; two
    chords cross when their ends alternate around the circle. Where one-way roads only merge and
    diverge (a ramp joining or leaving a carriageway, two carriageways meeting in a loop), no
    chords cross and a person sees no junction; two one-way streets crossing do cross.
    """
    place = {}
    for arm in arms:
        for lane in arm.incoming + arm.outgoing:
            place[lane.id] = arm.id
    where = {arm.id: (arm.heading + 180.0) % 360.0 for arm in arms}
    chords = sorted({(place[c.from_lane], place[c.to_lane]) for c in connections if c.from_lane in place})
    order = {arm_id: k for k, arm_id in enumerate(sorted(where, key=lambda a: (where[a], a)))}

    def between(x: int, a: int, b: int) -> bool:  # x strictly inside the arc from a to b, going round
        return 0 < (x - a) % len(order) < (b - a) % len(order)

    for (a, b), (c, d) in itertools.combinations(chords, 2):
        if len({a, b, c, d}) == 4:
            i, j, k, m = order[a], order[b], order[c], order[d]
            if between(k, i, j) != between(m, i, j):
                return True
    return False


def _arm_lanes(roads: RoadNet, arm: NodeArm) -> tuple[str, float, tuple[LaneInfo, ...], tuple[LaneInfo, ...]]:
    """An arm's id, heading and lanes, each lane chained back (incoming) or on (outgoing) through
    pass-through nodes while the lane count stays (incoming, also back through where lanes open:
    RoadNet.reach), up to ARM_REACH metres."""
    incoming: tuple[LaneInfo, ...] = ()
    outgoing: tuple[LaneInfo, ...] = ()
    if arm.incoming is not None:
        edges = roads.reach(arm.incoming, forward=False, length=ARM_REACH)
        incoming = roads.chained(edges, len(edges) - 1)
    if arm.outgoing is not None:
        outgoing = roads.chained(roads.reach(arm.outgoing, forward=True, length=ARM_REACH), 0)
    heading = end_heading(axis(incoming)) if incoming else (start_heading(axis(outgoing)) + 180.0) % 360.0
    arm_id = (arm.incoming or arm.outgoing).getID()
    return arm_id, round(heading, 6), incoming, outgoing


def _connections(roads: RoadNet, incoming: list[Any], outgoing_ids: set[str]) -> tuple[Connection, ...]:
    found = []
    for edge in incoming:
        for to_edge, links in edge.getOutgoing().items():
            if to_edge.getID() not in outgoing_ids:
                continue
            for link in links:
                src, dst = link.getFromLane(), link.getToLane()
                if src.allows(CAR) and dst.allows(CAR):
                    path = tuple(vias(roads, link))
                    via = path[0] if path else None
                    found.append(Connection(src.getID(), dst.getID(), link.getDirection(), via, path))
    return tuple(sorted(found, key=lambda c: (c.from_lane, c.to_lane, c.direction)))


def _cross_turn(entry_slot: int, exit_slot: int) -> str:
    """SUMO's name of the turn from the arm in `entry_slot` of a compass cross to the one in `exit_slot`."""
    return TURNS[(exit_slot - entry_slot) % 4]


def _by_cross(connections: tuple[Connection, ...], arms: list[Arm]) -> tuple[Connection, ...]:
    """The connections with each turn named by the exit arm's place in the junction's compass cross,
    as across a junction of several nodes. SUMO names a turn by its angle alone: where a junction is
    skewed (a road bending through a T, a Y, a spider's ring) it may call the way to the opposite
    arm a left or have no straight at all, while the site search places a scenario's moves by the
    cross, and a move must lead where the cross says. A way back into the arm it came by keeps
    SUMO's name: the arm's two edges may be two roads leaving side by side, not one road's two ways."""
    slot = {lane.id: arm.slot for arm in arms for lane in arm.incoming + arm.outgoing}
    named = []
    for c in connections:
        turn = _cross_turn(slot[c.from_lane], slot[c.to_lane])
        named.append(c if turn == TURNS[0] else replace(c, direction=turn))
    return tuple(sorted(named, key=lambda c: (c.from_lane, c.to_lane, c.direction)))


def _cluster_connections(roads: RoadNet, cluster: Cluster, arms: list[Arm]) -> tuple[Connection, ...]:
    """Every way across a junction of several nodes, from an arm's incoming lane to another's (or
    its own) outgoing lane, through the nodes and the short edges between them. Its direction is
    read from the arms' places in the junction's compass cross: SUMO's own names the turn at
    one node only (a left turn across a divided road is a 'straight on' and then a 'left')."""
    exits = {lane.edge: arm for arm in arms for lane in arm.outgoing}
    found = []
    for arm in arms:
        for lane in arm.incoming:
            start = roads.net.getLane(lane.id)
            for to, path, edges in paths(roads, cluster, start, set(exits)):
                if not to.allows(CAR):
                    continue
                direction = _cross_turn(arm.slot, exits[to.getEdge().getID()].slot)
                via = next((x for x in path if x.startswith(":")), None)
                found.append(Connection(lane.id, to.getID(), direction, via, path, edges))
    return tuple(sorted(found, key=lambda c: (c.from_lane, c.to_lane, c.direction)))
