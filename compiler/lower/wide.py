"""A heavy vehicle's corner: it swings wide where the junction's connection is drawn for a car.

SUMO draws a junction's connections for cars: a right turn at a town or CARLA corner bends at a
5.5-8 m radius, tighter than a bus or truck can follow (the vehicle model's tightest bend, 9 m, and
11.5 m for a bus's front at full lock). Its driver moves out away from the turn before the stop line
(into the lane beside, or the opposing lane of a street with one lane each way), turns wider than
the corner, comes out of it in the far part of the road it enters, and eases back into its exit
lane, as buses and trucks do.

`wide_turn` lays that line out: the approach's last SWING metres moved out by one of OUTS; from the
stop line, a circular arc through the turn's whole angle at the radius of the front's path at full
lock or a little wider (the wider, the less its trailing rear cuts in); then a smoothstep back onto
the exit lane's centre line over one of RETURNS. The first line, least moved out, tightest and
shortest, whose body stays on lanes the vehicle may drive is taken: the plan's box, its front on
the line and facing the way its rear axle trails (geometry/trailing.py), its corners and points
along its sides each within half a lane of one (moved in by the oracles' lane-line tolerance). The
lanes it comes near are its to use. A corner that even this cannot take stays refused (routes.py's
corner check), saying so.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from sovarc.compiler.crashes import LINE_TOLERANCE
from sovarc.compiler.geometry.angles import angle_diff, heading_vector
from sovarc.compiler.geometry.bodies import Box
from sovarc.compiler.geometry.polyline import Point, Polyline, blend, concat, distances_to
from sovarc.compiler.geometry.trailing import trailing_headings
from sovarc.compiler.maps import RoadMap
from sovarc.compiler.vehicles import Body, model

RETURNS = (8.0, 11.0, 14.0, 18.0, 23.0, 29.0, 36.0, 44.0)  # m over which the body eases back into its exit lane
OUTS = (0.0, 1.0, 2.0, 3.0)  # m it moves out to the side away from the turn before the stop line
SWING = 15.0  # m before the stop line over which it moves out
ARC_STEP = 0.5  # m between the arc's points
CHECK_STEP = 0.5  # m between the body poses checked
NEAR = 25.0  # m around the turn in which the map's lanes are looked at
MIN_TURN = 30.0  # deg: a gentler bend is no corner
# the arc's radius, as a share of the front's at full lock: the wider, the less the rear cuts in
WIDER = (1.0, 1.15, 1.3, 1.5)
SIDE_STEP = 2.0  # m between the points checked along a body's side
LANE_REACH = 0.5  # m: a lane the body comes this near is one it uses (the oracles allow it the lanes it uses)
INSIDE = 0.5  # m: an arc ending this far inside its exit lane's centre turns tighter than the lane does

Lane = tuple[str, np.ndarray, float]  # id, centre line, half width


@dataclass(frozen=True)
class Wide:
    approach: Polyline  # the line up to the stop line, its last SWING metres moved out (or as it was)
    turn: Polyline  # from the stop line through the corner and back into the exit lane
    lanes: frozenset[str]  # every lane its body covers on the way


def wide_turn(approach: Polyline, exit_line: Polyline, body: Body, road_map: RoadMap) -> Wide | None:
    """The line of a corner taken wide: `approach` (ending at the stop line), moved out before it as
    far as needed, an arc no tighter than the front's at full lock, and a return onto `exit_line`
    (the exit lane's centre line, from the junction on). None when the turn is no corner, the
    corner is wide enough as drawn, or no such line keeps the body on the road."""
    end = approach.length
    heading = approach.heading(end)
    turn = angle_diff(exit_line.heading(0.0), heading)  # signed, positive turning right (clockwise)
    if abs(turn) < MIN_TURN:
        return None
    side = math.copysign(1.0, turn)
    lanes = _drivable(road_map, body, np.vstack([approach.point(end), exit_line.point(0.0)]))
    for out in OUTS:
        if out and end < SWING + 1.0:
            break
        moved = blend(approach, approach.offset(-side * out), end - SWING, end - 1.0) if out else approach
        before = moved.sub(max(0.0, moved.length - SWING - body.length), moved.length)
        for share in WIDER:
            arc = _arc(moved.point(moved.length), heading, turn, share * model(body).front_radius)
            along, lateral = _frame(exit_line, arc.point(arc.length))
            if lateral * side > INSIDE:  # it ends inside its exit lane, turning tighter than the lane
                continue
            wide = exit_line.offset(lateral)
            begin = max(along, 0.0) + 0.5
            for length in RETURNS:
                if begin + length > exit_line.length - 1.0:
                    break
                back = blend(wide, exit_line, begin, begin + length).sub(begin, begin + length + 1.0)
                covered = _on_road(concat([before, arc, back]), body, lanes)
                if covered is not None:
                    return Wide(moved, concat([arc, back]), covered)
    return None


def _arc(start: Point, heading: float, turn: float, radius: float) -> Polyline:
    """A circular arc from `start` facing `heading`, turning `turn` degrees (positive: right) at `radius`."""
    side = math.copysign(1.0, turn)
    fx, fy = heading_vector(heading)
    rx, ry = fy * side, -fx * side  # towards the centre: right for a right turn
    cx, cy = start[0] + radius * rx, start[1] + radius * ry
    steps = max(4, math.ceil(radius * math.radians(abs(turn)) / ARC_STEP))
    angles = np.radians(np.linspace(0.0, turn, steps + 1))
    # the point's bearing from the centre, turned with the vehicle (clockwise for a right turn)
    ox, oy = start[0] - cx, start[1] - cy
    cos, sin = np.cos(angles), np.sin(angles)
    return Polyline(np.column_stack([cx + ox * cos + oy * sin, cy - ox * sin + oy * cos]))


def _frame(line: Polyline, point: Point) -> tuple[float, float]:
    """(arc length along `line`, offset right of it) of `point`, the line run straight back before its start."""
    fx, fy = heading_vector(line.heading(0.0))
    x0, y0 = line.point(0.0)
    dx, dy = point[0] - x0, point[1] - y0
    ahead = dx * fx + dy * fy
    if ahead < 0.0:
        return ahead, dx * fy - dy * fx
    s, _ = line.project(point)
    px, py = line.point(s)
    hx, hy = heading_vector(line.heading(s))
    return s, (point[0] - px) * hy - (point[1] - py) * hx


def _drivable(road_map: RoadMap, body: Body, near: np.ndarray) -> list[Lane]:
    """Every lane the body's class may drive, junction lanes included, whose shape comes within NEAR
    of the points."""
    low, high = near.min(axis=0) - NEAR, near.max(axis=0) + NEAR
    found = []
    for edge in road_map.net.getEdges(withInternal=True):
        for lane in edge.getLanes():
            if not lane.allows(body.vclass):
                continue
            shape = np.asarray([p[:2] for p in lane.getShape()], dtype=float)
            if len(shape) < 2 or (shape.max(axis=0) < low).any() or (shape.min(axis=0) > high).any():
                continue
            found.append((lane.getID(), shape, lane.getWidth() / 2.0))
    return found


def _on_road(line: Polyline, body: Body, lanes: list[Lane]) -> frozenset[str] | None:
    """The lanes the body reaches (within LANE_REACH of their area), its front along `line`, when
    its outline lies on `lanes` throughout; None when it does not."""
    at = np.arange(0.0, line.length + 1e-9, CHECK_STEP)
    points = line.points_at(at)
    kind = model(body)
    facing = trailing_headings(points, line.heading(0.0), kind.axle_reach) if kind.trails else line.headings(at)
    outline = np.vstack(
        [_outline(Box.of(body, float(x), float(y), float(h))) for (x, y), h in zip(points, facing, strict=True)]
    )
    covered = np.zeros(len(outline), dtype=bool)
    used = set()
    for lane_id, shape, half in lanes:
        distance = distances_to(shape, outline)
        covered |= distance <= half
        if (distance <= half + LANE_REACH).any():
            used.add(lane_id)
    return frozenset(used) if covered.all() else None


def _outline(box: Box) -> np.ndarray:
    """Points around the body, each face moved in by the oracles' tolerance: its corners, and along
    its long sides every SIDE_STEP (a long body's side may cross a kerb its corners clear)."""
    front_left, rear_left, rear_right, front_right = (np.asarray(c) for c in box.corners(shrink=LINE_TOLERANCE))
    u = np.linspace(0.0, 1.0, max(2, math.ceil(box.length / SIDE_STEP) + 1))[:, None]
    return np.vstack([front_left + u * (rear_left - front_left), front_right + u * (rear_right - front_right)])
