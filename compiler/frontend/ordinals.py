"""Vehicles numbered by ordinal: a report that calls its vehicles "the first vehicle", "the second vehicle" and
numbers them no other way names V1, V2 by those words."""

from __future__ import annotations

import re

from sovarc.compiler.frontend.words import ORDINALS

# (by whatever noun the report calls its vehicles: "the first car", "the second truck")
_NOUN = r"(?:vehicle|car|truck|van|pickup|suv|motorist|unit)"
_NAMED = re.compile(r"\b(?:the )?(first|second|third|fourth|fifth) " + _NOUN + r"\b(?![\w-])", re.I)
_NUMBERED = re.compile(r"\b[VP]\d\b")
# An ordinal said as a name opens a sentence or a clause somewhere ("The first vehicle was traveling north", "...,
# and the second vehicle turned left"), as the reports' numbers do.
_AS_SUBJECT = re.compile(
    r"(?:^|[.!?;]\s*|,? (?:and|when|while|as|then) )[Tt]he (?:first|second) " + _NOUN + r"\b", re.I
)
# One placed by where it stood or by the order it was met in is no name: "the first vehicle to the right", "the
# first vehicle in line", "the second vehicle ahead".
_PLACED = re.compile(
    r"\b(?:first|second|third|fourth|fifth) "
    + _NOUN
    + r" (?:to the|in line|in the (?:queue|line)|ahead|behind|in front)\b",
    re.I,
)


def ordinal_names(text: str) -> str:
    """ "The first vehicle struck the second vehicle" -> "V1 struck V2", when the text (its numbered names already
    read as V1, V2, ...) numbers no vehicle, names both a first and a second, one as a subject, and places
    neither: ordinals used as names come as a set, while a "first vehicle" met in a queue or in a sequence of
    impacts ("contact with the first vehicle to the right ... the second vehicle") names no participant."""
    said = {m.group(1).lower() for m in _NAMED.finditer(text)}
    if _NUMBERED.search(text) or not {"first", "second"} <= said:
        return text
    if not _AS_SUBJECT.search(text) or _PLACED.search(text):
        return text
    return _NAMED.sub(lambda m: f"V{ORDINALS[m.group(1).lower()]}", text)
