"""Constraint lowering: a scenario on one site of a map, solved with Z3 (the paper's Groups 1-5).

lowered = lower(scenario, road_map, roads=3, seed=0)   # one Lowered per chosen site
stagings_on(staged, match, road_map, notes)            # one site's solvable stagings, best first

Steps: fill unknown facts with noted choices (assume.py), pick sites (maps.match_sites),
build each participant's route on the site (routes.py, pedestrian.py), find where striker
and victim can meet (contact.py), and solve starts, stops, speeds and the impact time
(solve.py). A conflict is an UnsatError naming the IR facts that conflict.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from dataclasses import dataclass, replace

from sovarc.compiler.lower.assume import COMPASS, assume
from sovarc.compiler.lower.centre import centre_lanes
from sovarc.compiler.lower.consistency import check_headings
from sovarc.compiler.lower.contact import SIDE_TURNED, Contact, Lines, contacts, describe
from sovarc.compiler.lower.midturn import brakes_in_time, earlier_legs
from sovarc.compiler.lower.pedestrian import pedestrian_route, walking_speed
from sovarc.compiler.lower.route import Route
from sovarc.compiler.lower.routes import DEFAULT_MOVES, vehicle_route
from sovarc.compiler.lower.solve import V_PED_MAX, ConflictError, Fact, Problem, Solution, solve
from sovarc.compiler.maps import RoadMap, SiteMatch, match_sites, scenario_needs, site_rotations
from sovarc.compiler.maps.needs import JUNCTION_MOVES
from sovarc.compiler.vehicles import participant_model
from sovarc.dsl.errors import Diagnostic, LoweringError, Severity, UnsatError
from sovarc.dsl.ir import Action, ActionKind, CrashType, Heading, Participant, RoadKind, Role, Scenario, Side, Speed
from sovarc.dsl.printer import format_speed

DEFAULT_LIMIT_KMH = {RoadKind.STRAIGHT: 70.0, RoadKind.INTERSECTION: 50.0, RoadKind.T_JUNCTION: 50.0}
USUAL_SHARE = 0.8  # of the limit: the speed a vehicle with no reported speed prefers
MAX_CONTACTS = 4  # contacts tried, best first
_STANDING = frozenset({ActionKind.STOP, ActionKind.PARKED})  # a participant of only these stands throughout
PAST_CORNER = "past a corner its body swings over a lane line in"  # why a start is held back (corners.py)


@dataclass(frozen=True)
class Lowered:
    """A scenario staged on one site: routes, the contact, and the solved schedule."""

    scenario: Scenario  # with the assumed facts filled in
    match: SiteMatch
    road_map: RoadMap
    routes: dict[str, Route]
    contact: Contact
    solution: Solution
    crash: CrashType
    striker: str
    victim: str
    notes: tuple[str, ...]


def lower(scenario: Scenario, road_map: RoadMap, *, roads: int = 1, seed: int = 0) -> list[Lowered]:
    """Stage the scenario on up to `roads` distinct sites of the map."""
    staged, notes, matches = sites_for(scenario, road_map, roads=roads, seed=seed)
    return [lower_on(staged, match, road_map, notes) for match in matches]


def sites_for(
    scenario: Scenario, road_map: RoadMap, *, roads: int = 1, seed: int = 0
) -> tuple[Scenario, list[str], list[SiteMatch]]:
    """The scenario with its unknown facts filled, the notes saying how, and the sites chosen for it."""
    staged, notes = assume(scenario)
    check_headings(staged)
    return staged, notes, match_sites(staged, road_map, n=roads, seed=seed, clamp=True)


def lower_on(scenario: Scenario, match: SiteMatch, road_map: RoadMap, notes: list[str]) -> Lowered:
    return next(stagings_on(scenario, match, road_map, notes))


def stagings_on(scenario: Scenario, match: SiteMatch, road_map: RoadMap, notes: list[str]) -> Iterator[Lowered]:
    """Every staging of the scenario on the site that Z3 can solve, best first, made only when asked
    for: the chosen rotation's stagings, each with its contacts in turn, then the other rotations'.
    Synthesis takes the next when it refuses one (its bodies would not first touch as the crash
    type needs). None at all raises the first UnsatError met."""
    crash = scenario.crash
    assert isinstance(crash.type, CrashType) and isinstance(crash.striker, str) and isinstance(crash.victim, str)
    limit, limit_fact = _limit(scenario, notes := list(notes))
    first: UnsatError | None = None
    found = False
    # a frontal crash met at a corner across a crossing (contact._corner) only after every other
    # staging: a turn across the partner's path that meets it head-on is the likelier crash
    # last, the pair's junction moves made from the lanes the report puts them in, across the lanes
    # the map makes those moves from (routes._from_own_lane): the map's arrows are kept while they can be
    # last, where one of the pair turns in legs: the crash on an earlier leg of the turn, its route cut
    # where that leg ends (midturn.py), after every staging of the whole turn; and for a side crash, last
    # of all, the striker's front met where its leading corner just reaches the victim's side
    # (contact._grazing): a slow front closing at a shallow angle on a fast victim
    passes = [(False, False, False, False)] + ([(True, False, False, False)] if crash.type is CrashType.FRONTAL else [])
    passes += [(False, True, False, False), (False, False, True, False)]
    passes += [(False, False, False, True)] if crash.type is CrashType.SIDE else []
    for corner, keep, legs, grazing in passes:
        for rotated in _rotations(scenario, match):
            args = (limit, limit_fact, match, corner, keep, legs, grazing)
            for item in _lower_rotated(scenario, rotated, road_map, notes, *args):
                if isinstance(item, UnsatError):
                    first = first or item
                else:
                    found = True
                    yield item
    if not found:
        assert first is not None
        raise first


def _rotations(scenario: Scenario, match: SiteMatch) -> Iterator[SiteMatch]:
    """The chosen rotation of the site, then its other fitting rotations: a crash the first
    cannot stage (a car that drives on put on a T's stem) may fit another. The others are
    found only when the first fails."""
    yield match
    others = site_rotations(match.site, scenario_needs(scenario), clamp=True)
    yield from (m for m in others if m.rotation != match.rotation)


def _lower_rotated(
    scenario: Scenario,
    match: SiteMatch,
    road_map: RoadMap,
    notes: list[str],
    limit: float,
    limit_fact: Fact,
    chosen: SiteMatch,
    corner: bool = False,
    keep: bool = False,
    legs: bool = False,
    grazing: bool = False,
) -> Iterator[Lowered | UnsatError]:
    """The solved stagings on one rotation of the site, in order, with the reason each one that fails
    does; `corner`: those met at a corner (contact._corner) alone, else all others; `keep`: only the
    one with the pair's junction moves made from their own lanes, when the map makes one of them
    from another lane (none else); `legs`: only those where one of the pair turns in legs, met on
    an earlier leg of the turn (midturn.py; the first reason stands); `grazing`: a side crash's
    contacts where the striker's corner just reaches the victim's side (contact._grazing) alone."""
    crash = scenario.crash
    assert isinstance(crash.type, CrashType) and isinstance(crash.striker, str) and isinstance(crash.victim, str)
    kept = _off_their_lanes(scenario, match, (crash.striker, crash.victim)) if keep else set()
    if keep and not kept:
        return
    notes = notes + list(match.clamped)
    if match.rotation != chosen.rotation:
        notes.append(
            f"staged with the report's compass turned {match.rotation} degrees, not {chosen.rotation}: "
            "the crash cannot happen as first placed on this site"
        )
    stagings = [(scenario, {}, None)] if keep else _stagings(scenario, crash.type, crash.striker, crash.victim)
    for variant, prefer, why in stagings:
        try:
            routes = _routes(variant, match, road_map, limit, crash.striker, crash.victim, prefer, kept)
        except LoweringError:
            if not keep:
                raise
            return  # the last pass's own route cannot be laid (a corner too tight): the first reason stands
        striker, victim = routes[crash.striker], routes[crash.victim]
        if legs:
            routes, found, leg = _on_earlier_leg(routes, crash.type, crash.striker, crash.victim)
        else:
            leg = ""
            found = contacts(striker, victim, crash.type, grazing=grazing)
            found = [c for c in found if (c.kind == "corner") == corner]
        if not found and legs:
            continue
        if not found:
            if corner or grazing:
                continue  # the reason is the first pass's
            yield UnsatError(_no_contact(scenario, match, striker, victim, crash.type))
            continue
        extra = [note for note in (why, leg) if note]
        extra += [n for route in routes.values() for n in route.notes]
        for item in _schedules(scenario, routes, found, limit, limit_fact):
            if isinstance(item, ConflictError):
                yield UnsatError(_conflict(scenario, match, item.facts))
                continue
            contact, solution = item
            relaxed = ["no natural-looking timing fits: speeds or waits are at the edge of what the facts allow"]
            held = [
                f"{pid} starts at least {routes[pid].start_lo:.0f} m along its route, {PAST_CORNER}"
                for pid in solution.held
            ]
            yield Lowered(
                scenario,
                match,
                road_map,
                routes,
                contact,
                solution,
                crash.type,
                crash.striker,
                crash.victim,
                tuple(notes + extra + held + (relaxed if solution.relaxed else [])),
            )


Staging = tuple[Scenario, dict[str, tuple[ActionKind, str]], str | None]


def _on_earlier_leg(
    routes: dict[str, Route], crash: CrashType, striker_id: str, victim_id: str
) -> tuple[dict[str, Route], list[Contact], str]:
    """Where one of the pair turns in legs: the routes with that one's cut where the first leg
    that meets the other ends, its contacts and a note (midturn.py); else the routes, no contact
    and no note."""
    for pid in (striker_id, victim_id):
        for cut, note in earlier_legs(routes[pid]):
            tried = {**routes, pid: cut}
            # a turner creeps through its legs: a moving partner's side is met anywhere along it
            found = contacts(tried[striker_id], tried[victim_id], crash, sides=True)
            found = [c for c in found if brakes_in_time(cut, c, pid == striker_id)]
            if found:
                return tried, found, note
    return routes, [], ""


def _stagings(scenario: Scenario, crash: CrashType, striker_id: str, victim_id: str) -> list[Staging]:
    """The ways to stage the scenario, tried in turn: each changes only what the report left
    open (which way an unnamed junction move goes, which lane a turn enters), and says so."""
    striker, victim = scenario.participant(striker_id), scenario.participant(victim_id)
    assert striker is not None and victim is not None
    out: list[Staging] = []
    meet = _meeting_move(striker, victim, crash)
    if meet is not None:
        out.append((scenario, {striker_id: meet}, None))
    out.append((scenario, {}, None))
    loose = _without_turn_lanes(scenario, (striker_id, victim_id))
    if loose is not scenario:
        # The lanes the turns enter are the least certain facts of a report.
        why = "the turns' target lanes keep the pair apart on this site: they enter their own lanes"
        out.append((loose, {}, why))
    meet = _meeting_move(victim, striker, crash)
    if meet is not None:
        out.append((scenario, {victim_id: meet}, None))
    if crash is CrashType.SIDE:
        joined, who = _into_partners_lane(scenario, striker, victim)
        if who:
            why = (
                f"{who}'s turn ends in its partner's lane, where they meet side-on: "
                "the lane the report names keeps them apart on this site"
            )
            out.append((joined, {}, why))
    if crash is CrashType.FRONTAL:
        # Fronts also meet where one turns across the other's path at a wide angle (at a T, a
        # car turning out of the stem and one turning into the road it crosses): the other
        # unnamed junction moves, of one car or of both, before the site's other rotations.
        seen = [{pid: kind for pid, (kind, _) in moves.items()} for _, moves, _ in out]
        partner = {striker_id: victim_id, victim_id: striker_id}
        for kinds in _move_choices(striker, victim):
            if kinds and kinds not in seen:
                why = {pid: (kind, f"to cross {partner[pid]}'s path front to front") for pid, kind in kinds.items()}
                out.append((scenario, why, None))
    return out


def _schedules(
    scenario: Scenario, routes: dict[str, Route], found: list[Contact], limit: float, limit_fact: Fact
) -> Iterator[tuple[Contact, Solution] | ConflictError]:
    """For each of the best contacts in turn, the solution of its constraints, or Z3's conflict."""
    crash = scenario.crash
    facts = _facts(scenario, routes, limit, limit_fact)
    for contact in found[:MAX_CONTACTS]:
        problem = Problem(
            routes=routes,
            striker=str(crash.striker),
            victim=str(crash.victim),
            crash=crash.type,  # type: ignore[arg-type]
            contact=contact,
            vmax={pid: _vmax(r.participant, limit, limit_fact, facts) for pid, r in routes.items()},
            preferred={pid: _preferred(r.participant, limit) for pid, r in routes.items()},
            facts=facts,
            stationary=_stationary(scenario, str(crash.striker)),
        )
        try:
            yield contact, solve(problem)
        except ConflictError as failure:
            yield failure


def _without_turn_lanes(scenario: Scenario, ids: tuple[str, ...]) -> Scenario:
    """The scenario with the `to` lanes of the given participants' junction moves dropped."""
    changed = False
    participants = []
    for p in scenario.participants:
        if p.id in ids and any(a.kind in JUNCTION_MOVES and a.to is not None for a in p.known_actions):
            actions = tuple(replace(a, to=None) if a.kind in JUNCTION_MOVES else a for a in p.known_actions)
            p = replace(p, actions=actions)
            changed = True
        participants.append(p)
    return replace(scenario, participants=tuple(participants)) if changed else scenario


def _into_partners_lane(scenario: Scenario, *pair: Participant) -> tuple[Scenario, str]:
    """The scenario with a turner's target lane made its partner's, when both leave the junction
    the same way in different lanes (and which participant that was, or '')."""
    for p, partner in (pair, pair[::-1]):
        ends, lane = _final_heading(p), _final_lane(partner)
        move = _junction_move(p)
        if move is None or ends is None or ends != _final_heading(partner) or lane is None or move.to == lane:
            continue
        actions = tuple(replace(a, to=lane) if a is move else a for a in p.known_actions)
        people = tuple(replace(q, actions=actions) if q.id == p.id else q for q in scenario.participants)
        return replace(scenario, participants=people), p.id
    return scenario, ""


def _final_lane(p: Participant) -> int | None:
    """The lane a vehicle drives on after the junction, as far as the report says."""
    last = [a.to for a in p.known_actions if a.kind in JUNCTION_MOVES and isinstance(a.to, int)]
    if last:
        return last[-1]
    if _junction_move(p) is not None:
        return None
    return p.lane if isinstance(p.lane, int) else None


def _junction_move(p: Participant) -> Action | None:
    """A participant's first junction move, if its actions name one."""
    return next((a for a in p.known_actions if a.kind in JUNCTION_MOVES), None)


def _limit(scenario: Scenario, notes: list[str]) -> tuple[float, Fact]:
    limit = scenario.road.speed_limit
    if isinstance(limit, Speed):
        fact = Fact("road.speed_limit", f"speed limit {format_speed(limit)}", scenario.road.meta.where("speed_limit"))
        return limit.to_mps(), fact
    kind = scenario.road.kind if isinstance(scenario.road.kind, RoadKind) else RoadKind.STRAIGHT
    kmh = DEFAULT_LIMIT_KMH[kind]
    notes.append(f"speed limit unknown: planned with {kmh:.0f} km/h")
    return kmh / 3.6, Fact("road.speed_limit", f"the assumed speed limit of {kmh:.0f} km/h")


def _reported(p: Participant) -> float | None:
    return p.speed.to_mps() if isinstance(p.speed, Speed) else None


def _preferred(p: Participant, limit: float) -> float:
    if p.role is Role.PEDESTRIAN:
        return walking_speed(_reported(p))
    reported = _reported(p)
    return reported if reported else min(USUAL_SHARE * limit, participant_model(p).limits.usual_speed)


def _vmax(p: Participant, limit: float, limit_fact: Fact, facts: dict[str, Fact]) -> tuple[float, Fact]:
    reported = _reported(p)
    if p.role is Role.PEDESTRIAN:
        return max(V_PED_MAX, reported or 0.0), facts[f"{p.id}.speed"]
    if reported:
        return max(limit, 1.25 * reported), facts[f"{p.id}.speed"]
    return min(limit, participant_model(p).limits.top_speed), limit_fact  # a cyclist keeps below its top speed


def _stationary(scenario: Scenario, striker: str) -> set[str]:
    return {
        p.id
        for p in scenario.participants
        if p.id != striker
        and p.known_actions
        and (all(a.kind in _STANDING for a in p.known_actions) or _reported(p) == 0.0)
    }


def _routes(
    scenario: Scenario,
    match: SiteMatch,
    road_map: RoadMap,
    limit: float,
    striker: str,
    victim: str,
    prefer: dict[str, tuple[ActionKind, str]],
    keep: set[str] | frozenset[str] = frozenset(),
) -> dict[str, Route]:
    routes: dict[str, Route] = {}
    people = [p for p in scenario.participants if p.role is Role.PEDESTRIAN]
    centre = centre_lanes(scenario, match, striker, victim)
    for p in scenario.participants:
        if p.role is Role.VEHICLE:
            side = _driveway_side(p, scenario, striker, victim)
            partner = scenario.participant(victim if p.id == striker else striker)
            wrong_way = partner.lane if partner is not None and isinstance(partner.lane, int) else None
            if partner is not None and partner.id in centre:
                wrong_way = centre[partner.id][0]
            lane, why = centre.get(p.id, (None, None))
            route = vehicle_route(
                p, match, road_map, _preferred(p, limit), side, wrong_way, prefer.get(p.id), p.id in keep, lane
            )
            if why:
                route.notes.insert(0, f"{p.id} {why}")
            routes[p.id] = route
    for p in people:
        partner_id = victim if p.id == striker else striker
        partner = routes.get(partner_id) or next(iter(routes.values()), None)
        if partner is None:
            raise LoweringError(Diagnostic(f"{p.id}: a pedestrian needs a vehicle to meet", p.meta.span))
        crash = scenario.crash.type if isinstance(scenario.crash.type, CrashType) else None
        exit_s = max((e.hi for e in partner.events if e.kind in JUNCTION_MOVES), default=None)
        routes[p.id] = pedestrian_route(p, partner, match, crash, exit_s)
    return routes


def _off_their_lanes(scenario: Scenario, match: SiteMatch, ids: tuple[str, ...]) -> set[str]:
    """Those of `ids` whose junction move (named, else the one routes plan: straight on where the
    arm has a way, routes.DEFAULT_MOVES) the map makes from their arm, but not from the lane the
    report puts them in (so lowering would move them over first)."""
    found = set()
    for pid in ids:
        p, placement = scenario.participant(pid), match.placement(pid)
        if p is None or p.role is not Role.VEHICLE or placement is None or placement.arm is None:
            continue
        arm = match.site.arm(placement.arm)
        if not isinstance(p.lane, int) or not arm.incoming:
            continue
        named = _junction_move(p)
        for kind in (named.kind,) if named is not None else DEFAULT_MOVES:
            ways = [c for c in match.site.connections_from(arm) if c.direction in JUNCTION_MOVES[kind]]
            if ways:
                lane = arm.incoming[min(placement.lane or 1, len(arm.incoming)) - 1].id
                if not any(c.from_lane == lane for c in ways):
                    found.add(pid)
                break
    return found


def _move_choices(*people: Participant) -> list[dict[str, ActionKind]]:
    """Every choice of junction move for those of `people` whose actions name none."""
    moves = (ActionKind.TURN_RIGHT, ActionKind.TURN_LEFT, ActionKind.GO_ACROSS)
    free = [(None, *moves) if p.role is Role.VEHICLE and _junction_move(p) is None else (None,) for p in people]
    return [
        {p.id: kind for p, kind in zip(people, combo, strict=True) if kind is not None}
        for combo in itertools.product(*free)
    ]


def _meeting_move(p: Participant, partner: Participant, crash: CrashType) -> tuple[ActionKind, str] | None:
    """For a vehicle whose actions name no junction move: the move that makes it meet its
    partner the way the crash type says (head-on: leave facing the partner's way back)."""
    if crash not in (CrashType.FRONTAL, CrashType.REAR_END) or Role.PEDESTRIAN in (p.role, partner.role):
        return None
    if _junction_move(p) is not None:
        return None
    mine, theirs = _final_heading(p), _final_heading(partner)
    if mine is None or theirs is None:
        return None
    want = (theirs + 2) % 4 if crash is CrashType.FRONTAL else theirs
    move = {0: ActionKind.GO_ACROSS, 1: ActionKind.TURN_RIGHT, 3: ActionKind.TURN_LEFT}.get((want - mine) % 4)
    if move is None:
        return None
    return move, f"to meet {partner.id} {'head-on' if crash is CrashType.FRONTAL else 'from behind'}"


def _final_heading(p: Participant) -> int | None:
    """The compass quarter (0 north .. 3 west) a participant leaves the junction on."""
    if not isinstance(p.heading, Heading):
        return None
    quarter = COMPASS.index(p.heading)
    for action in p.known_actions:
        quarter += {ActionKind.TURN_RIGHT: 1, ActionKind.TURN_LEFT: -1, ActionKind.U_TURN: 2}.get(action.kind, 0)
    return quarter % 4


def _driveway_side(p: Participant, scenario: Scenario, striker: str, victim: str) -> Side:
    """A driveway move without a stated side crosses the partner's lanes when they come the other way."""
    other = scenario.participant(victim if p.id == striker else striker)
    if other is None or not isinstance(other.heading, Heading) or not isinstance(p.heading, Heading):
        return Side.RIGHT
    facing = (COMPASS.index(p.heading) - COMPASS.index(other.heading)) % 4 == 2
    return Side.LEFT if facing else Side.RIGHT


def _facts(scenario: Scenario, routes: dict[str, Route], limit: float, limit_fact: Fact) -> dict[str, Fact]:
    facts = {
        "impact": Fact("impact", "the crash happens within a minute", scenario.crash.meta.span),
        "road.speed_limit": limit_fact,
    }
    crash_type = scenario.crash.type
    if isinstance(crash_type, CrashType):
        facts[f"crash.{crash_type.value}"] = Fact(
            f"crash.{crash_type.value}",
            f"crash type {crash_type.value} between {scenario.crash.striker} and {scenario.crash.victim}",
            scenario.crash.meta.where("type"),
        )
    for pid, route in routes.items():
        p = route.participant
        heading = p.heading.value if isinstance(p.heading, Heading) else "unknown"
        facts[f"{pid}.route"] = Fact(
            f"{pid}.route", f"{pid} heading {heading} in lane {p.lane} on this site", p.meta.where("heading")
        )
        facts[f"{pid}.chain"] = Fact(f"{pid}.chain", f"{pid}'s actions in order", p.meta.where("actions"))
        reported = _reported(p)
        facts[f"{pid}.speed"] = Fact(
            f"{pid}.speed",
            f"{pid} speed {format_speed(p.speed)}" if reported is not None else f"{pid}'s usual speed",
            p.meta.where("speed"),
        )
        for k, action in enumerate(p.known_actions):
            facts[f"{pid}.action{k}"] = Fact(
                f"{pid}.action{k}", f"{pid} action {k + 1} ({action.kind.value})", action.meta.span
            )
        for j in range(len(p.known_actions) + 2 + len(route.rests())):  # a leg per stop, a turn's too
            facts[f"{pid}.curve{j}"] = Fact(
                f"{pid}.curve{j}", f"the curves of {pid}'s route on this site", p.meta.where("actions")
            )
    return facts


def _no_contact(
    scenario: Scenario, match: SiteMatch, striker: Route, victim: Route, crash: CrashType
) -> list[Diagnostic]:
    lines = Lines(striker, victim)  # every question below compares the same two lines
    seen = contacts_any(striker, victim, lines)
    how = "; ".join(dict.fromkeys(describe(c) for c in seen)) or "their paths never meet"  # each wording once
    # a victim that leaves the lane they share (its line angles off it: a rear-end's crossing contact)
    leaves = any(c.kind == "crossing" for c in contacts(striker, victim, CrashType.REAR_END, lines=lines))
    if crash is CrashType.SIDE and leaves and any(c.kind == "shared" and c.sign == 1 for c in seen):
        s, v = striker.participant.id, victim.participant.id
        how += (
            f"; following {v} in its lane, {s} meets its rear: {v} is never turned {SIDE_TURNED:.0f} degrees or "
            f"more off the lane while still in {s}'s way"
        )
    turning = " and ".join(r.participant.id for r in (striker, victim) if any(not m.backing for m in r.manoeuvres))
    if turning and contacts(striker, victim, crash, whole=True, lines=lines):
        how = (
            f"they meet only while {turning} still turns in legs (a three-point turn), before its last change "
            "of gear, and on no leg of it, driven forward or reversing, do they meet as the crash type needs"
        )
    message = (
        f"on {match.site.id}, {striker.participant.id} cannot strike {victim.participant.id} as a {crash.value} "
        f"crash needs: {how}"
    )
    diagnostics = [Diagnostic(message, scenario.crash.meta.where("type"))]
    for p in (striker.participant, victim.participant):
        diagnostics.append(
            Diagnostic(f"{p.id} heading and actions, from here", p.meta.where("heading"), severity=Severity.NOTE)
        )
    return diagnostics


def contacts_any(striker: Route, victim: Route, lines: Lines | None = None) -> list[Contact]:
    lines = lines if lines is not None else Lines(striker, victim)
    found: list[Contact] = []
    for crash in CrashType:
        for c in contacts(striker, victim, crash, lines=lines):
            if c not in found:
                found.append(c)
    return found


def _conflict(scenario: Scenario, match: SiteMatch, facts: list[Fact]) -> list[Diagnostic]:
    listed = "; ".join(f.message for f in facts)
    head = Diagnostic(
        f"scenario '{scenario.name}' cannot be staged on {match.site.id}: these facts conflict: {listed}",
        next((f.span for f in facts if f.span is not None), scenario.meta.span),
    )
    notes = [Diagnostic(f.message, f.span, severity=Severity.NOTE) for f in facts if f.span is not None]
    return [head, *notes]
