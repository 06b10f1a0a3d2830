"""A bend the car must drive, past where it may start, eased so its body keeps off the lane beside.

A plan's body trails its front bumper along the heading (compiler/plan.py; the SUMO oracle places
it the same way), so on a bend its rear swings to the outside by about L*sin(turn over a body
length). Where a lane's centre line kinks (a vertex turning tens of degrees: mapped roads often
jog just past a junction, the exit lane turning back a few metres after the junction turned the
other way), the smoothed line turns nearly all of it within a body length and the rear swings
over the line into the lane beside, the oncoming one on a two-lane road. swing.py reshapes only
the bend into the site's stop line, and corners.py only moves the start past a corner before it;
a bend past the latest start is driven whatever the start.

`keep_off_lines` finds the poses there that the oracle would judge crossing (corners.crossings)
and replaces the stretch around the first of them by a quintic curve meeting the line in
position, heading and curvature at both ends (swing's), among a few lengths and tangents the one
that crosses nothing, its corners moved out by swing.MARGIN (the synthesized path departs a little
from the line), and bends least tightly; then the next, if any. A line that crosses nothing
there, or for which no curve does, is returned as it is.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable

import numpy as np
from sovarc.compiler.geometry.lanes import LaneMap
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.lower.corners import crossings
from sovarc.compiler.lower.swing import MARGIN, MAX_SHIFT, REACH, end_pose, largest_shift, quintic, tightest_radius
from sovarc.compiler.vehicles import Body, model

BEFORE = (2.0, 4.0, 6.0, 8.0, 10.0, 12.0)  # m before the first crossing pose where an eased bend may begin
AFTER = (2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 15.0)  # m after it where it may rejoin the line
ROUNDS = 4  # bends eased at most, one after another along the line


def keep_off_lines(
    line: Polyline,
    from_s: np.ndarray,
    lanes: Iterable[str],
    net: LaneMap,
    body: Body,
    lo: float,
    *,
    kerb: bool = False,
    keep: Iterable[tuple[float, float]] = (),
) -> tuple[Polyline, np.ndarray]:
    """`line` (smoothed, with `from_s` from Polyline.smoothing) with each bend from `lo` on (the latest
    start) where the oracle would see the body cross a line into a lane beside (the route may use
    `lanes`) eased when some eased bend crosses none; returns the line and its `from_s`. `keep`:
    stretches (arc lengths on `from_s`'s scale) laid out as they must stay, a manoeuvre's legs."""
    lanes = sorted(set(lanes))
    kept = list(keep)
    since = lo
    for _ in range(ROUNDS):
        crossed = crossings(line, lanes, net, body, since, line.length, kerb=kerb, margin=MARGIN)
        if not len(crossed):
            break
        first = float(crossed[0])
        fixed = [(float(np.interp(a, from_s, line.s)), float(np.interp(b, from_s, line.s))) for a, b in kept]
        eased = _ease(line, first, lanes, net, body, kerb, fixed)
        if eased is None:
            # not this one; the next stretch that crosses, a body length on
            since = first + body.length
            continue
        new, start, end = eased
        grown = new.length - line.length
        from_s = _carry(line, from_s, new, start, end)
        line, since = new, end + grown
    return line, from_s


def _ease(
    line: Polyline,
    first: float,
    lanes: list[str],
    net: LaneMap,
    body: Body,
    kerb: bool,
    fixed: list[tuple[float, float]],
) -> tuple[Polyline, float, float] | None:
    """The best eased bend around the crossing pose at `first`: the line, and where the curve begins
    and ends (on the old line's arc length); None when none crosses nothing and stays near."""
    span = (first - max(BEFORE) - 1.0, first + max(AFTER) + 1.0)
    floor = min(tightest_radius(line, *span), model(body).limits.path_radius)
    best: tuple[float, Polyline, float, float] | None = None
    for before, after, reach in itertools.product(BEFORE, AFTER, REACH):
        start, end = first - before, first + after
        if start < 1.0 or end > line.length - 1.0 or any(a < end and start < b for a, b in fixed):
            continue
        new = _curve(line, start, end, reach)
        if new is None:
            continue
        grown = new.length - line.length
        radius = tightest_radius(new, start, end + grown)
        if radius < floor or (best is not None and radius <= best[0]):
            continue
        if largest_shift(line, new, start, end) > MAX_SHIFT:
            continue
        check_lo, check_hi = max(0.0, start - body.length), end + grown + body.length
        if len(crossings(new, lanes, net, body, check_lo, check_hi, kerb=kerb, margin=MARGIN)):
            continue
        best = (radius, new, start, end)
    return None if best is None else best[1:]


def _curve(line: Polyline, start: float, end: float, reach: float) -> Polyline | None:
    (p0, h0, k0), (p1, h1, k1) = end_pose(line, start), end_pose(line, end)
    curve = quintic(p0, h0, k0, p1, h1, k1, reach * math.dist(p0, p1))
    head, tail = line.points[line.s < start - 1e-6], line.points[line.s > end + 1e-6]
    try:
        new = Polyline(np.vstack([head, curve, tail]))
    except ValueError:
        return None
    if len(new.s) != len(head) + len(curve) + len(tail):
        return None  # a repeated point: arc lengths would not carry over vertex by vertex
    return new


def _carry(line: Polyline, from_s: np.ndarray, new: Polyline, start: float, end: float) -> np.ndarray:
    """`from_s` for `new`, which replaces `line` from `start` to `end`: the vertices before and after
    keep theirs, the curve's are spread evenly between the ends'."""
    head, tail = int((line.s < start - 1e-6).sum()), int((line.s > end + 1e-6).sum())
    middle = new.s[head : len(new.s) - tail]
    raw = np.interp([start, end], line.s, from_s)
    carried = np.interp(middle, [middle[0], middle[-1]], raw)
    return np.concatenate([from_s[:head], carried, from_s[len(from_s) - tail :]])
