"""The striker's and victim's first touch, as the SUMO oracle measures it, and whether it is the crash.

One measurement for two users: the oracle applies it to the poses SUMO had the bodies in at
each step of the replay, and synthesis (compiler/synth/impact.py) to the plan's own samples,
which the replay puts SUMO's bodies on. So a plan synthesis accepts is one the oracle sees the
same way, not one whose lane lines met at the right angle while its bodies touch at another.
"""

from __future__ import annotations

from collections.abc import Sequence

from sovarc.compiler.plan import Plan, Trajectory
from sovarc.dsl.ir import CrashType
from sovarc.targets.sumo.bodies import Body, Contact, first_touch, overlap
from sovarc.targets.verdict import CRASH_ANGLES

REAR_END_MAX_ANGLE = CRASH_ANGLES["rear_end"][1]
FRONTAL_MIN_ANGLE = CRASH_ANGLES["frontal"][0]
VICTIM_FACES = {CrashType.REAR_END: ("rear",), CrashType.FRONTAL: ("front",), CrashType.SIDE: ("left", "right")}


def body_at(t: Trajectory, x: float, y: float, heading: float) -> Body:
    """The participant's body with its reference point (front bumper, or a walker's centre) at (x, y)."""
    return Body(x, y, heading, t.body.length, t.body.width, t.body.vclass != "pedestrian")


def first_overlap(a: Sequence[Body | None], b: Sequence[Body | None]) -> int | None:
    """The first step at which both bodies are present and overlap."""
    for k, (p, q) in enumerate(zip(a, b, strict=True)):
        if p is not None and q is not None and overlap(p, q):
            return k
    return None


def touch(times: Sequence[float], a: Sequence[Body | None], b: Sequence[Body | None]) -> Contact | None:
    """Where bodies a and b, sampled at `times`, first touch: between the step before they first
    overlap and that step, each body moving straight between its two poses (None: they never do)."""
    k = first_overlap(a, b)
    if k is None:
        return None
    j = max(k - 1, 0)
    if any(p is None for p in (a[j], b[j])):
        j = k
    a0, a1, b0, b1 = a[j], a[k], b[j], b[k]
    assert a0 is not None and a1 is not None and b0 is not None and b1 is not None
    return first_touch(times[j], times[k], (a0, a1), (b0, b1))


def planned_touch(plan: Plan) -> Contact | None:
    """The first touch of the plan's striker and victim, read from its samples as the oracle reads
    SUMO's poses: the replay moves each body onto its sample at every step of the plan's own length."""
    striker, victim = plan.trajectory(plan.impact.striker), plan.trajectory(plan.impact.victim)
    times = [s.t for s in striker.samples]
    a = [body_at(striker, s.x, s.y, s.heading) for s in striker.samples]
    b = [body_at(victim, s.x, s.y, s.heading) for s in victim.samples]
    return touch(times, a, b)


def fits(kind: CrashType, contact: Contact) -> bool:
    """Whether the striker's front meets the face of the victim the crash type names, at an angle
    between the headings the type allows (a side crash: any angle)."""
    s_zone, v_zone = contact.zones
    ok = "front" in s_zone and any(face in v_zone for face in VICTIM_FACES[kind])
    if kind is CrashType.REAR_END:
        return ok and contact.angle <= REAR_END_MAX_ANGLE
    if kind is CrashType.FRONTAL:
        return ok and contact.angle >= FRONTAL_MIN_ANGLE
    return ok


def face_words(zone: tuple[str, ...]) -> str:
    """('front',) -> 'front'; ('left',) -> 'left side'; ('front', 'left') -> 'front-left corner'."""
    if len(zone) == 2:
        return f"{zone[0]}-{zone[1]} corner"
    return f"{zone[0]} side" if zone[0] in {"left", "right"} else zone[0]


def needs(kind: CrashType, striker: str, victim: str) -> str:
    """What the crash type needs at the first touch, in words."""
    wanted = " or ".join(face_words((face,)) for face in VICTIM_FACES[kind])
    text = f"{kind.value} needs {striker}'s front into {victim}'s {wanted}"
    if kind is CrashType.REAR_END:
        return text + f", headings within {REAR_END_MAX_ANGLE:.0f} degrees"
    if kind is CrashType.FRONTAL:
        return text + f", headings at least {FRONTAL_MIN_ANGLE:.0f} degrees apart"
    return text
