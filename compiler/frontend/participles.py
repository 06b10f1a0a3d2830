"""A move said as a participle before a road user's noun, put after it where the readers find a move.

English puts a bare participle before its noun ("a reversing SUV", "the left-turning van", "a U-turning car") and
one with a complement after it ("an SUV reversing out of a driveway", "a van turning left"). The naming of road
users keeps the noun and the words after it but folds the words before it into the road user's id, so a move
said before the noun was lost; said after it, the readers find it as they find "a van turning left from Elm
Street". Only moves are moved: a state before the noun ("the stopped V1", "a parked car") is read where it is.
"""

from __future__ import annotations

import re

# the nouns of road users a participle may qualify (see names._KINDS), with up to two words between
_NOUN = (
    r"(?:[\w-]+ ){0,2}?(?:passenger car|passenger vehicle|pick-?up truck|box truck|heavy truck|tractor[- ]trailer"
    r"|school bus|minivan|van|suv|sedan|pickup|truck|bus|taxi|motorcycle|car|vehicle)"
)
_BEFORE = re.compile(
    r"\b(?P<det>an?|the|another) (?P<move>(?:left|right)[- ]turning|u-turning|reversing|backing)"
    r" (?P<noun>" + _NOUN + r")\b(?![\w-])",
    re.I,
)


def _after(m: re.Match[str]) -> str:
    move = m.group("move").lower()
    said = (
        f"turning {move.split('-')[0].split()[0]}"
        if move.endswith("turning") and not move.startswith("u")
        else "making a U-turn"
        if move.startswith("u")
        else move
    )
    return f"{m.group('det')} {m.group('noun')} {said}"


def moves_after_nouns(text: str) -> str:
    """The text with each move said as a participle before a road user's noun said after it ("a left-turning van"
    as "a van turning left", "the reversing SUV" as "the SUV reversing")."""
    return _BEFORE.sub(_after, text)
