"""Report text handling shared by the rule and model front ends: participant
naming, sentences, and the cut at the first impact."""

from __future__ import annotations

import re

_NUMBER_WORDS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8}

# V1, V-1, Vehicle #1, Vehicle # 1, Vehicle 1, vehicle one, Vehicle No. 1
_VEHICLE = re.compile(
    r"\b(?:V-?(\d)|vehicle\s*(?:#|no\.?|number)?\s*(\d|one|two|three|four|five)(?![\w-]))", re.IGNORECASE
)
_PEDESTRIAN = re.compile(r"\b(pedestrian|pedalcyclist|bicyclist|cyclist)s?\b(?:\s*#?\s*(\d))?", re.IGNORECASE)
_IMPACT = re.compile(r"\b(struck|strik\w+|impact\w*|contact\w*|collid\w+|hit|crash\w+ into|collision)\b", re.IGNORECASE)


def normalize_names(text: str) -> str:
    """Rewrite every way of naming a vehicle as V1, V2, ... and pedestrians as P1, P2, ..."""

    def vehicle(m: re.Match[str]) -> str:
        raw = (m.group(1) or m.group(2)).lower()
        return f"V{_NUMBER_WORDS.get(raw, raw)}"

    def pedestrian(m: re.Match[str]) -> str:
        return f"P{m.group(2) or 1}"

    text = _VEHICLE.sub(vehicle, text)
    return _PEDESTRIAN.sub(pedestrian, text)


def sentences(text: str) -> list[str]:
    """Split on sentence ends, also where reports omit the space after a period."""
    text = re.sub(r"\s+", " ", text)
    text = re.sub(r"(?<=[a-z0-9)])\.(?=[A-Z])", ". ", text)
    parts = re.split(r"(?<=[.!?])\s+(?=[A-Z\"(])", text)
    return [p.strip() for p in parts if p.strip()]


def participants(text: str) -> list[str]:
    """Ids named in normalized text, vehicles first, in number order."""
    vehicles = sorted({int(m) for m in re.findall(r"\bV(\d)\b", text)})
    pedestrians = sorted({int(m) for m in re.findall(r"\bP(\d)\b", text)})
    return [f"V{n}" for n in vehicles] + [f"P{n}" for n in pedestrians]


def up_to_first_impact(sents: list[str]) -> list[str]:
    """The sentences up to and including the first one that describes an impact."""
    for i, s in enumerate(sents):
        if _IMPACT.search(s) and re.search(r"\b[VP]\d\b", s):
            return sents[: i + 1]
    return sents


_ENGLISH = frozenset(
    ("the", "a", "an", "was", "were", "and", "of", "in", "to", "on", "at", "with", "by", "from", "for", "it", "its")
)


def check_narrative(text: str, name: str) -> None:
    """Refuse text that is no English narrative, with one clear line (no guessing from it)."""
    from sovarc.compiler.frontend import FrontEndError

    words = re.findall(r"[^\W\d_]+", text.lower())
    if not words:
        raise FrontEndError(f"{name}: the report has no words to read")
    english = sum(w in _ENGLISH for w in words)
    if len(words) >= 8 and english / len(words) < 0.08:
        raise FrontEndError(f"{name}: the report does not read as English; sovarc reads English narratives only")


def unrepresented(text: str) -> list[str]:
    """What the report says that the scenario IR cannot hold, named for the user instead of dropped silently."""
    found: list[str] = []
    if re.search(r"\b(?:pedalcyclist|bicyclist|cyclist|bicycle)s?\b", text, re.IGNORECASE):
        found.append("a cyclist is represented as a pedestrian (the IR has no cyclist role)")
    named = normalize_names(text)
    impacts = [s for s in sentences(named) if _IMPACT.search(s) and re.search(r"\b[VP]\d\b", s)]
    if len(impacts) > 1:
        found.append(f"only the first impact is encoded; the report describes {len(impacts)} impact sentences")
    return found
