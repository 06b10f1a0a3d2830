"""Pedestrian routes: laid against the vehicle they meet.

A pedestrian who crosses (or who walks and is struck from the side) walks straight across
the vehicle's road, through a point of the vehicle's route: just past the junction when the
vehicle crosses one, else 60% of the way along. The walking direction is whichever across
the road is nearer the pedestrian's heading. A pedestrian walking along the road (struck from
behind or head-on) walks in the vehicle's lane, a little right of its centre line.
"""

from __future__ import annotations

from sovarc.compiler.geometry.angles import angle_diff, heading_vector
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.lower.route import Event, Route, order_stops
from sovarc.compiler.maps import SiteMatch
from sovarc.compiler.vehicles import PEDESTRIAN
from sovarc.dsl.ir import ActionKind, CrashType, Participant

KERB = 12.0  # m from the vehicle's line to where a crossing starts and ends
BESIDE = 0.3  # m right of the vehicle's line where a walking pedestrian is
BACKED = 10.0  # m a backing car has backed when it meets a pedestrian
WALK_BEFORE, WALK_AFTER = 40.0, 15.0  # m of walking before and after the meeting point


def pedestrian_route(
    p: Participant, partner: Route, match: SiteMatch, crash: CrashType | None, junction_exit: float | None
) -> Route:
    line = partner.line
    anchor = junction_exit + 5.0 if junction_exit is not None else 0.6 * line.length
    anchor = min(max(anchor, partner.start_hi + 30.0), line.length - 10.0)
    if partner.backs_at_end:  # a car backs slowly, a few metres: met where its rear is after BACKED metres
        anchor = min(partner.body.length + BACKED, line.length - 1.0)
    heading = line.heading(anchor)
    q = line.point(anchor)
    kinds = {a.kind for a in p.known_actions}
    along = ActionKind.WALK in kinds and crash in (CrashType.REAR_END, CrashType.FRONTAL)
    notes: list[str] = []
    placement = match.placement(p.id)
    wanted = placement.site_heading if placement is not None else None
    if along:
        start = max(0.0, anchor - WALK_BEFORE)
        path = line.sub(start, min(line.length, anchor + WALK_AFTER)).offset(BESIDE)
        if crash is CrashType.FRONTAL:
            path = path.reversed()
    else:
        options = [(heading + 90.0) % 360.0, (heading - 90.0) % 360.0]
        if wanted is None:
            walk = options[1]  # from the right-hand kerb, towards the centre of the road
            notes.append(f"{p.id} heading unknown: planned to cross from the right-hand kerb")
        else:
            walk = min(options, key=lambda h: (abs(angle_diff(h, wanted)), h))
        d = heading_vector(walk)
        path = Polyline([(q[0] - KERB * d[0], q[1] - KERB * d[1]), (q[0] + KERB * d[0], q[1] + KERB * d[1])])
    if wanted is not None and abs(angle_diff(path.heading(path.length / 2.0), wanted)) > 60.0:
        notes.append(f"{p.id} walks {path.heading(path.length / 2.0):.0f} degrees, not its reported heading")
    events: list[Event] = order_stops(p.known_actions, {}, path.length)
    return Route(
        participant=p,
        body=PEDESTRIAN,
        line=path,
        events=events,
        lanes=(),
        edges=(),
        start_hi=max(0.0, path.length / 2.0 - 2.0),
        starts_at_rest=bool(p.known_actions) and p.known_actions[0].kind is ActionKind.STOP,
        notes=notes,
    )


def walking_speed(reported: float | None) -> float:
    return reported if reported is not None and 0.3 <= reported <= 4.0 else 1.4
