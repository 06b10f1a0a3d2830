"""A participant's route on a site: the line it follows and where each of its actions happens.

The line is what a vehicle's front-bumper centre (a pedestrian's body centre) traces. Each
action is an `Event` with the stretch of the line it needs: a turn spans the junction, a
lane change the stretch over which it moves across, a stop is a point. A stop whose place
the site does not fix (anywhere along a lane) has a range, and the solver picks the point.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from sovarc.compiler.lower.polyline import Polyline
from sovarc.compiler.plan import Body
from sovarc.dsl.ir import Action, ActionKind, Participant

LATERAL_ACCEL = 2.5  # m/s^2: the most a turn may ask (comfortable; it caps speeds in curves)
LEAD = 20.0  # m: the least a participant drives before its first action, so that it is seen moving
CHANGE_TIME = 3.0  # s: a lane change takes about this long
MIN_CHANGE = 25.0  # m: the shortest lane change


@dataclass(frozen=True)
class Event:
    """Where one action happens along the route; `lo == hi` when its place is fixed."""

    index: int  # position in the participant's actions (-1 for none: an implied move)
    kind: ActionKind
    lo: float  # m along the line where it starts (a stop: the earliest place to stop)
    hi: float  # m where it ends (a stop: the latest place)

    @property
    def label(self) -> str:
        return f"{self.kind.value}" if self.index < 0 else f"action {self.index + 1} ({self.kind.value})"


@dataclass
class Route:
    participant: Participant
    body: Body
    line: Polyline
    events: list[Event]
    lanes: tuple[str, ...]
    edges: tuple[str, ...]
    start_hi: float  # latest place to start (when it starts moving); it may start anywhere from 0
    starts_at_rest: bool = False  # its first action is a stop (or it waits in a driveway)
    notes: list[str] = field(default_factory=list)
    caps: np.ndarray | None = None  # arc lengths and speed caps (m/s) along the smoothed line

    def cap_between(self, a: float, b: float) -> float:
        """The lowest curvature speed cap over [a, b]."""
        at, caps = self.speed_caps()
        inside = (at >= a - 3.0) & (at <= b + 3.0)
        return float(caps[inside].min()) if inside.any() else float(np.interp(a, at, caps))

    def speed_caps(self) -> tuple[np.ndarray, np.ndarray]:
        """(arc lengths, speed cap at each) along the line (a vehicle's is already smoothed)."""
        if self.caps is None:
            radii = self.line.curvature_radius(window=8.0)
            self.caps = np.vstack([self.line.s, np.sqrt(LATERAL_ACCEL * np.minimum(radii, 1e6))])
        return self.caps[0], self.caps[1]

    def stops(self) -> list[Event]:
        return [e for e in self.events if e.kind is ActionKind.STOP]


def change_length(speed: float) -> float:
    return max(MIN_CHANGE, CHANGE_TIME * speed)


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
