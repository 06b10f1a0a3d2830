"""Police forms' short labels for the parties, read as the front end's V1, V2 and "the driver of V1".

A form numbers its units, and each unit's driver and pedestrian with the same number: "U1", "D1" (the driver of
unit 1), "D1's vehicle" (unit 1 itself), "the #2 vehicle"; some forms letter them instead, in order ("Car A",
"Vehicle B": A is 1). Short labels are other things too ("U2" the band, "a D1 visa", "car a few metres away",
"a vehicle A-pillar"), so one is read as a label only when it is one: a label names a party, so it takes no
article ("a D1 visa" is a kind of visa); a form's numbering starts at 1 (or A), so a report that says "U2" or
"Vehicle B" with no "U1" or "Vehicle A" numbers nothing; and a letter is a label only in capitals, as a word of
its own.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.sentences import opens_sentence

_ARTICLE = r"(?<!\ba )(?<!\ban )(?<!\bthe )(?<!\bA )(?<!\bAn )(?<!\bThe )"
_VEHICLE_WORD = r"(?:vehicle|car|truck|van|suv|pickup|motorcycle|bus|unit)"
# "the #2 vehicle", "#1 VEH": the number before the noun
_HASH_FIRST = re.compile(r"\b(?:(?i:the) )?#\s*(\d) (?i:vehicle|veh|car|unit)\b(?![\w-])")
# "D1's vehicle", "Driver #1's car": the driver's vehicle is the unit of the driver's number
_DRIVERS_VEHICLE = re.compile(r"\b(?:D|(?i:driver)\s*#?\s*)(\d)'s (?i:" + _VEHICLE_WORD + r")\b(?![\w-])")
# "the driver of V1's car", "Driver A's van" (once a letter is read): a driver's vehicle is the driver's unit
_THEIR_VEHICLE = re.compile(
    r"\b(?i:the) (?i:driver|operator) of (V\d)'s (?i:" + _VEHICLE_WORD + r"|sedan|minivan|automobile|auto)\b(?![\w-])"
)
_UNIT = re.compile(_ARTICLE + r"\bU(\d)\b(?![\w-])")
_DRIVER = re.compile(_ARTICLE + r"\bD(\d)\b(?![\w-])")
# "Car A", "Vehicle B", "Unit A", "Driver A"
_LETTER = re.compile(r"\b((?i:car|vehicle|veh|unit|driver))\s*#?\s*([A-F])\b(?![\w-])")


def _numbered(pattern: re.Pattern[str], text: str, first: str) -> bool:
    """Whether the report numbers its parties by this label: it uses the first one (see above)."""
    return any(m.group(1) == first for m in pattern.finditer(text))


def police_labels(text: str) -> str:
    """The report with police forms' short labels as V1, V2, ... and "the driver of V1" (see above)."""
    text = _HASH_FIRST.sub(lambda m: f"V{m[1]}", text)
    text = _DRIVERS_VEHICLE.sub(lambda m: f"V{m[1]}", text)
    if _numbered(_UNIT, text, "1"):
        text = _UNIT.sub(lambda m: f"V{m[1]}", text)
    if _numbered(_DRIVER, text, "1"):
        text = _DRIVER.sub(lambda m: f"{'T' if opens_sentence(text, m.start()) else 't'}he driver of V{m[1]}", text)
    if any(m[2] == "A" for m in _LETTER.finditer(text)):

        def letter(m: re.Match[str]) -> str:
            n = ord(m[2]) - ord("A") + 1
            if m[1].lower() == "driver":
                return f"{'T' if opens_sentence(text, m.start()) else 't'}he driver of V{n}"
            return f"V{n}"

        text = _LETTER.sub(letter, text)
    return text


def drivers_vehicles(text: str) -> str:
    """ "the driver of V1's car" as V1 (see `_THEIR_VEHICLE`), once every driver is named so."""
    return _THEIR_VEHICLE.sub(lambda m: m[1], text)
