"""Crash findings: the encoded trajectories reach the collision area C_A together, the striker
and the victim first touch at the declared impact time, at the angle and on the faces the crash
type names, and no other pair of bodies collides before it."""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from itertools import combinations

from sovarc.targets.openscenario.kinematics import (
    Polygon,
    angle_diff,
    contact_point,
    face_of,
    footprint,
    gap,
    overlap,
    point_distance,
    pose_at,
)
from sovarc.targets.openscenario.readback import Entity, Pose, ScenarioFile
from sovarc.targets.verdict import Finding

AREA_TOL = 0.1  # m beyond C_A's radius
TOUCH_GAP = 0.25  # m: at the impact time the bodies are at most this far apart
CONTACT_TIME_TOL = 0.3  # s between the declared impact and the first contact
SCAN_STEP = 0.02  # s
OVERLAP_WINDOW = 1.0  # s after the impact in which the bodies must overlap (players detect the crash)

# Relative heading (degrees, 0..180) allowed per crash type, and the victim faces it names.
ANGLES: dict[str, tuple[float, float]] = {"rear_end": (0.0, 60.0), "frontal": (120.0, 180.0), "side": (20.0, 160.0)}
VICTIM_FACES: dict[str, frozenset[str]] = {
    "rear_end": frozenset({"rear"}),
    "frontal": frozenset({"front"}),
    "side": frozenset({"left", "right"}),
}


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

    def box(self, name: str, t: float) -> Polygon:
        return footprint(self.scenario.entities[name], self.pose(name, t))

    def entity(self, name: str) -> Entity:
        return self.scenario.entities[name]

    def end(self, *names: str) -> float:
        return min(self.paths[n][-1].t for n in names)


def crash_findings(
    scenario: ScenarioFile, paths: dict[str, tuple[Pose, ...]], crash: Crash
) -> tuple[list[Finding], dict[str, object]]:
    scene = Scene(scenario, paths)
    facts: dict[str, object] = {}
    findings = [_area(scene, crash), *_contact(scene, crash, facts), _overlap(scene, crash)]
    findings.extend(_angle_and_faces(scene, crash, facts))
    findings.extend(_other_contacts(scene, crash))
    return findings, facts


def _area(scene: Scene, crash: Crash) -> Finding:
    far = []
    for name in (crash.striker, crash.victim):
        distance = point_distance(crash.point, scene.box(name, crash.time))
        if distance > crash.radius + AREA_TOL:
            far.append(f"{name} is {distance:.2f} m from it")
    if far:
        return Finding("collision_area", False, f"at t={crash.time:g} s not both in C_A: {'; '.join(far)}", crash.time)
    message = f"striker and victim both reach C_A (radius {crash.radius:g} m) at t={crash.time:g} s"
    return Finding("collision_area", True, message, crash.time)


def _contact(scene: Scene, crash: Crash, facts: dict[str, object]) -> Iterator[Finding]:
    a, b = crash.striker, crash.victim
    first = next((t for t in _times(0.0, scene.end(a, b)) if gap(scene.box(a, t), scene.box(b, t)) <= 0.01), None)
    distance = gap(scene.box(a, crash.time), scene.box(b, crash.time))
    facts["first_contact_time"] = None if first is None else round(first, 3)
    facts["gap_at_impact"] = round(distance, 3)
    if first is None:
        yield Finding("first_contact", False, f"{a} and {b} never touch")
    elif abs(first - crash.time) > CONTACT_TIME_TOL:
        message = f"{a} and {b} first touch at t={first:.2f} s, not at the impact t={crash.time:g} s"
        yield Finding("first_contact", False, message, first)
    elif distance > TOUCH_GAP:
        apart = f"{distance:.2f} m" if distance <= 1.0 else "more than 1 m"
        message = f"at the impact t={crash.time:g} s {a} and {b} are {apart} apart"
        yield Finding("first_contact", False, message, crash.time)
    else:
        yield Finding("first_contact", True, f"{a} and {b} first touch at t={first:.2f} s", first)


def _overlap(scene: Scene, crash: Crash) -> Finding:
    a, b = crash.striker, crash.victim
    window = _times(crash.time, min(scene.end(a, b), crash.time + OVERLAP_WINDOW))
    hit = next((t for t in window if overlap(scene.box(a, t), scene.box(b, t))), None)
    if hit is None:
        message = f"the bounding boxes of {a} and {b} never overlap after the impact: a player sees no collision"
        return Finding("overlap", False, message, crash.time)
    return Finding("overlap", True, f"the bounding boxes overlap from t={hit:.2f} s", hit)


def _angle_and_faces(scene: Scene, crash: Crash, facts: dict[str, object]) -> Iterator[Finding]:
    s_pose, v_pose = scene.pose(crash.striker, crash.time), scene.pose(crash.victim, crash.time)
    relative = abs(math.degrees(angle_diff(s_pose.h, v_pose.h)))
    facts["relative_heading"] = round(relative, 1)
    if crash.type not in ANGLES:
        yield Finding("impact_angle", False, f"unknown crash type {crash.type!r}")
        return
    lo, hi = ANGLES[crash.type]
    if lo <= relative <= hi:
        message = f"{relative:.0f}° between the headings fits a {crash.type} crash"
        yield Finding("impact_angle", True, message, crash.time)
    else:
        message = f"{relative:.0f}° between the headings at impact; a {crash.type} crash needs {lo:g}° to {hi:g}°"
        yield Finding("impact_angle", False, message, crash.time)

    point = contact_point(scene.box(crash.striker, crash.time), scene.box(crash.victim, crash.time))
    striker, victim = scene.entity(crash.striker), scene.entity(crash.victim)
    s_face = None if striker.pedestrian else face_of(striker, s_pose, point)
    v_face = None if victim.pedestrian else face_of(victim, v_pose, point)
    facts["striker_face"], facts["victim_face"] = s_face, v_face
    problems = []
    if s_face is not None and s_face != "front":
        problems.append(f"the striker {crash.striker} hits with its {s_face}, not its front")
    wanted = VICTIM_FACES[crash.type]
    if v_face is not None and v_face not in wanted:
        problems.append(f"the victim {crash.victim} is hit on its {v_face}, not its {' or '.join(sorted(wanted))}")
    if problems:
        yield Finding("impact_faces", False, "; ".join(problems), crash.time)
    else:
        faces = f"{s_face or 'body'} of {crash.striker} into {v_face or 'body'} of {crash.victim}"
        yield Finding("impact_faces", True, f"{faces}, as a {crash.type} crash", crash.time)


def _other_contacts(scene: Scene, crash: Crash) -> Iterator[Finding]:
    """No two bodies overlap before the impact (the crash pair itself is judged by first_contact)."""
    pairs = [p for p in combinations(sorted(scene.paths), 2) if set(p) != {crash.striker, crash.victim}]
    for a, b in pairs:
        for t in _times(0.0, crash.time):
            if overlap(scene.box(a, t), scene.box(b, t)):
                yield Finding("other_contacts", False, f"{a} and {b} collide at t={t:.2f} s, before the impact", t)
                return
    yield Finding("other_contacts", True, "no other pair of bodies collides before the impact")
