"""Who did what: a report's sentences cut into pieces, each given to the participants it is about.

Police summaries name a participant as the subject of a clause ("V2 was traveling north") and then go on
with pronouns ("As he crossed the intersection he was contacted ...") or with other road users ("as a
non-contact school bus was slowing down to make a right turn"). A piece runs from one subject to the next:
- a participant named as an object ("behind V2", "struck V1", "the front of V2") does not start a piece;
- a sentence with no subject of its own (he, she, the driver) belongs to the last sentence's subject;
- another road user (a non-contact vehicle, traffic, an emergency vehicle) starts a piece that belongs to
  nobody, so its actions are not given to a participant;
- "both vehicles" and "the two vehicles" start a piece that belongs to every vehicle.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from sovarc.compiler.frontend.lexicon import BEFORE_OBJECT, struck

# Words right before a participant's name that make it an object, not the subject of what follows.
_OBJECT_BEFORE = re.compile(
    # (a preposition's object: "parked perpendicular to V1", "away from V1")
    r"(?:\b(?:by|with|behind|ahead of|in back of|of|than|to|from|toward|towards|into|onto|past|near|against|"
    + BEFORE_OBJECT
    + r"|avoid|see|saw|seen|observed|noticed|"
    r"detected|detecting|pass|passed|passing|enter|entered|entering|enters|crossed|crossing|"
    r"followed|following|around|alongside|beside|next to|approached|approaching|overtook|overtaking)|'s) "
    r"(?:the )?(?:(?:stationary|stopped|parked|standing|slowing|stopping) )?$",
    re.IGNORECASE,
)
_SUBJECT_OF = re.compile(
    r"\b(?:driver|operator|occupant)s? of (?:the )?$"
    # a part in subject position is its vehicle acting: "..., the front driver side of V2 made contact with"
    r"|(?:^|[,;] |\b(?:when|while|then|as) )(?:the|its) (?:[\w-]+ ){0,3}(?:front|rear|side|bumper|corner|end)"
    r" of (?:the )?$",
    re.IGNORECASE,
)
# Other road users: what follows them, up to the next participant, is not a participant's doing.
_OTHER = re.compile(
    r"\b(?:an?|another|the|other|one|several)\s+(?:(?:non-?contact|uninvolved|other|third|emergency|unknown|"
    r"unidentified|lead|leading|school|fire|police)\s+)+(?:[\w-]+\s+){0,2}?(?P<noun>vehicles?|cars?|trucks?|"
    r"bus(?:es)?|vans?|pickups?|motorists?|drivers?|motorcycles?|tractor-trailers?|semis?)\b"
    # "a slower traveling van", "another white sedan": one not numbered is none of the participants
    r"|(?<!\bwas )(?<!\bis )(?<!\bas )\b(?:an?|another)\s+(?:[a-z][a-z-]*\s+){0,2}?(?:vehicles?|cars?|trucks?|vans?|"
    r"suvs?|sedans?|pickups?|motorists?|buses)\b(?! (?:involved|[VP]\d))"
    r"|\bthe vehicles? (?:traveling |travelling )?(?:directly )?(?:in front|ahead)\b"
    # (not the flow a vehicle joins: "attempting to enter traffic", "merged into the flow of traffic"; nor the
    # one it goes against or into on the wrong side: "drove against traffic", "veered into oncoming traffic")
    r"|\b(?<!enter )(?<!entered )(?<!entering )(?<!enters )(?<!flow of )(?<!into )(?<!against )"
    r"(?<!into oncoming )(?<!into opposing )(?<!against oncoming )(?:vehicles|traffic)\b"
    r"(?! (?:signal|light|control|device|lane|way|island|count|volume))",
    re.IGNORECASE,
)
# An object described on the spot is the subject of the description: "struck V2, a 2000 Honda that was
# traveling north", "restricted by V2 making the right turn".
# So is one said in a state: "approached V2 stopped in the left lane", "passed V2 double parked".
_ASIDE = re.compile(
    # (not "passed V1 using the opposing lane": a preposition in -ing says how the subject did it)
    r", (?:an?|the) |,? (?:(?:an?|the) (?:[\w-]+ )*?\d{4}\b|(?:which|that|who)\b"
    r"|(?!(?:using|including|during|regarding|according|concerning)\b)\w+ing\b"
    r"|(?:double[- ])?(?:stopped|parked|stationary)\b)"
)
_BOTH = re.compile(r"\b(?:both|the two) (?:vehicles|drivers|cars)\b", re.IGNORECASE)
# Where a clause about another road user gives way to the subject's again: "stopped for traffic, then turned".
# A pronoun that begins a clause means a participant, not the other road user: "yielding to traffic as it
# prepared to turn", "yielding to approaching traffic, it stopped".
_CLAUSE_END = re.compile(
    r",? (?:and )?then\b|;|(?:,|,? (?:as|when|while|until|and|so|before|after)) (?=(?:it|he|she)\b)", re.I
)
# Another road user as a preposition's object ("yielding for traffic", "stopped behind a truck"): its clause
# ends where the subject's next verb is brought in by "and".
_GOVERNED = re.compile(r"\b(?:for|to|behind|from|past|around|of)\s+(?:[\w-]+\s+){0,2}$", re.I)
_OBJECT_CLAUSE_END = re.compile(
    _CLAUSE_END.pattern + r"|,? and (?=(?:then )?(?:came|began|went|made|took|[a-z]+ed)\b)", re.I
)
# A sentence about the place, not about a participant: "The roadway had ...", "It was dark".
_SCENE = re.compile(
    r"(?:the|this|that|both|each) (?:\w+ ){0,2}?(?:road(?:way)?s?|streets?|highways?|intersections?|lanes?|weather|"
    r"speed limits?|crash|collision|area|approach(?:es)?|median|shoulder|signal|light|sign)\b"
    # (not "It was rear-ended by V2": an impact said of "it" is about the one named before, not the place)
    r"|(?:it|there) (?:was|were|is|are)\b(?! (?:then |\w+ly )?" + struck() + r"\b)|conditions\b",
    re.IGNORECASE,
)
_NAME = re.compile(r"\b[VP]\d\b")
# An opening participle with no subject of its own ("While attempting to pass V1, V2 made contact", "After
# stopping, V2 began moving"): English gives it the subject of the clause it opens.
_OPENING_PARTICIPLE = re.compile(
    r"^(?:(?:while|when|after|before|upon|on|since|once|just after|just before) )?(?:\w+ly )?"
    r"(?!(?:during|including|regarding|according|concerning|following|considering|pending)\b)[a-z]+ing\b[^,;.]*, ",
    re.IGNORECASE,
)


@dataclass(frozen=True)
class Piece:
    who: tuple[str, ...]  # empty: another road user's doing
    text: str
    at: int  # offset in the report's sentences joined by one space, for ordering
    sentence: int  # index of its sentence
    context: str  # the whole sentence


def is_object(sentence: str, at: int) -> bool:
    """Whether the participant named at `at` is an object ("behind V2", "struck V1"), not a subject."""
    before = sentence[max(0, at - 40) : at]
    return bool(_OBJECT_BEFORE.search(before)) and not _SUBJECT_OF.search(before)


# After an object that ends a fronted phrase, ", a passenger car was ..." is the main clause's subject and its
# verb, not the object described ("In the lane ahead of V1, a passenger car was double parked").
_MAIN_SUBJECT = re.compile(r",? (?:an?|the) (?:[\w-]+ ){0,3}?(?:was|were|had|is|are)\b")


def _fronted_main(sentence: str, at: int) -> bool:
    """Whether the name ending at `at` ends a fronted phrase and ", a passenger car was" follows: the main
    clause's subject, not the name described."""
    return bool(
        "," not in sentence[:at]
        and re.match(r"(?:In|On|At|Ahead|Behind|Near|Along)\b", sentence)
        and _MAIN_SUBJECT.match(sentence, at)
    )


# A road user placed by its subject's place ("V2 ahead of V1 stopped abruptly"): "stopped" after it is the
# subject's verb, not a state said of the one placed by (as in "approached V1 stopped in the lane").
_PLACED_BY = re.compile(r"\b[VP]\d (?:directly |immediately )?(?:ahead of|in front of|behind|beside|next to) $")


def _subject_stopped(sentence: str, start: int, end: int) -> bool:
    return bool(_PLACED_BY.search(sentence[:start]) and re.match(r" stopped\b", sentence[end:]))


def _events(sentence: str, ids: list[str], others: re.Pattern[str] | None) -> list[tuple[int, tuple[str, ...]]]:
    """Where a piece starts in the sentence, and whose it is; `others` names the road users met before."""
    found: list[tuple[int, tuple[str, ...]]] = []
    for m in _NAME.finditer(sentence):
        if m.group() in ids and (
            not is_object(sentence, m.start())
            or (
                _ASIDE.match(sentence, m.end())
                and not _fronted_main(sentence, m.end())
                and not _subject_stopped(sentence, m.start(), m.end())
            )
        ):
            found.append((m.start(), (m.group(),)))
    vehicles = tuple(pid for pid in ids if pid.startswith("V"))
    found += [(m.start(), vehicles) for m in _BOTH.finditer(sentence)]
    # Another road user right after a participant's name is an apposition ("V2, an unknown type van").
    groups = [m.span() for m in _BOTH.finditer(sentence)]

    def apposition(at: int) -> bool:
        name = re.search(r"\b[VP]\d(?=,? ?$)", sentence[:at])
        return name is not None and not _fronted_main(sentence, name.end())

    found += [
        (m.start(), ())
        for pattern in (_OTHER, others)
        if pattern is not None
        for m in pattern.finditer(sentence)
        if not apposition(m.start()) and not any(a <= m.start() < b for a, b in groups)
    ]
    return sorted(set(found))


def _met(sents: list[str]) -> re.Pattern[str] | None:
    """ "the bus" after "a non-contact school bus": another road user named again by its noun."""
    nouns = {m.group("noun").lower() for s in sents for m in _OTHER.finditer(s) if m.group("noun")}
    nouns -= {"vehicle", "vehicles", "traffic", "car", "cars", "driver", "drivers"}  # too general to name one
    if not nouns:
        return None
    return re.compile(r"\b[Tt]he (?:" + "|".join(sorted(map(re.escape, nouns))) + r")\b")


def pieces(sents: list[str], ids: list[str]) -> list[Piece]:
    """Every sentence cut at each subject, each piece given to whom it is about (see the module's note)."""
    out: list[Piece] = []
    carry: tuple[str, ...] = ()
    offset = 0
    others = _met(sents)
    for index, sentence in enumerate(sents):
        events = _events(sentence, ids, others)
        who, start = (() if _SCENE.match(sentence) else carry), 0
        for at, whom in list(events):
            # other road users said in a "with" phrase ("with vehicles parked at the curb, and came to a stop")
            # are an aside: the subject's clause resumes after it
            aside = not whom and re.search(r"\bwith (?:\w+ ){0,2}$", sentence[:at])
            if aside and (comma := sentence.find(",", at)) >= 0:
                events.append((comma + 1, next((w for a, w in reversed(events) if a < at and w), carry)))
                continue
            # (and one that is a preposition's object ends where "and" brings in the subject's next verb:
            # "began yielding for approaching traffic and came to a stop")
            ends = _CLAUSE_END if not _GOVERNED.search(sentence[:at]) else _OBJECT_CLAUSE_END
            if not whom and (end := ends.search(sentence, at)):  # another road user's clause ends here
                back = next((w for a, w in reversed(events) if a < at and w), carry)
                events.append((end.end(), back))
        events.sort()
        opening = _OPENING_PARTICIPLE.match(sentence)
        main = next(((a, w) for a, w in events if w and opening and a >= opening.end()), None)
        if opening and main and main[0] == opening.end() and not any(a < main[0] for a, _ in events):
            who = main[1]
        for at, whom in events:
            if at > start and sentence[start:at].strip():
                out.append(Piece(who, sentence[start:at], offset + start, index, sentence))
            who, start = whom, at
        out.append(Piece(who, sentence[start:], offset + start, index, sentence))
        # The sentence's first participant is whom the next sentence's "he" or "the driver" means.
        carry = next((whom for _, whom in events if whom), carry)
        offset += len(sentence) + 1
    return out


def by_participant(parts: list[Piece], ids: list[str]) -> dict[str, list[Piece]]:
    """Each participant's pieces, in report order."""
    return {pid: [p for p in parts if pid in p.who] for pid in ids}
