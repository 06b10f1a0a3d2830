"""Three-point turns: a U-turn in forward and reverse legs, where one sweep does not fit the road.

uturn.py turns in one forward half circle, which takes some 11.6 m of road for a car; a city
street of one lane each way is 6-7 m wide. There a driver pulls over to the kerb, stops, and
turns in legs: forward at full left lock until the front nears the far kerb, stop, reverse at
full right lock until the rear nears the near kerb, stop, forward into the other lane. On a
narrower road it takes two more legs (a five-point turn); MAX_LEGS at the most.

The legs are laid out with the kinematic bicycle model, as a car moves at walking pace: the
centre of its rear axle drives arcs of the vehicle model's `axle_radius` (full lock) and the
body turns about it. The plan's point is the front bumper, `ahead` of the axle along the heading, and the heading
is the way the body faces (reversing, it moves against it): unlike on every other path, the
heading is not the tangent of the front bumper's path. The steering turns while the car stands
(at the kerb and at each change of gear), so that path has a corner there but the car no speed;
the last leg unwinds it over UNWIND metres as the car moves off, so that it leaves the turn
straight, heading as its path does again.

Each leg goes as far as the body stays on the road: within KERB_OVERHANG of its edges (a bumper
over the kerb, the wheels on the road), inside the SUMO oracle's tolerance for a lane line. The
first forward leg that can finish facing back does, so a turn has the fewest legs the road
allows; where it starts across the road is chosen likewise, from the car's lane towards the kerb.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from sovarc.compiler.crashes import LINE_TOLERANCE  # the SUMO oracle's: the body may reach this far over a line
from sovarc.compiler.geometry.bodies import Box
from sovarc.compiler.geometry.frame import Band
from sovarc.compiler.geometry.polyline import Point, Polyline
from sovarc.compiler.lower.uturn import MARGIN, move_across, move_length
from sovarc.compiler.vehicles import Body, model

UNWIND = 3.0  # m the rear axle travels while the last leg straightens the wheels
KERB_OVERHANG = LINE_TOLERANCE - 0.05  # m the body may reach past the road's edge (kept in hand: 5 cm)
MAX_LEGS = 5
MIN_LEG = 1.0  # m the rear axle travels at the least in a leg: a shorter one gains nothing
STEP = 0.05  # m of the rear axle's travel between checked poses
KEEP = 4  # every KEEP-th pose is a point of the line (0.2 m apart)
PULL_OVER = 0.1  # m between the starting places across the road that are tried
ALONG = 0.5  # of the road's length: where a turn in legs begins at the earliest (corridor.py)

Pose = tuple[float, float, float]  # the rear axle's centre (s, d) in a band, and the heading: radians left of s


@dataclass(frozen=True)
class Legs:
    """A turn in legs, in a band's coordinates, one pose every STEP of the rear axle's travel."""

    poses: tuple[Pose, ...]
    stops: tuple[int, ...]  # the poses where it stands: its start, then every change of gear
    gears: tuple[int, ...]  # the leg after each stop: +1 forward, -1 reverse
    ahead: float  # m from the rear axle to the front bumper

    def front(self, k: int) -> Point:
        s, d, theta = self.poses[k]
        return (s + self.ahead * math.cos(theta), d + self.ahead * math.sin(theta))


@dataclass(frozen=True)
class KLayout:
    """Where a turn in legs goes across the road: it moves over to `d0` (taking `before` metres of
    road), turns in `legs` (laid out from s = 0), and moves from `d1` (facing back) to the lane it
    ends in (taking `after` metres)."""

    d0: float
    legs: Legs
    d1: float
    before: float
    after: float

    @property
    def count(self) -> int:
        return len(self.legs.gears)

    @property
    def reach(self) -> float:
        """How far along the road the front bumper gets past where the legs begin."""
        return max(self.legs.front(k)[0] for k in range(len(self.legs.poses)))


def corners_d(pose: Pose, body: Body) -> tuple[float, float]:
    """The least and the greatest d of the body's corners at an axle pose: the kernel's box in the
    band's plane (x = s, y = d; a heading theta left of s is the compass heading 90 - theta there)."""
    s, d, theta = pose
    ahead = _ahead(body)
    front = (s + ahead * math.cos(theta), d + ahead * math.sin(theta))
    values = [y for _, y in Box.of(body, *front, 90.0 - math.degrees(theta)).corners()]
    return min(values), max(values)


def _ahead(body: Body) -> float:
    """m from the rear axle to the front bumper."""
    return body.length * (1.0 - model(body).rear_overhang)


def _arc(pose: Pose, gear: int, kappa: float, length: float) -> Pose:
    """The axle pose after `length` metres in `gear` on a curvature `kappa` (1/m, to the left driving forward)."""
    s, d, theta = pose
    turn = gear * kappa * length
    if abs(kappa) < 1e-12:
        return (s + gear * length * math.cos(theta), d + gear * length * math.sin(theta), theta)
    after = theta + turn
    return (s + (math.sin(after) - math.sin(theta)) / kappa, d - (math.cos(after) - math.cos(theta)) / kappa, after)


class _Road:
    """The band's edges as the body may reach them, and the check of one pose against them."""

    def __init__(self, low: float, high: float, body: Body) -> None:
        self.low, self.high, self.body = low, high, body

    def holds(self, pose: Pose) -> bool:
        low, high = corners_d(pose, self.body)
        return low >= self.low and high <= self.high


def _leg(road: _Road, pose: Pose, gear: int, kappa: float) -> list[Pose]:
    """From `pose`, in `gear` at the curvature, as far as the body stays on the road and the car
    has not yet turned back (heading pi); the poses, the first included."""
    out = [pose]
    while out[-1][2] < math.pi:
        step = min(STEP, (math.pi - out[-1][2]) / abs(kappa))
        nxt = _arc(out[-1], gear, kappa, step)
        if not road.holds(nxt):
            break
        out.append(nxt)
    return out


def _finish(road: _Road, pose: Pose) -> list[Pose] | None:
    """The last leg from `pose`: forward at full lock, then unwinding over UNWIND to end facing back
    (heading pi) and straight, or None when the body would leave the road on the way."""
    kappa = 1.0 / model(road.body).axle_radius
    left = math.pi - pose[2]
    out = [pose]
    arc = left - kappa * UNWIND / 2.0
    if arc > 0.0:  # full lock first, the unwinding turns the rest
        count = max(1, math.ceil(arc / kappa / STEP))
        for _ in range(count):
            out.append(_arc(out[-1], 1, kappa, arc / kappa / count))
            if not road.holds(out[-1]):
                return None
    else:  # less than the unwinding turns: the wheels start less than fully turned
        kappa = 2.0 * left / UNWIND
    count = math.ceil(UNWIND / STEP)
    for k in range(count):
        mid = kappa * (1.0 - (k + 0.5) / count)  # the wheels straighten at an even rate: linear curvature
        out.append(_arc(out[-1], 1, mid, UNWIND / count))
        if not road.holds(out[-1]):
            return None
    s, d, _ = out[-1]
    out[-1] = (s, d, math.pi)  # rounding: exactly facing back
    return out


def turn_in_legs(road: _Road, start: Pose, ahead: float) -> Legs | None:
    """Greedy legs from `start` (facing along the band): each forward leg finishes the turn if it
    can, else goes as far as the body stays on the road, and each reverse leg likewise."""
    kappa = 1.0 / model(road.body).axle_radius
    poses, stops, gears = [start], [0], []
    for leg in range(MAX_LEGS):
        here = poses[-1]
        if leg % 2 == 0:
            last = _finish(road, here)
            if last is not None:
                return Legs(tuple(poses + last[1:]), tuple(stops), (*gears, 1), ahead)
            if leg == MAX_LEGS - 1:
                return None
            driven = _leg(road, here, 1, kappa)
        else:
            driven = _leg(road, here, -1, -kappa)  # reversing on right lock turns the car on to the left
        if (len(driven) - 1) * STEP < MIN_LEG:
            return None  # stuck against the edge
        poses += driven[1:]
        stops.append(len(poses) - 1)
        gears.append(1 if leg % 2 == 0 else -1)
    return None


def layout(band: Band, d_from: float, d_to: float, body: Body) -> KLayout | None:
    """The turn in the fewest legs from lane position `d_from` to `d_to` (facing back), starting
    as near `d_from` as that allows; None when no turn of up to MAX_LEGS fits the road."""
    half = body.width / 2.0
    road = _Road(band.right - KERB_OVERHANG, band.left + KERB_OVERHANG, body)
    ahead = _ahead(body)
    kerb = band.right + MARGIN + half  # pulled over: the body inside the road, as on any move across
    best: KLayout | None = None
    starts = np.arange(d_from, kerb - 1e-9, -PULL_OVER) if d_from > kerb else np.array([d_from])
    for d0 in starts:  # from its lane towards the kerb: the first with the fewest legs
        legs = turn_in_legs(road, (-ahead, float(d0), 0.0), ahead)
        if legs is None or (best is not None and len(legs.gears) >= best.count):
            continue
        d1 = legs.front(len(legs.poses) - 1)[1]
        before = move_length(float(d0) - d_from, d_from - half - band.right - MARGIN, body)
        after = move_length(d1 - d_to, band.left - MARGIN - half - d1, body)
        if before is not None and after is not None:
            best = KLayout(float(d0), legs, d1, before, after)
    return best


@dataclass(frozen=True)
class KTurnLine:
    """A turn in legs on the map: the line from the start to the target lane, and along it (arc
    lengths from its start) the stretch of the legs with the heading at each of its points, the
    stops, and where the line joins the target lane (an arc length on `target`)."""

    line: Polyline
    s: np.ndarray  # arc lengths of the legs' points
    heading: np.ndarray  # compass heading the body faces there, unwrapped (no jump at 0/360)
    stops: tuple[float, ...]
    gears: tuple[int, ...]
    joins: float


def k_turn_line(band: Band, start: Point, target: Polyline, d_to: float, plan: KLayout) -> KTurnLine:
    """The turn from `start` (the front bumper, in its lane) onto `target`, a lane running the new
    way at `d_to` across the band: the move over, the legs, and the move into the lane."""
    s_a, d_a = band.place(start)
    before = move_across(s_a, d_a, plan.d0, plan.before, forward=True)
    s0 = before[-1][0] if before else s_a  # where the legs begin: the front bumper there
    legs = plan.legs
    keep = sorted({*range(0, len(legs.poses), KEEP), *legs.stops, len(legs.poses) - 1})
    fronts = [legs.front(k) for k in keep]
    points = [start, *(band.at(s, d) for s, d in before[1:]), *(band.at(s0 + s, d) for s, d in fronts[1:])]
    first = len(points) - len(fronts)  # the index of the legs' first point
    s_end, d_end = fronts[-1]
    after = move_across(s0 + s_end, d_end, d_to, plan.after, forward=False)
    tail = [band.at(s, d) for s, d in after[1:]]
    # without a move across it ends in the lane: join it a metre on, not sideways onto its line
    joins = target.project(tail[-1])[0] if tail else target.project(points[-1])[0] + 1.0
    points += [*tail[:-1], target.point(joins)]
    line = Polyline(points)
    arc = np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(np.asarray(points), axis=0).T))))
    along = arc[first : first + len(keep)]
    facing = np.array(
        [band.heading(s0 + s) - math.degrees(legs.poses[k][2]) for k, (s, _) in zip(keep, fronts, strict=True)]
    )
    stops = tuple(float(along[keep.index(k)]) for k in legs.stops)
    return KTurnLine(line, along, np.unwrap(facing, period=360.0), stops, legs.gears, joins)


def choose(
    band: Band, start: Point, lanes: Sequence[tuple[int, Polyline]], body: Body
) -> tuple[int, float, KLayout] | None:
    """Of the lanes the turn may end in (the preferred first), the first a turn in legs reaches:
    its number, its d and the layout; None when it reaches none."""
    d_from = band.place(start)[1]
    for number, line in lanes:
        d_to = band.d_abreast(line, start)
        plan = layout(band, d_from, d_to, body)
        if plan is not None:
            return number, d_to, plan
    return None
