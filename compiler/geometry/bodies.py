"""Participants' bodies as oriented boxes: corners, overlap, and where two of them first touch.

ONE touching rule for lowering, synthesis and every oracle: bodies overlap only when they share
area; touching (sharing an edge or a corner, or closer than OVERLAP_EPS) is not overlapping.

A box's reference point is a vehicle's front-bumper centre or a pedestrian's body centre (the
plan's convention, and SUMO's for vehicles; `front_ref` says which), or the box centre for a
target that places bodies by it. Headings are compass degrees (angles.py).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.vehicles import Body

Point = tuple[float, float]
FACES = ("front", "rear", "left", "right")
OVERLAP_EPS = 1e-9  # m: boxes must reach this far into each other to overlap (rounding is not contact)
SQUARE = 1e-12  # a contact's direction this close to a face's outward normal is that face's own


@dataclass(frozen=True)
class Box:
    x: float
    y: float
    heading: float  # compass degrees
    length: float
    width: float
    front_ref: bool  # True: (x, y) is the front-bumper centre; False: the body centre

    @classmethod
    def of(cls, body: Body, x: float, y: float, heading: float) -> Box:
        """A participant's body with its reference point (front bumper, or a walker's centre) at (x, y)."""
        return cls(x, y, heading, body.length, body.width, body.front_ref)

    @property
    def axes(self) -> tuple[Point, Point]:
        """Unit vectors forward and to the left."""
        r = math.radians(self.heading)
        return (math.sin(r), math.cos(r)), (-math.cos(r), math.sin(r))

    @property
    def centre(self) -> Point:
        if not self.front_ref:
            return (self.x, self.y)
        (fx, fy), _ = self.axes
        return (self.x - fx * self.length / 2.0, self.y - fy * self.length / 2.0)

    def corners(self, shrink: float = 0.0) -> list[Point]:
        """Front-left, rear-left, rear-right, front-right (counter-clockwise), each face moved in by `shrink`."""
        (fx, fy), (lx, ly) = self.axes
        cx, cy = self.centre
        hl, hw = max(self.length / 2.0 - shrink, 0.0), max(self.width / 2.0 - shrink, 0.0)
        return [
            (cx + a * hl * fx + b * hw * lx, cy + a * hl * fy + b * hw * ly)
            for a, b in ((1, 1), (-1, 1), (-1, -1), (1, -1))
        ]

    def faces_at(self, point: Point, primary: str) -> tuple[str, ...]:
        """`primary` and any other face the point is close to: a point near a corner (within a
        quarter of the length of the front or rear, a quarter of the width of a side) is on both."""
        (fx, fy), (lx, ly) = self.axes
        cx, cy = self.centre
        along = (point[0] - cx) * fx + (point[1] - cy) * fy
        left = (point[0] - cx) * lx + (point[1] - cy) * ly
        near = {
            "front": along >= self.length / 4.0,
            "rear": along <= -self.length / 4.0,
            "left": left >= self.width / 4.0,
            "right": left <= -self.width / 4.0,
        }
        return tuple(face for face in FACES if face == primary or (near[face] and _corner(primary, face)))

    def face_towards(self, direction: Point) -> str:
        """The face whose outward normal points most along `direction`."""
        (fx, fy), (lx, ly) = self.axes
        along = direction[0] * fx + direction[1] * fy
        left = direction[0] * lx + direction[1] * ly
        scores = {"front": along, "rear": -along, "left": left, "right": -left}
        return max(FACES, key=lambda face: scores[face])

    def face_along(self, direction: Point) -> str | None:
        """The face whose outward normal is the unit vector `direction` itself (None: no face's is)."""
        face = self.face_towards(direction)
        (fx, fy), (lx, ly) = self.axes
        nx, ny = {"front": (fx, fy), "rear": (-fx, -fy), "left": (lx, ly), "right": (-lx, -ly)}[face]
        return face if direction[0] * nx + direction[1] * ny >= 1.0 - SQUARE else None


def corner_array(poses: np.ndarray, length: float, width: float, shrink: float = 0.0) -> np.ndarray:
    """`Box.corners` of many front-referenced boxes at once: poses n x 3 (front x, y, compass
    heading) give 4n x 2 corners, the front-left ones first, then rear-left, rear-right, front-right."""
    rad = np.radians(poses[:, 2])
    fx, fy = np.sin(rad), np.cos(rad)
    lx, ly = -fy, fx
    cx, cy = poses[:, 0] - fx * length / 2.0, poses[:, 1] - fy * length / 2.0
    hl, hw = max(length / 2.0 - shrink, 0.0), max(width / 2.0 - shrink, 0.0)
    return np.vstack(
        [
            np.column_stack((cx + a * hl * fx + b * hw * lx, cy + a * hl * fy + b * hw * ly))
            for a, b in ((1, 1), (-1, 1), (-1, -1), (1, -1))
        ]
    )


def _corner(primary: str, face: str) -> bool:
    """Whether two faces meet at a corner (front/rear with left/right)."""
    return {primary, face} in ({"front", "left"}, {"front", "right"}, {"rear", "left"}, {"rear", "right"})


def overlap(a: Box, b: Box) -> bool:
    """Whether the two boxes share area (separating axis test); touching is not overlapping."""
    (ax, ay), (bx, by) = a.centre, b.centre
    if math.hypot(ax - bx, ay - by) > (math.hypot(a.length, a.width) + math.hypot(b.length, b.width)) / 2.0:
        return False  # their enclosing circles are apart: no axis needs testing
    return separation(a, b)[0] < -OVERLAP_EPS


def separation(a: Box, b: Box) -> tuple[float, Point]:
    """The widest gap between the boxes along any face normal of either (negative: the least
    they overlap by), and that normal pointing from a towards b. Where two bodies just touch, it is
    the normal of the face that is touched: the direction the contact pushes in."""
    pa, pb = a.corners(), b.corners()
    best: tuple[float, Point] = (-math.inf, (0.0, 0.0))
    for body in (a, b):
        for ax, ay in body.axes:
            ra = [p[0] * ax + p[1] * ay for p in pa]
            rb = [p[0] * ax + p[1] * ay for p in pb]
            ahead, behind = min(rb) - max(ra), min(ra) - max(rb)  # b beyond a along the axis, or before it
            gap = (ahead, (ax, ay)) if ahead >= behind else (behind, (-ax, -ay))
            if gap[0] > best[0]:
                best = gap
    return best


def _closest_on_segment(p: Point, a: Point, b: Point) -> Point:
    dx, dy = b[0] - a[0], b[1] - a[1]
    span = dx * dx + dy * dy
    u = 0.0 if span == 0.0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / span))
    return (a[0] + u * dx, a[1] + u * dy)


def closest_points(a: Box, b: Box) -> tuple[Point, Point]:
    """The nearest pair of points of two separate boxes' outlines (on a, on b)."""
    return _near_pairs(a, b)[0]


def _near_pairs(a: Box, b: Box, slack: float = 1e-3) -> list[tuple[Point, Point]]:
    """Pairs of outline points (on a, on b) within `slack` of the smallest distance, nearest first:
    two faces that meet flat give a pair at each end of the contact, a corner gives one."""
    pa, pb = a.corners(), b.corners()
    pairs: list[tuple[float, Point, Point]] = []
    for poly_p, poly_q, swap in ((pa, pb, False), (pb, pa, True)):
        for p in poly_p:
            for q0, q1 in itertools.pairwise([*poly_q, poly_q[0]]):
                q = _closest_on_segment(p, q0, q1)
                pairs.append((math.dist(p, q), q, p) if swap else (math.dist(p, q), p, q))
    pairs.sort(key=lambda item: item[0])
    least = pairs[0][0]
    return [(p, q) for d, p, q in pairs if d <= least + slack]


def between(a: Box, b: Box, u: float) -> Box:
    """The box a fraction u of the way from pose a to pose b (turning the shorter way)."""
    turn = ((b.heading - a.heading + 180.0) % 360.0) - 180.0
    return Box(
        a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), (a.heading + u * turn) % 360.0, a.length, a.width, a.front_ref
    )


@dataclass(frozen=True)
class Contact:
    """Two bodies' first touch: when, where, and which face of each meets the other."""

    time: float
    point: Point
    faces: tuple[str, str]  # of the first body, of the second: the face the contact pushes on
    zones: tuple[tuple[str, ...], tuple[str, ...]]  # each body's faces at the contact point (two at a corner)
    angle: float  # degrees between their headings, 0..180
    # Each body's face the contact pushes square into (`pressed`): None for a body whose corner is
    # what meets the other's face, so that which of its corner's faces is struck is left to the angle.
    pressed: tuple[str | None, str | None] = (None, None)


def pressed(a: Box, b: Box, direction: Point) -> tuple[str | None, str | None]:
    """At a touch whose direction (from a towards b) is the face normal that still separates the
    bodies: the face of each body that normal is its own, which the other's corner or face enters
    square (both, for faces that meet flat); None for a body whose corner enters the other's face.
    A corner into a face is the geometry that decides which face is struck: the entered face is."""
    return a.face_along(direction), b.face_along((-direction[0], -direction[1]))


def first_touch(t0: float, t1: float, a: tuple[Box, Box], b: tuple[Box, Box]) -> Contact:
    """The contact of bodies a and b between time t0 (apart) and t1 (overlapping), with the
    poses at both times; found by bisection on straight-line motion between them.

    At the last instant apart the bodies are under a nanometre from each other, so the direction
    between their nearest points is noise; the contact's direction is the face normal that still
    separates them, that of the face a corner (or face) meets. Each body's face is the one turned
    that way, and its zone the faces at the contact point: a corner driven into the middle of a
    side is that corner on one body and that side on the other, as the OpenSCENARIO oracle names them."""
    lo, hi = 0.0, 1.0
    if overlap(a[0], b[0]):  # already touching at t0: nothing to bisect
        hi = 0.0
    else:
        for _ in range(30):
            mid = (lo + hi) / 2.0
            if overlap(between(*a, mid), between(*b, mid)):
                hi = mid
            else:
                lo = mid
    body_a, body_b = between(*a, lo), between(*b, lo)
    if hi == 0.0:  # no instant of touch to read: the centres stand in for the contact
        near = [(body_a.centre, body_b.centre)]
        (ax, ay), (bx, by) = body_a.centre, body_b.centre
        direction = (bx - ax, by - ay)
    else:  # apart by under a nanometre: the nearest points coincide, the axis that still separates them does not
        near = _near_pairs(body_a, body_b)
        direction = separation(body_a, body_b)[1]
    faces = (body_a.face_towards(direction), body_b.face_towards((-direction[0], -direction[1])))
    angle = abs(angle_diff(body_a.heading, body_b.heading))
    points = [((p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0) for p, q in near]
    point = (sum(p[0] for p in points) / len(points), sum(p[1] for p in points) / len(points))
    zones = (body_a.faces_at(point, faces[0]), body_b.faces_at(point, faces[1]))
    square = (None, None) if hi == 0.0 else pressed(body_a, body_b, direction)
    return Contact(t0 + lo * (t1 - t0), point, faces, zones, angle, square)
