"""Where a car may start on its route: past the last corner the SUMO oracle sees its body cross a line in.

An arm runs back through pass-through nodes (`RoadNet.chain`), and some are corners: a grid's
2-arm node bends the road 90 degrees within a few metres, its kerb lane at a radius of a metre
or two. A plan's body trails its front bumper along the heading (compiler/plan.py; the SUMO
oracle places it the same way), so there its rear swings over the lane's line, and no smooth
bend keeps a car's body in such a lane (swing.keep_in_lane reshapes only the site's own stop
line). The corner is not the site's, and the car need not drive it: `clear_start` is the least
start from which no pose up to the latest start would be judged crossing a line, and the solver
bounds the start by it only when its own choice lies before it (solve.py), so a plan that
started past the corner is unchanged.

The poses judged are the oracle's (targets/sumo/oracle.lane_violation): the front on a lane of
a road (a junction's internal lanes have no painted lines), a body corner moved in by the
oracle's tolerance inside a lane of that road (its edge or the edge the other way) that the
route does not use, and outside every lane it does. A swing over the kerb, into a lane of
another road, or inside a junction, crosses no line the oracle checks, and bounds nothing.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np
from sovarc.compiler.crashes import LINE_TOLERANCE
from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.geometry.bodies import corner_array
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.lower.swing import STEP, line_poses
from sovarc.compiler.vehicles import Body

BEND = 2.0  # degrees the line turns over a body length before its rear can leave the front's lane
HEADING_MATCH = 60.0  # degrees: a lane runs the car's way within this (the oracle's lane lookup)


@dataclass(frozen=True)
class _Lane:
    id: str
    line: Polyline
    half: float  # half its width
    internal: bool
    edge: str
    sidewalk: bool  # only pedestrians may use it


def clear_start(
    line: Polyline, lanes: Iterable[str], net: Any, body: Body, upto: float, *, kerb: bool = False
) -> float:
    """The least arc length on `line` (smoothed, as driven) from which the front of a car whose
    route may use `lanes` (SUMO lane ids) reaches `upto` with no pose on the way that crosses a
    line into a lane beside it; 0.0 when it may start anywhere. `kerb`: the car drives into or off
    the road by a driveway, so the sidewalk is its to cross (the oracle's `kerb`)."""
    if upto <= 0.0:
        return 0.0
    crossed = crossings(line, lanes, net, body, 0.0, upto, kerb=kerb)
    return float(min(crossed[-1] + STEP, upto)) if len(crossed) else 0.0


def crossings(
    line: Polyline,
    lanes: Iterable[str],
    net: Any,
    body: Body,
    lo: float,
    hi: float,
    *,
    kerb: bool = False,
    margin: float = 0.0,
) -> np.ndarray:
    """The arc lengths on `line`, every STEP from `lo` to `hi`, where the front of a car whose route may
    use `lanes` stands in a pose the oracle would judge crossing a line into a lane beside it, its
    body's corners moved out by `margin` (for a path that departs a little from the line)."""
    none = np.zeros(0)
    if hi <= lo or body.vclass == "pedestrian":
        return none
    poses = line_poses(line, lo, hi)
    if len(poses) < 2:
        return none
    at = max(0.0, lo) + np.arange(len(poses)) * STEP
    # only where the line turns over a body length can a corner leave the lane the front is in
    behind = line.headings(np.clip(at - body.length, 0.0, line.length))
    turned = np.abs((poses[:, 2] - behind + 180.0) % 360.0 - 180.0) > BEND
    if not turned.any():
        return none
    allowed = [_lane(net, lane) for lane in sorted(set(lanes))]
    allowed = [lane for lane in allowed if lane is not None]
    if not allowed:
        return none
    beside: dict[str, list[_Lane]] = {}  # per edge the front is on: the lanes beside it the route does not use
    crossed = [int(k) for k in turned.nonzero()[0] if _crosses(poses[k], allowed, net, body, beside, kerb, margin)]
    return at[crossed]


def _crosses(
    pose: np.ndarray,
    allowed: list[_Lane],
    net: Any,
    body: Body,
    cache: dict[str, list[_Lane]],
    kerb: bool,
    margin: float = 0.0,
) -> bool:
    """Whether the oracle would judge the body, its front at `pose`, crossing a line."""
    front = _front_lane(pose, allowed)
    if front is None or front.internal:
        return False
    if front.edge not in cache:
        ids = {lane.id for lane in allowed}
        cache[front.edge] = [
            lane for lane in _alongside(net, front.edge) if lane.id not in ids and not (kerb and lane.sidewalk)
        ]
    beside = cache[front.edge]
    if not beside:
        return False
    corners = corner_array(pose[None, :], body.length, body.width, shrink=LINE_TOLERANCE - margin)
    inside_own = np.zeros(len(corners), dtype=bool)
    for lane in allowed:
        inside_own |= lane.line.distances(corners) <= lane.half
    out = corners[~inside_own]
    return bool(len(out)) and any((lane.line.distances(out) <= lane.half).any() for lane in beside)


def _front_lane(pose: np.ndarray, allowed: list[_Lane]) -> _Lane | None:
    """The lane the oracle's lookup puts the front on, among the route's own: one whose corridor
    holds it, running the car's way first, then the nearest centre line (Network.locate)."""
    point = pose[None, :2]
    ranked = []
    for lane in allowed:
        d = float(lane.line.distances(point)[0])
        if d <= lane.half + 1e-6:
            s = lane.line.project((float(pose[0]), float(pose[1])))[0]
            along = abs(angle_diff(lane.line.heading(s), float(pose[2]))) <= HEADING_MATCH
            ranked.append(((0 if along else 1, d, lane.id), lane))
    return min(ranked, key=lambda item: item[0])[1] if ranked else None


def _lane(net: Any, lane_id: str) -> _Lane | None:
    try:
        lane = net.getLane(lane_id)
    except KeyError:
        return None
    try:
        line = Polyline(lane.getShape())
    except ValueError:  # a junction lane of no length: nothing to be inside
        return None
    sidewalk = set(lane.getPermissions()) == {"pedestrian"}
    half = lane.getWidth() / 2.0
    return _Lane(lane_id, line, half, lane_id.startswith(":"), lane.getEdge().getID(), sidewalk)


def _alongside(net: Any, edge_id: str) -> list[_Lane]:
    """The lanes of an edge and of the edge between its nodes the other way (Network.alongside)."""
    edge = net.getEdge(edge_id)
    ends = {(edge.getFromNode().getID(), edge.getToNode().getID())}
    ends.add(tuple(reversed(next(iter(ends)))))
    node = edge.getFromNode()
    edges = {e.getID(): e for e in (*node.getOutgoing(), *node.getIncoming())}
    found = []
    for eid in sorted(edges):
        e = edges[eid]
        if (e.getFromNode().getID(), e.getToNode().getID()) in ends:
            found += [lane for lane in (_lane(net, la.getID()) for la in e.getLanes()) if lane is not None]
    return found
