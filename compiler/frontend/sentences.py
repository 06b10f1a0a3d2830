"""Splitting a report into sentences: the unit every front-end rule reads."""

from __future__ import annotations

import re


def sentences(text: str) -> list[str]:
    """Split on sentence ends, also where reports omit the space after a period, and at a semicolon before a
    participant: a semicolon joins two clauses that could each stand as a sentence ("V1 was traveling north; V2
    was traveling east"), and the readers take a sentence as one event's or one state's."""
    text = re.sub(r"\s+", " ", text)
    text = re.sub(r"(?<=[a-z0-9)])\.(?=[A-Z])", ". ", text)
    parts = re.split(r"(?<=[.!?])\s+(?=[A-Z\"(])|(?<=;)\s+(?=[VP]\d\b)", text)
    return [p.strip() for p in parts if p.strip()]


# Titles and Latin abbreviations whose full stop ends no sentence: "Ofc. Smith", "e.g. a van".
_ABBREVIATED = re.compile(r"\b(?:MR|MRS|MS|DR|SGT|OFC|LT|CPL|DEP|TPR|E\.G|I\.E)\.$", re.I)


def opens_sentence(text: str, at: int) -> bool:
    """Whether `at` opens a sentence of `text` (what a reader or a rewrite writes out there takes a capital):
    between it and the text's start or a sentence's end (".", "!", "?") stand only spaces and a quotation's or
    bracket's opening; a title's or an abbreviation's full stop ("Ofc. Smith", "e.g.") ends no sentence."""
    before = text[:at].rstrip().rstrip("\"'(").rstrip()
    return not before or before[-1] in "!?" or (before[-1] == "." and not _ABBREVIATED.search(before[-8:]))


# A filing's note before its narrative: an update says what changed in the report, and names the crash's parties
# as already known ("the vehicle that struck the AV had encountered debris", "an injury to the pedestrian involved
# in contact with the AV"). The note is about the report, not the crash: its sentences open on the report ("This
# is an update to report ...", "Other than noting ..., the content of this report is unchanged"), and the narrative
# starts where the account of the day does, at its date ("On May [XXX], 2022 at 3:11 PM ..."). A note says the
# report with a filing's words ("an update to report", "unchanged from the initial report"), unlike a narrative
# that quotes one ("According to the police report, V1 was ...").
_FILING = re.compile(r"\b(?:updat\w*|unchanged|submi\w+|supplement\w*|correct\w*|amend\w*)\b", re.I)
_REPORT = re.compile(r"\breport\b", re.I)
_DATED = re.compile(r"^On\b[^.]{0,60}?\b(?:19|20)\d\d\b")


def narrative_start(sents: list[str]) -> int:
    """The index of the sentence the narrative starts at: after a filing's note about the report (see above),
    else 0."""

    def about_report(s: str) -> bool:
        return bool(_FILING.search(s) and _REPORT.search(s))

    if not sents or not about_report(sents[0]):
        return 0
    dated = next((i for i, s in enumerate(sents) if _DATED.match(s)), None)
    if dated is not None:
        return dated
    return next((i for i, s in enumerate(sents) if not about_report(s)), 0)
