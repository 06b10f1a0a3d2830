"""The metamorphic benchmark's rewrites into terse and lettered styles (`rewrites.REWRITES` registers them):

- `bare_names`: each vehicle introduced by its description ("V1, a 2003 Honda Civic sedan, was" -> "A 2003 Honda
  Civic sedan was") and called by its kind afterwards (by its make where its description says no kind), without
  the article where it opens a sentence, as police and dispatch notes write ("Sedan struck the Ford.");
- `driver_letters`: the parties lettered by their drivers, as some agencies write: "the driver of V1" -> "Driver
  A", V1 -> "Driver A's vehicle".

`bare_names` applies only where each vehicle's first mention introduces it and the two names differ and name no third
road user, so "the sedan" names one vehicle only (as `rewrite_roles.unnumbered` needs two makes).
"""

from __future__ import annotations

import re

from sovarc.compiler.evaluation.rewrite_names import renamed
from sovarc.compiler.evaluation.rewrite_roles import by_descriptions, introduced_pair, two_vehicles
from sovarc.compiler.frontend.sentences import opens_sentence

_V = renamed(lambda n: f"V{n}")
# The kind word a description ends with, and what a terse note calls that kind.
_KIND = re.compile(
    r"\b(station wagon|pick-?up truck|pick-?up|sport utility vehicle|conversion van|minivan|van|sedan|coupe|wagon|"
    r"truck|suv|motorcycle|hatchback)$",
    re.I,
)
_CALLED = {
    "pick-up truck": "pickup",
    "pickup truck": "pickup",
    "pick-up": "pickup",
    "sport utility vehicle": "SUV",
    "suv": "SUV",
    "station wagon": "wagon",
    "conversion van": "van",
}


def _kind(desc: str) -> str | None:
    m = _KIND.search(desc)
    return _CALLED.get(m[1].lower(), m[1].lower()) if m else None


def bare_names(text: str) -> str:
    """ "V1, a 2003 Honda Civic sedan, was traveling ... V1 struck V2" -> "A 2003 Honda Civic sedan was traveling
    ... Sedan struck the pickup": each vehicle introduced by its description and called by its bare kind."""
    pair = introduced_pair(text)
    if pair is None:
        return text
    v, intros = pair
    # each by its kind, else by its make ("Sedan struck the Ford")
    kinds = {pid: _kind(m["desc"]) or m["make"] for pid, m in intros.items()}
    if len({k.lower() for k in kinds.values()}) < 2:
        return text
    # (no other road user of either: "a parked sedan" would make "the sedan" two)
    if any(len(re.findall(r"\b(?:an?|another) (?:[\w-]+ ){0,5}?" + k + r"s?\b", v, re.I)) != 1 for k in kinds.values()):
        return text

    def later(pid: str, at: int) -> str:
        kind = kinds[pid]
        return kind[0].upper() + kind[1:] if opens_sentence(v, at) else f"the {kind}"

    return by_descriptions(v, intros, later)


def driver_letters(text: str) -> str:
    """ "The driver of V1 ... V1 struck V2's side" -> "Driver A ... Driver A's vehicle struck Driver B's side"."""
    v = _V(text)
    if not two_vehicles(v):
        return text

    def letter(n: str) -> str:
        return chr(ord("A") + int(n) - 1)

    v = re.sub(r"\b[Tt]he (?:driver|operator) of V(\d)\b", lambda m: f"Driver {letter(m[1])}", v)
    v = re.sub(r"\bV(\d)'s\b", lambda m: f"Driver {letter(m[1])}'s", v)
    return re.sub(r"\bV(\d)\b", lambda m: f"Driver {letter(m[1])}'s vehicle", v)
