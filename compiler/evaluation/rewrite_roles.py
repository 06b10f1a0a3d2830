"""The metamorphic benchmark's rewrites of reports that number nobody (`rewrites.REWRITES` registers them):

- `unnumbered`: each vehicle introduced only by its description ("V1, a 2003 Honda Pilot, was" -> "A 2003 Honda
  Pilot was") and called by its make afterwards ("the Honda"), as a crash database's summary or a newspaper does;
- `first_person`: V1's driver tells it ("My vehicle was traveling east", "I stated that I ...");
- `insurer`: an adjuster's description, V1 the insured vehicle and its driver "our insured", V2 the claimant
  vehicle and its driver "the claimant".

Each applies only where it keeps the meaning: a report of two vehicles and no pedestrian, whose names are all
of the forms `rewrite_names.VEHICLE` reads (no "Driver #1"); `unnumbered` only where each vehicle's first mention
introduces it with its make and the two makes differ, so "the Honda" names one vehicle only; `first_person` only
where no one speaks in the first person already. A report that does not fit is left as it is.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from sovarc.compiler.evaluation.rewrite_names import cased, renamed
from sovarc.compiler.frontend.sentences import opens_sentence

_V = renamed(lambda n: f"V{n}")
# Kind words after a make and model: "a 1997 Dodge Ram pickup", "a 1998 Ford Taurus station wagon".
_BODY = (
    r"(?: (?:station wagon|pick-?up truck|pick-?up|pickup truck|sport utility vehicle|conversion van|minivan|van|"
    r"sedan|coupe|wagon|truck|pickup|suv|SUV|motorcycle|hatchback|Sedan))?"
)
# An introduction: "V1, a 2003 Honda Pilot," / "V1 was a 2003 Honda Pilot sedan" (its make and model, with what
# comes before the year: "a parked and unoccupied 1993 Oldsmobile").
_DESCRIPTION = (
    r"(?P<desc>[Aa]n? (?:[a-z][\w-]* ){0,3}?(?:(?:19|20)\d\d )?(?P<make>[A-Z][\w-]*[a-z][\w-]*)"
    r"(?:  ?[A-Z0-9][\w-]*(?:\.[\w-]+)*){0,3}" + _BODY + r")\b"
)
# (the aside's closing comma goes where a verb follows: "A 2003 Honda Pilot was traveling")
_FINITE = r"(?:then )?(?:was|were|had|is|[a-z]+ed|struck|hit|ran|made|went|came|drove|began)\b"
_INTRO_ASIDE = re.compile(r"\b(?P<name>V\d), " + _DESCRIPTION + r"(?P<close>,(?= " + _FINITE + r"))?")
_INTRO_WAS = re.compile(  # (at a sentence's start: see `_introductions`)
    r"\b(?P<name>V\d) was " + _DESCRIPTION + r"(?P<join>,? (?:that|which) was |,? and was | was | (?=[a-z]+ing\b))"
)


def two_vehicles(text: str) -> bool:
    """A report of two vehicles, V1 and V2, no pedestrian, every name read as V1/V2 (none as "Driver #1")."""
    return (
        set(re.findall(r"\bV\d\b", text)) == {"V1", "V2"}
        and not re.search(r"\bpedestrian|\bP\d\b|\b(?:driver|operator)\s*(?:#\s*|no\.\s*)?\d\b", text, re.I)
        and not re.search(r"\bV\d,? (?:and|or) V\d\b", text)  # ("V1 and V2 collided": "the two Hondas")
    )


def unnumbered(text: str) -> str:
    """ "V1, a 2003 Honda Pilot, was traveling ... V2 struck V1" -> "A 2003 Honda Pilot was traveling ... V2
    struck the Honda": each vehicle introduced by its description alone and called by its make after it."""
    pair = introduced_pair(text)
    if pair is None:
        return text
    v, intros = pair
    makes = {pid: m["make"] for pid, m in intros.items()}
    if len(set(makes.values())) < 2 or any(
        len(re.findall(r"\b(?:[Aa]n?|[Aa]nother) (?:[\w-]+ ){0,4}?" + make + r"\b", v)) != 1 for make in makes.values()
    ):
        return text  # one make for both, or a make said of a third road user: "the Honda" would not be one
    return by_descriptions(v, intros, lambda pid, at: cased(f"the {makes[pid]}", v, at))


def introduced_pair(text: str) -> tuple[str, dict[str, re.Match[str]]] | None:
    """A report of two vehicles (`two_vehicles`) with its names as V1 and V2 and its labels after words that already
    say them dropped ("the Honda (V1)"), and each vehicle's introduction; None unless each vehicle's first mention
    introduces it (a vehicle named before its introduction would be left unnamed by a rewrite of the names)."""
    v = _V(text)
    if not two_vehicles(v):
        return None
    v = re.sub(r"(?<=\w)\s*\(\s*V\d\s*\)", "", v)
    intros = _introductions(v)
    firsts = {pid: re.search(rf"\b{pid}\b", v) for pid in ("V1", "V2")}
    if set(intros) != {"V1", "V2"} or any(intros[p].start() != f.start() for p, f in firsts.items() if f):
        return None
    return v, intros


def by_descriptions(text: str, intros: dict[str, re.Match[str]], later: Callable[[str, int], str]) -> str:
    """`text` with each vehicle's introduction (`introduced_pair`) as its description alone, and every later
    mention of V1 or V2 as `later(id, where)` says it."""
    out, at = [], 0

    def mentions(part: str, offset: int) -> str:
        return re.sub(r"\bV\d\b", lambda m: later(m.group(), offset + m.start()), part)

    for m in sorted(intros.values(), key=lambda m: m.start()):
        out.append(mentions(text[at : m.start()], at))
        out.append(cased(m["desc"], text, m.start()) + (" was " if m.re is _INTRO_WAS else ""))
        at = m.end()
    out.append(mentions(text[at:], at))
    return "".join(out)


def _introductions(text: str) -> dict[str, re.Match[str]]:
    """Each vehicle's first introduction, "V1, a 2003 Honda Pilot," or a sentence "V1 was a 2003 Honda Pilot"."""
    found = [*_INTRO_ASIDE.finditer(text), *(m for m in _INTRO_WAS.finditer(text) if opens_sentence(text, m.start()))]
    intros: dict[str, re.Match[str]] = {}
    for m in sorted(found, key=lambda m: m.start()):
        intros.setdefault(m["name"], m)
    return intros


# A pronoun and the case it takes in the first person.
_PRONOUN = re.compile(r"\b(?:he|she|him|his|her|himself|herself)\b", re.I)
_PERSON = re.compile(r"\bV\d\b|\b(?:witness|officer|police|passenger|pedestrian)s?\b", re.I)
_OBJECT_AFTER = re.compile(r"\s*(?:[.,;:!?)]|$|(?:to|and|that|the|a|an|at|in|on|with|from|of|for|as|about)\b)")
_VERB_OF_I = {"has": "have", "is": "am", "does": "do", "was not": "was not", "isn't": "am not", "hasn't": "haven't"}


def first_person(text: str) -> str:
    """ "The driver of V1 stated that he was traveling north. V1 struck V2." -> "I stated that I was traveling
    north. My vehicle struck V2.": V1 told by its driver. A pronoun becomes the first person where the participant
    last named before it is V1 (its driver's "he", "his", "her")."""
    v = _V(text)
    if not two_vehicles(v) or re.search(r"\b(?:I|my|me|we|our)\b", v, re.I):
        return text
    # pronouns first, by the mention before each (then the names change)
    out, at = [], 0
    for m in _PRONOUN.finditer(v):
        last = None
        for p in _PERSON.finditer(v, 0, m.start()):
            last = p.group()
        if last != "V1":
            continue
        word = m.group().lower()
        if word in ("he", "she"):
            mine = "I"
        elif word in ("himself", "herself"):
            mine = "myself"
        elif word == "him" or (word == "her" and _OBJECT_AFTER.match(v, m.end())):
            mine = "me"
        else:
            mine = "my"
        if mine != "I":
            mine = cased(mine, v, m.start())
        out.append(v[at : m.start()] + mine)
        at = m.end()
    v = "".join(out) + v[at:]
    v = re.sub(r"\bI (has|is|does|isn't|hasn't)\b", lambda m: "I " + _VERB_OF_I[m.group(1)], v)
    v = re.sub(r"\b[Tt]he (?:driver|operator) of V1\b", lambda m: "I" if _subject(v, m.start()) else "me", v)
    v = re.sub(r"\bV1\b", lambda m: cased("my vehicle", v, m.start()), v)
    return v


def _subject(text: str, at: int) -> bool:
    """Whether a name at `at` opens its clause (a sentence, or after a conjunction or a comma)."""
    return opens_sentence(text, at) or bool(
        re.search(r"(?:[,;]|\b(?:that|and|but|when|as|while|because|after|before|if|so|then|where))\s*$", text[:at])
    )


def insurer(text: str) -> str:
    """ "The driver of V1 ... V1 struck V2 ... the driver of V2" -> "Our insured ... The insured vehicle struck the
    claimant vehicle ... the claimant": an adjuster's names for the two parties."""
    v = _V(text)
    if not two_vehicles(v) or re.search(r"\b(?:insured|claimant)\b", v, re.I):
        return text
    v = re.sub(r"\b[Tt]he (?:driver|operator) of V1\b", lambda m: cased("our insured", v, m.start()), v)
    v = re.sub(r"\b[Tt]he (?:driver|operator) of V2\b", lambda m: cased("the claimant", v, m.start()), v)
    v = re.sub(r"\bV1\b", lambda m: cased("the insured vehicle", v, m.start()), v)
    return re.sub(r"\bV2\b", lambda m: cased("the claimant vehicle", v, m.start()), v)
