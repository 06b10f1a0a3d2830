"""Splitting a report into sentences: the unit every front-end rule reads."""

from __future__ import annotations

import re


def sentences(text: str) -> list[str]:
    """Split on sentence ends, also where reports omit the space after a period."""
    text = re.sub(r"\s+", " ", text)
    text = re.sub(r"(?<=[a-z0-9)])\.(?=[A-Z])", ". ", text)
    parts = re.split(r"(?<=[.!?])\s+(?=[A-Z\"(])", text)
    return [p.strip() for p in parts if p.strip()]
