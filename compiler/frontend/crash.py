"""Who struck whom, and how, from the sentence of the first impact.

A police summary names the parts that met: "the front of V2 struck the left side of V1", "V1 was struck in
the right side by the front of V2", "V1's front impacted V2's rear", "V1 struck V2 in rear with front".
Each part is tied to a participant. The striker is the agent of a passive strike ("by the front of V2"),
else the subject of an active one, else the one whose front met the other's side or rear. The crash type is
the victim's part: its side (side), its rear (rear_end) or its front (frontal).
"""

from __future__ import annotations

import re
from dataclasses import replace

from sovarc.compiler.frontend.clauses import is_object
from sovarc.compiler.frontend.lexicon import (
    BEFORE_OBJECT,
    DIRECT,
    IMPACT_VERBS,
    INTO_ANYTHING,
    Form,
    forms,
    striking,
    struck,
)
from sovarc.compiler.frontend.words import PLACE_WORDS
from sovarc.dsl.ir import UNKNOWN, Crash, CrashType

_V = r"(?:[VP]\d)"
# A part named in the plural is the same part ("the front and rear passenger doors", "its rear wheels").
_WORD = (
    r"(?:left|right|center|centre|front|frontal|rear|back|side|end|bumpers?|corners?|plane|doors?|fenders?|wheels?|"
    r"tires?|quarter|panels?|drivers?'?s?|passenger'?s?|area|portion|section|part|sensors?|housing|"
    r"(?:rearview |side )?mirrors?|cab|hood|grille|headlights?|trunk|tailgate|taillights?|hatch)"
)
_PART = _WORD + r"(?:[- ]" + _WORD + r"){0,3}"
# A verb of motion into a road user or a part of one is a strike: "reversed at low speed into the rear bumper of
# V1", "backed into V1", "rode into the front bumper of V1" (not "drove into the intersection", "into V1's lane").
MOVED_INTO = (
    r"(?:back(?:ed|ing)|revers(?:ed|ing)|roll(?:ed|ing)|rode|riding|drove|driving|ran|running|collided|colliding"
    r"|crashed|crashing|slid|sliding|moved|moving)(?: [\w-]+){0,8}? into"
    r"(?= (?:the |its |his |her )?(?:(?:stationary|stopped|parked) )?[VP]\d\b(?!'s (?:lane|path))"
    r"| (?:the |its |his |her |[VP]\d's )?" + _PART + r"\b(?! (?:lane|path)))"
)
# An active strike (`lexicon.striking`: glancing blows too, "sideswiped", "brushed against"), or a move into a
# road user or a part of one.
_STRIKE = "(?:" + striking() + "|" + INTO_ANYTHING + "|" + MOVED_INTO + ")"
# the participles of a passive strike
_STRUCK = struck()
# the "-ing" form of a strike that takes its object straight after it ("striking its rear bumper")
_STRIKING = forms((Form.ING,), DIRECT)
# "the rear of the stationary V1": a state said of the owner
_STATE = r"(?:(?:stationary|stopped|parked|standing|slowing|stopping) )?"
_OWNED = [
    # the front of V2 (but not "in front of V1")
    re.compile(
        r"(?<!\bin )(?<!\bin the )\b(?P<part>" + _PART + r") of (?:the )?" + _STATE + r"(?P<v>" + _V + r")\b", re.I
    ),
    re.compile(r"\b(?P<v>" + _V + r")'s (?P<part>" + _PART + r")\b", re.I),  # V2's rear
    # V2 in the left side, V1 was struck on the right side
    # (not "passed V1 on the left": a bare side after a verb that is no strike is where it passed)
    re.compile(
        r"\b(?P<v>" + _V + r")(?: was| were)?(?: \w+ed)? (?:in|on) (?:the |its |his |her )?"
        r"(?P<part>(?!(?:left|right)\b(?![- ]" + _WORD + r"))(?!front of\b)" + _PART + r")\b",
        re.I,
    ),
]
# "with its front", "its front was struck", "contacting it's front to": the clause's subject.
_OWN_PART = re.compile(
    # (not "made contact with the front of V1": that part is the object's)
    # nor "made contact with its front": "with" that a contact verb takes names the object
    r"(?<!contact )(?<!collided )(?<!collision )\b(?:with|using) (?:its |his |her |it's |the )?(?P<part>"
    + _PART
    + r")\b"
    r"(?![- ](?:" + _WORD + r"|of)\b)"
    r"|\b(?:its|his|her|it's) (?P<part2>" + _PART + r") (?:was|were) " + _STRUCK,
    re.I,
)
# "its" after a contact, after a strike's participle ("struck V1, striking its rear bumper"), or after a strike's
# object ("struck V1 at its rear bumper") is the object's
# (not "contacting it's front to the left side of V2": a part the subject puts to the other is its own)
_OBJECT_ITS = re.compile(
    r"\b(?:(?:contact|collided|collision) with|"
    + _STRIKING
    + "|"
    + BEFORE_OBJECT
    + " (?:the )?"
    + _V
    + r",? (?:at|in|on))"
    r" (?:its|his|her|it's) (?P<part>" + _PART + r")\b(?![- ]" + _WORD + r"\b)(?! (?:to|into|against|with)\b)",
    re.I,
)
_AGENT = re.compile(
    r"\b" + _STRUCK + r"\b[^.;]{0,60}?\bby (?:the )?(?:(?:" + _PART + r") of (?:the )?)?"
    r"(?P<v>" + _V + r")\b",
    re.I,
)
_AGENT_OWNED = re.compile(r"\b" + _STRUCK + r"\b[^.;]{0,60}?\bby (?P<v>" + _V + r")'s\b", re.I)
_ACTIVE = re.compile(r"\b" + _STRIKE + r"\b(?! by)", re.I)
_PRONOUN_ACTIVE = re.compile(r"\b(?:it|he|she)\b (?:then |\w+ly )?" + _STRIKE + r"\b(?! by)", re.I)
_PASSIVE = re.compile(r"\b(?:was|were|is|got|been) (?:\w+ )?" + _STRUCK + r"\b", re.I)
_PATIENT = re.compile(r"\b(?P<v>" + _V + r")\b (?:was|were) (?:\w+ )?" + _STRUCK + r" by [^.;,]*$", re.I)
_REAR_ENDED = re.compile(r"\b(?P<a>" + _V + r") rear-ended (?:the )?" + _STATE + r"(?P<b>" + _V + r")\b", re.I)
_UNTIED_PART = re.compile(r"\b(?:front|rear|side|bumper|corner|end)\b", re.I)
_HEAD_ON = re.compile(r"\bhead[- ]on\b", re.I)
# The striker came from behind the victim: "from behind", "from the rear", "V2 behind V1", "V2 traveling directly
# behind": one that meets another it follows meets its rear, whatever part of it the report names ("the bumper").
_FROM_BEHIND = re.compile(r"\bfrom (?:behind|the rear)\b", re.I)
_FOLLOWER = (
    r"\b{},? (?:(?:that|which) )?(?:(?:was|were|had been) )?(?:\w+ing )?(?:directly |right |immediately |closely )?"
    r"behind\b"
)
# Failing to avoid a contact states it ("was unable to avoid contact with V2", "could not avoid striking V2");
# only avoiding it denies it, which `text` reads as no impact.
_NOT_AVOIDED = re.compile(
    r"\b(?:(?:was|were) unable to|failed to|could not|couldn't|did not|didn't) (?:fully )?avoid "
    r"(?P<met>(?:making )?contact with|a collision with|" + striking((Form.ING,)) + ")",
    re.I,
)
# the "-ing" form of each verb of impact, and its past (a compound in each spelling: "side-swiping", "sideswiping")
_PAST_OF_ING = {
    v.ing.replace("-", j): v.past.replace("-", j) for v in IMPACT_VERBS if " " not in v.base for j in ("-", "", " ")
}


def _made(met: str) -> str:
    """The strike not avoided, said in the past: "striking" -> "struck", "colliding with" -> "collided with"."""
    low = met.lower()
    ing = next((w for w in sorted(_PAST_OF_ING, key=len, reverse=True) if low.startswith(w)), None)
    return _PAST_OF_ING[ing] + met[len(ing) :] if ing else "made contact with"


_RIGHT_ANGLE = re.compile(r"\bright angle\b|\bbroadside|\bt-?boned?\b", re.I)


# Parts that are one end of a vehicle, or one side of it, whatever words go with them.
_FRONT_PARTS = frozenset(("front", "frontal", "cab", "hood", "grille", "headlight", "headlights"))
_REAR_PARTS = frozenset(("rear", "back", "trunk", "tailgate", "taillight", "taillights", "hatch"))
_SIDE_PARTS = frozenset(("side", "door", "panel", "fender", "quarter", "mirror"))
_SINGULAR = {f"{w}s": w for w in ("bumper", "corner", "door", "fender", "wheel", "tire", "panel", "mirror")}


def _kind(part: str) -> CrashType | None:
    """The crash type a part says when the victim's: an end (frontal, rear_end) or a side.

    The words before the head noun say where on it: "the right front side" and "the left front" are a side
    (its front half), as the labelled reports have it. A part named first by an end is that end's corner, and a
    corner is the end that met, as NHTSA codes it (Front Right, Rear Left): "the front passenger side", "the
    rear left sensor"; so is an end's bumper or corner named from a side ("the driver side front corner"), and
    an end named after a side ("the driver's side rear"). A door or a mirror is the side whatever end it is
    near: neither is at a corner."""
    low = part.lower()
    words = [_SINGULAR.get(w, w) for w in re.split(r"[- ]", low)]
    said = set(words)
    if said & {"door", "mirror", "rearview"}:
        return CrashType.SIDE
    if "cab" in said:  # a truck's cab is its front, whichever of its sides met ("the driver side of the cab")
        return CrashType.FRONTAL
    ends = [w for w in words if w in _FRONT_PARTS or w in _REAR_PARTS]
    corner = said & {"corner", "bumper"} or re.search(
        r"\bside[- ](?:front|rear|back)(?:[- ](?:section|portion|part|area|end))?$", low
    )
    if ends and (words[0] in ends or corner):
        return CrashType.FRONTAL if ends[0] in _FRONT_PARTS else CrashType.REAR_END
    if said & _SIDE_PARTS or ("plane" in said and not ends):
        return CrashType.SIDE
    if ends:  # "the left rear", "the right front": no side noun, the end is what is named
        return CrashType.FRONTAL if ends[0] in _FRONT_PARTS else CrashType.REAR_END
    if "end" in said:
        return CrashType.REAR_END
    if said <= {"left", "right"}:  # "the front of V2 contacted the left of V1"
        return CrashType.SIDE
    return None


# For readers of a part said elsewhere (`damage`): the words of a part, and what it says when the victim's.
PART = _PART
part_kind = _kind


def _names(text: str) -> list[str]:
    return re.findall(r"\b" + _V + r"\b", text)


# A part after a preposition of way is where a move went, not a part met: "around the left side of V1".
_WAY = re.compile(r"\b(?:around|past|along|alongside|beside|toward|towards) (?:the )?$", re.I)


def _parts(sentence: str, subject: str | None) -> list[tuple[int, str, CrashType]]:
    """(where, whose, what part) for every part the sentence ties to a participant."""
    parts: list[tuple[int, str, CrashType]] = []
    for pattern in _OWNED:
        for m in pattern.finditer(sentence):
            # "to the right of V1", "on the left of V2": where something was, not a part of it
            if m.group("part").lower() in ("left", "right") and re.search(
                r"\b(?:to|on|at) (?:the )?$", sentence[: m.start("part")], re.I
            ):
                continue
            # "passing V1 on the left side": the side it passed by, as with a bare side (see `_OWNED`)
            if pattern is _OWNED[2] and re.search(
                r"\bpass(?:ed|es|ing)?(?: by)? (?:the )?(?:\w+ )?$", sentence[: m.start()]
            ):
                continue
            # "maneuvered around the left side of V1", "passed along the driver side of V1": the way it went
            if _WAY.search(sentence[: m.start()]):
                continue
            who = m.group("v")
            # "V2 was struck by V1 in the left side": where a passive's agent struck is on the one struck
            by = pattern is _OWNED[2] and re.search(r"\bby $", sentence[: m.start()])
            if by and (patient := _PATIENT.search(sentence[: m.start()])):
                who = patient.group("v")
            if (kind := _kind(m.group("part"))) is not None:
                parts.append((m.start(), who, kind))
    agent = _AGENT.search(sentence) or _AGENT_OWNED.search(sentence)
    for m in _OWN_PART.finditer(sentence):
        kind = _kind(m.group("part") or m.group("part2"))
        # "V2 was struck by V1 in the left side with its front": what a strike is made with is the striker's, and
        # a passive names the striker as its agent
        owner = agent.group("v") if agent and m.group("part") and agent.end() <= m.start() else subject
        if owner is not None and kind is not None:
            parts.append((m.start(), owner, kind))
    for m in _OBJECT_ITS.finditer(sentence):
        # "V2 ... made contact with its front passenger side": "its" is the other one named, not the subject
        # (the subject of the contact is the last one named before it as a subject: not "V1" in "V2 reversed
        # into V1, making contact with its front bumper", whose "its" is V1's)
        before = [
            n.group() for n in re.finditer(r"\b" + _V + r"\b", sentence[: m.start()]) if _subject_like(sentence, n)
        ]
        owner = next((n for n in _names(sentence) if before and n != before[-1]), None)
        if owner is not None and (kind := _kind(m.group("part"))) is not None:
            parts.append((m.start("part"), owner, kind))
    return sorted(set(parts))


_SIDE_WORD = {"left": "left", "driver": "left", "drivers": "left", "right": "right", "passenger": "right"}


def sides_met(sentence: str) -> dict[str, str]:
    """Each participant's side ("left" or "right") that the impact sentence names a part on: "the driver side of
    V1", "V2's front passenger corner" (a car is driven from the left, so its driver side is its left). Only
    parts tied to their owner by "of" or "'s", the first one each, and none that names both sides."""
    found: dict[str, str] = {}
    for pattern in _OWNED[:2]:
        for m in pattern.finditer(sentence):
            sides = {_SIDE_WORD[w] for w in re.split(r"[- ']+", m.group("part").lower()) if w in _SIDE_WORD}
            if len(sides) == 1 and m.group("v") not in found:
                found[m.group("v")] = sides.pop()
    return found


def agent_named(sentence: str) -> bool:
    """Whether the sentence names its striker as the agent of a passive strike ("struck by the front of V1")."""
    return bool(_AGENT.search(sentence) or _AGENT_OWNED.search(sentence))


def _leads(who: str, kind: CrashType, backing: frozenset[str]) -> bool:
    """Whether the part is the end its vehicle moved with: the front, or the rear of one backing."""
    return kind is (CrashType.REAR_END if who in backing else CrashType.FRONTAL)


def _striker(
    sentence: str, subject: str | None, parts: list[tuple[int, str, CrashType]], backing: frozenset[str]
) -> str | None:
    if agent := _AGENT.search(sentence) or _AGENT_OWNED.search(sentence):
        return agent.group("v")
    leading = [who for _, who, kind in parts if _leads(who, kind, backing)]
    led = {who for _, who, kind in parts if not _leads(who, kind, backing)}
    if len(set(leading)) == 1 and led and leading[0] not in led:  # a leading end met the other's side or end
        return leading[0]
    fronts = [who for _, who, kind in parts if kind is CrashType.FRONTAL]
    others = {who for _, who, kind in parts if kind is not CrashType.FRONTAL}
    # "V2 ... made contact with the front of V1": the only part named is the object's front, so the front
    # that met the other is the object's (a front-to-front meeting would name both fronts, or say head-on);
    # not when the subject's own part is said in words not tied to it ("his vehicle's right front", "with its")
    hit = _ACTIVE.search(sentence)
    said = hit and (_UNTIED_PART.search(sentence[: hit.start()]) or _OWN_PART.search(sentence))
    if hit and not said and not others and len(set(fronts)) == 1 and all(at > hit.end() for at, _, _ in parts):
        named = [n.group() for n in re.finditer(r"\b" + _V + r"\b", sentence[: hit.start()])]
        # (a subject backing into the object's front met it with its rear: it is the striker, below)
        if named and named[-1] != fronts[0] and named[-1] not in backing and not _HEAD_ON.search(sentence):
            return fronts[0]
    for m in _ACTIVE.finditer(sentence):  # the subject of an active strike: the last one named before it
        named = [n for n in re.finditer(r"\b" + _V + r"\b", sentence[: m.start()]) if _subject_like(sentence, n)]
        if named and not _PASSIVE.search(sentence, max(0, m.start() - 12), m.end()):
            return named[-1].group()
    if _PRONOUN_ACTIVE.search(sentence) and subject is not None:
        return subject
    if front := next((w for w in fronts if w not in others), None):
        return front
    # "his vehicle ... before contacting the right rear corner of V2": the sentence's subject struck
    return subject if others and subject is not None and subject not in others else None


def _subject_like(sentence: str, name: re.Match[str]) -> bool:
    """A name that can be the subject of a strike: not an object ("pass V2"), except as "the front of V2"."""
    owner = re.search(r"(?<!\bin )\b" + _PART + r" of (?:the )?$", sentence[: name.start()], re.I)  # not "in front of"
    # (not "toward the right side of V1": the part a move heads for or goes around is the way, see `_parts`)
    if owner is not None and _WAY.search(sentence[: owner.start()]):
        return False
    return owner is not None or not is_object(sentence, name.start())


# A trailer, a truck body or a cab is part of the vehicle: "the passenger side of the trailer of V2", "its trailer
# (the right side, rear section)", "the driver side of V1 cab". A trailer's sides and rear are its vehicle's.
_BODY = r"(?:[\w-]+ ){0,2}?(?:trailer|truck body)"
_BODY_OF = re.compile(
    r"\b(?:the |a )?" + _BODY + r" (?:of|attached to|towed by|pulled by) (?:the )?(" + _V + r")\b", re.I
)
_ITS_BODY = re.compile(r"\b(?:its|his|her|their) " + _BODY + r"(?: \((?:the )?([^)]*)\))?", re.I)
_THE_BODY = re.compile(r"\bthe " + _BODY + r"\b", re.I)
_CAB_OF = re.compile(r"\bof (" + _V + r")(?:'s)? cab\b", re.I)
# "V2 and trailer", "V2 towing a flat-bed trailer": whose "the trailer" is when the sentence does not say
_TOWING = re.compile(r"\b(" + _V + r"),? (?:and|with|towing|pulling|hauling) (?:an? |its |the )?" + _BODY, re.I)


def towing(sents: list[str]) -> str | None:
    """The one participant the report says tows a trailer, if one does."""
    found = {m.group(1) for s in sents for m in _TOWING.finditer(s)}
    return next(iter(found)) if len(found) == 1 else None


def _bodies(sentence: str, subject: str | None, tower: str | None) -> str:
    """The sentence with each trailer, truck body or cab said as the vehicle it belongs to (see `_BODY`)."""
    sentence = _CAB_OF.sub(r"cab of \1", sentence)
    sentence = _BODY_OF.sub(r"\1", sentence)
    if subject is not None:
        sentence = _ITS_BODY.sub(
            lambda m: f"the {m.group(1).replace(',', '')} of {subject}" if m.group(1) else subject, sentence
        )
    return _THE_BODY.sub(tower, sentence) if tower is not None else sentence


def read_sentence(
    sentence: str, carry: str | None = None, tower: str | None = None, backing: frozenset[str] = frozenset()
) -> Crash | None:
    """The crash one sentence states, or None; `carry` is whom the sentence's pronouns mean when it names
    no participant before them, `tower` the participant the report says tows a trailer, `backing` those
    backing at the impact, which lead with their rear (see `_backed`)."""
    # "rear ended", "rear-ending": one verb however it is spelt
    sentence = re.sub(r"\brear[- ]end(ed|ing)\b", r"rear-end\1", sentence, flags=re.I)
    # An impact its subject could not avoid is one it made: "V1 ... was unable to avoid contact with V2"
    sentence = _NOT_AVOIDED.sub(lambda m: _made(m.group("met")), sentence)
    # A sentence opening on a pronoun is about the one it carries on with ("V1 stopped. It then proceeded to turn
    # and struck V2"): the pronoun is that participant, the subject of every verb it heads.
    if carry is not None and (opening := re.match(r"(?:It|He|She)\b(?!')", sentence)):
        sentence = carry + sentence[opening.end() :]
    # Whom "it", "its" and "with its front" mean: the first one named, unless a pronoun comes before it.
    first = re.search(r"\b" + _V + r"\b", sentence)
    pronoun = re.search(r"\b(?:it|he|she|its|his|her|it's)\b", sentence, re.I)
    subject = first.group() if first and (pronoun is None or first.start() < pronoun.start()) else carry
    sentence = _bodies(sentence, subject, tower)
    names = _names(sentence)
    if m := _REAR_ENDED.search(sentence):
        return Crash(CrashType.REAR_END, m.group("a"), m.group("b"))
    parts = _parts(sentence, subject)
    striker = _striker(sentence, subject, parts, backing)
    head_on = _HEAD_ON.search(sentence) is not None
    if striker is None:
        if head_on:
            return Crash(CrashType.FRONTAL)
        return Crash(CrashType.SIDE) if _RIGHT_ANGLE.search(sentence) and not parts else None
    victims = [(who, kind) for _, who, kind in parts if who != striker]
    if victims:
        victim, kind = victims[0]
        return Crash(CrashType.FRONTAL if head_on else _backed(kind, striker in backing), striker, victim)
    others = [n for n in names if n != striker]
    victim = others[0] if others else (subject if subject != striker else None)
    if victim is None:  # a single vehicle that struck something with its front ("struck a tree with its front")
        own = [kind for _, who, kind in parts if who == striker]
        return Crash(CrashType.FRONTAL, striker) if own == [CrashType.FRONTAL] else None
    if _FROM_BEHIND.search(sentence) or re.search(_FOLLOWER.format(striker), sentence, re.I):
        return Crash(CrashType.REAR_END, striker, victim)
    kind = CrashType.FRONTAL if head_on else _said_part(sentence)
    # "V2 ... made contact with the front of V1": V2 came across V1's path, so V1's front met its side
    hit = _ACTIVE.search(sentence)
    only_front = parts and all(w == striker and k is CrashType.FRONTAL for _, w, k in parts)
    if kind is None and hit and only_front and all(at > hit.end() for at, _, _ in parts):
        kind = CrashType.SIDE
    if kind is None and re.search(r"\brear-end(?:ed|ing|s)?\b", sentence, re.I):  # "before rear-ending V1"
        kind = CrashType.REAR_END
    if kind is None and re.search(r"\bside-?swip", sentence, re.I):  # a sideswipe is side against side
        kind = CrashType.SIDE
    return Crash(kind, striker, victim) if kind is not None else Crash(striker=striker, victim=victim)


def _backed(part: CrashType, backing: bool) -> CrashType:
    """The crash type when the victim's `part` was met: for a striker backing, which leads with its rear, the
    IR's type reads with front and rear swapped (its rear into the victim's front is `rear_end`, into its rear
    `frontal`; a side stays a side), as the lowering and every oracle read it."""
    if not backing or part is CrashType.SIDE:
        return part
    return CrashType.REAR_END if part is CrashType.FRONTAL else CrashType.FRONTAL


backed = _backed


def _said_part(sentence: str) -> CrashType | None:
    """The victim's part said without naming it again: "it was struck in the right side by the front of V2",
    or as the subject of the passive strike, its owner the clause before: "V1 turned left and the right side
    was struck by the front of V2"."""
    m = re.search(r"\b(?:struck|hit|impacted|contacted) (?:in|on) (?:the |its )?(" + _PART + r")\b", sentence, re.I)
    m = m or re.search(
        r"\b(?:the|its) (" + _PART + r") (?:was|were) (?:\w+ly )?(?:struck|hit|impacted|contacted)\b", sentence, re.I
    )
    return _kind(m.group(1)) if m else None


# "V2 was rear-ended by V3, causing the front of V2 to make contact with the rear of V1": a chain collision.
_PUSHED = re.compile(r"\b(?:causing|pushing|forcing|propelling|which pushed|which caused) (?P<rest>[^.;]*)", re.I)
_TO_MEET = re.compile(r"\bto (?:make contact|strike|hit|collide|contact|impact|rear-end)", re.I)
_MET = {"make contact": "made contact", "strike": "struck", "hit": "hit", "collide": "collided", "contact": "contacted"}


def _pushed_into_v1(sentence: str, crash: Crash, tower: str | None) -> Crash:
    """In a chain collision the automated vehicle's crash, the IR's subject, is the contact it is in: when the
    first impact does not involve V1 and the sentence says it pushed one of them into V1, that contact."""
    if "V1" in (crash.striker, crash.victim) or not (m := _PUSHED.search(sentence)):
        return crash
    rest = _TO_MEET.sub(lambda t: _MET.get(t.group()[3:].lower(), t.group()[3:]), m.group("rest"))
    pushed = read_sentence(rest, None, tower)
    return pushed if pushed is not None and "V1" in (pushed.striker, pushed.victim) else crash


# "V2 behind V1 was rear-ended by V3, and V2 then made contact with the rear of V1": two meetings told one after
# the other; where the first names V1 only as where another was (see `names.PLACE`), V1's is the one after it.
_THEN_AND = re.compile(r",? and (?=(?:then )?(?:the |its )?\w)|; ", re.I)
_WHEN = re.compile(r"^(?:\w+ )?(?:after|when|as|while|before|once)\b[^,]*, ", re.I)
V1_PLACED = re.compile(r"\b(?:" + PLACE_WORDS + r") V1\b")


def own_meeting(sentence: str) -> str:
    """The part of an impact sentence that tells V1's own meeting: from the first clause that names V1 as a party,
    when an earlier one names V1 only as a place (see `_THEN_AND`); else the sentence."""
    cuts = [0, *(m.end() for m in _THEN_AND.finditer(sentence))]
    first = sentence[: cuts[1]] if len(cuts) > 1 else sentence
    first = _WHEN.sub("", first)  # (not a clause that sets the time: "Shortly after V1 came to a stop, ...")
    if len(cuts) < 2 or not V1_PLACED.search(first) or re.search(r"\bV1\b", V1_PLACED.sub("", first)):
        return sentence
    if not (_ACTIVE.search(first) or _AGENT.search(first)):
        return sentence  # (the first tells no meeting: "V2 behind V1 braked late, and struck V1")
    # (a later clause with its own subject: "and V2 then made contact with the rear of V1")
    later = next(
        (
            at
            for at in cuts[1:]
            if re.match(r"(?:then )?" + _V + r"\b", sentence[at:]) and re.search(r"\bV1\b", sentence[at:])
        ),
        None,
    )
    return sentence if later is None else sentence[later:]


def read_crash(sents: list[str], impact: int, carry: str | None = None) -> Crash:
    """The first impact's crash: read from its sentence (index `impact`), else from a later sentence that
    restates it, else from an earlier one that says "head-on"."""
    return read_crash_at(sents, impact, carry)[0]


def read_crash_at(
    sents: list[str], impact: int, carry: str | None = None, backing: frozenset[str] = frozenset()
) -> tuple[Crash, int]:
    """`read_crash`, and the index of the sentence it was read from (-1: none); `backing` as for
    `read_sentence`."""
    order = [impact, *range(impact + 1, len(sents))] if 0 <= impact < len(sents) else list(range(len(sents)))
    tower = towing(sents)
    for i in order:
        crash = read_sentence(own_meeting(sents[i]), carry if i == impact else None, tower, backing)
        if crash is not None:
            return _pushed_into_v1(sents[i], crash, tower), i
    if (said := next((i for i, s in enumerate(sents[: impact + 1]) if _HEAD_ON.search(s)), None)) is not None:
        return Crash(CrashType.FRONTAL), said
    return Crash(), -1


def backed_into_follower(crash: Crash, backing: frozenset[str], text: str) -> Crash:
    """A vehicle backing into one the report puts behind it ("V1 came to a stop behind V2 ... V2 began to reverse
    and made contact with V1") met it rear first, and met its front: with no part named, that is the IR's
    `rear_end` of a backing striker (see `_backed`), as the follower struck from behind is one going forward."""
    striker, victim = crash.striker, crash.victim
    if crash.type is not UNKNOWN or not isinstance(striker, str) or not isinstance(victim, str):
        return crash
    if striker not in backing or victim in backing:
        return crash
    behind = re.compile(
        rf"\b{victim}\b[^.;]*?\bbehind (?:the |a )?{_STATE}{striker}\b"
        rf"|\b{striker}\b[^.;]*?\b(?:in front of|ahead of) (?:the )?{_STATE}{victim}\b",
        re.I,
    )
    return replace(crash, type=CrashType.REAR_END) if behind.search(text) else crash
