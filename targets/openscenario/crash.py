"""Crash findings: the encoded trajectories reach the collision area C_A together at the declared
impact time, the striker and the victim are both still in C_A when they first touch, their boxes
then overlap, where they begin to overlap the angle and the faces are those the crash type
names, and no other pair of bodies collides before it.

The first touch is judged by where the bodies are, with the same test of "in C_A" as at the
impact time, not by a time window: C_A's radius is the plan's own tolerance for where the crash
happens, and a time window is speed-dependent (0.3 s is 0.6 m at 2 m/s, 4 m at 13 m/s). An
oblique crash whose corner meets before the bumper centre reaches C_A still crashes in C_A;
a body that clips the other metres before C_A does not. Its time is kept as a fact.

Angles and faces follow the SUMO oracle, so that the two targets agree: rear_end = striker front
into victim rear, headings within 45 degrees; frontal = front into front, headings at least 100
degrees apart; side = striker front into a side of the victim (the faces decide, not the angle); at
a corner of the victim, the face struck is decided from the touch (compiler/crashes.struck_face). A
striker backing at the touch (it moves against the way it faces, as the file's poses show) leads with
its rear, and front and rear swap on both bodies: rear_end = its rear into the victim's front."""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from itertools import combinations

from sovarc.compiler.crashes import BACKING_FACES, CRASH_ANGLES, struck_face
from sovarc.compiler.crashes import VICTIM_FACES as CRASH_FACES
from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.geometry.bodies import Box, overlap, pressed, separation
from sovarc.targets.openscenario.kinematics import (
    box,
    contact_point,
    faces_at,
    footprint,
    gap,
    point_distance,
    pose_at,
)
from sovarc.targets.openscenario.readback import Entity, Pose, ScenarioFile
from sovarc.targets.verdict import Finding

AREA_TOL = 0.1  # m beyond C_A's radius
SCAN_STEP = 0.02  # s
BISECTIONS = 30  # of a scan step: far below a millimetre of travel
NEAR_SLACK = 1e-3  # m: points this close to the nearest distance are part of the contact (SUMO's oracle's)
OVERLAP_WINDOW = 1.0  # s after the first touch in which the bodies must overlap (players detect the crash)

# The victim faces each crash type names (compiler/crashes.py), by the type's name.
VICTIM_FACES: dict[str, frozenset[str]] = {kind.value: frozenset(faces) for kind, faces in CRASH_FACES.items()}
BACKED_INTO: dict[str, frozenset[str]] = {kind.value: frozenset(faces) for kind, faces in BACKING_FACES.items()}
BACKING_LOOK = 0.2  # s before the touch over which the striker's motion is read


@dataclass(frozen=True)
class Crash:
    type: str
    striker: str
    victim: str
    time: float
    point: tuple[float, float]
    radius: float


def _times(start: float, end: float) -> Iterator[float]:
    n = max(0, math.floor((end - start) / SCAN_STEP + 1e-9))
    for k in range(n + 1):
        yield start + k * SCAN_STEP


@dataclass(frozen=True)
class Scene:
    """The entities and their trajectories, to be asked where a body is at a time."""

    scenario: ScenarioFile
    paths: dict[str, tuple[Pose, ...]]

    def pose(self, name: str, t: float) -> Pose:
        return pose_at(self.paths[name], t)

    def box(self, name: str, t: float) -> Box:
        return box(self.scenario.entities[name], self.pose(name, t))

    def entity(self, name: str) -> Entity:
        return self.scenario.entities[name]

    def end(self, *names: str) -> float:
        return min(self.paths[n][-1].t for n in names)


def crash_findings(
    scenario: ScenarioFile, paths: dict[str, tuple[Pose, ...]], crash: Crash
) -> tuple[list[Finding], dict[str, object]]:
    scene = Scene(scenario, paths)
    facts: dict[str, object] = {}
    contact, first = _contact(scene, crash, facts)
    touch = crash.time if first is None else first  # the crash is judged where it happens, as SUMO's oracle does
    findings = [_area(scene, crash), contact, _overlap(scene, crash, touch)]
    findings.extend(_angle_and_faces(scene, crash, _onset(scene, crash, touch), facts))
    findings.extend(_other_contacts(scene, crash))
    return findings, facts


def _far_from_area(scene: Scene, crash: Crash, t: float) -> list[str]:
    """Whichever of striker and victim is not in C_A at time t, with its distance."""
    far = []
    for name in (crash.striker, crash.victim):
        distance = point_distance(crash.point, footprint(scene.entity(name), scene.pose(name, t)))
        if distance > crash.radius + AREA_TOL:
            far.append(f"{name} is {distance:.2f} m from it")
    return far


def _area(scene: Scene, crash: Crash) -> Finding:
    far = _far_from_area(scene, crash, crash.time)
    if far:
        return Finding("collision_area", False, f"at t={crash.time:g} s not both in C_A: {'; '.join(far)}", crash.time)
    message = f"striker and victim both reach C_A (radius {crash.radius:g} m) at t={crash.time:g} s"
    return Finding("collision_area", True, message, crash.time)


def first_touch_time(scenario: ScenarioFile, paths: dict[str, tuple[Pose, ...]], a: str, b: str) -> float | None:
    """When bodies a and b first touch as the file moves them (within 1 cm; None: never)."""
    scene = Scene(scenario, paths)
    return next((t for t in _times(0.0, scene.end(a, b)) if gap(scene.box(a, t), scene.box(b, t)) <= 0.01), None)


def _contact(scene: Scene, crash: Crash, facts: dict[str, object]) -> tuple[Finding, float | None]:
    """The first-contact finding and the time of the first touch (None: never)."""
    a, b = crash.striker, crash.victim
    first = first_touch_time(scene.scenario, scene.paths, a, b)
    facts["first_contact_time"] = None if first is None else round(first, 3)
    if first is None:
        return Finding("first_contact", False, f"{a} and {b} never touch"), None
    when = f"{a} and {b} first touch at t={first:.2f} s"
    far = _far_from_area(scene, crash, first)
    if far:
        side = "before" if first < crash.time else "after"
        message = f"{when}, {side} the impact t={crash.time:g} s, outside C_A: {'; '.join(far)}"
        return Finding("first_contact", False, message, first), first
    message = f"{when}, both in C_A (impact planned at {crash.time:g} s)"
    return Finding("first_contact", True, message, first), first


def _overlap(scene: Scene, crash: Crash, touch: float) -> Finding:
    a, b = crash.striker, crash.victim
    window = _times(touch, min(scene.end(a, b), touch + OVERLAP_WINDOW))
    hit = next((t for t in window if overlap(scene.box(a, t), scene.box(b, t))), None)
    if hit is None:
        message = f"the bounding boxes of {a} and {b} never overlap after the impact: a player sees no collision"
        return Finding("overlap", False, message, touch)
    return Finding("overlap", True, f"the bounding boxes overlap from t={hit:.2f} s", hit)


def _onset(scene: Scene, crash: Crash, touch: float) -> float:
    """The instant the boxes begin to overlap, bisected between the last scan step without overlap
    and the first with it, as SUMO's oracle bisects between its steps: the faces are read at the
    first instant of contact, where a corner that leads is still a corner (`touch` if they never
    overlap within OVERLAP_WINDOW)."""
    a, b = crash.striker, crash.victim
    window = _times(touch, min(scene.end(a, b), touch + OVERLAP_WINDOW))
    hi = next((t for t in window if overlap(scene.box(a, t), scene.box(b, t))), None)
    if hi is None:
        return touch
    lo = max(0.0, hi - SCAN_STEP)
    if overlap(scene.box(a, lo), scene.box(b, lo)):
        return lo  # overlapping from the start
    for _ in range(BISECTIONS):
        mid = (lo + hi) / 2
        if overlap(scene.box(a, mid), scene.box(b, mid)):
            hi = mid
        else:
            lo = mid
    return lo


def _angle_and_faces(scene: Scene, crash: Crash, touch: float, facts: dict[str, object]) -> Iterator[Finding]:
    s_pose, v_pose = scene.pose(crash.striker, touch), scene.pose(crash.victim, touch)
    relative = abs(angle_diff(math.degrees(s_pose.h), math.degrees(v_pose.h)))
    facts["relative_heading"] = round(relative, 1)
    if crash.type not in CRASH_ANGLES:
        yield Finding("impact_angle", False, f"unknown crash type {crash.type!r}")
        return
    lo, hi = CRASH_ANGLES[crash.type]
    s_box, v_box = scene.box(crash.striker, touch), scene.box(crash.victim, touch)
    square = pressed(s_box, v_box, separation(s_box, v_box)[1])[1]
    backing = _backing(scene, crash.striker, touch)
    if lo <= relative <= hi:
        message = f"{relative:.0f}° between the headings fits a {crash.type} crash"
        yield Finding("impact_angle", True, message, touch)
    elif crash.type == "frontal" and relative > CRASH_ANGLES["rear_end"][1] and square in _frontal_faces(backing):
        # a crossing met front to front at a corner (compiler/crashes.corner_frontal)
        message = f"{relative:.0f}° between the headings, the victim's front face entered square: a frontal crash"
        yield Finding("impact_angle", True, message, touch)
    else:
        message = f"{relative:.0f}° between the headings at impact; a {crash.type} crash needs {lo:g}° to {hi:g}°"
        yield Finding("impact_angle", False, message, touch)

    striker_box, victim_box = (
        footprint(scene.entity(crash.striker), s_pose),
        footprint(scene.entity(crash.victim), v_pose),
    )
    point = contact_point(striker_box, victim_box, NEAR_SLACK)
    # A pedestrian's faces count too (front = the way it walks), as in SUMO's oracle: a walker
    # struck from behind is a rear_end, one crossing the road is hit on a side.
    s_faces = faces_at(scene.entity(crash.striker), s_pose, point)
    v_faces = faces_at(scene.entity(crash.victim), v_pose, point)
    facts["striker_face"] = "-".join(s_faces)
    facts["victim_face"] = "-".join(v_faces)
    problems = []
    lead = "rear" if backing else "front"
    if lead not in s_faces:
        problems.append(f"the striker {crash.striker} hits with its {_words(s_faces)}, not its {lead}")
    wanted = (BACKED_INTO if backing else VICTIM_FACES)[crash.type]
    # which face of a corner is struck: the one definition (compiler/crashes.struck_face)
    struck = struck_face(v_faces, square if square in v_faces else None, relative, backing)
    if struck not in wanted:
        hit = _words(v_faces) + ("" if len(v_faces) == 1 else f", struck on its {struck}")
        problems.append(f"the victim {crash.victim} is hit on its {hit}, not its {' or '.join(sorted(wanted))}")
    if problems:
        yield Finding("impact_faces", False, "; ".join(problems), touch)
    else:
        faces = f"{_words(s_faces)} of {crash.striker} into {_words(v_faces)} of {crash.victim}"
        yield Finding("impact_faces", True, f"{faces}, as a {crash.type} crash", touch)


def _frontal_faces(backing: bool) -> tuple[str, ...]:
    return tuple((BACKED_INTO if backing else VICTIM_FACES)["frontal"])


def _backing(scene: Scene, name: str, t: float) -> bool:
    """Whether the body moves against the way it faces just before t."""
    before, at = scene.pose(name, max(0.0, t - BACKING_LOOK)), scene.pose(name, t)
    along = (at.x - before.x) * math.cos(at.h) + (at.y - before.y) * math.sin(at.h)
    return along < -1e-3


def _words(faces: tuple[str, ...]) -> str:
    return f"{faces[0]}-{faces[1]} corner" if len(faces) == 2 else faces[0]


def _other_contacts(scene: Scene, crash: Crash) -> Iterator[Finding]:
    """No two bodies overlap before the impact (the crash pair itself is judged by first_contact)."""
    pairs = [p for p in combinations(sorted(scene.paths), 2) if set(p) != {crash.striker, crash.victim}]
    for a, b in pairs:
        for t in _times(0.0, crash.time):
            if overlap(scene.box(a, t), scene.box(b, t)):
                yield Finding("other_contacts", False, f"{a} and {b} collide at t={t:.2f} s, before the impact", t)
                return
    yield Finding("other_contacts", True, "no other pair of bodies collides before the impact")
