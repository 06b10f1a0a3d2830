"""The defaults pass: facts a report leaves out, filled in by named rules and recorded.

Each default is one small function. It fills a fact only where the front end
left it `unknown`, and every fact it fills is listed in
`provenance.assumed`, so a reader (and `sovarc diff`) can tell a fact the
report states from one the compiler assumed. Nothing is filled silently.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from sovarc.compiler.frontend.words import opposite
from sovarc.dsl.ir import ActionKind, CrashType, Participant, Provenance, Role, Scenario, Unknown

Default = Callable[[Scenario], tuple[Scenario, list[str]]]

_STANDING_STARTS = (ActionKind.STOP, ActionKind.DRIVE_INTO, ActionKind.PARKED)


def lane_on_two_lane_road(s: Scenario) -> tuple[Scenario, list[str]]:
    """On a road with one lane in each direction (or a one-lane road), a vehicle driving in its own direction is
    in lane 1."""
    if s.road.lanes not in (1, 2):
        return s, []
    assumed: list[str] = []
    people: list[Participant] = []
    for p in s.participants:
        actions = p.known_actions
        moving = bool(actions) and actions[0].kind not in _STANDING_STARTS
        wrong_way = any(a.kind is ActionKind.RETROGRADE for a in actions[:1])
        if p.role is Role.VEHICLE and isinstance(p.lane, Unknown) and moving and not wrong_way:
            p = replace(p, lane=1)
            assumed.append(f"{p.id}.lane")
        people.append(p)
    return replace(s, participants=tuple(people)), assumed


def victim_of_two(s: Scenario) -> tuple[Scenario, list[str]]:
    """With two participants and a known striker, the victim is the other one."""
    c = s.crash
    if len(s.participants) != 2 or isinstance(c.striker, Unknown) or not isinstance(c.victim, Unknown):
        return s, []
    other = next((p.id for p in s.participants if p.id != c.striker), None)
    if other is None:
        return s, []
    return replace(s, crash=replace(c, victim=other)), ["crash.victim"]


def heading_from_crash(s: Scenario) -> tuple[Scenario, list[str]]:
    """Two vehicles in a rear-end crash travel the same way; head-on, opposite ways, also when one of them had
    gone into the other's lane (unless one turned or crossed, when the geometry says nothing)."""
    c = s.crash
    vehicles = [p for p in s.participants if p.role is Role.VEHICLE]
    if len(vehicles) != 2 or c.type not in (CrashType.REAR_END, CrashType.FRONTAL):
        return s, []
    known = [p for p in vehicles if not isinstance(p.heading, Unknown)]
    straight_on = (*_STRAIGHT_ON, ActionKind.RETROGRADE) if c.type is CrashType.FRONTAL else _STRAIGHT_ON
    if len(known) != 1 or any(a.kind not in straight_on for p in vehicles for a in p.known_actions):
        return s, []
    other = next(p for p in vehicles if isinstance(p.heading, Unknown))
    heading = known[0].heading if c.type is CrashType.REAR_END else opposite(known[0].heading)
    people = tuple(replace(p, heading=heading) if p is other else p for p in s.participants)
    return replace(s, participants=people), [f"{other.id}.heading"]


_STRAIGHT_ON = (ActionKind.FOLLOW_LANE, ActionKind.STOP, ActionKind.PARKED, ActionKind.CHANGE_LANE)

DEFAULTS: tuple[Default, ...] = (lane_on_two_lane_road, victim_of_two, heading_from_crash)


def apply_defaults(s: Scenario) -> Scenario:
    """Run every default in order; record what each filled in `provenance.assumed`."""
    assumed: list[str] = []
    for default in DEFAULTS:
        s, filled = default(s)
        assumed += filled
    if not assumed:
        return s
    provenance = s.provenance or Provenance()
    return replace(s, provenance=replace(provenance, assumed=(*provenance.assumed, *assumed)))
