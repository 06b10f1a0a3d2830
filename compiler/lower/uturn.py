"""U-turns that fit the road: one forward half circle, as round as the road's width allows.

In the plan's body model a vehicle's heading is the tangent of its front bumper's path and
its body trails behind it, so a car turning left on a circle of radius R swings its rear
out to the right: its rear outer corner reaches sqrt((R + w/2)^2 + L^2) from the circle's
centre on the side the car comes from, and its front outer corner R + w/2 on the far side.
A U-turn therefore needs R + w/2 + sqrt((R + w/2)^2 + L^2) of road across (11.6 m for a
4.6 x 1.8 m car at R = 4 m), and begins far enough from the kerb for the rear to stay on it.

The turn is laid out across the road, in a `Band` (the road frame, compiler/geometry/frame.py):
s along the right-most lane of the direction the car comes from, d to the left of it. The car
moves over from its lane to d0 (as far as the rear's swing needs), turns on a half circle to
d1 = d0 + 2R, facing back, and ends in its lane: R is chosen so that d1 is that lane when the
road lets it, else it is the tightest (the vehicle model's `front_radius`, full lock) or the
widest the road holds, and a move across after the half circle reaches the lane. A move across
swings the trailing rear the other way, so each is long enough to keep it on the road. On a
road narrower than the tightest turn the layout says it does not fit: on a straight road the
caller turns in legs instead (kturn.py), at a junction it reports the site unsatisfiable
(`too_narrow`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from sovarc.compiler.geometry.bodies import Box
from sovarc.compiler.geometry.frame import Band
from sovarc.compiler.geometry.polyline import Point, Polyline
from sovarc.compiler.vehicles import Body, model
from sovarc.dsl.errors import Diagnostic, UnsatError

MARGIN = 0.2  # m the body keeps from the road's edges
SHIFT = 6.0  # m of road per metre moved across before and after the half circle
MIN_SHIFT = 15.0  # m: the shortest move across (a short one swings the rear out)
MAX_SHIFT = 60.0  # m: the longest
NEAR = 1.0  # m: a half circle ending this close to the preferred lane turns into it


@dataclass(frozen=True)
class Layout:
    radius: float
    d0: float  # across the road, where the half circle begins
    d1: float  # where it ends, facing back
    fits: bool  # the body stays on the road with MARGIN to spare
    before: float = 0.0  # m of road the move across to d0 takes (0: none)
    after: float = 0.0  # m the move from d1 to the lane it ends in takes


def _start_range(band: Band, radius: float, body: Body) -> tuple[float, float]:
    """Where across the road a half circle of `radius` may begin: its rear swing keeps off the
    right edge, its far side off the left edge."""
    half = body.width / 2.0
    low = band.right + MARGIN - radius + math.hypot(radius + half, body.length)
    high = band.left - MARGIN - half - 2.0 * radius
    return low, high


def layout(band: Band, d_from: float, d_to: float, body: Body) -> Layout:
    """The half circle from lane position `d_from` that ends at `d_to` if the road lets it
    (moving over first as far as the rear's swing needs), else the roundest that fits: one
    no tighter than the front bumper's path at full lock, and then a move across to `d_to` after it."""
    tightest = model(body).front_radius
    widest = _widest(band, body)
    if widest is None:  # too narrow even at the tightest: overhang both edges alike
        low, high = _start_range(band, tightest, body)
        d0 = (low + high) / 2.0
        return Layout(tightest, d0, d0 + 2.0 * tightest, False)

    def start(radius: float) -> float:
        low, high = _start_range(band, radius, body)
        return min(max(d_from, low), high)

    lo, hi = tightest, widest
    if start(lo) + 2.0 * lo >= d_to:
        hi = lo
    elif start(hi) + 2.0 * hi <= d_to:
        lo = hi
    for _ in range(30):  # where the half circle ends grows with its radius: bisect for d_to
        mid = (lo + hi) / 2.0
        lo, hi = (mid, hi) if start(mid) + 2.0 * mid < d_to else (lo, mid)
    radius = hi
    d0 = start(radius)
    d1 = d0 + 2.0 * radius
    half = body.width / 2.0
    # a move across swings the rear the other way: towards the right edge before, the left after
    before = move_length(d0 - d_from, d_from - half - band.right - MARGIN, body)
    after = move_length(d1 - d_to, band.left - MARGIN - half - d1, body)
    fits = before is not None and after is not None
    return Layout(radius, d0, d1, fits, before or 0.0, after or 0.0)


def _widest(band: Band, body: Body) -> float | None:
    """The widest radius whose half circle fits the road (None: not even the tightest, at full lock)."""
    tightest = model(body).front_radius
    if not _fits(band, tightest, body):
        return None
    lo, hi = tightest, max(tightest, band.left - band.right)
    for _ in range(30):
        mid = (lo + hi) / 2.0
        lo, hi = (mid, hi) if _fits(band, mid, body) else (lo, mid)
    return lo


def move_length(gap: float, room: float, body: Body) -> float | None:
    """The length of road for a move across of `gap` metres (0: none) whose rear swing stays
    within `room` (None: no move up to MAX_SHIFT long does)."""
    if abs(gap) < 0.05:
        return 0.0
    length = max(MIN_SHIFT, SHIFT * abs(gap))
    while _swing(gap, length, body) > room + 1e-6:
        length *= 1.2
        if length > MAX_SHIFT:
            return None
    return length


def _swing(gap: float, length: float, body: Body) -> float:
    """How far the rear of a body trailing a move across (`_move`) reaches back beyond where
    the move began: it lies on the tangent behind the front bumper."""
    if gap <= 0.0:
        return 0.0  # moving towards the edge: the rear swings away from it
    u = np.linspace(0.0, 1.0, 101)
    ahead = body.length / length
    return float(gap * np.max(-3.0 * u**2 + 2.0 * u**3 + 6.0 * ahead * u * (1.0 - u)))


def choose(band: Band, start: Point, lanes: Sequence[tuple[int, Polyline]], body: Body) -> tuple[int, float, Layout]:
    """Of the lanes the turn may end in (number and line running the new way, the preferred
    first): the first whose half circle ends within NEAR of it, else the one it reaches with the
    least move across after the half circle. Also that lane's d and the layout."""
    d_from = band.place(start)[1]
    options = []
    for rank, (number, line) in enumerate(lanes):
        d_to = band.d_abreast(line, start)
        plan = layout(band, d_from, d_to, body)
        after = abs(plan.d1 - d_to)
        options.append(((after > NEAR, after if after > NEAR else 0.0, rank), number, d_to, plan))
    _, number, d_to, plan = min(options, key=lambda option: option[0])
    return number, d_to, plan


def too_narrow(band: Band, action: str, legs: int = 0) -> UnsatError:
    """The site cannot hold the U-turn: unsatisfiable, so that its other rotations are tried.
    `legs`: the most legs a turn was tried in (0: one sweep only, as at a junction)."""
    how = f"even in {legs} legs, forward and reverse" if legs else "in one sweep (a turn in legs is not planned here)"
    width = band.left - band.right
    return UnsatError(Diagnostic(f"{action}: the road is {width:.1f} m wide, too narrow for a U-turn {how}"))


def _fits(band: Band, radius: float, body: Body) -> bool:
    low, high = _start_range(band, radius, body)
    return low <= high


def u_turn_line(band: Band, start: Point, target: Polyline, d_to: float, plan: Layout) -> tuple[Polyline, float, float]:
    """The turn from `start` onto `target` (a lane running the new way, at `d_to` across the
    band): the move across, the half circle, the move to the lane. Also the arc length within
    the turn where the half circle ends, and the one on `target` where the turn joins it."""
    s_a, d_a = band.place(start)
    before = move_across(s_a, d_a, plan.d0, plan.before, forward=True)
    centre, d0 = (before[-1][0], plan.d0) if before else (s_a, d_a)
    theta = np.linspace(0.0, math.pi, 25)
    middle = (centre + plan.radius * np.sin(theta), d0 + plan.radius * (1.0 - np.cos(theta)))
    arc = [band.at(float(s), float(d)) for s, d in zip(*middle, strict=True)]
    after = move_across(centre, d0 + 2.0 * plan.radius, d_to, plan.after, forward=False)
    head = [band.at(s, d) for s, d in before[1:-1]]
    turn = Polyline([start, *head, *arc[0 if before else 1 :]])
    arc_end = turn.length
    tail = [band.at(s, d) for s, d in after[1:]]
    s_t = target.project(tail[-1] if tail else arc[-1])[0]
    ends = [*tail[:-1], target.point(s_t)] if tail else [target.point(s_t)]
    return Polyline(np.vstack([turn.points[:-1] if not tail else turn.points, np.asarray(ends)])), arc_end, s_t


def move_across(s: float, d_from: float, d_to: float, length: float, *, forward: bool) -> list[tuple[float, float]]:
    """(s, d) points of a smooth move across from d_from to d_to over `length` metres of road,
    going forward or back along the band from s (empty for no move)."""
    if length == 0.0:
        return []
    out = []
    for w in np.linspace(0.0, 1.0, max(3, math.ceil(length) + 1)):
        smooth = w * w * (3.0 - 2.0 * w)
        out.append((s + (length if forward else -length) * w, d_from + (d_to - d_from) * smooth))
    return out


def footprint(line: Polyline, band: Band, body: Body, step: float = 0.5) -> tuple[float, float]:
    """The least and the greatest d any corner of the body reaches while its front bumper
    follows `line` (heading along it): the road is [band.right, band.left]."""
    at = np.arange(0.0, line.length, step)
    return corner_span(line, at, line.headings(at), band, body)


def corner_span(line: Polyline, at: np.ndarray, headings: np.ndarray, band: Band, body: Body) -> tuple[float, float]:
    """The least and the greatest d of the body's corners with its front bumper at `line`'s arc
    lengths `at`, facing `headings` (compass degrees; the line's own, or those of a turn in legs)."""
    low, high = math.inf, -math.inf
    for s, heading in zip(at, headings, strict=True):
        for corner in Box.of(body, *line.point(float(s)), float(heading)).corners():
            d = band.place(corner)[1]
            low, high = min(low, d), max(high, d)
    return low, high
