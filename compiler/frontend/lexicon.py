"""The verbs of impact, written once: every reader of the front end that asks "does this say road users met, and
who struck whom" derives the regular expression it needs from them, so the readers cannot drift apart (a
glancing verb read as a strike by one and not seen by another).

A verb is said in its base ("strike"), third person ("strikes"), past ("struck"), participle ("was struck by")
and "-ing" form ("striking"). Some take their object through a word of their own ("collided with", "crashed
into"), some take it either way ("brushed V1", "brushed against V1"). A glancing blow ("sideswiped", "clipped",
"grazed", "brushed against", "scraped", "bumped") is an impact like any other: the parties met.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from enum import Enum


class Form(Enum):
    BASE = "base"
    THIRD = "third"
    PAST = "past"
    PARTICIPLE = "participle"
    ING = "ing"


ALL_FORMS = tuple(Form)
# The forms a narrative states a strike with: "V2 struck V1", "V2 strikes V1", "striking V1", "proceeded to strike
# V1" (a base only where it reads as the verb: see `Verb.base_reads`).
ACTIVE_FORMS = (Form.BASE, Form.THIRD, Form.PAST, Form.ING)


class BaseReads(Enum):
    """How a verb's base form reads where it stands alone: as the verb ("to strike", "proceeded to make contact"),
    as the noun of the meeting ("the impact", "contact", "a sideswipe"), or as a word for something else ("a
    speed bump", "a rear-end collision", "a brush", "the crash")."""

    VERB = "verb"
    MEETING = "meeting"
    OTHER = "other"


@dataclass(frozen=True)
class Verb:
    """One verb of impact in its five forms (a hyphen marks a compound's joint: "side-swipe"). `particle` is
    the word it takes before its object ("with", "into", "against"); `direct` whether it also takes the object
    straight after it ("brushed V1"), so has a passive ("was brushed by"); `alone` whether it says the parties
    met without its object ("V1 and V2 collided"), not so "crashed" (into the ditch, or a crash's scene)."""

    base: str
    third: str
    past: str
    participle: str
    ing: str
    particle: str = ""
    direct: bool = True
    alone: bool = True
    base_reads: BaseReads = BaseReads.OTHER

    def said(self, form: Form) -> str:
        """The form as a regular expression: a compound may be joined, hyphenated or written apart ("rear
        ended"), but not apart in its base, where two words are the noun ("the rear end", "a side swipe")."""
        word = re.escape(getattr(self, form.value)).replace(r"\ ", " ")
        return word.replace(r"\-", "-?" if form is Form.BASE else "[- ]?")

    def says(self, form: Form, active: bool) -> bool:
        """Whether the form says an impact (`active`: a strike with its subject; see `BaseReads`)."""
        if form is not Form.BASE:
            return True
        return self.base_reads is BaseReads.VERB or (not active and self.base_reads is BaseReads.MEETING)


def _regular(base: str, particle: str = "", direct: bool = True, alone: bool = True, reads: str = "other") -> Verb:
    stem = base[:-1] if base.endswith("e") else base
    double = base + base[-1] if re.search(r"[^aeiou][aeiou][bdgmnpt]$", base) else stem
    third = base + ("es" if base.endswith(("sh", "ch", "s", "x")) else "s")
    return Verb(base, third, double + "ed", double + "ed", double + "ing", particle, direct, alone, BaseReads(reads))


STRIKE = Verb("strike", "strikes", "struck", "struck", "striking", base_reads=BaseReads.VERB)
HIT = Verb("hit", "hits", "hit", "hit", "hitting", base_reads=BaseReads.VERB)
# A glancing blow: the parties met along a side, or at a corner.
GLANCING = (
    _regular("side-swipe", reads="meeting"),
    _regular("clip"),
    _regular("graze"),
    _regular("brush", "against"),
    _regular("scrape", "against"),
    _regular("bump", "into"),
)
IMPACT_VERBS = (
    STRIKE,
    HIT,
    _regular("impact", reads="meeting"),
    _regular("contact", reads="meeting"),
    _regular("collide", "with", direct=False, reads="verb"),
    _regular("rear-end"),
    _regular("crash", "into", direct=False, alone=False),
    # A violent blow into another, its subject the striker: said only with "into" ("slammed on its brakes",
    # "plowed through the snow" are no impacts).
    _regular("smash", "into", direct=False, alone=False),
    _regular("slam", "into", direct=False, alone=False),
    _regular("plow", "into", direct=False, alone=False),
    # ("made contact" alone: its front made contact, the object said elsewhere)
    Verb(
        "make contact",
        "makes contact",
        "made contact",
        "made contact",
        "making contact",
        "with|to",
        base_reads=BaseReads.VERB,
    ),
    *GLANCING,
)
# The verbs that take their object straight after them ("struck V1", "striking its rear").
DIRECT = tuple(v for v in IMPACT_VERBS if v.direct and " " not in v.base)
# The nouns of a meeting: "the impact", "made contact", "a collision". "A collision" is also what a summary calls
# the crash ("was in a collision involving a car"), which names the parties and not how they met.
MEETING_NOUNS = ("impacts?", "contacts?")
IMPACT_NOUNS = (*MEETING_NOUNS, "collisions?")
# A move into something, which before the road users are numbered is read as meeting it ("backed into a parked
# car"); once they are, `crash.MOVED_INTO` says which moves into what are strikes.
INTO_ANYTHING = r"(?:ran|backed|reversed) into"


# A meeting word before a place's noun names a place on a body or a form's field ("the contact area", "the impact
# point"), not a meeting.
_NOT_PLACE = r"(?! (?:areas?|points?|zones?)\b)"


def _one_of(words: set[str]) -> str:
    """The words as one alternation, longest first (so a longer form is not cut at a shorter one)."""
    return "(?:" + "|".join(sorted(words, key=lambda w: (-len(w), w))) + ")"


def forms(forms: tuple[Form, ...] = ALL_FORMS, verbs: tuple[Verb, ...] = IMPACT_VERBS) -> str:
    """The verbs' forms, each as the verb says an impact: with its particle where it needs one to ("crashed
    into"), alone where it can be ("collided")."""
    said = set()
    for verb in verbs:
        for form in (f for f in forms if verb.says(f, active=False)):
            word = verb.said(form)
            said.add(word if verb.alone else f"{word} (?:{verb.particle})")
    return _one_of(said)


def striking(forms: tuple[Form, ...] = ACTIVE_FORMS) -> str:
    """The verbs' forms as a strike with its subject, each with the word before its object: needed where the
    verb takes none without it ("collided with V2"), optional where it takes either ("brushed (against) V2")."""
    said = set()
    for verb in IMPACT_VERBS:
        for form in (f for f in forms if verb.says(f, active=True)):
            word = verb.said(form)
            if verb.particle:
                word += f" (?:{verb.particle})" if not verb.direct else f"(?: (?:{verb.particle}))?"
            said.add(word)
    return _one_of(said)


def struck() -> str:
    """The participles of a passive strike ("was struck", "was sideswiped"): a verb that takes its object
    directly and is one word ("made contact" has no passive)."""
    return forms((Form.PARTICIPLE,), DIRECT)


def stems(nouns: tuple[str, ...] = IMPACT_NOUNS) -> str:
    """Any word built on an impact verb's stem ("strik-", "bump-", "scrap-"), in any form or as any noun ("the
    bumper", "a scrape"), and `nouns`: a net for the readers that look for any sentence that may speak of the
    meeting (a report is refused as describing no crash only when no word in it could say one)."""
    said = set(nouns)
    for verb in IMPACT_VERBS:
        if " " in verb.base:
            continue  # ("made contact": its noun is a stem of its own)
        stem = re.escape(verb.base).replace(r"\-", "[- ]?").removesuffix("e")
        words = {stem + r"\w*", verb.said(Form.PAST)}
        said |= {f"{w} (?:{verb.particle})" for w in words} if not verb.alone else words
    return r"(?<!non-)(?<!non)" + _one_of(said) + _NOT_PLACE


# A strike's verb right before its object: "struck V1", "striking its rear bumper".
BEFORE_OBJECT = forms((Form.PAST, Form.ING), DIRECT)
# Any word saying road users met, in any form: a sentence with one describes an impact (the readers then blank the
# ones only feared, avoided or denied: `text.without_non_impacts`), not one denied by its prefix ("a non-contact
# vehicle") nor one naming a place (`_NOT_PLACE`).
IMPACT_WORD = r"(?<!non-)(?<!non)(?:" + forms() + "|" + "|".join(IMPACT_NOUNS) + ")" + _NOT_PLACE
