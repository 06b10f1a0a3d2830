"""Who stood still at the impact, and what the words that introduce a road user say it was doing.

A vehicle that stood still struck nobody: the crash readers take a named front for the striking face, so
"the passenger side of V2 made contact with the front corner of the stationary V1" reads V1 striking; the one
that moved into it is the striker. And a road user renamed V2 loses the words that introduced it ("an unoccupied
parked passenger vehicle"), which may be all the report says of what it was doing.
"""

from __future__ import annotations

import re
from dataclasses import replace

from sovarc.compiler.frontend.crash import agent_named
from sovarc.compiler.frontend.lexicon import Form, forms
from sovarc.dsl.ir import Action, ActionKind, Crash, Participant, Role, Unknown

# A span a reader read a fact from, as in `rules.Spot`.
Spot = tuple[str, str, int, int]


# A vehicle the impact sentence says stood still when it was hit: "the stationary V1", "while V1 remained
# stopped". Its front may have met the other (a car reversing into it), but it had not moved off.
_STILL = r"(?:stationary|stopped|parked|standing still|at a stop|at rest)"


def still_at_impact(sentence: str, pid: str) -> bool:
    return bool(
        re.search(rf"\b(?:the )?{_STILL} {pid}\b", sentence, re.I)
        # (not "was nearly stopped": it was still moving)
        or re.search(
            rf"\b{pid} (?:remained|was still|was|sat|had been|stayed) (?:(?!nearly|almost)\w+ )?{_STILL}\b",
            sentence,
            re.I,
        )
    )


def stood_at_impact(sentence: str, pid: str) -> ActionKind | None:
    """How the impact sentence says the participant stood, if it does (see `still_at_impact`): parked, or stopped."""
    if not still_at_impact(sentence, pid):
        return None
    return ActionKind.PARKED if re.search(rf"\bparked {pid}\b|\b{pid} \w+ parked\b", sentence) else ActionKind.STOP


def standing_struck(people: list[Participant], crash: Crash, sentence: str) -> Crash:
    """A vehicle that stood still at the impact struck nobody: the striker is the one that moved into it,
    whichever of its parts the sentence names first (the crash readers take a named front for the striking
    face). It stood still when the impact sentence says so ("While V1 remained stopped", "the stationary V1"),
    or when its actions end standing (stopped for a pickup, parked) and the other's end in a move ("V1 was
    stopped for a passenger pickup when V2 ... maneuvered to pass V1"). Not when the sentence names it the
    agent ("it was struck by the front left of V1": it moved off again) or its front the strike's subject."""
    striker, victim = crash.striker, crash.victim
    if not isinstance(striker, str) or not isinstance(victim, str):
        return crash
    if agent_named(sentence) or _front_strikes(sentence, striker):
        return crash
    by_id = {p.id: p for p in people}
    stood, moved = by_id.get(striker), by_id.get(victim)
    if stood is None or moved is None:
        return crash
    if not still_at_impact(sentence, striker):
        standing = (ActionKind.STOP, ActionKind.PARKED)
        if not stood.known_actions or not moved.known_actions:
            return crash
        if stood.known_actions[-1].kind not in standing or moved.known_actions[-1].kind in standing:
            return crash
    # (one that stopped earlier may move again in the impact sentence: "V2 proceeded westbound and ..."; one
    # parked throughout stood too)
    if still_at_impact(sentence, victim) or [a.kind for a in moved.known_actions] == [ActionKind.PARKED]:
        return crash
    return replace(crash, striker=victim, victim=striker)


# A move under way, said in a clause of time: "as V2 turned left", "while V2 was passing V1", "as V2 passed by".
_MOVE = (
    r"(?:pass|turn|overt[ao]k|mov|drov|driv|went|go|proceed|travel|pull|revers|back|merg|chang|maneuver|manoeuvr"
    r"|cross|continu|approach|accelerat|swerv|veer|enter|exit|leav|navigat|made a (?:left|right|u-)|making a)\w*"
)


def moving_met_standing(crash: Crash, sentence: str, own: tuple[Action, ...] | Unknown) -> Crash:
    """A vehicle that came to a stop and is not said to move off again stood at the impact when the impact
    sentence tells the other's move under way then ("As V2 turned left, ... the left side of V2 made contact
    with the front corner of V1", "and as V2 passed by V1, ..."): the one moving met the one standing, whichever
    of its parts the sentence names first. `own` are the named striker's actions read as if it struck nobody
    (the crash readers take a named front for the striking face, and a striker that had stopped is given a
    crossing: it moved off again). Read before the actions, so the crossing is not given."""
    striker, victim = crash.striker, crash.victim
    if not isinstance(striker, str) or not isinstance(victim, str) or isinstance(own, Unknown) or not own:
        return crash
    if own[-1].kind not in (ActionKind.STOP, ActionKind.PARKED):
        return crash
    if agent_named(sentence) or _front_strikes(sentence, striker):
        return crash
    if not re.search(rf"\b(?:as|while) {victim} (?:was |were )?(?:\w+ly )?{_MOVE}\b", sentence, re.I):
        return crash
    return replace(crash, striker=victim, victim=striker)


# a strike said in the past ("made contact", "struck", "sideswiped")
_MET = forms((Form.PAST,))


def _front_strikes(sentence: str, pid: str) -> bool:
    """Whether the sentence makes the participant's front the subject of the strike."""
    return bool(
        re.search(
            rf"\bfront\b[\w' -]{{0,30}}? of (?:the )?(?:\w+ )?{pid}\b[^.;]{{0,30}}?"
            r"\b" + _MET + r"\b",
            sentence,
            re.I,
        )
        or re.search(rf"\b{pid}'s front\b[^.;]{{0,30}}?\b" + _MET + r"\b", sentence)
    )


# Words that introduce a road user in motion along the road: "an approaching van", "the trailing bus", "an
# oncoming SUV".
_MOVING = re.compile(
    r"\b(?:approaching|oncoming|trailing|following|moving|travell?ing|speeding|passing|overtaking)\b", re.I
)


# Words that introduce a road user leaving its lane: "a merging SUV", "a lane-changing van" (a lane change whose side
# lowering chooses), "a wrong-way sedan" (driving in the other direction's lanes).
_LEAVING = (
    (re.compile(r"\b(?:merging|lane[- ]chang(?:ing|er)|lane[- ]switching)\b", re.I), ActionKind.CHANGE_LANE),
    (re.compile(r"\bwrong[- ]way\b", re.I), ActionKind.RETROGRADE),
)


# What the words that introduce a road user say it was doing, first match first: a participle used as an adjective
# ("a reversing SUV", "a left-turning car", "a stopped van", "an approaching bus") or put after the name.
_INTRODUCED: tuple[tuple[ActionKind, re.Pattern[str]], ...] = (
    (ActionKind.REVERSE, re.compile(r"\b(?:reversing|backing)\b", re.I)),
    (ActionKind.U_TURN, re.compile(r"\bu-?turning\b", re.I)),
    (ActionKind.TURN_LEFT, re.compile(r"\bleft[- ]turning\b|\bturning left\b", re.I)),
    (ActionKind.TURN_RIGHT, re.compile(r"\bright[- ]turning\b|\bturning right\b", re.I)),
    (ActionKind.PARKED, re.compile(r"\bparked\b", re.I)),
    (ActionKind.STOP, re.compile(r"\b(?:stationary|stopped|standing|idling|queued)\b", re.I)),
    (ActionKind.FOLLOW_LANE, _MOVING),
)


def introduced_doing(
    people: list[Participant], words: dict[str, str], named: str, spots: list[Spot]
) -> list[Participant]:
    """A vehicle the report says nothing of before the impact, introduced as parked ("an unoccupied parked
    passenger vehicle"), standing ("a stationary SUV"), turning ("a left-turning van"), reversing ("a reversing
    pickup"), moving ("an approaching van", "the trailing bus") or leaving its lane ("a merging SUV", "a wrong-way
    sedan"): the words that introduce a road user state
    what it was doing (see `_INTRODUCED`). `words` are the words each party numbered by rule was first named by
    (see `names.parties`)."""
    out = []
    for p in people:
        first = re.search(rf"\b{p.id}\b", named)
        if p.role is not Role.VEHICLE or not isinstance(p.actions, Unknown) or first is None:
            out.append(p)
            continue
        # the words before its name, and a state put after it ("V2 parked along the curb", "V2, which was turning
        # left,"; not "V2 stopped", a verb as much as a state)
        after = re.findall(
            rf"\b{p.id}(?:,? (?:that|which) (?:was|were|had been) (\w+(?:[- ]\w+)?)"
            r"| (parked|stationary|standing|idling|queued)\b)",
            named,
        )
        said = " ".join([words.get(p.id, ""), *(w for pair in after for w in pair)])
        if leaving := next((k for pattern, k in _LEAVING if pattern.search(said)), None):
            spots.append((f"{p.id}.actions[2]", "named", *first.span()))
            out.append(replace(p, actions=(Action(ActionKind.FOLLOW_LANE), Action(leaving))))
            continue
        kind = next((k for k, pattern in _INTRODUCED if pattern.search(said)), None)
        if kind is None:
            out.append(p)
            continue
        spots.append((f"{p.id}.actions[1]", "named", *first.span()))
        out.append(replace(p, actions=(Action(kind),)))
    return out
