"""Where the striker can meet the victim: the collision area C_A (the paper's Group 5).

At impact the striker's front-bumper centre touches the face of the victim the crash type
names: its rear (rear_end), its front (frontal) or the middle of its side (side). With the
victim's line V and its body length L, that face is at V(u) where u = s_v - k L and
k = 1, 0, 1/2; so a contact is a point where the striker's line meets the victim's line. A bus
or truck faces the way its rear axle trails (Route.facing), metres off its path in a bend: its
face is placed k L behind its front along that heading, as synthesis and the oracles place it.
Lines meet in two ways:

- a crossing: one point (s_striker, u), the lines at an angle;
- a shared stretch: the lines run together (one lane), in the same or opposite direction;
  there the contact may be anywhere, so it is a range with s_v = offset +- s_striker;
- where a shared stretch begins (a merge; or the striker swerving into an oncoming lane) or
  the victim's line leaves it (a diverge), one point at the angle between the lines.

A crash type accepts only some: a rear-end needs a shared stretch in the same direction
(or a shallow merge), a head-on a stretch in opposite directions (or a crossing met front
to front), a side impact a crossing, met where the striker's front face first reaches the
victim's side, before the lines cross (`_face_reaches`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from sovarc.compiler.crashes import CRASH_ANGLES  # what every oracle calls frontal
from sovarc.compiler.geometry.angles import angle_diff, angle_diffs
from sovarc.compiler.lower.route import Route
from sovarc.compiler.vehicles import Body
from sovarc.dsl.ir import CrashType

STEP = 0.5  # m between the points compared
TOUCH = 0.45  # m: lines closer than this meet
MERGE_BACK = 4.0  # m before a merge (after a diverge) from where the lines' angle is measured
APART = 1.0  # m: ... at the first point where they are this far apart
SHALLOW = 30.0  # degrees: lines crossing at less than this meet side to front before they cross
SIDE_OVERLAP = 0.1  # m a striker's front corner reaches into the victim's side at a shallow contact:
# small, since at 6 degrees each 0.1 m of it puts the first touch about 1 m before C_A
APART_WITHIN = 30.0  # m: lines that stay closer over this far do not merge, they run together
FRONT_OFFSET = 0.9  # m: fronts this far apart sideways still meet (about half a car's width)
HEAD_ON = 135.0  # degrees between headings for an offset frontal contact
# Lines that cross for a frontal crash meet at least as far apart as every oracle's frontal angle:
# a crossing under it is no frontal crash (it used to be planned and then failed the replay). No
# margin for the angle the bodies first touch at, which is not the lines' (a front corner touches
# earlier in a turn: crossings at 100-101 degrees touched at 99 on SUMO's Braunschweig network):
# synthesis measures that as the oracle does and refuses such a plan (compiler/synth/impact.py).
FRONTAL_CROSSING = CRASH_ANGLES["frontal"][0]
# A victim whose front has turned further than this from the striker's heading has left the lane
# they shared: 15 degrees inside every oracle's bound for a rear-end.
ALONG = CRASH_ANGLES["rear_end"][1] - 15.0
# Lines crossing between these angles can also meet front to front at a corner: the striker's front
# corner just inside the victim's way, struck square by the victim's front face (crashes.fits).
CORNER_ANGLES = (CRASH_ANGLES["rear_end"][1] + 15.0, FRONTAL_CROSSING)
CORNER_DEPTH = 0.5  # m the striker's front corner is into the victim's way: inside the corner of its front
FACE = {CrashType.REAR_END: 1.0, CrashType.FRONTAL: 0.0, CrashType.SIDE: 0.5}
# A striker backing into its victim leads with its rear: the crash type reads with front and rear
# swapped on both bodies (compiler/crashes.py), so the victim's face is the other type's, and a rear
# end (its rear into the victim's front) is two lines met head-on. A victim that backs names its faces
# as ever, but runs against them: its lines too meet as the other type's do (`meeting`).
AS_BACKING = {
    CrashType.REAR_END: CrashType.FRONTAL,
    CrashType.FRONTAL: CrashType.REAR_END,
    CrashType.SIDE: CrashType.SIDE,
}
# A vehicle turning off the lane its follower keeps is met on its side only once it has turned this
# far from the follower's heading: before that its rear corner is what the follower meets, from behind
# (compiler/crashes.struck_face: a rear-end up to 45 degrees). 5 degrees past that bound: a driveway
# turn's rear corner leaves the follower's way soon after, and synthesis measures the touch itself.
SIDE_TURNED = CRASH_ANGLES["rear_end"][1] + 5.0
SIDE_MARGIN = 0.1  # m the victim's rear corner is inside the striker's way at such a contact
# Where along the victim's side a side crash puts the striker's front, of its length from the front:
# the middle first, then further back. A car turning in legs lies across a lane as it moves off from
# its last change of gear, its middle often past the striker's path; and a striker that meets a moving
# victim's side at an angle (a left turner across an oncoming car) placed at the middle first touches
# its front corner as the victim drives on into it (synthesis refuses such a plan: the next is tried).
TURNING_SIDE = (0.5, 0.65, 0.8)


@dataclass(frozen=True)
class Contact:
    """Striker at arc length s in [lo, hi] meets the victim at s_v = offset + sign * s."""

    lo: float
    hi: float
    sign: int  # +1: same direction; -1: opposite; 0: a crossing (lo == hi, s_v = offset)
    offset: float
    angle: float  # degrees between the two directions of travel at the contact, 0..180
    kind: str  # 'crossing', 'shared', 'offset' (fronts meet head-on beside each other) or 'corner' (_corner)

    def victim_s(self, s: float) -> float:
        return self.offset + self.sign * s if self.sign else self.offset


def contacts(
    striker: Route,
    victim: Route,
    crash: CrashType,
    *,
    whole: bool = False,
    lines: Lines | None = None,
    sides: bool = False,
    grazing: bool = False,
) -> list[Contact]:
    """Every contact the crash type accepts, best first. A participant that turns in legs (a
    three-point turn) meets the other only after its last change of gear: the crash is on a
    forward leg and the solver puts it on the last one. A striker backing at the end of its route
    meets the victim with its rear, the line `body.length` behind its front bumper along the way it
    faces. `whole`: on the whole lines (to tell why there is no contact). `lines`: the pair's views
    and distances already made, for a caller asking of the same two routes more than once. `sides`:
    a side crash met at each of TURNING_SIDE's places on the victim's side, whoever turns in legs.
    `grazing`: only a side crash's contacts where the striker's corner just reaches the victim's side."""
    lines = lines if lines is not None else Lines(striker, victim)
    assert lines.striker is striker and lines.victim is victim
    backing = striker.backs_at_end
    named, crash = meeting(crash, striker, victim)
    k = FACE[named] * victim.body.length
    side = crash is CrashType.SIDE
    if whole or not (striker.manoeuvres or victim.manoeuvres):
        faces = [face * victim.body.length for face in TURNING_SIDE] if side and not whole else [k]
        mine = lines.view(striker, "front")
        if victim.trails:  # each face placed from the heading: k is in the view
            fronts = lines.view(victim, "body")
            views = [lines.view(victim, "body", back) for back in faces]
            met = (c for view in views for c in lines.meetings(mine, view, 0.0, side, fronts, grazing))
        else:
            theirs = lines.view(victim, "line")
            met = (c for back in faces for c in lines.meetings(mine, theirs, back, side, theirs, grazing))
        found = list(dict.fromkeys(met))
    else:
        lead = striker.body.length if backing else 0.0
        mine = lines.view(striker, "turns", lead) if striker.manoeuvres else lines.view(striker, "front")
        found = []
        for face in TURNING_SIDE if side and (victim.manoeuvres or sides) else (FACE[named],):
            fronts: _View | None = None  # the victim's front bumper's line, when it has one
            if victim.manoeuvres:  # the face itself: k is in the view
                theirs, back = lines.view(victim, "turns", face * victim.body.length), 0.0
            elif victim.trails:
                theirs, back = lines.view(victim, "body", face * victim.body.length), 0.0
                fronts = lines.view(victim, "body")
            else:
                theirs, back = lines.view(victim, "line"), face * victim.body.length
                fronts = theirs
            met = lines.meetings(mine, theirs, back, side, fronts, grazing)
            found += [_on_routes(c, mine, theirs) for c in met]
    found = [c for c in found if _accepts(crash, c)]
    preference = {
        CrashType.REAR_END: lambda c: (c.kind != "shared", c.angle, -c.hi),
        CrashType.FRONTAL: lambda c: (c.kind != "shared", -c.angle, c.lo),
        CrashType.SIDE: lambda c: (-min(c.angle, 90.0) // 15, c.lo),
    }[crash]
    return sorted(found, key=preference)


def meeting(crash: CrashType, striker: Route, victim: Route) -> tuple[CrashType, CrashType]:
    """The crash type whose victim face the striker's leading face meets, and the type whose lines'
    meeting it is: a backing striker swaps the first (its rear leads), each backing body the second
    (it runs against the way it faces)."""
    named = AS_BACKING[crash] if striker.backs_at_end else crash
    lines = AS_BACKING[named] if victim.backs_at_end else named
    return named, lines


def _accepts(crash: CrashType, c: Contact) -> bool:
    if crash is CrashType.REAR_END:
        return (c.kind == "shared" and c.sign == 1) or (c.kind == "crossing" and c.angle < 45.0)
    if crash is CrashType.FRONTAL:
        return (
            (c.kind == "shared" and c.sign == -1)
            or (c.kind in ("crossing", "offset") and c.angle >= FRONTAL_CROSSING)
            or c.kind == "corner"
        )
    if c.kind in ("offset", "corner"):
        return False
    return (c.kind == "crossing" and 5.0 <= c.angle <= 175.0) or (c.kind == "shared" and c.hi - c.lo < 8.0)


@dataclass(frozen=True)
class _View:
    """A route as the contact search sees it: points every STEP from its start, the heading the
    body faces at each, the body; the route's arc length is the view's plus `shift`."""

    points: np.ndarray
    s: np.ndarray
    headings: np.ndarray
    body: Body
    shift: float = 0.0

    @classmethod
    def of_line(cls, route: Route) -> _View:
        """The front bumper's line: the body trails along it. A car parked at the kerb is seen on its
        lane's line, which the kerb line runs beside at the same arc lengths: a car in the lane meets it
        there, its body overlapping the parked one by most of a width."""
        line = route.line.offset(-route.kerb) if route.kerb else route.line
        points, s = _samples(line.points, line.s)
        return cls(points, s, _headings(points), route.body)

    @classmethod
    def of_body(cls, route: Route, back: float) -> _View:
        """Where the point `back` metres behind the front bumper, along the heading the body faces, is
        when the front is at each arc length: a trailing body's faces lie along its heading, which in a
        bend is tens of degrees off its front's path (a victim's side met mid-turn is metres from where
        a body laid along the path puts it). Compared by the way it faces, as every oracle does."""
        line = route.line.offset(-route.kerb) if route.kerb else route.line
        s = np.arange(0.0, line.length + 1e-9, STEP)
        headings = route.facing(s)
        rad = np.radians(headings)
        points = line.points_at(s) - back * np.column_stack((np.sin(rad), np.cos(rad)))
        return cls(points, s, headings, route.body)

    @classmethod
    def of_front(cls, route: Route) -> _View:
        """A route's front bumper as it leads forwards: on its line, facing the way its body does."""
        return cls.of_body(route, 0.0) if route.trails else cls.of_line(route)

    @classmethod
    def after_turns(cls, route: Route, back: float) -> _View:
        """From the last stop of its three-point turns on: where the point `back` metres behind the
        front bumper, along the heading, is when the front is at each arc length. On a turn's last
        leg the body turns about its rear axle, far off the line the front bumper draws behind it,
        so a face is placed from the heading, as every oracle places the body."""
        last = route.rests()[-1]
        s = np.arange(last, route.line.length + 1e-9, STEP)
        headings = route.facing(s)
        rad = np.radians(headings)
        points = route.line.points_at(s) - back * np.column_stack((np.sin(rad), np.cos(rad)))
        # the lines are compared by the way they run: a backing body runs against the way it faces
        # (and so does one on a reverse leg its route ends in, midturn.py)
        reverse_leg = route.backs_at_end and not route.manoeuvres[-1].backing
        travel = (headings + 180.0 * np.array([reverse_leg or route.backing(float(x)) for x in s])) % 360.0
        return cls(points, s - last, travel, route.body, last)


def _on_routes(c: Contact, striker: _View, victim: _View) -> Contact:
    """A contact between views as one between the routes."""
    offset = c.offset + victim.shift - c.sign * striker.shift
    return replace(c, lo=c.lo + striker.shift, hi=c.hi + striker.shift, offset=offset)


class Lines:
    """A striker's and a victim's routes as the contact search compares them: each view of a route and
    each pair of views' distances made once, for every crash type and face asked of the pair (made
    again for each, the distance matrices were most of the contact search's time: on the truth scenarios
    on Town04, 958 were made where 333 serve). Lives as long as the caller's question about these two
    routes, which are not changed meanwhile."""

    def __init__(self, striker: Route, victim: Route) -> None:
        self.striker, self.victim = striker, victim
        self._views: dict[tuple[bool, str, float], _View] = {}
        self._near: dict[tuple[int, int], _Near] = {}

    def view(self, route: Route, how: str, back: float = 0.0) -> _View:
        """The route's view: its front bumper's line ('line'), its body's point `back` behind the front
        ('body'), its front as it leads ('front'), or that point from its last change of gear ('turns')."""
        assert route is self.striker or route is self.victim
        key = (route is self.striker, how, back)
        if key not in self._views:
            make = {
                "line": lambda: _View.of_line(route),
                "body": lambda: _View.of_body(route, back),
                "front": lambda: _View.of_front(route),
                "turns": lambda: _View.after_turns(route, back),
            }[how]
            self._views[key] = make()
        return self._views[key]

    def meetings(
        self,
        striker: _View,
        victim: _View,
        k: float,
        side: bool = False,
        fronts: _View | None = None,
        grazing: bool = False,
    ) -> list[Contact]:
        """`_meetings` of two of this pair's views, their distances made once."""
        key = (id(striker), id(victim))  # the views are this pair's own, kept as long as it is
        if key not in self._near:
            self._near[key] = _Near.of(striker, victim)
        near = self._near[key]
        if grazing:
            return _grazing(striker, victim, k, near) if side else []
        return _meetings(striker, victim, k, side, fronts, near)


@dataclass(frozen=True)
class _Near:
    """How a striker's view lies to a victim's: the distance between every two of their points, each
    striker point's nearest victim point, its distance from it and the angle between their headings."""

    d: np.ndarray
    nearest: np.ndarray
    apart: np.ndarray
    angle: np.ndarray

    @classmethod
    def of(cls, striker: _View, victim: _View) -> _Near:
        a, b = striker.points, victim.points
        d = np.hypot(a[:, None, 0] - b[None, :, 0], a[:, None, 1] - b[None, :, 1])
        nearest = d.argmin(axis=1)
        apart = d[np.arange(len(a)), nearest]  # each striker point's distance from the victim's line
        angle = np.abs(angle_diffs(striker.headings, victim.headings[nearest]))
        for shared in (d, nearest, apart, angle):
            shared.setflags(write=False)  # read by every crash type and face asked: none may change them
        return cls(d, nearest, apart, angle)


def _meetings(striker: _View, victim: _View, k: float, side: bool, fronts: _View | None, near: _Near) -> list[Contact]:
    """The contacts of the two views' lines; `k` m behind the victim's point is the face met, and
    `fronts`: the victim's front bumper at the same arc lengths, where it has one (not over a turn in legs)."""
    a, sa, ha = striker.points, striker.s, striker.headings
    b, sb, hb = victim.points, victim.s, victim.headings
    d, nearest, apart, angle = near.d, near.nearest, near.apart, near.angle
    close = apart < TOUCH
    parallel = close & ((angle < 20.0) | (angle > 160.0))
    found: list[Contact] = []
    gap = (striker.body.width + victim.body.width) / 2.0 - SIDE_OVERLAP
    for lo, hi in _runs(parallel):
        if sa[hi] - sa[lo] < 8.0:
            continue  # a brief touch: counted as a crossing below
        same = float(np.median(angle[lo : hi + 1])) < 90.0
        sign = 1 if same else -1
        offsets = sb[nearest[lo : hi + 1]] - sign * sa[lo : hi + 1]
        offset = float(np.median(offsets)) + k
        face_lo, face_hi = _along_face(ha, hb, sa, offset, sign, lo, hi)
        if sa[face_hi] - sa[face_lo] >= STEP:
            found.append(
                Contact(float(sa[face_lo]), float(sa[face_hi]), sign, offset, 0.0 if same else 180.0, "shared")
            )
        close[lo : hi + 1] = False
        if same and side and fronts is not None:
            # a side crash on a vehicle turning off: met where its side lies across the striker's line
            turned = _turned_side(striker, fronts, hi, int(nearest[hi]))
            if turned is not None:
                s_striker, u, turn = turned
                found.append(Contact(s_striker, s_striker, 0, u, turn, "crossing"))
            meets = (_merge(ha, hb, d, apart, nearest, lo, gap),)
        elif same:
            rear = victim.body.length / 2.0  # from the middle of the victim's side to its rear
            meets = (
                _merge(ha, hb, d, apart, nearest, lo, gap),
                _diverge(a, b, ha, hb, d, nearest, hi, victim.body.width / 2.0, rear),
            )
        else:
            meets = (_swerve_into(ha, hb, apart, nearest, lo, gap),)
        for meet in meets:
            if meet is not None:
                s_striker, u, turn = meet
                found.append(Contact(s_striker, s_striker, 0, u + k, turn, "crossing"))
    for lo, hi in _runs(close):
        i = lo + int(np.argmin(d[np.arange(lo, hi + 1), nearest[lo : hi + 1]]))
        if side:
            # a front meets a side before the lines cross, where its leading corner reaches it
            met = _face_reaches(apart, angle, nearest, i, striker.body.width / 2.0, victim.body.width / 2.0)
            if met is None and angle[i] < SHALLOW:
                continue  # never that far apart just before: the end of a shared stretch
            s_striker, u = met if met is not None else (float(sa[i]), float(sb[nearest[i]]))
            found.append(Contact(s_striker, s_striker, 0, u + k, float(angle[i]), "crossing"))
            continue
        if angle[i] < SHALLOW:
            # bodies touch well before shallow lines cross: meet where they are `gap` apart; lines
            # never that far apart just before are the end of a shared stretch (a diverge, above)
            back = _apart_before(apart, i, gap)
            if back is None:
                continue
            i = back
        s_striker, u = float(sa[i]), float(sb[nearest[i]])
        found.append(Contact(s_striker, s_striker, 0, u + k, float(angle[i]), "crossing"))
        if CORNER_ANGLES[0] < angle[i] < CORNER_ANGLES[1]:
            found.append(_corner(s_striker, u + k, float(angle[i]), striker.body, victim.body))
    # Fronts meet head-on a little to one side of each other before the lines cross (a car
    # turning across an oncoming one is hit early in its turn): an offset frontal contact.
    offset = (d[np.arange(len(a)), nearest] < FRONT_OFFSET) & (angle >= HEAD_ON) & ~parallel
    for lo, hi in _runs(offset):
        i = lo + int(np.argmax(angle[lo : hi + 1]))
        s_striker, u = float(sa[i]), float(sb[nearest[i]])
        found.append(Contact(s_striker, s_striker, 0, u + k, float(angle[i]), "offset"))
    return found


def _grazing(striker: _View, victim: _View, k: float, near: _Near) -> list[Contact]:
    """A side crash's crossings met where the striker's leading corner just reaches the victim's side
    (`_face_reaches`, no depth for the angle), tried after every other contact. A left turner across a
    narrow oncoming lane (2.7-3.0 m) has its corner in that lane 30 degrees into its turn: at 4 m/s
    it takes 0.2 s to go the 0.3 m deeper the usual contact puts it, and an oncoming victim at 15 m/s
    drives on 3 m meanwhile, so the victim's front corner touched first."""
    d, nearest, apart, angle = near.d, near.nearest, near.apart, near.angle
    close = (apart < TOUCH) & ~((angle < 20.0) | (angle > 160.0))
    found: list[Contact] = []
    for lo, hi in _runs(close):
        i = lo + int(np.argmin(d[np.arange(lo, hi + 1), nearest[lo : hi + 1]]))
        met = _face_reaches(apart, angle, nearest, i, striker.body.width / 2.0, victim.body.width / 2.0, 0.0)
        if met is not None and angle[i] >= SHALLOW:
            s_striker, u = met
            found.append(Contact(s_striker, s_striker, 0, u + k, float(angle[i]), "crossing"))
    return found


def _corner(s: float, u: float, angle: float, striker: Body, victim: Body) -> Contact:
    """Two fronts met across a crossing near right angles (`crashes.fits`): the striker's front is
    CORNER_DEPTH into the victim's way when the victim's front reaches the striker's near side, so
    the striker's leading corner enters the victim's front face. `s`, `u`: where the lines cross."""
    across = max(np.sin(np.radians(angle)), 0.5)
    ahead = (victim.width / 2.0 - CORNER_DEPTH) / across  # the striker's front short of the crossing
    return Contact(s - ahead, s - ahead, 0, u - striker.width / 2.0 / across, angle, "corner")


def _along_face(
    ha: np.ndarray, hb: np.ndarray, sa: np.ndarray, offset: float, sign: int, lo: int, hi: int
) -> tuple[int, int]:
    """A shared stretch [lo, hi] cut back to where the victim's front (at offset + sign * s, a body
    ahead of a rear-end's striker) last runs with the striker: past that the victim has turned
    out of the lane they share, and a striker there meets it angled away, in no rear-end."""
    j = np.clip(np.rint((offset + sign * sa[lo : hi + 1]) / STEP).astype(int), 0, len(hb) - 1)
    angle = np.abs(angle_diffs(ha[lo : hi + 1], hb[j]))
    along = np.flatnonzero((angle < ALONG) if sign == 1 else (angle > 180.0 - ALONG))
    return (lo, lo + int(along[-1])) if len(along) else (lo, lo)


def _face_reaches(
    apart: np.ndarray,
    angle: np.ndarray,
    nearest: np.ndarray,
    i: int,
    half_striker: float,
    half_victim: float,
    deeper: float = 0.5,
) -> tuple[float, float] | None:
    """Where, at or before striker point `i` (within APART_WITHIN), its front's leading corner,
    (half_striker) cos(angle) nearer the victim's line than its middle, is SIDE_OVERLAP into the
    victim's side, and `deeper` of its half width more when head-on to it (a quarter of its width), as
    (s, u) interpolated between points. A front meeting a side touches first there, not where the lines cross: a
    slow U-turn across a car beside it touched 3-5 m before a contact placed at the crossing."""
    rad = np.radians(angle)
    # deeper the steeper: a steep front closes fast, and a deeper touch is not lost if they part
    reach = half_victim + half_striker * np.abs(np.cos(rad)) - SIDE_OVERLAP - deeper * (half_victim * np.sin(rad))
    gap = apart - reach
    b = _last_at_least(gap, i, 0.0)
    if b is None:
        return None
    if b == i:
        return b * STEP, float(nearest[b]) * STEP
    t = float(gap[b] / (gap[b] - gap[b + 1]))  # gap[b + 1] < 0 <= gap[b]
    return (b + t) * STEP, float(nearest[b] + t * (nearest[b + 1] - nearest[b])) * STEP


def _apart_before(apart: np.ndarray, i: int, gap: float) -> int | None:
    """The last striker point at or before `i` (within APART_WITHIN) at least `gap` from the victim's line."""
    return _last_at_least(apart, i, gap)


def _last_at_least(values: np.ndarray, i: int, floor: float) -> int | None:
    """The last index at or before `i`, within APART_WITHIN of it, whose value is at least `floor`."""
    return next((b for b in range(i, max(-1, i - int(APART_WITHIN / STEP)), -1) if values[b] >= floor), None)


def _merge(
    ha: np.ndarray, hb: np.ndarray, d: np.ndarray, apart: np.ndarray, nearest: np.ndarray, lo: int, gap: float
) -> tuple[float, float, float] | None:
    """Where two lines that come from different places join one lane, as (s, u, angle): the
    lines converge at a shallow angle, and the side of one meets the other's front where they
    are still `gap` apart. At 8 degrees bodies touch some 10 m before the lines join, so a
    contact placed at the join would be preceded by that first touch, outside C_A."""
    j = int(nearest[lo])
    for k in range(int(MERGE_BACK / STEP), int(APART_WITHIN / STEP) + 1):
        if lo < k or j < k:
            return None
        if apart[lo - k] > APART or d[:, j - k].min() > APART:
            angle = max(_turn(ha[lo - k], hb[j - k]), 5.0)
            back = _apart_before(apart, lo, gap)
            back = lo if back is None else back
            return back * STEP, float(nearest[back]) * STEP, angle
    return None


def _turned_side(striker: _View, victim: _View, i0: int, j0: int) -> tuple[float, float, float] | None:
    """Where a striker keeping its lane meets the side of a victim turning off it, as (s, u, angle)
    with u the victim's front's arc length: the first point of the victim's line past the end of
    their shared stretch (striker point i0, victim point j0) where it has turned between SIDE_TURNED
    and 180 less that from the striker's heading while the rear corner of its side that faces the
    striker is still in the striker's way (at most its half width, less a margin, to the side the
    victim turns to). The striker's front is placed where it first reaches that side: at the rear
    corner, or where the side crosses the striker's far edge. Before the victim has turned that far
    the rear corner is met from behind; a turn so wide that its rear has left the striker's way
    first is met on no side (None): the rear face is what lies across the striker's path."""
    a, sa, ha = striker.points, striker.s, striker.headings
    b, sb, hb = victim.points, victim.s, victim.headings
    length, half = victim.body.length, victim.body.width / 2.0
    reach = striker.body.width / 2.0
    for j in range(j0, min(len(b), j0 + int(APART_WITHIN / STEP))):
        f = _unit(float(hb[j]))
        i = max(i0, int(np.argmin(np.hypot(*(a - (b[j] - length / 2.0 * f)).T))))
        g = _unit(float(ha[i]))
        turn = angle_diff(float(hb[j]), float(ha[i]))  # positive: turned to the striker's right
        if not SIDE_TURNED <= abs(turn) <= 180.0 - SIDE_TURNED:
            continue
        away = np.array([g[1], -g[0]]) if turn > 0 else np.array([-g[1], g[0]])  # the way it turns
        # the rear corner of the side it turns to, which faces the striker behind it
        corner = b[j] - length * f + half * np.array([-f[1], f[0]]) * (1.0 if turn < 0 else -1.0)
        lateral = float((corner - a[i]) @ away)
        if lateral > reach - SIDE_MARGIN:
            continue  # the rear lies across the striker's path: its rear face is what is met
        # the far edge of the striker's front (at -reach) meets the side where the side crosses it
        along = (-reach - lateral) / float(f @ away) if lateral < -reach else 0.0
        point = corner + along * f
        s = float(sa[i] + (point - a[i]) @ g)
        if along > length * 0.75 or not 0.0 <= s <= float(sa[-1]):
            return None
        return s, float(sb[j]), abs(turn)
    return None


def _unit(heading: float) -> np.ndarray:
    rad = np.radians(heading)
    return np.array([np.sin(rad), np.cos(rad)])


def _diverge(
    a: np.ndarray,
    b: np.ndarray,
    ha: np.ndarray,
    hb: np.ndarray,
    d: np.ndarray,
    nearest: np.ndarray,
    hi: int,
    half_width: float,
    rear: float,
) -> tuple[float, float, float] | None:
    """Where the victim's line leaves a lane the striker's line stays in, as (s, u, angle): a
    striker following a vehicle that turns off hits it as it angles out of the lane. At a
    shallow angle what it hits first is the rear corner still in the lane, so the contact puts
    the victim's rear at the striker's front once the victim's line is half its width out (u is
    the arc length where the middle of its side must then be, `rear` further on)."""
    j = int(nearest[hi])
    for k in range(int(MERGE_BACK / STEP), int(APART_WITHIN / STEP) + 1):
        if hi + k >= len(a) or j + k >= len(b):
            return None
        if d[hi + k].min() > APART and d[:, j + k].min() > APART:
            if _turn(hb[j], hb[j + k]) <= _turn(ha[hi], ha[hi + k]):
                return None  # the striker is the one that leaves: its front moves away from the victim
            angle = max(_turn(ha[hi + k], hb[j + k]), 5.0)
            if angle >= SHALLOW:
                return hi * STEP, j * STEP, angle  # turned away steeply: its side is what is hit
            out = next((i for i in range(hi, hi + k + 1) if d[i].min() >= half_width), hi)
            return out * STEP, float(nearest[out]) * STEP + rear, angle
    return None


def _swerve_into(
    ha: np.ndarray, hb: np.ndarray, apart: np.ndarray, nearest: np.ndarray, lo: int, gap: float
) -> tuple[float, float, float] | None:
    """Where the striker's line swerves into a lane the victim drives the other way, as
    (s, u, angle): its front, still angled, meets the oncoming victim's side where the lines
    are still `gap` apart (as in a merge)."""
    for k in range(int(MERGE_BACK / STEP), int(APART_WITHIN / STEP) + 1):
        if lo < k:
            return None
        if apart[lo - k] > APART:
            back = _apart_before(apart, lo, gap)
            back = lo if back is None else back
            return back * STEP, float(nearest[back]) * STEP, _turn(ha[lo - k], hb[int(nearest[lo])])
    return None


def _turn(a: float, b: float) -> float:
    """Degrees between two compass headings, 0..180."""
    return abs(angle_diff(float(a), float(b)))


def _samples(points: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    at = np.arange(0.0, s[-1] + 1e-9, STEP)
    return np.column_stack((np.interp(at, s, points[:, 0]), np.interp(at, s, points[:, 1]))), at


def _headings(points: np.ndarray) -> np.ndarray:
    d = np.diff(points, axis=0, append=points[-1:] + (points[-1:] - points[-2:-1]))
    return np.degrees(np.arctan2(d[:, 0], d[:, 1])) % 360.0


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    runs, start = [], None
    for i, flag in enumerate(mask):
        if flag and start is None:
            start = i
        elif not flag and start is not None:
            runs.append((start, i - 1))
            start = None
    if start is not None:
        runs.append((start, len(mask) - 1))
    return runs


def describe(c: Contact) -> str:
    if c.kind == "crossing":
        return f"paths cross at {c.angle:.0f} degrees"
    if c.kind == "offset":
        return f"fronts pass beside each other at {c.angle:.0f} degrees"
    if c.kind == "corner":
        return f"paths cross at {c.angle:.0f} degrees, a front corner into a front"
    return f"paths share {c.hi - c.lo:.0f} m of lane, {'same' if c.sign == 1 else 'opposite'} direction"
