"""The synthesized crash, judged as its replay will be: the first touch of the planned bodies.

Lowering places the contact where the two lanes' lines meet and measures the angle there, between
the lines; the oracle measures it between the headings of the bodies where they first touch. At a
crossing these differ: a front corner touches before the bumper centres meet, earlier in a turn,
and the synthesized path turns a little off the lane line. Crossings lowered at 100-101 degrees
first touched at 99 in SUMO. So each plan is judged here with the oracle's own measurement
(compiler/crashes.py) on its samples, which the replay puts SUMO's bodies on; a plan the
oracle would fail is refused, and the next staging is tried.
"""

from __future__ import annotations

from sovarc.compiler.crashes import backing_at, face_words, fits, needs, planned_touch, struck_words, victim_face
from sovarc.compiler.plan import Plan
from sovarc.dsl.errors import Diagnostic, SynthesisError


def check_impact(plan: Plan) -> None:
    """Raise a SynthesisError unless the plan's striker and victim first touch as its crash type needs."""
    kind, striker, victim = plan.impact.type, plan.impact.striker, plan.impact.victim
    span = plan.scenario.crash.meta.where("type")
    contact = planned_touch(plan)
    if contact is None:
        message = f"on {plan.site}, the planned bodies of {striker} and {victim} never touch"
        raise SynthesisError(Diagnostic(message, span))
    backing = backing_at(plan, striker, contact.time)
    if fits(kind, contact, backing):
        return
    s_zone, v_zone = contact.zones
    struck = struck_words(v_zone, victim_face(contact, backing))
    message = (
        f"on {plan.site}, {striker}'s {face_words(s_zone)} would first touch {victim}'s {struck} "
        f"at {contact.angle:.1f} degrees (t={contact.time:.2f} s); {needs(kind, striker, victim, backing)}"
    )
    raise SynthesisError(Diagnostic(message, span))
