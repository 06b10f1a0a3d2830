"""A turn said by where it led on the compass, not by its side: "turned onto eastbound Elm Street", "turned east".

A vehicle heading south that turns to head east has turned a quarter turn anticlockwise: a left turn; one that
turns to head west has turned right. So a turn said with no side but with the heading it led to is the turn to
that side of the heading the vehicle had (its heading as the report says it, before the turn). A heading the same
as or opposite to the one it had says no side.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.words import turned
from sovarc.dsl.ir import Action, ActionKind, Heading, Unknown

_COMPASS = r"(north|south|east|west)"
# (not "turned left onto eastbound Elm Street": the side is said, and read as said)
_LED_TO = re.compile(
    # (an adverb may stand between, "turned sharply east"; not "a turn from westbound Elm Street": where it came from)
    r"\bturn(?:ed|ing|s)? (?:\w+ly )?" + _COMPASS + r"(?:bound|ward)?\b"
    r"|\bturn(?:ed|ing|s)? (?:onto|into|on to) (?:the )?" + _COMPASS + r"[- ]?bound\b"
    r"|\b(?:made|make|makes|making|initiated|began|completed|executed) (?:a|its|the) turn (?:onto|into) (?:the )?"
    + _COMPASS
    + r"[- ]?bound\b",
    re.I,
)


def compass_turns(text: str, heading: Heading | Unknown) -> list[tuple[int, Action]]:
    """The turns `text` says by the heading they led to, with where each is said (see the module)."""
    if isinstance(heading, Unknown):
        return []
    found = []
    for m in _LED_TO.finditer(text):
        to = Heading(next(g for g in m.groups() if g).lower())
        side = (
            ActionKind.TURN_RIGHT
            if to is turned(heading, 1)
            else ActionKind.TURN_LEFT
            if to is turned(heading, -1)
            else None
        )
        if side is not None:
            found.append((m.start(), Action(side)))
    return found
