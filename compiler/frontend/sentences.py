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
