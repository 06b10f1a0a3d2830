"""Rewrites of a report into a police agency's conventions (`rewrites.py` registers them): the narrative as
agencies export it in capitals, the units as forms label them ("VEH 1", "Vehicle A", "Car A", "D1" for the
driver of V1), and the forms' abbreviations ("RT LN", "INTX", "OPP DIR", "APPROX", "FTYROW", "EBL").

The patterns are written here, not taken from the front end (`frontend/capitals.py`, `labels.py`, `forms.py`),
so the benchmark is no copy of what it measures.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from sovarc.compiler.evaluation.rewrite_names import ANY_NAME, renamed


def all_caps(text: str) -> str:
    """The whole report in capitals, as agencies export their narratives."""
    return text.upper()


def veh_caps(text: str) -> str:
    """ "V1" -> "VEH 1"."""
    return renamed(lambda n: f"VEH {n}")(text)


def _lettered(noun: str) -> Callable[[str], str]:
    """ "V1", "V2" -> "Vehicle A", "Vehicle B": the units lettered in order."""
    return renamed(lambda n: f"{noun} {chr(ord('A') + n - 1)}")


letters = _lettered("Vehicle")
car_letters = _lettered("Car")


def driver_short(text: str) -> str:
    """ "the driver of V1" -> "D1": a form numbers each driver as the driver's unit."""
    v = renamed(lambda n: f"V{n}")
    return re.sub(r"\b[Tt]he (?:driver|operator) of (" + ANY_NAME + ")", lambda m: f"D{v(m[1])[1:]}", text)


_SIDE = {"left": "LT", "right": "RT"}
_FORMS: tuple[tuple[re.Pattern[str], Callable[[re.Match[str]], str]], ...] = (
    (re.compile(r"\bfailed to yield (?:the )?right[- ]of[- ]way\b", re.I), lambda m: "FTYROW"),
    (re.compile(r"\b(left|right)(?:[- ]most)? lane\b", re.I), lambda m: f"{_SIDE[m[1].lower()]} LN"),
    (re.compile(r"\b(left|right)(?=[- ]turn\b)", re.I), lambda m: _SIDE[m[1].lower()]),
    (re.compile(r"\b(north|south|east|west)bound lane\b", re.I), lambda m: f"{m[1][0].upper()}BL"),
    (re.compile(r"\b(?<=the )(?:travel )?lane\b(?![\w-])"), lambda m: "LN"),
    (re.compile(r"\bintersection\b", re.I), lambda m: "INTX"),
    (re.compile(r"\bopposite direction\b", re.I), lambda m: "OPP DIR"),
    (re.compile(r"\bapproximately\b", re.I), lambda m: "APPROX"),
)


def form_abbrev(text: str) -> str:
    """ "failed to yield the right of way" -> "FTYROW", "the left lane" -> "the LT LN", "a right turn" -> "a RT
    turn", "the eastbound lane" -> "the EBL", "the lane" -> "the LN", "intersection" -> "INTX", "opposite
    direction" -> "OPP DIR", "approximately" -> "APPROX": police forms' abbreviations."""
    for pattern, form in _FORMS:
        text = pattern.sub(form, text)
    return text


POLICE: dict[str, Callable[[str], str]] = {
    "all_caps": all_caps,
    "veh_caps": veh_caps,
    "letters": letters,
    "car_letters": car_letters,
    "driver_short": driver_short,  # (it drops names: the others keep their own words)
    "form_abbrev": form_abbrev,
}
