"""Fill the facts a report left unknown with the choices that stage the crash, and say so.

Lowering needs a heading, a lane and actions for every vehicle, and a crash type with its
striker and victim. Each choice here follows from the facts that are known (a rear-end's
vehicles share a heading, a head-on's oppose unless one of them turns back) and is
returned as a note that ends up in the plan (the side of a lane change said without one:
sides.py). Known facts are never changed, but for one contradiction no site can stage: two
cars crossing at right angles cannot both go straight across a T-junction, since one of them
comes from its stem (`_across_a_t`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from sovarc.compiler.lower.sides import choose_sides
from sovarc.dsl.ir import (
    Action,
    ActionKind,
    Crash,
    CrashType,
    Heading,
    Participant,
    RoadKind,
    Role,
    Scenario,
    Side,
    Unknown,
)

COMPASS = (Heading.NORTH, Heading.EAST, Heading.SOUTH, Heading.WEST)
CROSSING_KINDS = frozenset(
    {
        ActionKind.TURN_LEFT,
        ActionKind.TURN_RIGHT,
        ActionKind.DRIVE_INTO,
        ActionKind.DRIVE_OFF,
        ActionKind.U_TURN,
        ActionKind.CHANGE_LANE,
        ActionKind.RETROGRADE,
    }
)


@dataclass
class _Known:
    """What the choices depend on: everyone (as filled in so far), the crash, the road."""

    people: dict[str, Participant]
    striker: str
    victim: str
    crash: CrashType
    kind: RoadKind | None
    notes: list[str]

    def partner(self, p: Participant) -> Participant | None:
        other = self.victim if p.id == self.striker else self.striker
        if p.id not in (self.striker, self.victim):
            other = self.striker
        return self.people.get(other) if other != p.id else None


def assume(scenario: Scenario) -> tuple[Scenario, list[str]]:
    notes: list[str] = []
    crash = _crash(scenario, notes)
    kind = scenario.road.kind if isinstance(scenario.road.kind, RoadKind) else None
    known = _Known(
        {p.id: p for p in scenario.participants}, str(crash.striker), str(crash.victim), crash.type, kind, notes
    )  # type: ignore[arg-type]
    people = known.people
    # actions first: a heading's choice depends on them
    for pid, p in list(people.items()):
        people[pid] = _actions(p, known)
    _across_a_t(known)
    for pid in (known.striker, known.victim, *people):
        p = people.get(pid)
        if p is not None and isinstance(p.heading, Unknown) and p.role is Role.VEHICLE:
            people[pid] = _heading(p, known)
    choose_sides(known)  # the side of a lane change the report left out: it may place the pair's lanes
    for pid, p in list(people.items()):
        if isinstance(p.lane, Unknown) and p.role is Role.VEHICLE:
            people[pid] = _lane(p, known)
    participants = tuple(people[p.id] for p in scenario.participants)
    return replace(scenario, participants=participants, crash=crash), notes


def _crash(scenario: Scenario, notes: list[str]) -> Crash:
    crash = scenario.crash
    ids = [p.id for p in scenario.participants]
    striker, victim = crash.striker, crash.victim
    if isinstance(striker, Unknown):
        striker = next((i for i in ids if i != victim), ids[0])
        notes.append(f"striker unknown: planned as {striker}")
    if isinstance(victim, Unknown):
        victim = next(i for i in ids if i != striker) if len(ids) > 1 else striker
        notes.append(f"victim unknown: planned as {victim}")
    kind = crash.type
    if isinstance(kind, Unknown):
        a, b = scenario.participant(str(striker)), scenario.participant(str(victim))
        kind = CrashType.SIDE
        if a and b and isinstance(a.heading, Heading) and isinstance(b.heading, Heading):
            turn = (COMPASS.index(a.heading) - COMPASS.index(b.heading)) % 4
            kind = {0: CrashType.REAR_END, 2: CrashType.FRONTAL}.get(turn, CrashType.SIDE)
            if _turns_back(a) != _turns_back(b):
                kind = {CrashType.REAR_END: CrashType.FRONTAL, CrashType.FRONTAL: CrashType.REAR_END}.get(kind, kind)
        notes.append(f"crash type unknown: planned as {kind.value}, from the headings")
    return replace(crash, type=kind, striker=striker, victim=victim)


def _turns_back(p: Participant) -> bool:
    """Whether it ends up travelling against its starting heading (an odd number of U-turns).
    A retrograde driver does not: it keeps its heading in the other direction's lane."""
    return [a.kind for a in p.known_actions].count(ActionKind.U_TURN) % 2 == 1


def _actions(p: Participant, known: _Known) -> Participant:
    if not isinstance(p.actions, Unknown) and p.actions:
        return p
    if p.role is Role.PEDESTRIAN:
        chosen = ActionKind.CROSS
    else:
        chosen = ActionKind.FOLLOW_LANE
        partner = known.partner(p)
        partner_crosses = partner is not None and any(a.kind in CROSSING_KINDS for a in partner.known_actions)
        if known.kind is RoadKind.STRAIGHT and known.crash is CrashType.SIDE and not partner_crosses:
            chosen = ActionKind.DRIVE_INTO  # two cars along one road meet side-on only if one comes in
    what = "unknown" if isinstance(p.actions, Unknown) else "none"
    known.notes.append(f"{p.id} actions {what}: planned as {chosen.value}")
    return replace(p, actions=(Action(chosen),))


def _across_a_t(known: _Known) -> None:
    """At a T, of two cars going straight across from crossing directions one comes from the
    stem and must turn: the victim turns left, which crosses the near lane and enters the far
    one, so it meets a striker from either side."""
    a, b = known.people.get(known.striker), known.people.get(known.victim)
    if known.kind is not RoadKind.T_JUNCTION or a is None or b is None or a.id == b.id:
        return
    if not (isinstance(a.heading, Heading) and isinstance(b.heading, Heading)):
        return
    if (COMPASS.index(a.heading) - COMPASS.index(b.heading)) % 2 == 0 or not (_goes_across(a) and _goes_across(b)):
        return
    left = ActionKind.TURN_LEFT
    known.people[b.id] = replace(
        b, actions=tuple(replace(x, kind=left) if x.kind is ActionKind.GO_ACROSS else x for x in b.known_actions)
    )
    known.notes.append(
        f"{b.id} go_across: planned as turn_left, because {a.id} and {b.id} cross at right angles and a T-junction "
        f"cannot take both straight across; the victim turns out of the stem"
    )


def _goes_across(p: Participant) -> bool:
    return ActionKind.GO_ACROSS in [a.kind for a in p.known_actions]


def _heading(p: Participant, known: _Known) -> Participant:
    crash = known.crash
    partner = known.partner(p)
    if partner is None or not isinstance(partner.heading, Heading):
        heading = Heading.NORTH
        reason = "no participant to take it from"
    else:
        base = COMPASS.index(partner.heading)
        if crash is CrashType.SIDE and known.kind is not RoadKind.STRAIGHT:
            turn, reason = 1, f"crossing {partner.id}'s path"
        else:
            turn = 2 if crash is CrashType.FRONTAL else 0
            if _turns_back(p) != _turns_back(partner):
                turn = 2 - turn
            reason = f"{'opposite' if turn == 2 else 'same'} as {partner.id}, for a {crash.value} crash"
            if crash is CrashType.SIDE and _wrong_way(partner) and not _wrong_way(p):
                # a wrong-way driver side-swipes a car in the lane it swerves into: an oncoming one
                turn, reason = 2, f"opposite to {partner.id}, whose wrong-way drive swerves into its lane"
        heading = COMPASS[(base + turn) % 4]
    known.notes.append(f"{p.id} heading unknown: planned {heading.value} ({reason})")
    return replace(p, heading=heading)


def _lane(p: Participant, known: _Known) -> Participant:
    partner = known.partner(p)
    lane, reason = 1, ""
    if partner is not None and partner.heading == p.heading and isinstance(p.heading, Heading):
        lanes_known = isinstance(partner.lane, int)
        other = partner.lane if isinstance(partner.lane, int) else 1
        if known.crash is CrashType.REAR_END and lanes_known and not _changes_lane(p, partner):
            lane, reason = other, f" (as {partner.id}, for a rear-end crash)"
        elif lanes_known and any(a.kind is ActionKind.DRIVE_INTO for a in p.known_actions):
            lane, reason = other, f" (pulls into {partner.id}'s lane)"
        elif known.crash is CrashType.SIDE and _cuts_across(p, partner) is Side.RIGHT:
            lane, reason = other + 1, f" (left of {partner.id}: its right turn cuts across {partner.id}'s lane)"
        elif known.crash is CrashType.SIDE and _cuts_across(partner, p) is Side.LEFT:
            lane, reason = other + 1, f" (left of {partner.id}, whose left turn cuts across it)"
        elif known.crash is CrashType.SIDE and _same_turn(p, partner):
            lane, reason = other + 1, f" (beside {partner.id}, turning the same way: side by side in two turn lanes)"
    known.notes.append(f"{p.id} lane unknown: planned in lane {lane}{reason}")
    return replace(p, lane=lane)


def _changes_lane(*people: Participant) -> bool:
    return any(a.kind is ActionKind.CHANGE_LANE for p in people for a in p.known_actions)


def _wrong_way(p: Participant) -> bool:
    return any(a.kind is ActionKind.RETROGRADE for a in p.known_actions)


_TURN_SIDES = {ActionKind.TURN_RIGHT: Side.RIGHT, ActionKind.TURN_LEFT: Side.LEFT}


def _first_turn(p: Participant) -> Side | None:
    """The side of a participant's first left or right turn, if it makes one."""
    return next((_TURN_SIDES[a.kind] for a in p.known_actions if a.kind in _TURN_SIDES), None)


def _same_turn(p: Participant, partner: Participant) -> bool:
    """Both turn, and their first turns go the same way."""
    mine = _first_turn(p)
    return mine is not None and mine is _first_turn(partner)


def _cuts_across(p: Participant, partner: Participant) -> Side | None:
    """The side p turns to when it turns and its partner, going the same way, does not."""
    return _first_turn(p) if _first_turn(partner) is None else None
