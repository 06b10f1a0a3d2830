"""THE lane-line test: does a body, its front on a lane, reach over a painted line into a lane its
route may not use? The SUMO oracle judges replayed poses by it (targets/sumo/oracle.py), and
lowering asks it of planned poses to keep bodies off those lanes (compiler/lower/corners.py).

A lane's lines are those between it and the lanes beside it: the others of its road and of the
road the other way between the same junctions (`LaneMap.alongside`). A junction's internal lanes
have no painted lines and are not checked, nor lanes ahead or behind (a body overhanging a
lane's end). A body crosses into a lane beside when a corner of it, moved in by the tolerance
(compiler/crashes.LINE_TOLERANCE), lies inside that lane and inside none of the allowed ones.
Sidewalks are always open to pedestrians, and to a car driving into or off the road by a
driveway (it crosses the sidewalk on its way).
"""

from __future__ import annotations

from collections.abc import Collection, Iterable

from sovarc.compiler.geometry.lanes import Lane, LaneMap, Point


def crossed_lane(
    lanes: LaneMap,
    front: Lane,
    allowed: Collection[str],
    corners: Iterable[Point],
    *,
    pedestrian: bool = False,
    kerb: bool = False,
) -> str | None:
    """The lane a participant whose front is on `front`, and whose route may use the lanes
    `allowed` (ids), is judged to enter: `front` itself when it is not allowed (a vehicle's),
    or a lane beside it that a corner of its body (`corners`, already moved in by the tolerance)
    reaches into; None when it keeps to its lanes. `kerb`: a car driving into or off the road by
    a driveway."""
    if front.internal:
        return None
    may_cross = pedestrian or kerb
    if front.id not in allowed and not (may_cross and front.pedestrian_only):
        return None if pedestrian else front.id
    beside = [
        other
        for other in lanes.alongside(front)
        if other.id not in allowed and not (may_cross and other.pedestrian_only)
    ]
    if not beside:
        return None
    own = [lanes.lanes[i] for i in sorted(allowed) if i in lanes.lanes]
    for x, y in corners:
        for other in beside:
            if lanes.reaches(other, x, y, other.width / 2.0) and not inside_any(lanes, own, x, y):
                return other.id
    return None


def inside_any(lanes: LaneMap, among: Iterable[Lane], x: float, y: float) -> bool:
    """Whether the point lies within half its width of the centre line of one of the lanes `among`."""
    return any(lanes.reaches(lane, x, y, lane.width / 2.0) for lane in among)
