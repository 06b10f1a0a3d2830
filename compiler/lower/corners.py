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

The poses are judged by the lane-line test the SUMO oracle judges by (compiler/geometry/lane_lines.py),
the front put on the lane the oracle's lookup would pick among the route's own: a body corner moved
in by the tolerance inside a lane of the front's road (its edge or the edge the other way) that the
route does not use, and outside every lane it does. A swing over the kerb, into a lane of another
road, or inside a junction (a junction's lanes have no painted lines), crosses no line the oracle
checks, and bounds nothing.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np
from sovarc.compiler.crashes import LINE_TOLERANCE
from sovarc.compiler.geometry.bodies import corner_array
from sovarc.compiler.geometry.lane_lines import crossed_lane
from sovarc.compiler.geometry.lanes import Lane, LaneMap
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.lower.swing import STEP, line_poses
from sovarc.compiler.vehicles import Body

BEND = 2.0  # degrees the line turns over a body length before its rear can leave the front's lane


def clear_start(
    line: Polyline, lanes: Iterable[str], net: LaneMap, body: Body, upto: float, *, kerb: bool = False
) -> float:
    """The least arc length on `line` (smoothed, as driven) from which the front of a car whose
    route may use `lanes` (lane ids of the map `net`) reaches `upto` with no pose on the way that
    crosses a line into a lane beside it; 0.0 when it may start anywhere. `kerb`: the car drives
    into or off the road by a driveway, so the sidewalk is its to cross (the oracle's `kerb`)."""
    if upto <= 0.0:
        return 0.0
    crossed = crossings(line, lanes, net, body, 0.0, upto, kerb=kerb)
    return float(min(crossed[-1] + STEP, upto)) if len(crossed) else 0.0


def crossings(
    line: Polyline,
    lanes: Iterable[str],
    net: LaneMap,
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
    ids = frozenset(lanes)
    allowed = [net.lanes[lane] for lane in sorted(ids) if lane in net.lanes]
    crossed = [int(k) for k in turned.nonzero()[0] if _crosses(poses[k], ids, allowed, net, body, kerb, margin)]
    return at[crossed]


def _crosses(
    pose: np.ndarray, ids: frozenset[str], allowed: list[Lane], net: LaneMap, body: Body, kerb: bool, margin: float
) -> bool:
    """Whether the oracle would judge the body, its front at `pose`, crossing a line: its front on
    the lane the oracle's lookup puts it on among the route's own (LaneMap.holding)."""
    front = net.holding(float(pose[0]), float(pose[1]), float(pose[2]), allowed)
    if front is None:
        return False
    corners = corner_array(pose[None, :], body.length, body.width, shrink=LINE_TOLERANCE - margin)
    return crossed_lane(net, front, ids, corners.tolist(), kerb=kerb) is not None
