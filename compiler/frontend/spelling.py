"""One spelling for what reports write several ways, word for word, so that every reader reads one: a direction
of travel abbreviated as police forms do ("N/B"), a turn's hand ("a left-hand turn"), British words for the road
("carriageway", "junction"), police forms' abbreviations ("RT LN", "INTX": `forms`). Word for word, so that the
evidence of a fact read from the respelt text maps back to the report's own words (`evidence.Alignment` compares
words by their respelling).
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.forms import police_forms

# Police forms' abbreviations of a direction of travel: "traveling N/B", "the S/B lanes", "EB on Main St" (in
# capitals, a token of its own: "NB" in a sentence is no other word).
_BOUND_SHORT = re.compile(r"(?<![\w/])([NSEW])(?:/B|\.B\.|B)(?![\w/])")
_POINTS = {"N": "north", "S": "south", "E": "east", "W": "west"}


_JUNCTION = re.compile(r"\b([Jj]unction|[Cc]rossroads)(s?)\b(?! box)")
_HANDED = re.compile(r"\b(left|right)[- ]hand(?=[- ]turn)", re.I)


def spell_out(text: str) -> str:
    """The report with its abbreviations written out, word for word ("N/B" -> "northbound"), so that every reader
    reads one spelling."""
    text = police_forms(text)
    text = _BOUND_SHORT.sub(lambda m: _POINTS[m.group(1)] + "bound", text)
    # "an Olli shuttle (V1.0)": a capital V before a dotted number is a version, not a vehicle's label
    text = re.sub(r"\bV(?=\d+(?:\.\d+)+\b)", "v", text)
    # "a left-hand turn" is a left turn: the hand says the side, as "left" alone does
    text = _HANDED.sub(r"\1", text)
    # "the carriageway": British English for the roadway
    text = re.sub(r"\b([Cc])arriageway(s?)\b", lambda m: ("R" if m[1] == "C" else "r") + "oadway" + m[2], text)
    # "a T-junction", "the junction", "a crossroads": British English for the intersection
    return _JUNCTION.sub(lambda m: ("I" if m[1] in "JC" else "i") + "ntersection" + ("s" if m[2] else ""), text)
