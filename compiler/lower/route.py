"""A participant's route on a site: the line it follows and where each of its actions happens.

The line is what a vehicle's front-bumper centre (a pedestrian's body centre) traces. Each
action is an `Event` with the stretch of the line it needs: a turn spans the junction, a
lane change the stretch over which it moves across, a stop is a point. A stop whose place
the site does not fix (anywhere along a lane) has a range, and the solver picks the point.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.geometry.trailing import trailing_headings
from sovarc.compiler.vehicles import PLANNED, Body, model
from sovarc.dsl.ir import Action, ActionKind, Participant

LATERAL_ACCEL = PLANNED.lateral_accel  # m/s^2: the most a car's turn may ask (each body's own caps its curve speeds)
LEAD = 20.0  # m: the least a participant drives before its first action, so that it is seen moving
CHANGE_TIME = 3.0  # s: a lane change takes about this long
MIN_CHANGE = 25.0  # m: the shortest lane change
MANOEUVRE_SPEED = 2.5  # m/s: the legs of a three-point turn are driven at walking pace
CAP_REACH = 3.0  # m either side of a leg whose curves cap its speed
TRAIL_STEP = 0.25  # m between the points a trailing body's heading is computed at (interpolated between)


@dataclass(frozen=True)
class Event:
    """Where one action happens along the route; `lo == hi` when its place is fixed."""

    index: int  # position in the participant's actions (-1 for none: an implied move)
    kind: ActionKind
    lo: float  # m along the line where it starts (a stop: the earliest place to stop)
    hi: float  # m where it ends (a stop: the latest place)
    gear_stop: bool = False  # a stop within a three-point turn (before it, or where it changes gear)

    @property
    def label(self) -> str:
        return f"{self.kind.value}" if self.index < 0 else f"action {self.index + 1} ({self.kind.value})"


@dataclass(frozen=True, eq=False)
class Manoeuvre:
    """A stretch of a route driven in legs that stop between them: a three-point turn (kturn.py).
    Over it the heading is the way the body faces, not the line's direction; elsewhere it is that."""

    index: int  # the action it performs (its position in the participant's actions)
    s: np.ndarray  # arc lengths on the route's line of the stretch's points, rising
    heading: np.ndarray  # compass heading the body faces at each, unwrapped
    stops: tuple[float, ...]  # where it stands: where the turn begins, then every change of gear
    gears: tuple[int, ...]  # the leg after each stop: +1 forward, -1 reverse
    backing: bool = False  # a car backing along the road (`reverse`), not a turn in legs: capped at its reversing speed

    @property
    def lo(self) -> float:
        return float(self.s[0])

    @property
    def hi(self) -> float:
        return float(self.s[-1])

    def carried(self, carry: Callable[[float], float]) -> Manoeuvre:
        """The same stretch with its arc lengths carried onto another line (a smoothed one)."""
        s = np.array([carry(float(x)) for x in self.s])
        stops = tuple(carry(x) for x in self.stops)
        return Manoeuvre(self.index, s, self.heading, stops, self.gears, self.backing)

    def facing(self, at: np.ndarray) -> np.ndarray:
        return np.interp(at, self.s, self.heading) % 360.0

    def gear(self, at: float) -> int:
        """The gear at arc length `at` (forward before the turn; at a stop, that of the leg it ends)."""
        k = int(np.searchsorted(np.asarray(self.stops), at, side="left"))  # the stops before it
        return self.gears[k - 1] if k > 0 else 1


@dataclass
class Route:
    participant: Participant
    body: Body
    line: Polyline
    events: list[Event]
    lanes: tuple[str, ...]
    edges: tuple[str, ...]
    start_hi: float  # latest place to start (when it starts moving); it may start anywhere from 0
    # where it starts at the earliest, past a corner its body would cross a line in (corners.py);
    # the solver holds a start to it only when its own choice lies before it (solve.py)
    start_lo: float = 0.0
    starts_at_rest: bool = False  # its first action is a stop (or it waits in a driveway)
    notes: list[str] = field(default_factory=list)
    caps: np.ndarray | None = None  # arc lengths and speed caps (m/s) along the smoothed line
    manoeuvres: tuple[Manoeuvre, ...] = ()  # its three-point turns and its backing, in order
    kerb: float = 0.0  # m its line lies right of its lane's centre line: a car parked at the kerb (`parked`)
    # a trailing body's heading along its line: the line, and its arc lengths and unwrapped headings
    trail: tuple[Polyline, np.ndarray] | None = None

    def cap_between(self, a: float, b: float) -> float:
        """The lowest curvature speed cap over [a, b] and CAP_REACH beyond, but not beyond a stop
        of a three-point turn: a car that stands there is not slowed by the legs on its other side."""
        at, caps = self.speed_caps()
        rests = self.rests()
        lo = max([a - CAP_REACH, *(r for r in rests if r <= a + 1e-6)])
        hi = min([b + CAP_REACH, *(r for r in rests if r >= b - 1e-6)])
        inside = (at >= lo) & (at <= hi)
        return float(caps[inside].min()) if inside.any() else float(np.interp(a, at, caps))

    def speed_caps(self) -> tuple[np.ndarray, np.ndarray]:
        """(arc lengths, speed cap at each) along the line (a vehicle's is already smoothed)."""
        if self.caps is None:
            limits = model(self.body).limits
            caps = np.sqrt(limits.lateral_accel * np.minimum(self._radii(), 1e6))
            backing = limits.reverse_speed
            for m in self.manoeuvres:
                # backing: from where it starts, a line of few vertices (a straight lane) capped throughout
                legs = (self.line.s > m.lo + (-1e-6 if m.backing else 1e-6)) & (self.line.s <= m.hi)
                caps[legs] = np.minimum(caps[legs], backing if m.backing else MANOEUVRE_SPEED)
            self.caps = np.vstack([self.line.s, caps])
        return self.caps[0], self.caps[1]

    def _radii(self) -> np.ndarray:
        """The line's radius of curvature at each vertex, measured within each stretch between the
        stops of its three-point turns (a change of gear is a turn back on the spot, no curve)."""
        rests = self.rests()
        if not rests:
            return self.line.curvature_radius(window=8.0)
        radii = np.zeros(len(self.line.s))  # a vertex shared by two stretches keeps the wider radius
        for a, b in zip([0.0, *rests], [*rests, self.line.length], strict=True):
            inside = (self.line.s >= a - 1e-6) & (self.line.s <= b + 1e-6)
            if b - a < 1e-6 or inside.sum() < 2:
                continue
            sub = self.line.sub(a, b)  # its vertices are the line's (stops are vertices)
            part = np.minimum(sub.curvature_radius(window=8.0), 1e6)
            if len(part) != inside.sum():
                part = np.interp(self.line.s[inside] - a, sub.s, part)
            radii[inside] = np.maximum(radii[inside], part)
        return np.where(radii > 0.0, radii, 1e6)

    def rests(self) -> list[float]:
        """Arc lengths where a three-point turn stands: before it and at every change of gear."""
        return sorted(s for m in self.manoeuvres for s in m.stops)

    @property
    def trails(self) -> bool:
        """Whether its body faces the way its rear axle trails its front's path (a bus or truck driving
        forwards throughout, as synthesis and the targets place it; geometry/trailing.py), not along it."""
        return model(self.body).trails and not self.manoeuvres

    def facing(self, at: np.ndarray) -> np.ndarray:
        """The compass heading the body faces at arc lengths `at`: the line's direction, a trailing
        body's heading (its rear axle's tractrix from the line's start), or over a three-point turn
        the heading its legs give."""
        if self.trails:
            if self.trail is None or self.trail[0] is not self.line:
                s = np.append(np.arange(0.0, self.line.length, TRAIL_STEP), self.line.length)
                headings = trailing_headings(
                    self.line.points_at(s), self.line.heading(0.0), model(self.body).axle_reach
                )
                self.trail = (self.line, np.vstack([s, np.degrees(np.unwrap(np.radians(headings)))]))
            s, unwrapped = self.trail[1]
            return np.interp(at, s, unwrapped) % 360.0
        out = self.line.headings(at)
        for m in self.manoeuvres:
            inside = (at >= m.lo) & (at <= m.hi)
            out[inside] = m.facing(at[inside])
        return out

    def gear(self, at: float) -> int:
        """+1 driving forward at arc length `at`, -1 reversing."""
        return next((m.gear(at) for m in self.manoeuvres if m.lo <= at <= m.hi), 1)

    def backing(self, at: float) -> bool:
        """Whether it backs along the road at arc length `at` (`reverse`; not a leg of a turn in legs),
        from where it stands to back on."""
        return any(m.backing and m.lo <= at <= m.hi for m in self.manoeuvres)

    @property
    def backs_at_end(self) -> bool:
        """Whether it is reversing on the last stretch of its line, where a crash is planned: it
        leads with its rear there (every crash type then reads with the striker's rear as its front).
        Backing along the road, or on a reverse leg of a turn in legs cut there (midturn.py)."""
        last = self.manoeuvres[-1] if self.manoeuvres else None
        return last is not None and (last.backing or last.gears[-1] < 0) and last.hi >= self.line.length - 1e-6

    @property
    def ends_in_legs(self) -> bool:
        """Whether its line ends within a turn in legs (cut where a leg ends, midturn.py): it stands
        there, at the change of gear, once it has driven its line."""
        last = self.manoeuvres[-1] if self.manoeuvres else None
        return last is not None and not last.backing and last.hi >= self.line.length - 1e-6

    def stops(self) -> list[Event]:
        """The places it stands, in order along the line: its stop actions and those of its turns."""
        return sorted((e for e in self.events if e.kind is ActionKind.STOP or e.gear_stop), key=lambda e: e.lo)


def change_length(speed: float) -> float:
    return max(MIN_CHANGE, CHANGE_TIME * speed)


def swept_change_length(body: Body, shift: float, room: float) -> float:
    """The shortest lane change (a smoothstep sideways move of `shift` metres) over which a body
    keeps its rear within `room` metres of its front's starting line on the far side: as the front
    turns across, the rear (a body length behind, along the heading) swings out the other way, by
    about the length times the heading's slope. A car's need (about 12 m) is under MIN_CHANGE;
    a 12 m bus's is some 40 m."""
    if shift <= 0.0:
        return 0.0
    u = np.linspace(0.0, 1.0, 201)
    across, slope = u * u * (3.0 - 2.0 * u), 6.0 * u * (1.0 - u)  # the smoothstep and its derivative

    def swing(length: float) -> float:
        return shift * float(np.max(body.length * slope / length - across))

    lo, hi = 1.0, 400.0
    if swing(hi) > room:
        return hi
    for _ in range(40):  # bisection: the swing falls as the change grows longer
        mid = (lo + hi) / 2.0
        lo, hi = (mid, hi) if swing(mid) > room else (lo, mid)
    return hi


def stop_range(before: float, after: float) -> tuple[float, float]:
    """A stop between the end of one stretch and the start of the next."""
    lo, hi = before + 1.0, after - 1.0
    if hi < lo:
        mid = (before + after) / 2.0
        return mid, mid
    return lo, hi


def order_stops(actions: tuple[Action, ...], stretches: dict[int, tuple[float, float]], length: float) -> list[Event]:
    """Events for every action: stretched ones as given, stops placed between their neighbours.

    Actions without a stretch or a stop (follow_lane, go_across on a straight road) happen
    wherever they fall and get no event.
    """
    events: list[Event] = []
    for k, action in enumerate(actions):
        if k in stretches:
            lo, hi = stretches[k]
            events.append(Event(k, action.kind, lo, hi))
        elif action.kind is ActionKind.STOP:
            before = max((hi for j, (_, hi) in stretches.items() if j < k), default=0.0)
            after = min((lo for j, (lo, _) in stretches.items() if j > k), default=length)
            lo, hi = stop_range(before, after)
            events.append(Event(k, ActionKind.STOP, lo, hi))
    return events
