"""Report text handling shared by the rule and model front ends: participant
naming, sentences, and the cut at the first impact."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from sovarc.compiler.frontend.capitals import sentence_case
from sovarc.compiler.frontend.choice import FrontEndError
from sovarc.compiler.frontend.crash import MOVED_INTO, V1_PLACED
from sovarc.compiler.frontend.labels import drivers_vehicles, police_labels
from sovarc.compiler.frontend.lexicon import IMPACT_NOUNS, IMPACT_VERBS, IMPACT_WORD, Form, forms, striking, struck
from sovarc.compiler.frontend.names import PLACE, THING, parties
from sovarc.compiler.frontend.ordinals import ordinal_names
from sovarc.compiler.frontend.participles import moves_after_nouns
from sovarc.compiler.frontend.sentences import narrative_start, sentences
from sovarc.compiler.frontend.spelling import spell_out
from sovarc.compiler.frontend.words import number

# V1, V-1, V 1, V#1, Vehicle #1, Vehicle # 1, Vehicle 1, vehicle one, Vehicle No. 1, Unit 1, Unit #1
_VEHICLE = re.compile(
    r"\b(?:V(?:-|#\s*|(?<=\bV) )?(\d)(?![\w-])(?!\.\d)"
    r"|(?:vehicle|unit)\s*(?:#|no\.?|number)?\s*(\d|one|two|three|four|five)(?![\w-])"
    # (not a count of what follows: "a passenger vehicle two vehicles behind V1", "a vehicle 3 car lengths ahead")
    r"(?!\s+(?:(?:car|vehicle) )?(?:vehicles|cars|lanes|lengths|feet|ft|meters|seconds|times|miles)\b))",
    re.IGNORECASE,
)
# Police forms number the drivers as their vehicles: "Driver #1", "Driver 2", "driver one" is the driver of V1.
_DRIVER = re.compile(
    r"\b([Dd])(?:river|RIVER)\s*(?:#\s*|no\.\s*|number\s+)?(\d|one|two|three|four|five)(?![\w-])(?!\s*(?:years?|mph)\b)"
)
_PEDESTRIAN = re.compile(r"\b(pedestrian)s?\b(?:\s*#?\s*(\d))?", re.IGNORECASE)
# A group of pedestrians counted, not numbered: "struck three pedestrians" is three road users.
_PEDESTRIAN_GROUP = re.compile(r"\b(two|three|four|five) pedestrians\b", re.IGNORECASE)
# A cyclist the report does not number: a vehicle (of kind bicycle), numbered after the vehicles it numbers.
_CYCLIST = re.compile(r"\b(?:an?|the) (?:[\w-]+ ){0,2}?(?:pedal|bi)?cyclist\b(?![\w-])(?! lanes?\b)", re.IGNORECASE)
_IMPACT = re.compile(r"\b(?:" + IMPACT_WORD + "|" + MOVED_INTO + r")\b", re.IGNORECASE)
# the nouns of a meeting, and the crash's own
_MET_NOUNS = "|".join((*IMPACT_NOUNS, r"crash(?:es)?"))
# An impact only feared or avoided is none: "steered left to avoid a collision", "a non-contact vehicle"; one
# that could not be avoided is one ("was unable to avoid contact with V2").
_NO_IMPACT = re.compile(
    r"\b(?<!unable to )(?<!failed to )(?<!not )(?<!n't )(?:avoid|prevent)(?:ing)? (?:a |the |an |making )?(?:\w+ )?"
    r"(?:" + _MET_NOUNS + "|" + forms((Form.ING,)) + r")\b"
    # the scene, not the participants meeting; but one "between V1 and V2" names both parties of the impact
    r"|\b(?:collision|crash|impact) (?:occurred|happened|took place)\b(?! between\b)"
    r"|\bat the time of (?:the )?(?:impact|contact|collision|crash)\b"  # what held then, not the meeting
    # a meeting denied: "no collision occurred", "passed without contact", "did not strike", "never made contact"
    r"|\b(?:no|without|never|(?:did|does|do|was|were|is) ?(?:not|n't)) (?:a |the |an |any |make |making |made )?"
    r"(?:(?!avoid|prevent)\w+ )?"
    r"(?:" + _MET_NOUNS + "|" + forms() + r")\b",
    re.IGNORECASE,
)


def without_non_impacts(sentence: str) -> str:
    """The sentence with the impact words that say no participants met blanked: a crash avoided, denied, or
    named only as the scene or the time."""
    return _NO_IMPACT.sub(" ", sentence)


# A narrative told in the present says the same events as one told in the past ("V2 stops at the sign, then turns
# left and strikes V1"). The readers read the past, so a crash narrative's verb in the third person present, right
# after its subject (a participant, a pronoun, a part of a vehicle, or "and"/"then" going on with the subject), is
# read as its past, word for word.
_IRREGULAR = (
    "comes came makes made begins began drives drove sees saw goes went runs ran "
    "spins spun loses lost occurs occurred happens happened passes passed "
    "approaches approached proceeds proceeded crosses crossed"
)
_REGULAR = (
    "turn stop slow brake steer swerve enter accelerate attempt start change pull back continue merge "
    "travel fail depart rotate yield move veer exit overcorrect drift observe notice decelerate skid"
)
_PAST_OF = dict(zip(_IRREGULAR.split()[::2], _IRREGULAR.split()[1::2], strict=True))


def _regular_past(verb: str) -> str:
    """A regular verb's past: "-d" after an "e"; a one-syllable verb ending in one vowel and a consonant doubles
    the consonant ("stop" -> "stopped", "skid" -> "skidded"); else "-ed"."""
    if verb.endswith("e"):
        return f"{verb}d"
    if re.fullmatch(r"[^aeiou]*[aeiou][^aeiouwxy]", verb):
        return f"{verb}{verb[-1]}ed"
    return f"{verb}ed"


_PAST_OF.update({f"{v}s": _regular_past(v) for v in _REGULAR.split()})
# (the verbs of impact as the lexicon writes them, a compound also joined: "sideswipes")
for _v in (v for v in IMPACT_VERBS if " " not in v.base):
    _PAST_OF.update({_v.third.replace("-", j): _v.past.replace("-", j) for j in ("-", "")})
_VERBS_NOW = "|".join(sorted(_PAST_OF, key=len, reverse=True))
_NOW = re.compile(
    r"(\b(?:[VP]\d|he|she|it|they|and|then|vehicle|crash|collision)(?: then)? )(" + _VERBS_NOW + r")\b", re.I
)
# after a part ("its right front impacts") or a comma going on with the subject ("overcorrected, comes back"),
# not a noun: "the front brakes", "two quarter turns, ..."
_NOW_AFTER_PART = re.compile(
    r"(\b(?:front|rear|side|bumper|corner|end|driver|operator)(?: then)? |, )"
    r"(?!(?:brakes|stops|turns|impacts|backs)\b(?! (?:the|V\d|at|for|in|to|left|right)\b))(" + _VERBS_NOW + r")\b",
    re.I,
)
# a strike said in the present passive: "its left side is struck by the front of V1"
_IS_STRUCK = re.compile(r"\b(is|are)(?= (?:then )?" + struck() + r"\b)")


def in_past(text: str) -> str:
    """The narrative with its present-tense verbs of the crash in the past (see above)."""

    def past(m: re.Match[str]) -> str:
        return m.group(1) + _PAST_OF[m.group(2).lower()]

    text = _NOW_AFTER_PART.sub(past, _NOW.sub(past, text))
    return _IS_STRUCK.sub(lambda m: "was" if m.group(1) == "is" else "were", text)


def normalize_names(text: str) -> str:
    """Rewrite every way of naming a vehicle as V1, V2, ... and pedestrians as P1, P2, ..."""

    def pedestrian(m: re.Match[str]) -> str:
        return f"P{m.group(2) or 1}"

    def group(m: re.Match[str]) -> str:
        ids = [f"P{n}" for n in range(1, number(m.group(1)) + 1)]
        return " and ".join(ids)  # (no commas: a comma parts the clauses of an impact sentence)

    text = number_vehicles(text)
    if not re.search(r"\bpedestrian\s*#?\s*\d", text, re.I):  # (a report that numbers them says who is who)
        text = _PEDESTRIAN_GROUP.sub(group, text, count=1)
    return _number_cyclist(_PEDESTRIAN.sub(pedestrian, text))


def _number_cyclist(text: str) -> str:
    """ "struck a bicyclist" -> "struck V3, a bicyclist": one unnumbered cyclist gets the next vehicle number;
    its later mentions ("the cyclist") are it."""
    found = _CYCLIST.search(text)
    if found is None or re.search(r"\b[VP]\d,?\s*\(?$", text[: found.start()]):
        return text  # none, or one the report numbers itself ("P1, a bicyclist,")
    taken = [int(n) for n in re.findall(r"\bV(\d)\b", text)]
    pid = f"V{max(taken, default=0) + 1}"
    text = text[: found.start()] + f"{pid}, {found.group()}," + text[found.end() :]
    rest = found.start() + len(pid) + 2 + len(found.group()) + 1
    later = re.compile(r"\b[Tt]he (?:pedal|bi)?cyclist\b(?![\w-])")
    return text[:rest] + later.sub(pid, text[rest:])


def number_vehicles(text: str) -> str:
    """Rewrite every way of numbering a vehicle ("V 1", "Vehicle #1", "Unit 1", police forms' "U1", "Car A": see
    `labels`) as V1, V2, ..."""

    def vehicle(m: re.Match[str]) -> str:
        if re.match(r"unit\b", m.group(), re.I) and re.match(r"\s+of (?:the|an?)\b", text[m.end() :], re.I):
            return m.group()  # "Unit 4 of the apartment building": a unit of a place, not a vehicle's label
        raw = (m.group(1) or m.group(2)).lower()
        return f"V{number(raw)}"

    def driver(m: re.Match[str]) -> str:
        raw = m.group(2).lower()
        return f"{'T' if m.group(1) == 'D' else 't'}he driver of V{number(raw)}"

    text = police_labels(text)
    return drivers_vehicles(ordinal_names(_DRIVER.sub(driver, _VEHICLE.sub(vehicle, text))))


# "V2, a 2002 Mercury Mountaineer pickup" / "V1 was a 4-door 1999 Nissan Altima": make, model and body words
_DESCRIBED = re.compile(
    r"\b([VP]\d),? (?:was |is )?(?:an? |the )(?:[\w-]+ )?(?:19|20)\d\d ((?:[A-Z0-9][\w-]*)(?: [A-Z0-9][\w-]*){0,3})"
    r"((?: [a-z][\w-]*){0,2})"
)
_BODY = re.compile(
    r"\b(pickup|truck|van|minivan|bus|motorcycle|sedan|coupe|wagon|hatchback|suv|tractor-trailer|semi|jeep)\b",
    re.IGNORECASE,
)


def _aliases(text: str) -> dict[str, str]:
    """Words a report uses for one participant after naming it once ("the Mercedes", "the pickup").

    Only words that name exactly one participant are kept: two Fords make "the Ford" ambiguous."""
    seen: dict[str, set[str]] = {}
    for m in _DESCRIBED.finditer(text):
        words = m.group(2).split()
        names = {" ".join(words), *words[:2]}  # the make, its model and both together
        names |= {b.lower() for b in _BODY.findall(m.group(2) + m.group(3))}
        for name in names:
            if (
                name.islower()
                and len(re.findall(r"\b(?:an?|another) (?:[\w-]+ ){0,4}?" + name + r"\b", text, re.I)) > 1
            ):
                continue  # "a non-contact school bus" too: "the bus" is not only this participant
            if len(name) > 2 and not name.isdigit():
                seen.setdefault(name, set()).add(m.group(1))
    return {name: next(iter(ids)) for name, ids in seen.items() if len(ids) == 1}


def resolve_aliases(text: str) -> str:
    """Rewrite "the Mercedes" and "the pickup" as the participant the report introduced with those words."""
    aliases = _aliases(text)
    for name in sorted(aliases, key=len, reverse=True):  # "the Mercedes Benz" before "the Mercedes"
        flags = re.IGNORECASE if name.islower() else 0
        text = re.sub(r"\b[Tt]he " + re.escape(name) + r"\b(?![\w-])", aliases[name], text, flags=flags)
    return text


_PARKED = re.compile(
    r"\b(?:a|an|the) (?:legally |illegally )?parked(?:,? (?:and )?unoccupied)? (?:[\w-]+ ){0,3}?"
    r"(?:vehicle|car|van|truck|pickup|suv|sedan|bus|trailer)\b",
    re.IGNORECASE,
)


def name_parked(text: str) -> str:
    """A parked vehicle the first impact hits without numbering it ("struck a legally parked Ford van") is a
    participant: it gets the next free number, so the crash has its victim."""
    sents = sentences(text)
    impact = first_impact(sents)
    m = _PARKED.search(sents[impact]) if impact >= 0 else None
    # (not one that says where another was: "pass between V1 and a parked passenger vehicle")
    if m is None or re.search(r"\bV\d,? $", sents[impact][: m.start()]) or PLACE.search(sents[impact][: m.start()]):
        return text
    taken = [int(n) for n in re.findall(r"\bV(\d)\b", text)]
    return text.replace(m.group(), f"V{max(taken, default=0) + 1}, {m.group()},", 1)


@dataclass(frozen=True)
class Prepared:
    """A report ready to read, and how its participants were named: computed once per report (`prepare_report`)
    and handed to whatever needs the naming (the refusals, the rules, the kinds, the user's note)."""

    named: str  # every participant under one name: the text the readers read
    labelled: str  # the parties numbered or labelled only (before makes, cyclists and a parked victim)
    note: str | None  # how they were numbered, when the report does not number them itself
    words: dict[str, str] = field(default_factory=dict)  # the words each party numbered here was first named by


def prepare_report(text: str) -> Prepared:
    """Every participant under one name: V1/P1 numbering (the report's own, its labels, or the rule for reports
    that name none: see `names`), makes and body words, an unnumbered parked victim; with the naming's note and
    the words each party numbered by rule was named by."""
    labelled, note, words = parties(number_vehicles(moves_after_nouns(spell_out(sentence_case(text)))))
    labelled = in_past(labelled)
    return Prepared(name_parked(resolve_aliases(normalize_names(labelled))), labelled, note, words)


def prepare(text: str) -> str:
    """The text of `prepare_report`."""
    return prepare_report(text).named


def participants(text: str) -> list[str]:
    """Ids named in normalized text, vehicles first, in number order."""
    vehicles = sorted({int(m) for m in re.findall(r"\bV(\d)\b", text)})
    pedestrians = sorted({int(m) for m in re.findall(r"\bP(\d)\b", text)})
    return [f"V{n}" for n in vehicles] + [f"P{n}" for n in pedestrians]


def describes_impact(sentence: str) -> bool:
    """A sentence that says participants met (not one that only says a crash was avoided)."""
    return bool(_IMPACT.search(without_non_impacts(sentence)) and re.search(r"\b[VP]\d\b", sentence))


# A summary only names the parties ("V1 ... was in a collision involving V2 on [XXX]"); the impact is where the
# report describes the contact, so the summary is the impact only when no sentence describes one.
_SUMMARY = re.compile(
    r"\b(?:was|were) (?:in|involved in) an? (?:\w+ )?(?:collision|crash|incident)\b|\bcollision involving\b", re.I
)


# Where a sentence's clauses part: "V1 was yielding to P1 crossing the street | when V2 made contact with V1".
_CLAUSE = re.compile(r",? \b(?:when|while|as|after|before|because|and then)\b |[,;] ", re.I)


def impact_clause(sentence: str) -> str:
    """The clauses of a sentence that say participants met; the whole sentence when none does alone. A road
    user named only in another clause ("yielding to P1 crossing") is a bystander to this impact."""
    clauses = [c for c in _CLAUSE.split(sentence) if describes_impact(c)]
    return " ".join(clauses) if clauses else sentence


# A summary run together with the description (no full stop between them) still describes the contact.
_MET = re.compile(r"\b" + striking() + r"\b", re.I)


def _thing_only(sentence: str) -> bool:
    """An impact of one party with a thing the IR has no role for ("the front of V1 made contact with the cat")."""
    clause = impact_clause(sentence)
    return len(set(re.findall(r"\b[VP]\d\b", clause))) < 2 and THING.search(clause) is not None


def first_impact(sents: list[str]) -> int:
    """The index of the first sentence that describes an impact (see `_SUMMARY`), or -1. An impact with an
    animal or an object before the parties met is not theirs: the crash is the first between road users."""
    found = [i for i, s in enumerate(sents) if describes_impact(s)]
    found = [i for i in found if i >= narrative_start(sents)] or found  # (not a filing's note: see there)
    found = [i for i in found if not _thing_only(sents[i])] or found
    described = [i for i in found if not _SUMMARY.search(sents[i]) or _MET.search(sents[i])]
    return (described or found or [-1])[0]


def own_impact(sents: list[str], impact: int) -> int:
    """The automated vehicle's impact in a chain collision, for a report whose V1 is that vehicle: when the first
    impact (index `impact`) is between two other road users ("the SUV made contact with the pickup truck. After
    that, the SUV swerved into V1"), the first later sentence whose impact clause names V1, for the scenario is
    V1's crash; else `impact`. A pronoun in the impact clause may be V1 ("when it made contact with V2"): then
    the impact stays."""
    if impact < 0 or re.search(_V1_MET + r"|\b(?:it|its|they|them)\b", _unplaced(sents[impact]), re.I):
        return impact
    later = (i for i in range(impact + 1, len(sents)) if describes_impact(sents[i]))
    return next((i for i in later if re.search(_V1_MET, _unplaced(sents[i]))), impact)


def _unplaced(sentence: str) -> str:
    """The impact clause without V1 where it only says where another was ("V2 behind V1 was hit by V3")."""
    return V1_PLACED.sub("", impact_clause(sentence))


# V1 as a party of an impact clause, not as the owner of a place another crossed ("turned left across V1's path
# and made contact with V3": V1 was not met there).
_V1_MET = r"\bV1\b(?!'s (?:lane|path)\b)"


def up_to_first_impact(sents: list[str]) -> list[str]:
    """The sentences up to and including the first one that describes an impact."""
    i = first_impact(sents)
    return sents[: i + 1] if i >= 0 else sents


_ENGLISH = frozenset(
    ("the", "a", "an", "was", "were", "and", "of", "in", "to", "on", "at", "with", "by", "from", "for", "it", "its")
)


def check_narrative(text: str, name: str) -> None:
    """Refuse text that is no English narrative, with one clear line (no guessing from it)."""
    words = re.findall(r"[^\W\d_]+", text.lower())
    if not words:
        raise FrontEndError(f"{name}: the report has no words to read")
    english = sum(w in _ENGLISH for w in words)
    if len(words) >= 8 and english / len(words) < 0.08:
        raise FrontEndError(f"{name}: the report does not read as English; sovarc reads English narratives only")


def unrepresented(text: str) -> list[str]:
    """What the report says that the scenario IR cannot hold, named for the user instead of dropped silently."""
    found: list[str] = []
    named = normalize_names(spell_out(sentence_case(text)))
    impacts = [s for s in sentences(named) if describes_impact(s)]
    if len(impacts) > 1:
        found.append(f"only the first impact is encoded; the report describes {len(impacts)} impact sentences")
    return found
