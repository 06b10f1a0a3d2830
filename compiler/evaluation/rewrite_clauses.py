"""The metamorphic benchmark's rewrites of how a narrative's sentences are built, and of what a participant is
called after it is introduced (`rewrites.REWRITES` registers them):

- a time clause before or after what it times ("As V1 entered the intersection, V2 struck V1" <-> "V2 struck V1
  as V1 entered the intersection"), and a place phrase the same ("At the intersection, V2 struck V1");
- a participant's kind as an aside or as what it was ("V1, a 1996 Honda Civic, was traveling east" <-> "V1 was a
  1996 Honda Civic, which was traveling east");
- a participant called by its make after its introduction ("the Honda"), by its ordinal ("the first vehicle"),
  or in a police narrative's abbreviations ("Veh. #1", "approx.");
- the right lane as the curb lane.

Each keeps the meaning exactly: a move is made only where it cannot change what a word refers to or what a phrase
qualifies (no pronoun whose antecedent the move would change, no clause joined by "and" that a moved phrase
would stop or start qualifying), and a sentence that does not fit is left as it is.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from sovarc.compiler.evaluation.rewrite_names import ANY_NAME, ORDINALS, VEHICLE, cased, digit, renamed
from sovarc.compiler.evaluation.rewrite_tense import in_case_of

# A sentence and the space after it; reports sometimes omit the space ("to damage.Vehicle #1 was").
_SENTENCE_END = re.compile(r"(?<=[.!?])(\s*)(?=[A-Z]|$)")


def per_sentence(one: Callable[[str], str]) -> Callable[[str], str]:
    """A rewrite of single sentences, applied to each sentence of a report (the spacing kept)."""

    def run(text: str) -> str:
        parts = _SENTENCE_END.split(text)  # sentence, space, sentence, space, ...
        return "".join(p if i % 2 else one(p) for i, p in enumerate(parts))

    return run


# A clause's subject, a participant named any way the reports number one (a move keeps each name's own words):
# "V1", "the driver of Vehicle #1", "the front of Unit 1".
_NAME = ANY_NAME
_SUBJECT = r"(?:" + _NAME + r"|[Tt]he (?:driver|operator) of " + _NAME + r"|[Tt]he (?:[\w-]+ ){1,3}?of " + _NAME + ")"
_PRONOUN = re.compile(r"\b(?:he|she|it|its|his|her|him|they|them|their|this vehicle|the other vehicle)\b", re.I)
# Words that make a main clause more than one event, or another's words: moving a phrase past them could change
# what it qualifies ("As V1 entered, V2 braked and V1 struck V2"; "V1 stated that it stopped when ...").
_NOT_ONE_EVENT = re.compile(
    r"\band\b|,|;|\b(?:stated|said|reported|told|indicated|according|believed|thought)\b|\bthat\b|\bthen\b", re.I
)
_CONJ = r"(?:when|as|while|after|before)"
# A finite verb opens the clause after its subject ("V1 entered", "V1 was", not "V1's"): a clause, not a phrase.
_VERB = r"(?:was|were|had|[a-z]+ed|struck|hit|ran|went|came|made|began|drove|saw)\b"
_FINITE_NEXT = r" (?:then )?" + _VERB


def _one_event(clause: str) -> bool:
    """A clause of one event said in one's own words: no "and", no list, no reported speech (a participant's kind
    between commas, "V1, a 1996 Honda Civic,", is no list)."""
    return not _NOT_ONE_EVENT.search(re.sub(r", an? [^,;]*,", "", clause))


def _lower_first(s: str) -> str:
    return s[0].lower() + s[1:] if s.startswith(("The ", "Its ")) else s


def _upper_first(s: str) -> str:
    return s[0].upper() + s[1:]


_FRONTED = re.compile(
    r"^(?P<conj>As|When|While|After|Before) (?P<sub>" + _SUBJECT + _FINITE_NEXT + r"[^,;]*), "
    r"(?P<main>(?:" + _SUBJECT + r"|[Ii]ts (?:[\w-]+ ){0,2}?(?:side|front|rear|end|corner|plane))"
    r"(?:'s)? [^;]*)\.$"
)


def clause_after(sentence: str) -> str:
    """ "As V1 entered the intersection, V2 struck V1." -> "V2 struck V1 as V1 entered the intersection.": a time
    clause said after what it times. A main clause opening on the time clause's participant's part ("its left
    side") names it ("V1's left side"), since after the move the pronoun would come before its participant."""
    m = _FRONTED.match(sentence)
    if m is None or _PRONOUN.search(m["sub"]) or not _one_event(m["main"]):
        return sentence
    main = m["main"]
    if main.lower().startswith("its "):
        name = re.match(_NAME, m["sub"])
        main = f"{name[0]}'s {main[4:]}" if name else ""
    if not main or _PRONOUN.search(main):
        return sentence
    return f"{_upper_first(main)} {m['conj'].lower()} {_lower_first(m['sub'])}."


_TRAILING = re.compile(
    r"^(?P<main>" + _SUBJECT + r"(?:, an? [^,;]*,)? [^;]*?)(?<!\bwas)(?<!\bis)(?<!\bwere),? (?P<conj>" + _CONJ + r") "
    r"(?P<sub>(?:" + _SUBJECT + _FINITE_NEXT + r"|(?:it|its (?:[\w-]+ ){0,2}?(?:side|front|rear|end|corner|plane))"
    r" " + _VERB + r")[^,;]*(?:, an? [^,;]*)?)\.$"
)


def clause_fronted(sentence: str) -> str:
    """ "V2 struck V1 as V1 entered the intersection." -> "As V1 entered the intersection, V2 struck V1.": a time
    clause said before what it times. A time clause on the main clause's participant as "it" ("V1 was turning
    when it was struck") takes the name, and the main clause the pronoun ("When V1 was struck, it was
    turning"), as a writer puts them: the name first."""
    m = _TRAILING.match(sentence)
    if m is None or not _one_event(m["main"]) or _PRONOUN.search(m["main"]):
        return sentence
    sub, main = m["sub"], m["main"]
    lead = re.match(r"(it|its) ", sub)
    if lead:
        # (the name with its kind, if said: "When V1, a 1996 Honda Civic, went ..., it was traveling")
        name = re.match(_NAME + r"(?:, an? [^,;]*,)?", main)
        if name is None or (lead[1] == "its" and name[0].endswith(",")):
            return sentence  # "the driver of V1 ... when it": the pronoun's participant is not the subject's
        sub = (name[0] if lead[1] == "it" else name[0] + "'s") + sub[len(lead[1]) :]
        main = "it" + main[len(name[0]) :]
    if _PRONOUN.search(re.sub(r"\bits\b", "", sub)):
        return sentence
    return f"{m['conj'].capitalize()} {sub}, {_lower_first(main)}."


_WHILE = re.compile(
    r"^(?P<name>" + _NAME + r"(?:, an? [^,;]*,)?) (?:was|were) (?P<ing>[a-z]+ing\b[^,;]*?),? when (?:it|he|she) "
    r"(?P<rest>" + _VERB + r"[^,;]*(?:, an? [^,;]*)?)\.$"
)


def while_participle(sentence: str) -> str:
    """ "V1 was attempting a U-turn when it was struck by V2." -> "While attempting a U-turn, V1 was struck by
    V2.": what a participant was doing when it met the event, said as a participle before it (the participle's
    subject is the sentence's)."""
    m = _WHILE.match(sentence)
    if m is None or not _one_event(m["ing"]) or _PRONOUN.search(re.sub(r"\bits\b", "", m["ing"] + m["rest"])):
        return sentence
    return f"While {m['ing']}, {m['name']} {m['rest']}."


_PLACE = re.compile(
    r"^(?P<prep>At|In|On) (?P<place>the (?:[\w/-]+ ){0,3}?(?:intersection|junction|roadway|road|street|lane|"
    r"driveway|crosswalk|curve)), (?P<main>" + _SUBJECT + r" [^;]*)\.$"
)


def place_after(sentence: str) -> str:
    """ "At the intersection, the front of V2 struck V1." -> "The front of V2 struck V1 at the intersection.": a
    place phrase said after the one event it places."""
    m = _PLACE.match(sentence)
    if m is None or not _one_event(m["main"]) or re.search(r"\b" + _CONJ + r"\b", m["main"]):
        return sentence
    return f"{_upper_first(m['main'])} {m['prep'].lower()} {m['place']}."


# An event (not a state) said of a participant: "V2 stopped at the sign", "the driver of V2 then steered left".
_EVENT = re.compile(r"^" + _SUBJECT + r"(?:, an? [^,;]*,)? (?:then )?(?!(?:was|were|had|need|used)\b)" + _VERB)


def join_after(text: str) -> str:
    """ "V2 stopped at the sign. V2 turned left." -> "After V2 stopped at the sign, V2 turned left.": an event
    told in a sentence of its own, said as the time clause of the next (the narrative's order is the events').
    Only a short sentence (at most 12 words) of one event, with no pronoun, is joined to the next event."""
    parts = _SENTENCE_END.split(text)
    out: list[str] = []
    i = 0
    while i < len(parts):
        a, b = parts[i], parts[i + 2] if i + 2 < len(parts) else ""
        if (
            b
            and a.endswith(".")
            and len(a.split()) <= 12
            and _EVENT.match(a)
            and _EVENT.match(b)
            and _one_event(a)
            and not _PRONOUN.search(a)
        ):
            out += [f"After {_lower_first(a[:-1])}, {_lower_first(b)}", parts[i + 3] if i + 3 < len(parts) else ""]
            i += 4
            continue
        out.append(a)
        i += 1
    return "".join(out)


# ---- what a participant is --------------------------------------------------------------------------------
# A kind: "a 1996 Honda Civic", "an unoccupied 2002 Ford F-150 pickup" (no phrase of place or relation).
_KIND = r"an? (?:(?!(?:in|of|on|at|to|by|with|from|behind|directly|which|that|was|were)\b)[\w/.-]+ ){0,6}?[\w/.-]+"
_ASIDE_KIND = re.compile(r"^(?P<name>" + _NAME + r"), (?P<kind>" + _KIND + r"), was (?P<ing>[a-z]+ing\b)")


def kind_which(sentence: str) -> str:
    """ "V1, a 1996 Honda Civic, was traveling east" -> "V1 was a 1996 Honda Civic, which was traveling east":
    the kind as what the participant was, its course in a relative clause."""
    m = _ASIDE_KIND.match(sentence)
    if m is None:
        return sentence
    return f"{m['name']} was {m['kind']}, which was {m['ing']}" + sentence[m.end() :]


_PREDICATE_KIND = re.compile(
    r"^(?P<name>" + _NAME + r") was (?P<kind>" + _KIND + r")"
    r"(?:,? (?:which|that) (?P<verb>was (?:[a-z]+ly )?[a-z]+ing|[a-z]+ed)|,? (?P<ing>[a-z]+ing))\b"
)


def kind_aside(sentence: str) -> str:
    """ "V1 was a 1996 Honda Civic, which was traveling east" / "... that turned left" / "... traveling east" ->
    "V1, a 1996 Honda Civic, was traveling east" / "... turned left": the kind as an aside."""
    m = _PREDICATE_KIND.match(sentence)
    if m is None or not re.search(r"\b(?:19|20)\d\d\b|\b[A-Z]", m["kind"]):
        return sentence  # "V1 was a vehicle that ...": only a stated make or model year is a kind
    verb = m["verb"] or f"was {m['ing']}"
    return f"{m['name']}, {m['kind']}, {verb}" + sentence[m.end() :]


# ---- what a participant is called --------------------------------------------------------------------------
# A participant introduced with its model year and make: "Vehicle #1, a 1996 Honda Civic", "V2 was a 1999 Ford".
_INTRODUCED = re.compile(
    r"(?P<name>" + ANY_NAME + r")(?:,| was) an? (?:[a-z][\w-]* ){0,2}(?:19|20)\d\d (?P<make>[A-Z][\w-]+)\b"
)


def make_names(text: str) -> str:
    """ "Vehicle #1, a 1996 Honda Civic, ... Vehicle #1 struck Vehicle #2" -> "... The Honda struck Vehicle #2":
    after its introduction a participant is called by its make, where no other road user has that make. (Its
    name in a label, "(Vehicle #1)", stays: the label says which the words are.)"""
    ids = renamed(lambda n: f"V{n}")
    makes: dict[str, tuple[str, int]] = {}
    for m in _INTRODUCED.finditer(text):
        makes.setdefault(ids(m["name"]), (m["make"], m.end()))
    unique = {
        pid: (make, at)
        for pid, (make, at) in makes.items()
        if [k for k, _ in makes.values()].count(make) == 1
        and len(re.findall(r"\b(?:an?|another) (?:[\w-]+ ){0,3}?" + make + r"\b", text)) == 1
    }

    def one(m: re.Match[str]) -> str:
        pid = ids(m.group())
        if pid not in unique or m.start() < unique[pid][1] or re.search(r"\(\s*$", text[: m.start()]):
            return m.group()
        if re.match(r",? \(", text[m.end() :]):
            return m.group()  # "Vehicle 1, (the Honda Pilot)": the report's own label follows
        return cased(f"the {unique[pid][0]}", text, m.start())

    return VEHICLE.sub(one, text)


def vehicle_ordinal(text: str) -> str:
    """ "V1 struck V2" -> "The first vehicle struck the second vehicle"."""

    def one(m: re.Match[str]) -> str:
        n = digit(m.group("v") or m.group("w") or m.group("u"))
        return cased(f"the {ORDINALS[n]} vehicle", text, m.start())

    return VEHICLE.sub(one, text)


def police_abbrev(text: str) -> str:
    """ "Vehicle #1 was traveling approximately 30 mph" -> "Veh. #1 was traveling approx. 30 mph": a police
    narrative's abbreviations (with their full stops inside a sentence)."""
    text = renamed(lambda n: f"Veh. #{n}")(text)
    return re.sub(r"\b([Aa])pproximately\b", r"\1pprox.", text)


def then_first(text: str) -> str:
    """ "V1 then turned left" -> "Then V1 turned left": "then" before the clause it orders."""
    return re.sub(
        r"(?:(?<=^)|(?<=[.!?])|(?<=[.!?] )|(?<=[.!?]  ))(?P<subject>" + _SUBJECT + r") then\b",
        lambda m: "Then " + _lower_first(m["subject"]),
        text,
    )


_FRONT_TO_REAR = re.compile(
    r"\b[Tt]he front of (?P<a>" + _NAME + r") (?:struck|impacted|hit|contacted) the (?:back|rear)(?: end| bumper)? of "
    r"(?P<b>" + _NAME + r")"
    r"|\b(?P<a2>" + _NAME + r") (?:struck|impacted|hit|contacted) the (?:back|rear)(?: end| bumper)? of "
    r"(?P<b2>" + _NAME + r") with its front\b"
)


def rear_ended(text: str) -> str:
    """ "The front of V1 struck the rear of V2" / "V1 impacted the rear of V2 with its front" -> "V1 rear-ended
    V2": a front-to-rear impact in its one word."""
    return _FRONT_TO_REAR.sub(lambda m: f"{m['a'] or m['a2']} rear-ended {m['b'] or m['b2']}", text)


def crashed_into(text: str) -> str:
    """ "V1 struck V2" -> "V1 crashed into V2": an impact in the active voice, in the plain word."""
    return re.sub(
        r"(?<!was )(?<!were )(?<!being )(?<!been )\b(?:struck|hit)(?= (?:the|V\d|" + _NAME + r"))", "crashed into", text
    )


def road_word(text: str) -> str:
    """ "the roadway" -> "the road": the plain word for the road's travelled way."""
    return re.sub(r"\b([Rr])oadway(s?)\b", r"\1oad\2", text)


def three_leg(text: str) -> str:
    """ "a T-intersection" -> "a three-leg intersection": a crash database's word for a junction of three legs."""
    return re.sub(r"\bT[- ]?intersection\b|'T' intersection\b", "three-leg intersection", text)


_SIDE = r"(?:(?:left|right|front|rear|back)(?:[- ](?:front|rear|side|corner|quarter|door|bumper))*(?: side)?)"
_PART_OF = re.compile(
    r"\b(?P<the>[Tt]he) (?P<part>" + _SIDE + r") of (?P<a>" + _NAME + r") (?P<verb>struck|impacted|hit|contacted) "
    r"(?P<b>(?:the " + _SIDE + r" of )?" + _NAME + r")(?=[.;]| in\b| at\b)"
)


def part_with(text: str) -> str:
    """ "The front of V1 struck the left side of V2" -> "V1 struck the left side of V2 with its front": the
    striking part said after the impact."""
    return _PART_OF.sub(lambda m: f"{m['a']} {m['verb']} {m['b']} with its {m['part']}", text)


_NOUN_PART = (
    r"(?:left|right|front|rear|back)(?:[- ](?:front|rear|side|corner|quarter|door|bumper|end))+|front|rear|back"
)
# (a part named by a noun: "in the left" is no English; and not before an aside on the vehicle, "the rear of V2, a
# parked car", which would then follow the part)
_STRUCK_PART = re.compile(
    r"\b(?P<verb>struck|impacted|hit|contacted) the (?P<part>" + _NOUN_PART + r") of "
    r"(?P<b>" + _NAME + r")(?![\w-])(?!,? \(?an? )"
)


def struck_in_side(text: str) -> str:
    """ "V1 struck the left side of V2" -> "V1 struck V2 in the left side": the struck part after its vehicle."""
    return _STRUCK_PART.sub(lambda m: f"{m['verb']} {m['b']} in the {m['part']}", text)


def stationary(text: str) -> str:
    """ "V2 was stopped at the light" -> "V2 was stationary at the light": a vehicle at a standstill (not "was
    stopped by the police": an agent makes it an event)."""
    return re.sub(r"\b(was|were) stopped\b(?! by\b)", r"\1 stationary", text)


def decelerated(text: str) -> str:
    """ "V2 slowed" / "was slowing" -> "V2 decelerated" / "was decelerating" (not "slowed down": "decelerated
    down" is no English; it is dropped)."""
    return re.sub(
        r"\b([Ss])low(ed|ing)(?: down)?\b(?! (?:traffic|vehicles?|cars?)\b)",
        lambda m: in_case_of(m[1], "decelerat") + ("ed" if m[2] == "ed" else "ing"),
        text,
    )


def lane_curb(text: str) -> str:
    """ "in the right lane" -> "in the curb lane": the rightmost lane, next to the curb (not "the right lane
    line", a line)."""
    return re.sub(r"\b(the|its|his|her) right(?:[- ]hand)? lane\b(?![\w-])(?! lines?\b)", r"\1 curb lane", text)
