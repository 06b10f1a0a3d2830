"""Parked and reversing vehicles on a straight site: where a parked car stands, and the line a
car backs along.

A parked car stands at the kerb: off the travel lane as far as the road allows, its body's right
side KERB_GAP inside the road's right edge (a street without a parking lane leaves part of its
right-most lane under a parked car, as real kerbside parking does). Its line is its lane's line
moved right by `kerb` metres; `parked` alone stands there throughout.

A car backs with its body facing its reported heading and its front bumper trailing: the line
runs against the heading, and the route keeps the stretch as a backing manoeuvre (route.py), the
heading the body faces at each point the line's direction turned round. It stands before it backs
(a car changes into reverse at rest), at PARK_AT of the road. `reverse` alone backs along its lane;
`parked, reverse` backs out of the space, moving across from the kerb into the right-most lane
over BACK_OUT metres, then on along it; `parked, drive_into` pulls out forwards the same way.
"""

from __future__ import annotations

import numpy as np
from sovarc.compiler.geometry.polyline import Polyline, blend
from sovarc.compiler.lower.corridor import Corridor
from sovarc.compiler.lower.route import Event, Manoeuvre, Route
from sovarc.compiler.maps import SiteMatch
from sovarc.compiler.vehicles import Body
from sovarc.dsl.errors import Diagnostic, LoweringError
from sovarc.dsl.ir import ActionKind, Participant, RoadKind

KERB_GAP = 0.15  # m between a parked body's right side and the road's edge
PARK_AT = 0.6  # of the road's length: where a parked or backing car stands
BACK_OUT = 10.0  # m along the road over which a car moves between the kerb and its lane
MOVES = frozenset({ActionKind.PARKED, ActionKind.REVERSE})


def is_backing(p: Participant) -> bool:
    """Whether its route is laid out here: it starts parked or backing."""
    actions = p.known_actions
    return bool(actions) and actions[0].kind in MOVES


def kerb_offset(corridor: Corridor, body: Body) -> float:
    """How far right of the right-most lane's centre a parked body's line lies."""
    return max(0.0, corridor.own[0].width / 2.0 - body.width / 2.0 - KERB_GAP)


def backing_route(p: Participant, match: SiteMatch, body: Body, lanes_touched: object) -> Route:
    """The route of a vehicle whose first action is `parked` or `reverse` (straight sites only)."""
    placement = match.placement(p.id)
    if placement is None or placement.arm is None:
        raise LoweringError(Diagnostic(f"{p.id} has no place on site {match.site.id}", p.meta.where("heading")))
    kinds = [a.kind for a in p.known_actions]
    where = p.meta.where("actions")
    if match.site.kind is not RoadKind.STRAIGHT:
        message = f"{p.id} {kinds[0].value}: a parked or backing car is staged on a straight road only"
        raise LoweringError(Diagnostic(message, where))
    parked = kinds[0] is ActionKind.PARKED
    rest = kinds[1:] if parked else kinds
    leaves = rest[0] if rest else None
    if any(k not in (ActionKind.STOP,) for k in rest[1:]) or leaves not in (
        None,
        ActionKind.STOP,
        ActionKind.REVERSE,
        ActionKind.DRIVE_INTO,
    ):
        message = f"{p.id}: after `parked` or `reverse` only `reverse`, `drive_into` or `stop` are staged"
        raise LoweringError(Diagnostic(message, where))
    if leaves is ActionKind.DRIVE_INTO and not parked:
        raise LoweringError(Diagnostic(f"{p.id}: `drive_into` pulls out of a space only after `parked`", where))
    arm = match.site.arm(placement.arm)
    corridor = Corridor.entering(arm)
    lane = 1 if parked else min(max(placement.lane or 1, 1), len(corridor.own))
    lane_line = corridor.own_line(lane)
    kerb = kerb_offset(corridor, body)
    at = PARK_AT * lane_line.length
    used = list(corridor.own[lane - 1].lanes)
    edges = list(corridor.own[lane - 1].edges)
    notes: list[str] = []
    manoeuvres: tuple[Manoeuvre, ...] = ()
    events: list[Event] = []
    if parked and leaves in (None, ActionKind.STOP):  # it stands throughout
        line, offset = corridor.own_line(1).offset(kerb), kerb
        notes.append(f"{p.id} parked at the kerb, {kerb:.2f} m right of lane 1's centre")
    elif leaves is ActionKind.DRIVE_INTO:
        line = blend(corridor.own_line(1).offset(kerb), lane_line, at, at + BACK_OUT).sub(at, lane_line.length)
        offset = 0.0
        events.append(Event(1, ActionKind.DRIVE_INTO, 0.0, BACK_OUT))
        notes.append(f"{p.id} pulls out of a kerbside space into lane 1")
    else:
        back = lane_line.reversed()
        start = lane_line.length - at
        if parked:
            kerb_back = corridor.own_line(1).offset(kerb).reversed()
            line = blend(kerb_back, back, start, start + BACK_OUT).sub(start, back.length)
            notes.append(f"{p.id} backs out of a kerbside space into lane 1")
        else:
            line = back.sub(start, back.length)
            notes.append(f"{p.id} backs along lane {lane}")
        offset = 0.0
        index = kinds.index(ActionKind.REVERSE)
        manoeuvres = (_backing(index, line, (back.heading(start) + 180.0) % 360.0),)
        events.append(Event(index, ActionKind.REVERSE, 0.0, BACK_OUT if parked else 0.0))
    touched = lanes_touched(line, match)  # type: ignore[operator]
    return Route(
        participant=p,
        body=body,
        line=line,
        events=events,
        lanes=tuple(sorted(set(used) | set(touched))),
        edges=tuple(edges),
        start_hi=0.0,
        starts_at_rest=True,
        notes=notes,
        manoeuvres=manoeuvres,
        kerb=offset,
    )


def _backing(index: int, line: Polyline, parked: float) -> Manoeuvre:
    """The whole line driven in reverse: the body faces against the way the line runs, and where it
    stands, the way it was parked (along the road; it turns as it moves off)."""
    facing = (line.headings(line.s) + 180.0) % 360.0
    facing[0] = parked
    unwrapped = np.degrees(np.unwrap(np.radians(facing)))
    return Manoeuvre(index, line.s.copy(), unwrapped, (0.0,), (-1,), backing=True)
