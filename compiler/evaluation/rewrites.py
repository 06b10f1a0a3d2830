"""Meaning-preserving rewrites of a crash report: the metamorphic benchmark's inputs.

Unseen reports differ from the shared ones in wording, not in the crashes. Each rewrite here is one general
variation of how police and crash-database writers phrase the same fact (a participant's name, a speed's unit,
a heading, a lane's number, who is the subject, where a sentence ends), applied everywhere it fits in a report.
The right extraction of a rewritten report is the extraction of the original: a reading that changes says the
front end depends on that wording.

Every rewrite is deterministic, leaves text it does not fit unchanged, and keeps the meaning: it touches only
the words of its variation (`tests/compiler/evaluation/test_rewrites.py` shows each on sentences of our own).
The patterns are written here, not taken from the front end, so a benchmark is no copy of what it measures.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from sovarc.compiler.evaluation import rewrite_clauses as clauses
from sovarc.compiler.evaluation import rewrite_road as road
from sovarc.compiler.evaluation import rewrite_roles as roles
from sovarc.compiler.evaluation import rewrite_styles as styles
from sovarc.compiler.evaluation.rewrite_names import (
    ANY_NAME,
    ORDINALS,
    WORDS,
    digit,
    renamed,
    through_v,
)
from sovarc.compiler.evaluation.rewrite_police import POLICE
from sovarc.compiler.evaluation.rewrite_tense import in_case_of, present_tense
from sovarc.compiler.frontend.sentences import opens_sentence

# "V1's front" -> "the front of V1": the possessive and the of-phrase name the same part.
_PARTS = (
    r"(?:(?:left|right|front|rear|back|driver|passenger)(?:[- ](?:front|rear|side|corner|quarter|door|bumper))+"
    r"(?: (?:side|corner|quarter|door|bumper|fender|panel|area|end|plane))?"
    r"|(?:left|right|front|rear|back)"
    r"(?: (?:side|corner|quarter|door|bumper|fender|panel|area|end|plane))?|front|rear|bumper|fender)"
)
_POSSESSIVE = re.compile(r"\b(?P<name>V\d)'s (?P<part>" + _PARTS + r")\b(?![\w-])")


def possessive_of(text: str) -> str:
    """ "V2's right front contacted V1" -> "the right front of V2 contacted V1"."""

    def of(m: re.Match[str]) -> str:
        return f"{'The' if opens_sentence(text, m.start()) else 'the'} {m.group('part')} of {m.group('name')}"

    return _POSSESSIVE.sub(of, text)


# ---- units ------------------------------------------------------------------------------------------------
_SPEED = re.compile(
    r"\b(?P<n>\d{1,3})(?P<gap>\s*-?\s*)(?P<unit>mph|mi/h|miles per hour|km/h|km/hr|kmph|kph|kilometers per hour)\b",
    re.I,
)


def _is_km(unit: str) -> bool:
    return unit.lower().startswith(("k", "km"))


def _speed(mile: str, km: str) -> Callable[[str], str]:
    def rewrite(text: str) -> str:
        return _SPEED.sub(lambda m: f"{m.group('n')} {km if _is_km(m.group('unit')) else mile}", text)

    return rewrite


# ---- compass ----------------------------------------------------------------------------------------------
_POINT = r"(?P<point>north|south|east|west)"
# a heading said of a moving vehicle: "was traveling northbound", "proceeding west", "heading in a southerly
# direction" (a road's "northbound lanes" is not touched: there the word names the road, not a motion)
_MOTION = r"(?P<verb>travel(?:l)?ing|travel(?:l)?ed|proceeding|proceeded|heading|headed|going|driving|moving)"
_COURSE = re.compile(
    r"\b" + _MOTION + r" (?:" + _POINT + r"(?:bound|ward|wards)?|in an? (?P<point2>north|south|east|west)(?:erly|ern) "
    r"direction)\b(?![\w-])",
    re.I,
)


def _course(form: Callable[[str], str], verb: str | None = None) -> Callable[[str], str]:
    def rewrite(text: str) -> str:
        def one(m: re.Match[str]) -> str:
            point = (m.group("point") or m.group("point2")).lower()
            said = verb if verb and m.group("verb").lower().endswith("ing") else m.group("verb")
            return f"{said} {form(point)}"

        return _COURSE.sub(one, text)

    return rewrite


_BOUND = re.compile(r"\b(?P<point>north|south|east|west)(?:[- ]?bound)\b(?![\w-])", re.I)


def compass_abbreviated(text: str) -> str:
    """ "northbound" -> "N/B": the abbreviation police forms use, for a road's direction and a vehicle's."""
    return _BOUND.sub(lambda m: f"{m.group('point')[0].upper()}/B", text)


# ---- lanes ------------------------------------------------------------------------------------------------
_LANE_NUMBER = re.compile(
    r"\b(?P<lane>[Ll]ane) (?:#\s*|number |no\. )?(?P<n>[1-6]|one|two|three|four|five|six)\b(?![\w-])"
)
_LANE_ORDINAL = re.compile(
    r"\b(?P<the>[Tt]he) (?P<n>first|second|third|fourth|fifth|sixth) lane\b(?! (?:from|to)\b)(?P<of> of travel)?"
)


def _lane_number(form: Callable[[int], str]) -> Callable[[str], str]:
    def rewrite(text: str) -> str:
        text = _LANE_NUMBER.sub(lambda m: f"{m.group('lane')} {form(digit(m.group('n')))}", text)
        return _LANE_ORDINAL.sub(
            lambda m: f"{'L' if m.group('the') == 'The' else 'l'}ane {form(digit(m.group('n')))}", text
        )

    return rewrite


# "in lane one" -> "in the first lane": the article goes with the ordinal (a preposition is what the lane follows)
_LANE_AFTER = re.compile(
    r"\b(?P<prep>in|into|from|to|of|within|across|entered|entering|occupied|occupying) (?:the )?lane "
    r"(?:#\s*|number |no\. )?(?P<n>[1-6]|one|two|three|four|five|six)\b(?![\w-])",
    re.I,
)


def lane_ordinal(text: str) -> str:
    """ "in lane one" / "into lane #2" -> "in the first lane" / "into the second lane"."""
    return _LANE_AFTER.sub(lambda m: f"{m.group('prep')} the {ORDINALS[digit(m.group('n'))]} lane", text)


# ---- counts -----------------------------------------------------------------------------------------------
_COUNT_WORD = re.compile(
    r"\b(?P<n>[Tt]wo|[Tt]hree|[Ff]our|[Ff]ive|[Ss]ix|[Ss]even|[Ee]ight)(?P<rest>[- ]lanes?|-way)\b"
)
_COUNT_DIGIT = re.compile(r"\b(?P<n>[2-8])(?P<rest>[- ]lanes?|-way)\b")


def count_digits(text: str) -> str:
    """ "a two-lane road", "three lanes", "a four-way stop" -> "a 2-lane road", "3 lanes", "a 4-way stop"."""
    return _COUNT_WORD.sub(lambda m: f"{digit(m.group('n'))}{m.group('rest')}", text)


def count_words(text: str) -> str:
    """ "a 2-lane road", "3 lanes" -> "a two-lane road", "three lanes"."""
    return _COUNT_DIGIT.sub(lambda m: f"{WORDS[int(m.group('n'))]}{m.group('rest')}", text)


# ---- who is the subject: the vehicle or its driver ----------------------------------------------------------
# Verbs of driving: the driver of V1 does what V1 does. (Not "was a 2002 Hyundai", "was towed", "sustained".)
_DRIVE = (
    r"(?:was |were )?(?:travel(?:l)?ing|travel(?:l)?ed|proceed(?:ed|ing)|turn(?:ed|ing)|stopp(?:ed|ing)|"
    r"slow(?:ed|ing)|brak(?:ed|ing)|steer(?:ed|ing)|swerv(?:ed|ing)|enter(?:ed|ing)|accelerat(?:ed|ing)|"
    r"attempt(?:ed|ing)|began|beginning|started|starting|made|making|changed|changing|pulled|pulling|"
    r"backed|backing|drove|driving|continued|continuing|passed|passing|merged|merging|approach(?:ed|ing))\b"
)
_VEHICLE_DOES = re.compile(
    r"(?P<lead>(?:^|(?<=[.!?;,])\s*|\b(?:and|when|while|as|but|then) ))(?P<name>V\d) (?P<then>then )?(?=" + _DRIVE + ")"
)
_DRIVER_DOES = re.compile(r"\b(?P<the>[Tt]he) (?:driver|operator) of (?P<name>V\d) (?P<then>then )?(?=" + _DRIVE + ")")


def driver_of(text: str) -> str:
    """ "V1 was traveling north" -> "The driver of V1 was traveling north": the driver does what the car does."""

    def one(m: re.Match[str]) -> str:
        lead = m.group("lead")
        the = "The" if opens_sentence(text, m.start("name")) else "the"
        return f"{lead}{the} driver of {m.group('name')} {m.group('then') or ''}"

    return _VEHICLE_DOES.sub(one, text)


def driver_dropped(text: str) -> str:
    """ "The driver of V1 slowed" -> "V1 slowed"."""
    return _DRIVER_DOES.sub(lambda m: f"{m.group('name')} {m.group('then') or ''}", text)


# ---- where sentences end ------------------------------------------------------------------------------------
# a conjunct that is a whole clause: it has its own subject (a participant, its part, a pronoun, its driver)
_CLAUSE_SUBJECT = (
    r"(?:V\d|(?:he|she|it|they)|the (?:driver|operator) of V\d|the (?:[\w-]+ ){0,3}(?:front|rear|side|corner|"
    r"bumper|end) of V\d)\b(?! (?:and|or)\b)"
)
# a clause before "and" has a verb of its own after its subject ("V2 turned left and ..."; not "the posted limit
# for V1 and V2 was", where the article makes "posted" no verb)
_FINITE = re.compile(
    r"(?<!\bthe )(?<!\ban )(?<!\ba )\b(?:was|were|had|is|\w{2,}[^\We]ed|struck|hit|went|came|made|began|saw|drove"
    r"|ran)\b",
    re.I,
)
_AND = re.compile(r"(?:,? and (?P<then>then )?|, then )(?=" + _CLAUSE_SUBJECT + r")", re.I)


def split_and(text: str) -> str:
    """ "V2 turned left, and the front of V1 struck V2" -> "V2 turned left. The front of V1 struck V2": two
    clauses joined by "and" (or "then") are two sentences; "and then" keeps its "then"."""

    out: list[str] = []
    last = 0
    for m in _AND.finditer(text):
        clause = re.split(r"[.!?]\s+", text[: m.start()])[-1]
        if re.search(r"\b(?:between|both)\b", clause) or not _FINITE.search(clause):
            continue  # "between V1 and V2", "the limit for V1 and V2 was": a pair, not two clauses
        then = bool(m.group("then")) or m.group().strip(", ") == "then"
        out.append(text[last : m.start()] + ". " + ("Then " if then else text[m.end()].upper()))
        last = m.end() + (0 if then else 1)
    return "".join(out) + text[last:]


_SENTENCE = re.compile(r"(?<=[.!?])\s+")
# an event (not a state) said of a participant: "V2 stopped", "V1 then proceeded" (not "V1 was ...")
_EVENT = re.compile(r"^(?:V\d|The (?:driver|operator) of V\d) (?:then )?(?!(?:was|were|is|had|has)\b)[a-z]+ed\b")


def join_then(text: str) -> str:
    """ "V2 stopped at the sign. V2 proceeded to turn left." -> "V2 stopped at the sign, and then V2 proceeded to
    turn left.": two short sentences about events in their order, joined by "and then" (the narrative's order
    is the events' order). Only a sentence of at most 12 words that ends with a full stop is joined to the
    next."""
    parts = _SENTENCE.split(text)
    out: list[str] = []
    i = 0
    while i < len(parts):
        a = parts[i]
        b = parts[i + 1] if i + 1 < len(parts) else ""
        if (
            b
            and a.endswith(".")
            and len(a.split()) <= 12
            and _EVENT.match(a)
            and _EVENT.match(b)
            and not re.match(r"^\S+ then\b", b)
        ):
            lead = b if b.startswith("V") else "t" + b[1:]
            out.append(a[:-1] + ", and then " + lead)
            i += 2
            continue
        out.append(a)
        i += 1
    return " ".join(out) if len(out) != len(parts) else text


# ---- verbs ----------------------------------------------------------------------------------------------------
def travelling(text: str) -> str:
    """ "traveling", "traveled" -> "travelling", "travelled": the other spelling."""
    return re.sub(r"\b([Tt]ravel)(ing|ed)\b", r"\1l\2", text)


def proceeding(text: str) -> str:
    """ "was traveling north" -> "was proceeding north": the police word for a vehicle under way."""
    return re.sub(r"\b([Tt])ravel(?:l)?ing\b", lambda m: "Proceeding" if m.group(1) == "T" else "proceeding", text)


# ---- verbs of a move --------------------------------------------------------------------------------------
_HAND = r"(?P<side>left|right)(?:[- ]hand)?[- ]turn"
_MAKE_TURN = re.compile(r"\b(?P<verb>[Mm]ade|[Mm]ake|[Mm]akes|[Mm]aking) an? " + _HAND + r"\b(?![\w-])")
_TURN_VERB = re.compile(
    r"\b(?P<verb>[Tt]urned|[Tt]urning|[Tt]urns|(?<=to )turn) (?P<side>left|right)\b(?![\w-])(?! (?:of|side)\b)"
)
_AS_TURN = {"made": "turned", "make": "turn", "makes": "turns", "making": "turning"}
_AS_MAKE = {v: k for k, v in _AS_TURN.items()}


def turn_verb(text: str) -> str:
    """ "made a left turn" -> "turned left", "making a right-hand turn" -> "turning right"."""
    return _MAKE_TURN.sub(lambda m: f"{in_case_of(m['verb'], _AS_TURN[m['verb'].lower()])} {m['side']}", text)


def turn_noun(text: str) -> str:
    """ "turned left" -> "made a left turn", "to turn right" -> "to make a right turn"."""
    return _TURN_VERB.sub(lambda m: f"{in_case_of(m['verb'], _AS_MAKE[m['verb'].lower()])} a {m['side']} turn", text)


def turn_hand(text: str) -> str:
    """ "a left turn" -> "a left-hand turn"."""
    return re.sub(r"\b(left|right)[- ]turn\b(?![\w-])", r"\1-hand turn", text)


# an impact in the active voice: "V1 struck V2" (a passive "was struck by" keeps its verb: "was collided with by"
# is no English)
_STRUCK = re.compile(r"(?<!was )(?<!were )(?<!being )(?<!been )\b(?:struck|impacted|hit|contacted)(?= (?:the|V\d)\b)")


def impact_collided(text: str) -> str:
    """ "the front of V1 struck the rear of V2" -> "the front of V1 collided with the rear of V2"."""
    return _STRUCK.sub("collided with", text)


def impact_impacted(text: str) -> str:
    """ "struck", "hit", "contacted" (an impact's verb, either voice) -> "impacted", the crash database's word."""
    return re.sub(r"\b(?:struck|contacted)\b|\bhit(?= (?:the|V\d|by)\b)", "impacted", text)


# "V2 stopped at the sign" (a move, not "was stopped", not "a stopped car") -> "V2 came to a stop at the sign"
_STOPPED = re.compile(r"\b(?P<who>V\d|[Hh]e|[Ss]he|[Ii]t|and|then) stopped\b(?! (?:V\d|the|his|her|its|it)\b)")


def came_to_stop(text: str) -> str:
    """ "V2 stopped at the stop sign" -> "V2 came to a stop at the stop sign"."""
    return _STOPPED.sub(lambda m: f"{m['who']} came to a stop", text)


def braked(text: str) -> str:
    """ "applied the brakes" <-> "braked": one way of saying it for the other."""
    text2 = re.sub(r"\b([Aa])ppl(?:ied|ying) (?:the|his|her|its) brakes\b", "braked", text)
    if text2 != text:
        return text2
    return re.sub(r"\bbraked\b", "applied the brakes", text)


# ---- speed pairs ----------------------------------------------------------------------------------------------
_PAIR = re.compile(
    r"\b(?P<km>\d{2,3}\s*-?\s*(?:km/h|km/hr|kmph|kph))\s*\((?P<mi>\d{2,3}\s*-?\s*(?:mph|mi/h))\)",
    re.I,
)


def mph_only(text: str) -> str:
    """ "48 KMPH (30 MPH)" -> "30 MPH": a US police report gives the miles only."""
    return _PAIR.sub(lambda m: m["mi"], text)


def mph_first(text: str) -> str:
    """ "48 KMPH (30 MPH)" -> "30 MPH (48 KMPH)"."""
    return _PAIR.sub(lambda m: f"{m['mi']} ({m['km']})", text)


# ---- asides ---------------------------------------------------------------------------------------------------
_ASIDE = re.compile(r"\b(?P<name>V\d), (?P<aside>an? [^,()]{3,80}?), (?=(?:was|were|is|had|then|driven)\b)")


def aside_parenthesis(text: str) -> str:
    """ "V2, a 1998 Ford Taurus sedan, was traveling" -> "V2 (a 1998 Ford Taurus sedan) was traveling"."""
    return _ASIDE.sub(lambda m: f"{m['name']} ({m['aside']}) ", text)


_OF = re.compile(r"\b(?P<the>[Tt]he) (?P<part>" + _PARTS + r") of (?P<name>V\d)\b(?!,? \(?(?:an?|the) )")


def driver_possessive(text: str) -> str:
    """ "the driver of V1 steered" -> "V1's driver steered"."""
    return re.sub(r"\b([Tt])he (driver|operator) of (V\d)\b(?!,? \(?(?:an?|the) )", lambda m: f"{m[3]}'s {m[2]}", text)


def of_possessive(text: str) -> str:
    """ "the front of V1 struck the rear of V2" -> "V1's front struck V2's rear"."""
    return _OF.sub(lambda m: f"{m['name']}'s {m['part']}", text)


_EXECUTE = {"made": "executed", "make": "execute", "makes": "executes", "making": "executing"}


def turn_executed(text: str) -> str:
    """ "made a left turn" -> "executed a left turn"."""
    return _MAKE_TURN.sub(
        lambda m: f"{in_case_of(m['verb'], _EXECUTE[m['verb'].lower()])} {m.group()[len(m['verb']) + 1 :]}", text
    )


def intending_on(text: str) -> str:
    """ "intending to turn left" -> "intending on turning left", "intending to make" -> "intending on making"."""
    return re.sub(
        r"\b(intend(?:ing|ed)|planning) to (turn|make)\b",
        lambda m: f"{m[1]} on {'turning' if m[2] == 'turn' else 'making'}",
        text,
    )


# an impact said actively between two named sides: "the front of V1 struck the rear of V2"
_SIDE_OF = r"(?:[Tt]he (?:[\w-]+ ){1,3}?of )?" + ANY_NAME
_ACTIVE = re.compile(r"(?P<a>" + _SIDE_OF + r") (?P<verb>struck|impacted|hit|contacted) (?P<b>" + _SIDE_OF + r")\b")


def impact_passive(text: str) -> str:
    """ "The front of V1 struck the rear of V2" -> "The rear of V2 was struck by the front of V1"."""

    def one(m: re.Match[str]) -> str:
        a, b = m["a"], m["b"]
        start = m["a"][0].isupper() and m["a"].startswith("The")
        b = b[0].upper() + b[1:] if start else b
        a = a[0].lower() + a[1:] if a.startswith("The") else a
        return f"{b} was {m['verb']} by {a}"

    return _ACTIVE.sub(one, text)


def compass_was(text: str) -> str:
    """ "V1 was traveling northbound" -> "V1 was northbound": the heading said as the vehicle's state."""
    return re.sub(
        r"\b(was|were) (?:travel(?:l)?ing|proceeding|heading|going|driving) (north|south|east|west)(?:bound)?"
        r"\b(?![\w-])",
        lambda m: f"{m[1]} {m[2]}bound",
        text,
    )


def driver_number(text: str) -> str:
    """ "the driver of V1 stopped" -> "Driver #1 stopped": police forms number the drivers as the vehicles."""
    v = renamed(lambda n: f"V{n}")
    return re.sub(
        r"\b[Tt]he (?:driver|operator) of (" + ANY_NAME + r") (then )?(?=" + _DRIVE + ")",
        lambda m: f"Driver #{v(m[1])[1:]} {m[2] or ''}",
        text,
    )


def pronoun_subject(text: str) -> str:
    """ "V2 stopped at the sign. V2 then turned left." -> "V2 stopped at the sign. It then turned left.": a
    sentence whose subject is the last one's, when the last names no other participant."""
    parts = _SENTENCE.split(text)
    v = renamed(lambda n: f"V{n}")
    for i in range(1, len(parts)):
        a = re.match(f"({ANY_NAME}) ", parts[i - 1])
        b = re.match(f"({ANY_NAME}) (?!(?:was|is) an? )", parts[i])
        if a and b and v(a[1]) == v(b[1]) and {v(n) for n in re.findall(ANY_NAME, parts[i - 1])} == {v(a[1])}:
            parts[i] = "It " + parts[i][b.end() :]
    return " ".join(parts) if any(p.startswith("It ") for p in parts) else text


def semicolons(text: str) -> str:
    """ "V1 was traveling north. V2 was traveling east." -> "V1 was traveling north; V2 was traveling east.": two
    sentences about the participants as one, parted by a semicolon."""
    return re.sub(r"\.\s+(?=V\d\b)", "; ", text)


# ---- the road's words ------------------------------------------------------------------------------------------
def junction(text: str) -> str:
    """ "intersection" -> "junction", "T-intersection" -> "T-junction": the British word for the same place."""
    return re.sub(r"\b([Ii])ntersection(s?)\b", lambda m: ("J" if m[1] == "I" else "j") + "unction" + m[2], text)


def signal_light(text: str) -> str:
    """ "traffic signal" -> "traffic light", "signal-controlled" -> "light-controlled"."""
    text = re.sub(r"\b([Tt]raffic) signal(s?)\b", r"\1 light\2", text)
    return re.sub(r"\bsignal-controlled\b", "light-controlled", text)


_BRITISH = {"curb": "kerb", "maneuver": "manoeuvre", "center": "centre", "gray": "grey", "tire": "tyre"}


def british_spelling(text: str) -> str:
    """ "the curb lane", "the center line", "maneuvered" -> "the kerb lane", "the centre line", "manoeuvred"."""

    def one(m: re.Match[str]) -> str:
        word, end = _BRITISH[m[1].lower()], m[2] or ""
        if m[1].lower() == "maneuver" and end in ("ed", "ing"):
            return in_case_of(m[1], word[:-1]) + end  # manoeuvred, manoeuvring
        return in_case_of(m[1], word) + end

    return re.sub(r"\b(curb|maneuver|center|gray|tire)(s|ed|ing)?\b", one, text, flags=re.I)


def carriageway(text: str) -> str:
    """ "the roadway" -> "the carriageway": the British word for the road's travelled way."""
    return re.sub(r"\b([Rr])oadway(s?)\b", lambda m: ("C" if m[1] == "R" else "c") + "arriageway" + m[2], text)


REWRITES: dict[str, Callable[[str], str]] = {
    "v_short": renamed(lambda n: f"V{n}"),
    "vehicle_hash": renamed(lambda n: f"Vehicle #{n}"),
    "vehicle_number": renamed(lambda n: f"Vehicle {n}"),
    "vehicle_word": renamed(lambda n: f"Vehicle {WORDS[n]}"),
    "unit": renamed(lambda n: f"Unit {n}"),
    "v_dash": renamed(lambda n: f"V-{n}"),
    "v_space": renamed(lambda n: f"V {n}"),
    "possessive_of": through_v(possessive_of),
    "speed_upper": _speed("MPH", "KMPH"),
    "speed_words": _speed("miles per hour", "kilometers per hour"),
    "speed_kph": _speed("mph", "kph"),
    "speed_km_h": _speed("mph", "km/h"),
    "compass_plain": _course(lambda p: p),
    "compass_bound": _course(lambda p: f"{p}bound"),
    "compass_heading": _course(lambda p: p, verb="heading"),
    "compass_direction": _course(lambda p: f"in {'an' if p[0] in 'aeiou' else 'a'} {p}erly direction"),
    "compass_abbreviated": compass_abbreviated,
    "compass_was": compass_was,
    "lane_digit": _lane_number(str),
    "lane_hash": _lane_number(lambda n: f"#{n}"),
    "lane_word": _lane_number(lambda n: WORDS[n]),
    "lane_ordinal": lane_ordinal,
    "count_digits": count_digits,
    "count_words": count_words,
    "driver_of": through_v(driver_of),
    "driver_dropped": through_v(driver_dropped),
    "driver_number": driver_number,  # (it drops a name: the others keep their own words)
    "pronoun_subject": pronoun_subject,  # (it drops names: the others keep their own words)
    "semicolons": through_v(semicolons),
    "split_and": through_v(split_and),
    "join_then": through_v(join_then),
    "travelling": travelling,
    "present_tense": present_tense,
    "turn_verb": turn_verb,
    "turn_noun": turn_noun,
    "turn_hand": turn_hand,
    "turn_executed": turn_executed,
    "intending_on": intending_on,
    "impact_passive": impact_passive,  # (it swaps the names: each keeps its own words)
    "impact_collided": through_v(impact_collided),
    "impact_impacted": through_v(impact_impacted),
    "came_to_stop": through_v(came_to_stop),
    "braked": braked,
    "mph_only": mph_only,
    "mph_first": mph_first,
    "aside_parenthesis": through_v(aside_parenthesis),
    "of_possessive": through_v(of_possessive),
    "driver_possessive": through_v(driver_possessive),
    "proceeding": proceeding,
    "junction": junction,
    "signal_light": signal_light,
    "british_spelling": british_spelling,
    "carriageway": carriageway,
    # how sentences are built, and what a participant is called after its introduction (`rewrite_clauses`)
    "clause_after": clauses.per_sentence(clauses.clause_after),
    "clause_fronted": clauses.per_sentence(clauses.clause_fronted),
    "place_after": clauses.per_sentence(clauses.place_after),
    "join_after": clauses.join_after,
    "while_participle": clauses.per_sentence(clauses.while_participle),
    "then_first": clauses.then_first,
    "rear_ended": clauses.rear_ended,
    "crashed_into": clauses.crashed_into,
    "road_word": clauses.road_word,
    "three_leg": clauses.three_leg,
    "part_with": clauses.part_with,
    "struck_in_side": clauses.struck_in_side,
    "stationary": clauses.stationary,
    "decelerated": clauses.decelerated,
    "kind_which": clauses.per_sentence(clauses.kind_which),
    "kind_aside": clauses.per_sentence(clauses.kind_aside),
    "make_names": clauses.make_names,  # (it drops names: the others keep their own words)
    "vehicle_ordinal": clauses.vehicle_ordinal,
    "police_abbrev": clauses.police_abbrev,
    "lane_curb": clauses.lane_curb,
    # how the road and its conditions are said (`rewrite_road`)
    "limit_posted_at": road.limit_posted_at,
    "lanes_each_way": road.lanes_each_way,
    "lanes_total": road.lanes_total,
    "dark_lighted": road.dark_lighted,
    # a police agency's conventions: capitals, form labels and abbreviations (`rewrite_police`)
    **POLICE,
    # reports that number nobody: road users named by description, by the narrator, by an insurer (`rewrite_roles`)
    "unnumbered": roles.unnumbered,
    "first_person": roles.first_person,
    "insurer": roles.insurer,
    # terse and lettered styles: bare kinds opening a sentence, drivers lettered (`rewrite_styles`)
    "bare_names": styles.bare_names,
    "driver_letters": styles.driver_letters,
}


def _chain(*names: str) -> Callable[[str], str]:
    def run(text: str) -> str:
        for name in names:
            text = REWRITES[name](text)
        return text

    return run


# Writers, not words: several variations at once, as one writer's habits come together in a report.
REWRITES["writer_police"] = _chain(
    "unit", "compass_abbreviated", "mph_only", "driver_number", "lane_hash", "count_digits", "present_tense"
)
REWRITES["writer_british"] = _chain(
    "vehicle_number", "speed_words", "carriageway", "junction", "british_spelling", "travelling", "compass_direction"
)
# (an insurance adjuster's: kinds said as what each was, time clauses first, makes for names, the curb lane)
REWRITES["writer_adjuster"] = _chain(
    "kind_which",
    "join_after",
    "clause_fronted",
    "place_after",
    "struck_in_side",
    "make_names",
    "lane_curb",
    "stationary",
)
# (an agency's export: form labels and abbreviations, all in capitals)
REWRITES["writer_agency"] = _chain("driver_short", "veh_caps", "compass_abbreviated", "form_abbrev", "all_caps")
REWRITES["writer_terse"] = _chain("v_dash", "speed_upper", "compass_was", "pronoun_subject", "semicolons", "turn_verb")


def rewrite(name: str, text: str) -> str:
    """The report rewritten by the named rewrite (see `REWRITES`)."""
    return REWRITES[name](text)
