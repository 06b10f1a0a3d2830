"""The metamorphic benchmark's rewrites of how the road and its conditions are said (`rewrites.REWRITES` registers
them): a limit "posted at" a speed, a road's lanes counted in all or in each direction, the dark lighted as a
crash form codes it. Each keeps the meaning exactly and leaves text it does not fit unchanged."""

from __future__ import annotations

import re

from sovarc.compiler.evaluation.rewrite_tense import in_case_of

_SPEED = r"\d{1,3}\s*-?\s*(?:mph|kmph|kph|km/h|km/hr)(?:\s*\(\d{1,3}\s*-?\s*(?:mph|kmph|kph|km/h|km/hr)\))?"


def limit_posted_at(text: str) -> str:
    """ "The roadway had a posted speed limit of 30 mph" -> "The roadway was posted at 30 mph"; "a road with a
    posted speed limit of 30 mph" -> "a road posted at 30 mph"; "The posted speed limit was 30 mph" -> "The
    speed limit was posted at 30 mph"."""
    text = re.sub(r"\bhad a posted speed limit of (?=" + _SPEED + ")", "was posted at ", text, flags=re.I)
    text = re.sub(r"\bwith a posted speed limit of (?=" + _SPEED + ")", "posted at ", text, flags=re.I)
    return re.sub(
        r"\b([Tt])he posted speed limit was (?=(?i:" + _SPEED + "))", r"\1he speed limit was posted at ", text
    )


_HALF = {"two": "one", "four": "two", "six": "three", "2": "one", "4": "two", "6": "three"}
_DOUBLE = {"one": "two", "two": "four", "three": "six"}
# "a two-lane, two-way roadway", "a two lane undivided roadway" (undivided: a two-way road with no median)
_TOTAL = re.compile(
    r"\b(?P<art>[Aa]n?) (?P<pre>(?:level |straight |dry )*)(?P<n>two|four|six|2|4|6)[- ]lane,? "
    r"(?P<kind>(?:two-way|undivided)(?:,? (?:two-way|undivided))?) (?P<road>roadway|road)\b"
)
# "a two-way roadway with one lane in each direction"
_EACH = re.compile(
    r"\b(?P<art>[Aa]n?) (?P<kind>(?:(?:level|straight|dry|undivided|divided|two-way|asphalt),? ){1,3})"
    r"(?P<road>roadway|road) with (?P<n>one|two|three)[- ]lanes? (?:of travel )?in each direction\b"
)


def _article(like: str, word: str) -> str:
    return in_case_of(like, "an" if word[0] in "aeiou" else "a")


def lanes_each_way(text: str) -> str:
    """ "a two-lane, two-way roadway" -> "a two-way roadway with one lane in each direction"; "a four lane
    undivided road" -> "an undivided road with two lanes in each direction"."""

    def one(m: re.Match[str]) -> str:
        half = _HALF[m["n"]]
        said = f"{m['pre']}{m['kind']} {m['road']} with {half} lane{'' if half == 'one' else 's'} in each direction"
        return f"{_article(m['art'], said)} {said}"

    return _TOTAL.sub(one, text)


def lanes_total(text: str) -> str:
    """ "a two-way roadway with one lane in each direction" -> "a two-lane, two-way roadway"."""

    def one(m: re.Match[str]) -> str:
        kind = m["kind"].rstrip(", ")
        return f"{in_case_of(m['art'], 'a')} {_DOUBLE[m['n']]}-lane, {kind} {m['road']}"

    return _EACH.sub(one, text)


def dark_lighted(text: str) -> str:
    """ "dark, but lighted" / "dark but lighted" -> "dark-lighted": a crash form's light condition, street lights
    lit in the dark."""
    return re.sub(r"\b([Dd])ark,? but lighted\b", r"\1ark-lighted", text)
