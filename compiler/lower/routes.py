"""Build every vehicle's route on a matched site (pedestrians: see pedestrian.py).

On a junction site a vehicle drives its arm's lane to the stop line, takes the junction
connection its manoeuvre names (SUMO's own internal lanes, so the line is a lane SUMO
knows), and leaves on the lane it enters. A vehicle whose actions name no manoeuvre goes
straight across when it can (else turns right, else left), and the route says so in a note.
On a straight site it drives its lane along the road. Actions before and after the
junction are applied by a `Drive` along the road they happen on.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np
from sovarc.compiler.geometry.frame import Band
from sovarc.compiler.geometry.polyline import Polyline, bezier, concat
from sovarc.compiler.lower import kturn
from sovarc.compiler.lower.backing import backing_route, is_backing
from sovarc.compiler.lower.bends import keep_off_lines
from sovarc.compiler.lower.corners import clear_start
from sovarc.compiler.lower.corridor import Corridor, Drive, side_of
from sovarc.compiler.lower.route import LEAD, Event, Route, order_stops
from sovarc.compiler.lower.swing import Approach, keep_in_lane
from sovarc.compiler.lower.uturn import choose, too_narrow, u_turn_line
from sovarc.compiler.lower.wide import wide_turn
from sovarc.compiler.maps import Arm, Connection, LaneInfo, RoadMap, SiteMatch
from sovarc.compiler.maps.lane_map import lane_map
from sovarc.compiler.maps.needs import JUNCTION_MOVES
from sovarc.compiler.maps.search import geometric_exit
from sovarc.compiler.vehicles import PLANNED, Body, model, participant_model
from sovarc.dsl.errors import Diagnostic, LoweringError
from sovarc.dsl.ir import ActionKind, Heading, Participant, RoadKind, Side

ROAD_MOVES = frozenset({ActionKind.TURN_LEFT, ActionKind.TURN_RIGHT, ActionKind.DRIVE_OFF})
DEFAULT_MOVES = (ActionKind.GO_ACROSS, ActionKind.TURN_RIGHT, ActionKind.TURN_LEFT)
GAP = 10.0  # m between two actions' stretches
DRIVEWAY_TO_JUNCTION = 35.0  # m from a driveway a car pulls out of to the junction it then crosses
CORNER_WINDOW = 8.0  # m over which a corner's radius is measured (the speed caps' window)
CORNER_SLACK = 0.9  # a path may bend this much tighter than the line it follows (synthesis's Dubins radii)


def vehicle_route(
    p: Participant,
    match: SiteMatch,
    road_map: RoadMap,
    speed: float,
    side: Side,
    wrong_way_lane: int | None = None,
    prefer: tuple[ActionKind, str] | None = None,
    keep_lane: bool = False,
    lane: int | None = None,
) -> Route:
    """`side`: where a driveway move without a stated side goes; `wrong_way_lane`: which lane of the
    other direction a retrograde move drives in (the crash partner's); `prefer`: the junction move
    (and why) to plan when the actions name none; `keep_lane`: make the junction move from the lane
    the car drives in, across its neighbours, where the map makes it from another lane only
    (`_from_own_lane`); `lane`: the start lane, when not the placement's (centre.py). All are
    chosen by the caller."""
    if is_backing(p):  # parked, or backing along the road (backing.py)
        return backing_route(p, match, participant_model(p).body, lanes_touched)
    placement = match.placement(p.id)
    if placement is None or placement.arm is None or not isinstance(p.heading, Heading):
        raise LoweringError(Diagnostic(f"{p.id} has no place on site {match.site.id}", p.meta.where("heading")))
    arm = match.site.arm(placement.arm)
    body = participant_model(p).body
    # A cyclist keeps to the right-most lane of its direction (the kerb lane), whatever lane the
    # report gives; the junction move then leaves from that lane, as a vehicle's does.
    lane = 1 if body.vclass == "bicycle" else lane or placement.lane or 1
    corridor = Corridor.entering(arm)
    drive = Drive(
        corridor,
        corridor.own_line(lane),
        lane,
        speed=speed,
        wrong_way_lane=wrong_way_lane,
        site=match.site.id,
        median=match.site.median,
        body=body,
    )
    actions = p.known_actions
    approach_lanes: tuple[LaneInfo, ...] = ()
    bike = _bike_lane(corridor.own[0], road_map) if body.vclass == "bicycle" else None
    if bike is not None and match.site.kind is RoadKind.STRAIGHT:  # along a road, in its bike lane
        # the stretch of lane 1 the site uses, moved over onto the bike lane's centre
        drive.line = drive.line.offset((corridor.own[0].width + bike.width) / 2.0)
        drive.lanes = set(bike.lanes)
        drive.notes.append(f"rides in bike lane {bike.id}")
    if match.site.kind is RoadKind.STRAIGHT:
        _along(drive, actions, range(len(actions)), start=max(LEAD + 10.0, 0.3 * drive.line.length), side=side)
        entry = None
    else:
        entry, approach_lanes = _through_junction(drive, p, match, road_map, side, prefer, keep_lane)
    events = order_stops(actions, drive.stretches, drive.line.length)
    first = min((e.lo for e in events if e.kind is not ActionKind.STOP), default=entry or drive.line.length * 0.6)
    if entry is not None:
        events = [_at_stop_line(e, entry, actions) for e in events]
    starts_at_rest = bool(actions) and actions[0].kind is ActionKind.STOP
    # Smoothed once, here: the contact, the curve caps and the synthesized path all measure
    # arc length on the line the car really drives, so the crash lands where it was solved.
    # The legs of a three-point turn stay as laid out.
    line, from_s = drive.line.smoothing_except([(m.lo, m.hi) for m in drive.manoeuvres])
    if entry is not None and approach_lanes:  # its body kept in its lane up to the stop line (swing.py)
        approach = Approach.of(float(np.interp(entry, from_s, line.s)), ((a.shape, a.width) for a in approach_lanes))
        line, from_s, _ = keep_in_lane(line, from_s, approach, body)
    kerb = any(a.kind in (ActionKind.DRIVE_INTO, ActionKind.DRIVE_OFF) for a in actions)  # crosses the sidewalk
    # past the latest start its bends are driven whatever the start: eased where its body would cross a line
    latest = 0.0 if drive.start_off_road else float(np.interp(max(0.0, first - LEAD), from_s, line.s))
    lanes = drive.lanes | lanes_touched(line, match)
    keep = _laid_across(drive, events)
    lines = lane_map(road_map)  # the lanes as the oracle's lane-line test sees them
    line, from_s = keep_off_lines(line, from_s, lanes, lines, body, latest, kerb=kerb, keep=keep)

    def carry(x: float) -> float:
        return float(np.interp(x, from_s, line.s))

    if drive.junction is not None:
        _check_corner(line, carry(drive.junction[0]), carry(drive.junction[1]), body, p, match.site.id)

    events = [replace(e, lo=carry(e.lo), hi=carry(e.hi)) for e in events]
    manoeuvres = tuple(m.carried(carry) for m in drive.manoeuvres)
    events += [Event(m.index, ActionKind.U_TURN, s, s, gear_stop=True) for m in manoeuvres for s in m.stops]
    drive.lanes.update(lanes_touched(line, match))
    start_hi = carry(max(0.0, first - LEAD)) if not drive.start_off_road else 0.0
    moving = not (starts_at_rest or drive.start_off_road)
    return Route(
        participant=p,
        body=body,
        line=line,
        events=events,
        lanes=tuple(sorted(drive.lanes)),
        edges=tuple(drive.edges),
        start_hi=start_hi,
        start_lo=clear_start(line, drive.lanes, lines, body, start_hi, kerb=kerb) if moving else 0.0,
        starts_at_rest=starts_at_rest or drive.start_off_road,
        notes=[f"{p.id} {n}" for n in drive.notes],
        manoeuvres=manoeuvres,
    )


ACROSS_LINES = frozenset(
    {
        ActionKind.TURN_LEFT,
        ActionKind.TURN_RIGHT,
        ActionKind.CHANGE_LANE,
        ActionKind.RETROGRADE,
        ActionKind.DRIVE_INTO,
        ActionKind.DRIVE_OFF,
        ActionKind.U_TURN,
        ActionKind.REVERSE,
    }
)  # actions whose stretch of line is laid out by their own geometry, over lines or off the road


def _laid_across(drive: Drive, events: list[Event]) -> list[tuple[float, float]]:
    """The stretches of the line (on the raw line's arc length) laid out across lines, which easing a
    bend must leave as they are: a manoeuvre's legs, and the turns and the actions that move over."""
    kept = [(m.lo, m.hi) for m in drive.manoeuvres]
    return kept + [(e.lo, e.hi) for e in events if e.kind in ACROSS_LINES and e.hi > e.lo]


def _along(drive: Drive, actions: tuple[Any, ...], indices: range, *, start: float, side: Side) -> float:
    """Apply the actions with `indices` along the current road, from arc length `start`."""
    cursor = start
    kinds = tuple(a.kind for a in actions)
    for k in indices:
        action = actions[k]
        kind = action.kind
        if drive.left_road:
            break
        if kind is ActionKind.CHANGE_LANE:
            cursor = drive.change_lane(k, cursor, action.to) + GAP
        elif kind is ActionKind.RETROGRADE:
            cursor = drive.retrograde(k, cursor) + GAP
        elif kind is ActionKind.U_TURN:
            cursor = drive.u_turn(k, cursor, action.to) + GAP
        elif kind in ROAD_MOVES:
            neighbours = kinds[max(0, k - 1) : k + 2]
            cursor = drive.leave(k, cursor, side_of(kind, neighbours, side))
        elif kind is ActionKind.DRIVE_INTO:
            neighbours = kinds[max(0, k - 1) : k + 2]
            cursor = drive.enter(k, cursor, side_of(kind, neighbours, side)) + GAP
    return cursor


def _through_junction(
    drive: Drive,
    p: Participant,
    match: SiteMatch,
    road_map: RoadMap,
    side: Side,
    prefer: tuple[ActionKind, str] | None,
    keep_lane: bool = False,
) -> tuple[float, tuple[LaneInfo, ...]]:
    """Extend the drive's line across the junction; returns the stop line's arc length and the
    lanes of the arm the car may use up to it (none when it does not drive there in its own
    direction, or turns back)."""
    actions = p.known_actions
    site = match.site
    move_at = next((k for k, a in enumerate(actions) if a.kind in JUNCTION_MOVES), None)
    arm = site.arm(match.placement(p.id).arm)  # type: ignore[union-attr,arg-type]
    before = range(move_at if move_at is not None else len(actions))
    after = range(move_at + 1, len(actions)) if move_at is not None else range(0)
    if move_at is None:
        move = _default_move(site, arm, prefer[0] if prefer else None)
        why = f" ({prefer[1]})" if prefer and move is prefer[0] else ""
        drive.notes.append(f"names no manoeuvre at the junction: planned to {move.value}{why}")
    else:
        move = actions[move_at].kind
    start = max(LEAD, 0.35 * drive.line.length)
    if any(actions[k].kind is ActionKind.DRIVE_INTO for k in before):
        # Out of a driveway near the junction: its slow, tight start (which caps the speed of
        # the whole first leg) then leaves the car a short way to go.
        start = max(start, drive.line.length - DRIVEWAY_TO_JUNCTION)
    start = min(start, max(1.0, drive.line.length - 5.0))  # a short city arm: just before the junction
    _along(drive, actions, before, start=start, side=side)
    if drive.left_road:
        return drive.line.length, ()
    to = actions[move_at].to if move_at is not None else None
    index = move_at if move_at is not None else -1
    turn, exit_corridor, exit_number = _junction_line(drive, arm, move, to, match, road_map, index, keep_lane)
    entry = drive.line.length
    # a U-turn's or a wrong-way line is laid out, and so is a corner taken wide (its body crosses lane lines)
    own = () if drive.against or move is ActionKind.U_TURN or drive.wide else arm.incoming
    approach = tuple(lane for lane in own if lane.id in drive.lanes)
    exit_line = exit_corridor.own_line(exit_number)
    joins = exit_line.project(turn.point(turn.length))[0]  # a U-turn may join its lane past the start
    if joins > exit_line.length - 0.05:  # the way across ends where the exit lane does: no road leads on
        raise LoweringError(
            Diagnostic(
                f"{p.id}'s way across {site.id} ends at the end of the lane it leads into, not on a road that "
                "goes on (the map's lanes there may run the other way)",
                p.meta.where("heading"),
            )
        )
    if joins > 0.5:
        exit_line = exit_line.sub(joins, exit_line.length)
    drive.line = concat([drive.line, turn, exit_line])
    drive.corridor, drive.lane, drive.against = exit_corridor, exit_number, False
    drive._use(exit_corridor.own[exit_number - 1])
    done = entry + turn.length
    if isinstance(to, int) and to != exit_number and 1 <= to <= len(exit_corridor.own):
        settled = drive.drift_to(to, done + 2.0)
        if settled > done:
            drive.notes.append(
                f"turns into lane {exit_number} (no connection enters lane {to}), then moves to lane {to}"
            )
            done = settled
    if own:  # its line follows one of the junction's connections (a U-turn's or a wrong-way line is laid out)
        drive.junction = (entry, done)
    if move_at is not None:
        drive.stretches[move_at] = (entry, done)
    _along(drive, actions, after, start=done + GAP, side=side)
    return entry, approach


def _bike_lane(lane: LaneInfo, road_map: RoadMap) -> LaneInfo | None:
    """The bike lane beside a road's right-most car lane (SUMO's lane that allows bicycles and no
    cars, just right of it), when the car lane runs on one edge; None when it has none."""
    if len(lane.edges) != 1:
        return None
    edge = road_map.net.getEdge(lane.edge)
    beside = next((x for x in edge.getLanes() if x.getIndex() == lane.index - 1), None)
    if beside is None or not beside.allows("bicycle") or beside.allows("passenger"):
        return None
    shape = tuple((float(x), float(y)) for x, y, *_ in beside.getShape())
    length, speed = round(beside.getLength(), 3), round(beside.getSpeed(), 3)
    return LaneInfo(beside.getID(), lane.edge, beside.getIndex(), 1, round(beside.getWidth(), 3), length, speed, shape)


def _check_corner(line: Polyline, lo: float, hi: float, body: Body, p: Participant, site: str) -> None:
    """Refuse a junction connection whose line bends tighter than the body can: a bus or truck cannot
    follow a corner a car takes (its tightest bend is three times as wide), and its planned path,
    kept to its own radius, would leave the line and the road. Another site may have a wider corner.
    A connection is drawn (by SUMO) for a car, which takes it as it is: only a body that turns wider
    than the car's tightest is checked."""
    radius = _too_tight(line, body, lo, hi)
    if radius is not None:
        tightest = model(body).limits.path_radius
        raise LoweringError(
            Diagnostic(
                f"on {site}, {p.id} ({body.vclass}, {body.length:g} m) cannot take the junction's corner: "
                f"its line bends at a {radius:.1f} m radius, the body's tightest is {tightest:g} m, and the road "
                "has no room to swing wide through it",
                p.meta.span,
            )
        )


def _too_tight(line: Polyline, body: Body, lo: float = 0.0, hi: float = math.inf) -> float | None:
    """The radius `line` bends at between two arc lengths, when that is tighter than `body` can follow
    (within CORNER_SLACK); None when it can, and always for a body that turns as tight as a car."""
    tightest = model(body).limits.path_radius
    if tightest <= PLANNED.path_radius:
        return None
    inside = (line.s >= lo) & (line.s <= hi)
    radius = float(line.curvature_radius(window=CORNER_WINDOW)[inside].min()) if inside.any() else math.inf
    return radius if radius < CORNER_SLACK * tightest else None


def _default_move(site: Any, arm: Arm, prefer: ActionKind | None) -> ActionKind:
    for move in ((prefer,) if prefer else ()) + DEFAULT_MOVES:
        if any(c.direction in JUNCTION_MOVES[move] for c in site.connections_from(arm)):
            return move
    return ActionKind.U_TURN


def _junction_line(
    drive: Drive,
    arm: Arm,
    move: ActionKind,
    to: Any,
    match: SiteMatch,
    road_map: RoadMap,
    index: int,
    keep_lane: bool = False,
) -> tuple[Polyline, Corridor, int]:
    """The line across the junction, the corridor it leaves on and the lane number it enters
    (`index`: the move's action; -1 when the actions name none)."""
    connection: Connection | None = None
    across = None if drive.against or move is ActionKind.U_TURN else _no_connection(match, arm, move)
    if not drive.against and move is not ActionKind.U_TURN and across is None:
        current = drive.corridor.own[drive.lane - 1]
        connection = _pick_connection(match, arm, move, current, to)
        if connection.from_lane != current.id and keep_lane:
            return _from_own_lane(drive, match, move, connection, current)
        if connection.from_lane != current.id:
            number = _number(arm, connection.from_lane)
            try:
                drive.shift_to(number)
                drive.notes.append(f"moves to lane {number} to {move.value}")
            except LoweringError:
                if drive.stretches:
                    raise  # actions already placed on this arm: no other lane to start from
                drive.start_in(number)
                why = "the arm is too short to change lanes"
                drive.notes.append(f"starts in lane {number}, the lane its {move.value} leaves from: {why}")
    if move is ActionKind.U_TURN:
        return _u_turn(drive, arm, to, match.site.id, index)
    end = drive.line.point(drive.line.length)
    heading = drive.line.heading(drive.line.length)
    if drive.against or across is not None:
        corridor = Corridor.leaving(across or _wrong_way_exit(match, arm, move))
        count = len(corridor.own)
        # into the lane it names, else (across a junction by geometry) the nearest: a left turn's
        # left-most, a right turn's right-most, straight on its own lane number
        nearest = {ActionKind.TURN_LEFT: count, ActionKind.TURN_RIGHT: 1}.get(move, drive.lane)
        number = min(to if isinstance(to, int) else (count if drive.against else nearest), count)
        start = corridor.own_line(number)
        return bezier(end, heading, start.point(0.0), start.heading(0.0)), corridor, number
    assert connection is not None
    target = _lane(match, connection.to_lane)
    exit_arm = match.site.arm_of_lane(connection.to_lane)
    assert exit_arm is not None
    corridor = Corridor.leaving(exit_arm)
    shape = _via_shape(road_map, connection)
    if shape is None:
        turn = bezier(end, heading, target.shape[0], Polyline(target.shape).heading(0.0))
    else:
        turn = Polyline([end, *shape, target.shape[0]])
    if _too_tight(turn, drive.body) is not None:
        # a corner drawn for a car: a bus or truck swings wide through it, if the road lets it (wide.py)
        wide = wide_turn(drive.line, corridor.own_line(target.number), drive.body, road_map)
        if wide is not None:
            drive.line, turn, drive.wide = wide.approach, wide.turn, True
            drive.lanes.update(wide.lanes)
            drive.notes.append("swings wide through the junction's corner, then back into its lane")
    drive.lanes.update(_via_lanes(road_map, connection))
    drive.edges.extend(edge for edge in connection.edges if edge not in drive.edges)
    return turn, corridor, target.number


def _from_own_lane(
    drive: Drive, match: SiteMatch, move: ActionKind, connection: Connection, current: LaneInfo
) -> tuple[Polyline, Corridor, int]:
    """The move made from the lane the car is in, laid by geometry into the lane the map's own
    connection for it enters: a report that names the lane a car turned from (a right turn from
    the middle lane, straight on from a turn lane) describes a car that crossed its neighbours'
    paths to do it, whatever the map's arrows say. Tried only after every staging that keeps them."""
    target = _lane(match, connection.to_lane)
    exit_arm = match.site.arm_of_lane(connection.to_lane)
    assert exit_arm is not None
    corridor = Corridor.leaving(exit_arm)
    end, heading = drive.line.point(drive.line.length), drive.line.heading(drive.line.length)
    start = corridor.own_line(target.number)
    drive.notes.append(
        f"makes its {move.value} from lane {current.number}, as reported, across the lanes the map makes it from"
    )
    return bezier(end, heading, start.point(0.0), start.heading(0.0)), corridor, target.number


def _u_turn(drive: Drive, arm: Arm, to: Any, site: str, index: int) -> tuple[Polyline, Corridor, int]:
    """A U-turn at the junction back onto the arm's outgoing lanes (see uturn.py): its half circle
    begins at the stop line, and any move across before it ends there (the line is cut back to
    where it begins). Every lane of the arm's road is the U-turn's to use. Where no half circle
    fits, the car turns in legs (kturn.py) on the arm's road, the front no further than the stop line."""
    band = Band.across(arm.incoming, arm.outgoing)
    corridor = Corridor.leaving(arm)
    count = len(corridor.own)
    numbers = [min(max(to, 1), count)] if isinstance(to, int) else [count, *range(1, count)]
    end = drive.line.point(drive.line.length)
    lanes = [(n, corridor.own_line(n)) for n in numbers]
    number, d_to, plan = choose(band, end, lanes, drive.body)
    if not plan.fits:
        found = kturn.choose(band, end, lanes, drive.body)
        if found is None:
            raise too_narrow(band, f"on {site}, the U-turn from {arm.id}", kturn.MAX_LEGS)
        number, d_to, legs = found
        drive.line = drive.line.sub(0.0, max(1.0, drive.line.length - legs.before - legs.reach))
        turn = kturn.k_turn_line(band, drive.line.point(drive.line.length), corridor.own_line(number), d_to, legs)
        drive.record_turn(index, turn, drive.line.length, band, legs.count)
        drive.lanes.update(lane.id for lane in arm.incoming + arm.outgoing)
        return turn.line, corridor, number
    at = drive.line.length - plan.before
    if at > 1.0:
        drive.line = drive.line.sub(0.0, at)
    turn, _, _ = u_turn_line(band, drive.line.point(drive.line.length), corridor.own_line(number), d_to, plan)
    drive.lanes.update(lane.id for lane in arm.incoming + arm.outgoing)
    return turn, corridor, number


def _wrong_way_exit(match: SiteMatch, arm: Arm, move: ActionKind) -> Arm:
    """The arm a car driving the wrong way on `arm` leaves by: where the arm's connections for the
    move go (the map's own left and right, by which an unnamed move was chosen), else the arm in
    the move's slot of the compass cross (the two differ where roads meet askew). Never `arm`
    itself: its outgoing lanes are the ones the car is driving, so no line leads into them."""
    site = match.site
    linked = [site.arm_of_lane(c.to_lane) for c in site.connections_from(arm) if c.direction in JUNCTION_MOVES[move]]
    by_slot = _arm_in_move_slot(match, arm, move)
    ranked = ([by_slot] if by_slot in linked else []) + linked + [by_slot]
    found = next((a for a in ranked if a is not None and a.id != arm.id and a.outgoing), None)
    if found is None:
        raise LoweringError(
            Diagnostic(f"on {site.id}, no arm to {move.value} into from arm {arm.id} for a car driving the wrong way")
        )
    return found


def _arm_in_move_slot(match: SiteMatch, arm: Arm, move: ActionKind) -> Arm | None:
    """The arm a manoeuvre leaves by on the compass cross. Slots run clockwise by the heading of
    ENTERING traffic, so straight ahead leaves by the opposite slot, a left turn by the next slot."""
    return match.site.arm_in_slot(arm.slot + {ActionKind.TURN_LEFT: 1, ActionKind.TURN_RIGHT: 3}.get(move, 2))


def _no_connection(match: SiteMatch, arm: Arm, move: ActionKind) -> Arm | None:
    """The arm a move leaves by across the junction by geometry, when the map has no connection for
    it from `arm` (maps/search.geometric_exit); None when it has one."""
    if any(c.direction in JUNCTION_MOVES[move] for c in match.site.connections_from(arm)):
        return None
    return geometric_exit(match.site, arm, move)


def _pick_connection(match: SiteMatch, arm: Arm, move: ActionKind, current: LaneInfo, to: Any) -> Connection:
    options = [c for c in match.site.connections_from(arm) if c.direction in JUNCTION_MOVES[move]]
    if not options:
        raise LoweringError(Diagnostic(f"arm {arm.id} of {match.site.id} has no connection to {move.value}"))
    wanted_to = to if isinstance(to, int) else current.number

    def rank(c: Connection) -> tuple[int, int, str, str]:
        return (
            abs(_number(arm, c.from_lane) - current.number),
            abs(_lane(match, c.to_lane).number - wanted_to),
            c.from_lane,
            c.to_lane,
        )

    return min(options, key=rank)


def _number(arm: Arm, lane_id: str) -> int:
    return next(lane.number for lane in arm.incoming if lane.id == lane_id)


def _lane(match: SiteMatch, lane_id: str) -> LaneInfo:
    return next(lane for a in match.site.arms for lane in a.outgoing + a.incoming if lane.id == lane_id)


def _via_chain(road_map: RoadMap, connection: Connection) -> list[Any]:
    """The SUMO lanes a connection runs on between its two lanes, in order (SUMO splits some left
    turns in two; a junction of several nodes adds the short edges between them)."""
    return [road_map.net.getLane(lane) for lane in connection.path]


def _via_shape(road_map: RoadMap, connection: Connection) -> list[tuple[float, float]] | None:
    chain = _via_chain(road_map, connection)
    if not chain:
        return None
    return [tuple(p[:2]) for lane in chain for p in lane.getShape()]  # type: ignore[misc]


def _via_lanes(road_map: RoadMap, connection: Connection) -> list[str]:
    return [lane.getID() for lane in _via_chain(road_map, connection)]


def _at_stop_line(event: Event, entry: float, actions: Any) -> Event:
    """A stop just before the junction manoeuvre waits at the stop line."""
    if event.kind is not ActionKind.STOP:
        return event
    following = actions[event.index + 1].kind if event.index + 1 < len(actions) else None
    if following in JUNCTION_MOVES and event.hi >= entry - 2.0:
        return Event(event.index, event.kind, entry - 1.0, entry - 1.0)
    return event


def lanes_touched(line: Polyline, match: SiteMatch, margin: float = 0.3) -> set[str]:
    """Every lane of the site whose area the line passes through (within `margin` of its edge)."""
    points = line.resample(1.0)
    points = points[:: max(1, len(points) // 400)]
    low, high = points.min(axis=0), points.max(axis=0)
    found = set()
    for arm in match.site.arms:
        for lane in arm.incoming + arm.outgoing:
            shape = np.asarray(lane.shape)
            reach = lane.width / 2.0 + margin
            lane_low, lane_high = shape.min(axis=0), shape.max(axis=0)
            if (lane_high < low - reach).any() or (lane_low > high + reach).any():
                continue  # the lane's box misses the line's
            # only points near the lane's box can be within reach of it (the margin is far
            # above rounding), so the distances of the others need not be measured
            near = ((points >= lane_low - reach - 1e-6) & (points <= lane_high + reach + 1e-6)).all(axis=1)
            if near.any() and (Polyline(lane.shape).distances(points[near]) <= reach).any():
                found.update(lane.lanes)  # every SUMO lane of a chained lane
    return found
