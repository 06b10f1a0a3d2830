"""Who is in whose lane: wrong-way driving read from the situation, not from its usual words.

On a road away from junctions, two vehicles travelling in opposite directions meet only if one of them has
left its own side of the road: neither turned, so one was in the other's lanes. The report may never say
"crossed the center line"; it says the vehicle "entered oncoming traffic", "overcompensated", "drifted",
"lost control", or that the other vehicle "was traveling in the opposite direction". So:
- two vehicles are opposed when their headings are opposite, or a clause about one says it travelled in the
  opposite direction or was oncoming;
- the one the report shows moving sideways before the impact (a lateral verb in its own clauses, evasive
  moves already taken out) is the one on the wrong side: retrograde. If both or neither are shown so, the
  situation does not say which, and nothing is added;
- a vehicle whose heading is not stated but which travelled "in the opposite direction" of the other heads
  the other way, and a crash between opposed vehicles with no turn, whose parts are not stated, is frontal.
"""

from __future__ import annotations

import re
from dataclasses import replace

from sovarc.compiler.frontend.actions import what_was_done
from sovarc.compiler.frontend.clauses import Piece
from sovarc.compiler.frontend.words import opposite
from sovarc.dsl.ir import Action, ActionKind, Crash, CrashType, Heading, Participant, Role, Unknown

# Leaving one's lane sideways, said any way: the verb, not the lane line, carries it.
_LATERAL = re.compile(
    r"\b(?:veer|swerv|drift|overcorrect|over-correct|overcompensat|oversteer|yaw|fishtail|skid|slid(?:e|ing)?\b)\w*"
    r"|\b(?:lost|lose|losing|loses) control\b|\bleft (?:its|the|his|her) (?:travel )?lane\b"
    r"|\b(?:enter|cross|mov|went|go|drove|travel)\w* (?:over )?(?:in)?to (?:the )?(?:oncoming|opposing|opposite)\b"
    r"|\benter\w* (?:the )?(?:oncoming|opposing)\b",
    re.I,
)
_OPPOSED = re.compile(
    r"\b(?:in|from) the opposite direction\b|\b(?:was|were) oncoming\b|\ban oncoming\b|\bopposing direction\b",
    re.I,
)
_TURNED = frozenset(
    (ActionKind.TURN_LEFT, ActionKind.TURN_RIGHT, ActionKind.U_TURN, ActionKind.CHANGE_LANE, ActionKind.DRIVE_INTO)
)


def _opposed_by_words(pieces: list[Piece]) -> bool:
    return any(_OPPOSED.search(p.text) for p in pieces)


def wrong_side(
    people: list[Participant], early: dict[str, list[Piece]], crash: Crash, straight_road: bool
) -> tuple[list[Participant], Crash]:
    """The participants with retrograde added to the one on the wrong side, headings and crash type completed
    as the situation fixes them (see the module's note). `early` is each one's clauses up to the impact."""
    pair = [p for p in people if p.role is Role.VEHICLE and p.id in (crash.striker, crash.victim)]
    if not straight_road or len(pair) != 2 or crash.type is CrashType.REAR_END:
        return people, crash
    if any(a.kind in _TURNED for p in pair for a in p.known_actions):
        return people, crash
    a, b = pair
    if isinstance(a.heading, Unknown) or isinstance(b.heading, Unknown):
        opposed = any(_opposed_by_words(early.get(p.id, [])) for p in pair)
    else:
        opposed = opposite(a.heading) == b.heading
    if not opposed:
        return people, crash
    heading: dict[str, Heading | Unknown] = {p.id: p.heading for p in pair}
    for p, other in ((a, b), (b, a)):
        if isinstance(p.heading, Unknown) and not isinstance(other.heading, Unknown):
            heading[p.id] = opposite(other.heading)
    sideways = [p for p in pair if any(_LATERAL.search(what_was_done(x.text)) for x in early.get(p.id, []))]
    wrong = sideways[0].id if len(sideways) == 1 else None
    out = []
    for p in people:
        if p.id in heading:
            p = replace(p, heading=heading[p.id])
        kinds = {x.kind for x in p.known_actions}
        if p.id == wrong and not isinstance(p.actions, Unknown) and ActionKind.RETROGRADE not in kinds:
            p = replace(p, actions=(*p.actions, Action(ActionKind.RETROGRADE)))
        out.append(p)
    if isinstance(crash.type, Unknown):
        crash = replace(crash, type=CrashType.FRONTAL)
    return out, crash
