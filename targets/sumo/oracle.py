"""The SUMO oracle's judgement (the paper's SIM function): a replay trace in, a Verdict out.

Checks, in order:
- `replay`: every participant is in the simulation at every step, on its recorded position.
- `collision`: some participants collide. SUMO's own detection (`getCollisions`) comes first,
  confirmed by the bodies (as SUMO placed them) overlapping at some step; where SUMO is blind
  (see below) the bodies overlapping counts too, and the verdict says which of the two saw it.
- `pair`: the first collision is between the report's striker and victim.
- `impact_angle`: at the first touch, the faces and the angle between headings match the
  crash type: rear_end = striker front into victim rear, headings within 45 degrees;
  frontal = front into front, headings at least 100 degrees apart (approaching each other;
  see `compiler/crashes.CRASH_ANGLES`); side = striker front into a side of the victim. At
  a corner of the victim, the face struck is decided from the touch (`crashes.struck_face`). A
  striker backing at the touch (as planned) leads with its rear: front and rear swap on both.
- `lane_lines`: until the impact, no participant's body reaches more than 25 cm into a lane
  its actions do not allow. Junction interiors have no painted lines and are not checked;
  sidewalks are always allowed to pedestrians, and to a car driving into or off the road by a
  driveway (it crosses the sidewalk).
- `on_road`: made only when a participant reverses: until the impact its body, as SUMO placed
  it, stays on the road's lanes (on_road.py).

SUMO's collision detection sees vehicles that overlap along one lane (including a wrong-way
driver on the lane: head-on), and, with `--collision.check-junctions`, vehicle shapes that
overlap on a junction. It does not see a vehicle striking a pedestrian who is not on a lane
or crossing the vehicle uses (a mid-block crossing), nor bodies that overlap across a lane
line while each one's front is still on its own lane; those are found from the bodies.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

from sovarc.compiler.crashes import (
    LINE_TOLERANCE,
    backing_at,
    face_words,
    first_overlap,
    fits,
    needs,
    struck_words,
    touch,
    victim_face,
)
from sovarc.compiler.geometry.bodies import Box, Contact, closest_points
from sovarc.compiler.geometry.lane_lines import crossed_lane
from sovarc.compiler.plan import Plan, Trajectory
from sovarc.dsl.ir import ActionKind
from sovarc.targets.sumo.network import Network
from sovarc.targets.sumo.on_road import on_road_finding
from sovarc.targets.sumo.replay import Pose, Trace
from sovarc.targets.verdict import Finding, Verdict

TARGET = "sumo"
TRACK_TOLERANCE = 0.10  # m between a replayed position and its sample


@dataclass(frozen=True)
class Crash:
    pair: tuple[str, str]  # sorted
    time: float  # s, the first step either SUMO or the bodies saw it
    detected_by: str  # 'sumo' or 'bodies'
    sumo_kind: str | None


def judge(plan: Plan, trace: Trace, network: Network) -> Verdict:
    crashes, unconfirmed = _crashes(plan, trace)
    striker, victim = plan.impact.striker, plan.impact.victim
    pair = tuple(sorted((striker, victim)))
    hit = next((c for c in crashes if c.pair == pair), None)
    contact = _contact(plan, trace) if hit else None
    until = contact.time if contact else trace.times[-1]
    findings = [
        _replay_finding(plan, trace),
        _collision_finding(plan, trace, crashes, unconfirmed),
        _pair_finding(crashes, striker, victim),
        _angle_finding(plan, contact),
        _lanes_finding(plan, trace, network, until),
    ]
    on_road = on_road_finding(plan, trace, network, until)  # a reversing body, as SUMO placed it (on_road.py)
    if on_road is not None:
        findings.append(on_road)
    facts = {
        "sumo": trace.sumo,
        "collisions": [
            {"pair": list(c.pair), "time": _t(c.time), "detected_by": c.detected_by, "sumo_type": c.sumo_kind}
            for c in crashes
        ],
        "planned_impact_time": _t(plan.impact.time),
    }
    if unconfirmed:
        facts["sumo_collisions_without_contact"] = [list(pair) for pair in unconfirmed]
    if contact:
        facts["impact"] = {
            "time": _t(contact.time),
            "point": [round(v, 3) for v in contact.point],
            "striker_face": "-".join(contact.zones[0]),
            "victim_face": "-".join(contact.zones[1]),
            "angle": round(contact.angle, 1),
        }
    return Verdict(TARGET, plan.scenario.name, plan.site, tuple(findings), facts)


def _t(value: float) -> float:
    return round(value, 3)


def body_of(t: Trajectory, pose: Pose) -> Box:
    return Box.of(t.body, pose.x, pose.y, pose.angle)


def _bodies(plan: Plan, trace: Trace, participant: str) -> list[Box | None]:
    t = plan.trajectory(participant)
    return [None if pose is None else body_of(t, pose) for pose in trace.poses[participant]]


def _crashes(plan: Plan, trace: Trace) -> tuple[list[Crash], list[tuple[str, str]]]:
    """Collisions in order, and the pairs SUMO reported whose bodies never touch.

    SUMO's report counts when the bodies, as SUMO placed them, overlap at some step: its
    one-dimensional lane check takes a wrong-way driver's body to lie behind its front along
    the lane, and so reports a head-on a body length early, or a near miss as a crash.
    """
    sumo = {tuple(sorted((c.collider, c.victim))): c for c in trace.collisions}
    found: list[Crash] = []
    unconfirmed: list[tuple[str, str]] = []
    for a, b in itertools.combinations(sorted(t.participant for t in plan.trajectories), 2):
        key = (a, b)
        step = _first_overlap(plan, trace, a, b)
        reported = sumo.get(key)
        if reported is not None and step is None:
            unconfirmed.append(key)
        elif reported is not None:
            found.append(Crash(key, reported.first, "sumo", reported.kind))
        elif step is not None:
            found.append(Crash(key, trace.times[step], "bodies", None))
    return sorted(found, key=lambda c: (c.time, c.pair)), unconfirmed


def _first_overlap(plan: Plan, trace: Trace, a: str, b: str) -> int | None:
    return first_overlap(_bodies(plan, trace, a), _bodies(plan, trace, b))


def _contact(plan: Plan, trace: Trace) -> Contact:
    """The striker's and victim's first touch, from the poses SUMO had them in."""
    s, v = plan.impact.striker, plan.impact.victim
    contact = touch(trace.times, _bodies(plan, trace, s), _bodies(plan, trace, v))
    assert contact is not None, "a crash is confirmed by the bodies"
    return contact


# --- findings ---------------------------------------------------------------------------


def _replay_finding(plan: Plan, trace: Trace) -> Finding:
    worst = (0.0, "", 0.0)
    for t in plan.trajectories:
        for k, pose in enumerate(trace.poses[t.participant]):
            time = trace.times[k]
            if pose is None:
                return Finding(
                    "replay", False, f"{t.participant} is not in the SUMO simulation at t={time:.2f} s", time
                )
            sample = t.at(time)
            error = math.dist((pose.x, pose.y), (sample.x, sample.y))
            if error > worst[0]:
                worst = (error, t.participant, time)
    error, who, time = worst
    if error > TRACK_TOLERANCE:
        return Finding("replay", False, f"SUMO placed {who} {error:.2f} m from its trajectory at t={time:.2f} s", time)
    return Finding("replay", True, "every participant follows its trajectory in SUMO at every step")


def _collision_finding(
    plan: Plan, trace: Trace, crashes: Sequence[Crash], unconfirmed: Sequence[tuple[str, str]]
) -> Finding:
    if crashes:
        c = crashes[0]
        a, b = c.pair
        if c.detected_by == "sumo":
            return Finding("collision", True, f"SUMO reports {a} and {b} colliding ({c.sumo_kind})", c.time)
        message = f"the bodies of {a} and {b} overlap in SUMO (a collision SUMO's own check does not report)"
        return Finding("collision", True, message, c.time)
    gap, time = _closest_approach(plan, trace)
    striker, victim = plan.impact.striker, plan.impact.victim
    message = f"no collision: {striker} and {victim} come no closer than {gap:.2f} m (at t={time:.2f} s)"
    if tuple(sorted((striker, victim))) in unconfirmed:
        message += "; SUMO reports one, but its bodies never touch (its lane model misplaces wrong-way bodies)"
    return Finding("collision", False, message, time)


def _closest_approach(plan: Plan, trace: Trace) -> tuple[float, float]:
    s, v = plan.trajectory(plan.impact.striker), plan.trajectory(plan.impact.victim)
    best = (math.inf, 0.0)
    for k, (ps, pv) in enumerate(zip(trace.poses[s.participant], trace.poses[v.participant], strict=True)):
        if ps is not None and pv is not None:
            a, b = closest_points(body_of(s, ps), body_of(v, pv))
            best = min(best, (math.dist(a, b), trace.times[k]))
    return best


def _pair_finding(crashes: Sequence[Crash], striker: str, victim: str) -> Finding:
    wanted = tuple(sorted((striker, victim)))
    if not crashes:
        return Finding("pair", False, f"{striker} and {victim} do not collide")
    first = crashes[0]
    if first.pair == wanted:
        return Finding(
            "pair", True, f"the first collision is between striker {striker} and victim {victim}", first.time
        )
    a, b = first.pair
    if any(c.pair == wanted for c in crashes):
        message = f"{a} and {b} collide first, before striker {striker} and victim {victim}"
    else:
        message = f"{a} and {b} collide; striker {striker} and victim {victim} never do"
    return Finding("pair", False, message, first.time)


def _angle_finding(plan: Plan, contact: Contact | None) -> Finding:
    kind = plan.impact.type
    if contact is None:
        return Finding("impact_angle", False, f"no {kind.value} impact: the striker and victim do not collide")
    striker, victim = plan.impact.striker, plan.impact.victim
    s_zone, v_zone = contact.zones
    backing = backing_at(plan, striker, contact.time)  # the striker as planned at the touch SUMO placed
    struck = struck_words(v_zone, victim_face(contact, backing))
    seen = f"{striker}'s {face_words(s_zone)} meets {victim}'s {struck} at {contact.angle:.0f} degrees"
    ok = fits(kind, contact, backing)
    message = f"{seen} ({kind.value})" if ok else f"{seen}; {needs(kind, striker, victim, backing)}"
    return Finding("impact_angle", ok, message, _t(contact.time))


def _lanes_finding(plan: Plan, trace: Trace, network: Network, until: float) -> Finding:
    for k, time in enumerate(trace.times):
        if time >= until - 1e-9:
            break
        for t in plan.trajectories:
            pose = trace.poses[t.participant][k]
            if pose is None or not t.lanes:
                continue
            crossed = lane_violation(network, t, pose, kerb=_uses_driveway(plan, t.participant))
            if crossed is not None:
                message = f"{t.participant} enters lane {crossed}, which its actions do not allow"
                return Finding("lane_lines", False, message, time)
    return Finding("lane_lines", True, "every participant keeps to the lanes its actions allow until the impact")


def _uses_driveway(plan: Plan, participant: str) -> bool:
    p = plan.scenario.participant(participant)
    kinds = {ActionKind.DRIVE_INTO, ActionKind.DRIVE_OFF}
    return p is not None and any(a.kind in kinds for a in p.known_actions)


def lane_violation(network: Network, t: Trajectory, pose: Pose, kerb: bool = False) -> str | None:
    """A lane beside the one SUMO has the participant on (same road, either direction) that its
    body reaches into beyond the tolerance, or that lane itself, when its actions do not allow it:
    the kernel's lane-line test (compiler/geometry/lane_lines.py). `kerb`: it drives into or off
    the road by a driveway, and so crosses the sidewalk on its way."""
    lane = network.lanes.get(pose.lane)
    if lane is None:
        return None
    corners = body_of(t, pose).corners(shrink=LINE_TOLERANCE)
    pedestrian = t.body.vclass == "pedestrian"
    return crossed_lane(network, lane, set(t.lanes), corners, pedestrian=pedestrian, kerb=kerb)
