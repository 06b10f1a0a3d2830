"""A crash database's coded pre-crash event, which NMVCCS narratives often repeat after the impact."""

from __future__ import annotations

import re

_PRECRASH_LEFT = re.compile(
    r"critical pre-?crash event\b[^.]*?\b(V\d)\b[^.]*?\b(?:over the lane line on (?:the )?left side|"
    r"lane line on left side|cross(?:ed|ing)? (?:the )?cent(?:er|re) ?line|left of cent(?:er|re))",
    re.I,
)


def precrash_wrong_way(sents: list[str]) -> dict[str, int]:
    """Vehicles whose coded pre-crash event ("travelling over the lane line on the left side"), often written
    after the impact, says they went into the opposing lane; each with the index of the sentence that says so."""
    return {m.group(1): i for i, s in enumerate(sents) if (m := _PRECRASH_LEFT.search(s))}
