"""THE crash definitions, for lowering, synthesis and every oracle: the angle between the headings
each crash type allows, the faces it names, the lane-line tolerance, and the first touch of a
plan's striker and victim read from its samples.

One measurement for all its users: the SUMO oracle applies `touch` to the poses SUMO had the
bodies in at each step of the replay, and synthesis (compiler/synth/impact.py) `planned_touch`
to the plan's own samples, which the replay puts SUMO's bodies on. So a plan synthesis accepts is
one the oracle sees the same way, not one whose lane lines met at the right angle while its
bodies touch at another.
"""

from __future__ import annotations

from collections.abc import Sequence

from sovarc.compiler.geometry.bodies import Box, Contact, first_touch, overlap
from sovarc.compiler.plan import Plan
from sovarc.dsl.ir import CrashType

# Degrees between the headings at first touch that each crash type allows, for every oracle.
# Frontal is front into front with the two approaching each other: head-on, or a car turning
# across an oncoming one (crash databases, and the ground truth, code that front-to-front). A
# front corner touching a crossing car's side at right angles is not frontal: that is a side crash.
# Two cars crossing at right angles meet front to front only at a corner: one's front corner just
# inside the other's way, its front face struck square by the other's front (`fits`); crossing at
# 90 degrees, that is the only frontal crash two cars going straight over can have.
CRASH_ANGLES: dict[str, tuple[float, float]] = {
    "rear_end": (0.0, 45.0),
    "frontal": (100.0, 180.0),
    "side": (0.0, 180.0),
}
REAR_END_MAX_ANGLE = CRASH_ANGLES["rear_end"][1]
FRONTAL_MIN_ANGLE = CRASH_ANGLES["frontal"][0]
# The victim's faces the striker's front must meet, per crash type.
VICTIM_FACES: dict[CrashType, tuple[str, ...]] = {
    CrashType.REAR_END: ("rear",),
    CrashType.FRONTAL: ("front",),
    CrashType.SIDE: ("left", "right"),
}
# A striker backing into its victim leads with its rear. A crash type then reads with front and rear
# swapped on both bodies: rear_end is its rear into the victim's front (a car backing into the one
# stopped behind it: same headings), frontal its rear into the victim's rear (back to back, headings
# apart), side its rear into the victim's side. The angles stay the type's.
BACKING_FACES: dict[CrashType, tuple[str, ...]] = {
    CrashType.REAR_END: ("front",),
    CrashType.FRONTAL: ("rear",),
    CrashType.SIDE: ("left", "right"),
}
# m/s: a striker moving backwards faster than this at the first touch leads with its rear
BACKING_SPEED = 0.05
# m a body may reach over a lane line before it counts as crossing it: the SUMO oracle's bound,
# which lowering (compiler/lower/swing.py, kturn.py) plans inside.
LINE_TOLERANCE = 0.25


def first_overlap(a: Sequence[Box | None], b: Sequence[Box | None]) -> int | None:
    """The first step at which both bodies are present and overlap."""
    for k, (p, q) in enumerate(zip(a, b, strict=True)):
        if p is not None and q is not None and overlap(p, q):
            return k
    return None


def touch(times: Sequence[float], a: Sequence[Box | None], b: Sequence[Box | None]) -> Contact | None:
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
    a = [Box.of(striker.body, s.x, s.y, s.heading) for s in striker.samples]
    b = [Box.of(victim.body, s.x, s.y, s.heading) for s in victim.samples]
    return touch(times, a, b)


def backing_at(plan: Plan, participant: str, time: float) -> bool:
    """Whether the participant is moving backwards at `time` in the plan (the last planned move up
    to then, so that a body that has just stopped against its victim still counts as backing)."""
    samples = plan.trajectory(participant).samples
    moving = [s.speed for s in samples if s.t <= time + 1e-9 and abs(s.speed) > BACKING_SPEED]
    return bool(moving) and moving[-1] < 0.0


def struck_face(zone: tuple[str, ...], pressed: str | None, angle: float, backing: bool = False) -> str:
    """The one face of the victim the striker enters by, at a touch on the victim's `zone` (one face,
    or the two of a corner) with `angle` degrees between the headings.

    At a corner the geometry of the touch decides. Where the striker's corner (or face) enters a face
    of the victim square (`pressed`: the contact pushes along that face's own normal), that face is
    struck: a corner beside the victim meets its side, one behind it its rear. Where it is the
    victim's corner that enters the striker's leading face, both of the corner's faces meet it, and
    the way the bodies are turned decides: the corner's end (front or rear) is struck when the
    striker heads as the crash type naming that end allows (its rear by a striker within 45 degrees
    of its heading: a car turning off the lane with its rear corner still in the follower's way is
    struck from behind; its front by one 100 degrees or more apart), else its side."""
    if len(zone) == 1:
        return zone[0]
    if pressed is not None:
        return pressed
    end, side = zone
    faces = BACKING_FACES if backing else VICTIM_FACES
    kind = next(k for k in (CrashType.REAR_END, CrashType.FRONTAL) if faces[k] == (end,))
    lo, hi = CRASH_ANGLES[kind.value]
    return end if lo <= angle <= hi else side


def victim_face(contact: Contact, backing: bool = False) -> str:
    """The face of the victim (the contact's second body) its striker enters by (`struck_face`)."""
    return struck_face(contact.zones[1], contact.pressed[1], contact.angle, backing)


def fits(kind: CrashType, contact: Contact, backing: bool = False) -> bool:
    """Whether the striker's leading face (its front; its rear when `backing`) meets the face of the
    victim the crash type names (the one it enters by, at a corner), at an angle between the headings
    the type allows (side: any)."""
    s_zone = contact.zones[0]
    lead, faces = ("rear", BACKING_FACES[kind]) if backing else ("front", VICTIM_FACES[kind])
    ok = lead in s_zone and victim_face(contact, backing) in faces
    if kind is CrashType.REAR_END:
        return ok and contact.angle <= REAR_END_MAX_ANGLE
    if kind is CrashType.FRONTAL:
        return ok and (contact.angle >= FRONTAL_MIN_ANGLE or corner_frontal(contact, backing))
    return ok


def corner_frontal(contact: Contact, backing: bool = False) -> bool:
    """A frontal crash across a crossing: the victim's front face (its rear, backing) entered square
    by the striker's leading corner, the two heading apart by more than a rear-end allows."""
    return (
        contact.angle > REAR_END_MAX_ANGLE
        and contact.pressed[1] in (BACKING_FACES if backing else VICTIM_FACES)[CrashType.FRONTAL]
    )


def face_words(zone: tuple[str, ...]) -> str:
    """('front',) -> 'front'; ('left',) -> 'left side'; ('front', 'left') -> 'front-left corner'."""
    if len(zone) == 2:
        return f"{zone[0]}-{zone[1]} corner"
    return f"{zone[0]} side" if zone[0] in {"left", "right"} else zone[0]


def struck_words(zone: tuple[str, ...], struck: str) -> str:
    """The victim's faces at the touch, and at a corner the one struck: 'rear-left corner, struck on its rear'."""
    return face_words(zone) if len(zone) == 1 else f"{face_words(zone)}, struck on its {face_words((struck,))}"


def needs(kind: CrashType, striker: str, victim: str, backing: bool = False) -> str:
    """What the crash type needs at the first touch, in words."""
    wanted = " or ".join(face_words((face,)) for face in (BACKING_FACES if backing else VICTIM_FACES)[kind])
    lead = "rear (backing)" if backing else "front"
    text = f"{kind.value} needs {striker}'s {lead} into {victim}'s {wanted}"
    if kind is CrashType.REAR_END:
        return text + f", headings within {REAR_END_MAX_ANGLE:.0f} degrees"
    if kind is CrashType.FRONTAL:
        return text + f", headings at least {FRONTAL_MIN_ANGLE:.0f} degrees apart (or its front face entered square)"
    return text
