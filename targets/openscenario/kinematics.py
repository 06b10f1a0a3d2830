"""Plane geometry for the oracle: poses over time, body footprints, gaps, contact faces.

Poses are OpenSCENARIO's (heading h in radians, counter-clockwise from +x). Bodies are the
geometry kernel's boxes (compiler/geometry/bodies.py), with its one touching rule, and angle
differences its `angle_diff`: headings are converted at this boundary.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.geometry.bodies import Box, overlap
from sovarc.targets.openscenario.bodies import compass_of
from sovarc.targets.openscenario.readback import Entity, Pose

Point = tuple[float, float]
Polygon = tuple[Point, ...]
TAU = 2.0 * math.pi


def turn(a: float, b: float) -> float:
    """The turn from heading a to heading b, radians in (-pi, pi]: the kernel's angle_diff(b, a)."""
    return math.radians(angle_diff(math.degrees(b), math.degrees(a)))


def pose_at(poses: Sequence[Pose], t: float) -> Pose:
    """The pose at time t, linear between vertices (headings along the shorter arc), clamped to the ends."""
    if t <= poses[0].t:
        return poses[0]
    if t >= poses[-1].t:
        return poses[-1]
    lo, hi = 0, len(poses) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if poses[mid].t <= t:
            lo = mid
        else:
            hi = mid
    a, b = poses[lo], poses[hi]
    u = (t - a.t) / (b.t - a.t) if b.t > a.t else 0.0
    return Pose(t, a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), (a.h + u * turn(a.h, b.h)) % TAU)


def driven_point(entity: Entity, pose: Pose) -> Point:
    """The point whose path synthesis timed: a vehicle's front-bumper centre, a pedestrian's centre.

    In a turn the reference point (rear axle) of a rigid body swings sideways as the heading
    turns, so its speed is not the speed the vehicle was planned and limited at."""
    c, s = math.cos(pose.h), math.sin(pose.h)
    ahead = entity.center_x + (0.0 if entity.pedestrian else entity.length / 2)
    return pose.x + c * ahead - s * entity.center_y, pose.y + s * ahead + c * entity.center_y


def box(entity: Entity, pose: Pose) -> Box:
    """The entity's bounding box on the ground: the kernel's box about its centre."""
    c, s = math.cos(pose.h), math.sin(pose.h)
    cx = pose.x + c * entity.center_x - s * entity.center_y
    cy = pose.y + s * entity.center_x + c * entity.center_y
    return Box(cx, cy, compass_of(pose.h), entity.length, entity.width, front_ref=False)


def footprint(entity: Entity, pose: Pose) -> Polygon:
    """The bounding box's corners on the ground, counter-clockwise (front-left first)."""
    return tuple(box(entity, pose).corners())


def _circle(poly: Polygon) -> tuple[float, float, float]:
    cx, cy = sum(p[0] for p in poly) / len(poly), sum(p[1] for p in poly) / len(poly)
    return cx, cy, max(math.hypot(p[0] - cx, p[1] - cy) for p in poly)


def _circle_gap(a: Polygon, b: Polygon) -> float:
    """A lower bound of the distance between two polygons, from their enclosing circles."""
    (ax, ay, ar), (bx, by, br) = _circle(a), _circle(b)
    return math.hypot(ax - bx, ay - by) - ar - br


def _point_segment(p: Point, a: Point, b: Point) -> tuple[float, Point]:
    ex, ey = b[0] - a[0], b[1] - a[1]
    length2 = ex * ex + ey * ey
    u = 0.0 if length2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / length2))
    q = (a[0] + u * ex, a[1] + u * ey)
    return math.hypot(p[0] - q[0], p[1] - q[1]), q


def _edges(poly: Polygon) -> list[tuple[Point, Point]]:
    return [(poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly))]


def gap(box_a: Box, box_b: Box) -> float:
    """The distance between two boxes (0 when they overlap or touch); beyond 1 m, a lower bound."""
    if overlap(box_a, box_b):
        return 0.0
    a, b = tuple(box_a.corners()), tuple(box_b.corners())
    bound = _circle_gap(a, b)
    if bound > 1.0:  # far apart: the exact distance does not matter, only that it is large
        return bound
    return min(
        min(_point_segment(p, *e)[0] for p in a for e in _edges(b)),
        min(_point_segment(p, *e)[0] for p in b for e in _edges(a)),
    )


def point_distance(p: Point, poly: Polygon) -> float:
    """Distance from a point to a convex polygon; 0 inside it."""
    if all((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= 0 for a, b in _edges(poly)):
        return 0.0
    return min(_point_segment(p, *e)[0] for e in _edges(poly))


def _clip(subject: list[Point], a: Point, b: Point) -> list[Point]:
    """Sutherland-Hodgman: the part of `subject` left of the directed line a -> b."""

    def inside(p: Point) -> bool:
        return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= 0

    def cross(p: Point, q: Point) -> Point:
        dx, dy = q[0] - p[0], q[1] - p[1]
        ex, ey = b[0] - a[0], b[1] - a[1]
        den = ex * dy - ey * dx
        u = 0.0 if den == 0 else (ey * (p[0] - a[0]) - ex * (p[1] - a[1])) / den
        return (p[0] + u * dx, p[1] + u * dy)

    out: list[Point] = []
    for i, p in enumerate(subject):
        q = subject[(i + 1) % len(subject)]
        if inside(q):
            if not inside(p):
                out.append(cross(p, q))
            out.append(q)
        elif inside(p):
            out.append(cross(p, q))
    return out


def _area_centroid(region: list[Point]) -> tuple[float, Point]:
    """(area, centroid) of a simple polygon."""
    area = cx = cy = 0.0
    for (x1, y1), (x2, y2) in _edges(tuple(region)):
        cross = x1 * y2 - x2 * y1
        area += cross
        cx += (x1 + x2) * cross
        cy += (y1 + y2) * cross
    if abs(area) < 1e-12:
        return 0.0, region[0]
    return abs(area) / 2, (cx / (3 * area), cy / (3 * area))


CONTACT_AREA = 1e-3  # m²: less overlap than this is a touch, judged by the closest points


def contact_point(a: Polygon, b: Polygon, slack: float = 0.02) -> Point:
    """Where two bodies meet: the centre of their overlap, or (when they just touch) the middle of
    the stretch along which they are closest, within `slack` metres of the least distance."""
    region = list(a)
    for edge in _edges(b):
        region = _clip(region, *edge)
        if not region:
            break
    if len(region) >= 3:
        area, centre = _area_centroid(region)
        if area > CONTACT_AREA:
            return centre
    pairs = []  # (distance, vertex, its closest point on the other polygon)
    for p, poly in [(p, b) for p in a] + [(p, a) for p in b]:
        for e in _edges(poly):
            d, q = _point_segment(p, *e)
            pairs.append((d, p, q))
    nearest = min(d for d, _, _ in pairs)
    # Faces that lie parallel touch along a stretch: take its middle, not one of its ends.
    mids = [((p[0] + q[0]) / 2, (p[1] + q[1]) / 2) for d, p, q in pairs if d <= nearest + slack]
    return (sum(m[0] for m in mids) / len(mids), sum(m[1] for m in mids) / len(mids))


def faces_at(entity: Entity, pose: Pose, point: Point) -> tuple[str, ...]:
    """The faces of the body a point is on: the nearest one, and the adjacent face when the point
    is near that corner (beyond a quarter of the length or width from the centre), as the SUMO
    oracle counts and names them ('front-left', never 'left-front'), so that both judge alike."""
    c, s = math.cos(pose.h), math.sin(pose.h)
    dx, dy = point[0] - pose.x, point[1] - pose.y
    u = c * dx + s * dy - entity.center_x  # along the body, from its centre
    v = -s * dx + c * dy - entity.center_y  # to the left
    nu, nv = u / (entity.length / 2), v / (entity.width / 2)
    end = "front" if nu >= 0 else "rear"
    side = "left" if nv >= 0 else "right"
    if abs(nu) >= abs(nv):
        return (end, side) if abs(nv) >= 0.5 else (end,)
    return (end, side) if abs(nu) >= 0.5 else (side,)
