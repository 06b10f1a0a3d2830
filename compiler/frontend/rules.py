"""The deterministic rules-only front end (`--llm none`).

It reads what text patterns state exactly (speed limits in either unit, lane
counts, weather and light words, headings, participant names) and makes a
best, conservative reading of actions and the crash. A fact no rule finds
stays `unknown`. The model front end uses the same static rules and
cross-checks its answer against them.
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass, field, replace

from sovarc.compiler.frontend.text import normalize_names, participants, sentences, up_to_first_impact
from sovarc.dsl.ir import (
    UNKNOWN,
    Action,
    ActionKind,
    Crash,
    CrashType,
    Environment,
    Heading,
    Lighting,
    Participant,
    Provenance,
    Road,
    RoadKind,
    Role,
    Scenario,
    Side,
    Speed,
    SpeedUnit,
    Unknown,
    Weather,
)

_NUM = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "single": 1}
_ORDINAL = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5}
_NUMBER = r"(\d|one|two|three|four|five|six|seven|eight|single)"

_WEATHER = [
    (Weather.CLEAR, r"\bclear\b(?! of)|no adverse (?:atmospheric|weather)"),
    (Weather.CLOUDY, r"\bcloudy\b|\bovercast\b"),
    (Weather.RAINY, r"\brain(?:y|ing|ed)?\b|\bdrizzl"),
    (Weather.FOGGY, r"\bfog(?:gy)?\b|\bmist(?:y)?\b"),
    (Weather.SNOWY, r"\bsnow(?:y|ing|ed|fall)?\b(?! embankment| bank| pile)|\bsleet"),
    (Weather.WINDY, r"\bwindy\b|\bwinds? (?:was|were)\b|\bhigh winds?\b"),
    (Weather.SUNNY, r"\bsunny\b"),
]
_DARK = r"\bdark(?:ness)?\b|\bnight(?:time)?\b|\bdusk\b|\bdawn\b|\bevening\b"
_LIT = r"\b(?:dark,? but lighted|lighted|street ?lights?|street lamps?|lit by|illuminated|dark with lights)\b"
_DAYLIGHT = r"\bdaylight\b|\bdaytime\b"
_DAY = r"\b(?:morning|afternoon|noon|midday|mid-day)\b|\bduring the day\b|\bsunny\b"

_SPEED = re.compile(r"(\d{2,3})\s*-?\s*(km/?h|kmph|kph|mph)\b", re.IGNORECASE)
_HEADING = re.compile(r"\b(north|east|south|west)(?:bound|ward|erly)?\b", re.IGNORECASE)

_ACTION_PATTERNS: list[tuple[ActionKind, str]] = [
    (ActionKind.U_TURN, r"\bu-?\s?turn|\bturn(?:ed|ing)? around\b"),
    (ActionKind.TURN_LEFT, r"\bturn(?:ed|ing|s)? (?:to the )?left\b|\bleft[- ]turn(?:ing)?\b"),
    (ActionKind.TURN_RIGHT, r"\bturn(?:ed|ing|s)? (?:to the )?right\b|\bright[- ]turn(?:ing)?\b"),
    (ActionKind.CHANGE_LANE, r"\bchang(?:e|ed|ing) lanes?\b|\blane change\b|\bmerg(?:e|ed|ing)\b"),
    (
        ActionKind.RETROGRADE,
        r"\bcross(?:ed|ing)? (?:over )?(?:the )?(?:double yellow|cent(?:er|re) ?line)|\bleft of cent(?:er|re)\b"
        r"|\binto the (?:opposing|oncoming) (?:lane|traffic)|\bwrong (?:way|side)\b"
        r"|\bover the left (?:side )?(?:double yellow|lane line|cent(?:er|re))"
        r"|\bover the lane line on (?:the )?left side|\blane departure to the left"
        r"|\bcrossed over\b(?! the (?:curb|median))",
    ),
    (
        ActionKind.DRIVE_INTO,
        r"\bpull(?:ed|ing)? (?:out )?(?:of|from) (?:a|the|an) (?:private )?(?:driveway|parking|lot)"
        r"|\bexit(?:ed|ing)? (?:a|the|an) (?:private )?(?:driveway|parking)|\bfrom (?:a|the) (?:private )?driveway"
        r"|\bre-?entered the road",
    ),
    (ActionKind.DRIVE_OFF, r"\bran off the road|\bdeparted the road|\bleft the road|\bonto the shoulder"),
    (
        ActionKind.GO_ACROSS,
        r"\bgo(?:ing)? straight\b|\bstraight through\b|\bcross(?:ed|ing)? the intersection|\bthrough the intersection"
        r"|\bproceed(?:ed|ing)? (?:straight|through)",
    ),
    (
        ActionKind.STOP,
        r"\b(?:was|were|had) stopped\b|\bstopped (?:for|at|in)\b|\bcame to a (?:stop|complete stop)\b"
        r"|\bslowed to a stop\b|\bwaiting\b|\bstationary\b",
    ),
]
# Words that say a participant was moving, and a crossing after a stop; used for ordering, not as actions alone.
_TRAVELLING = re.compile(
    r"\b(?:travel(?:l)?(?:ed|ing)|approach(?:ed|ing)|driving|proceed(?:ed|ing)|head(?:ed|ing))\b", re.I
)
_CROSSING_AFTER_STOP = re.compile(
    r"\b(?:proceed(?:ed|ing)|pull(?:ed|ing)|drove|continu(?:ed|ing)|enter(?:ed|ing)|accelerat(?:ed|ing))\b"
    r"(?: \w+){0,3} (?:into|through|across) the intersection|\battempt(?:ed|ing) to cross\b",
    re.IGNORECASE,
)
_PRECRASH_LEFT = re.compile(
    r"critical pre-?crash event\b[^.]*?\b(V\d)\b[^.]*?\b(?:over the lane line on (?:the )?left side|"
    r"lane line on left side|cross(?:ed|ing)? (?:the )?cent(?:er|re) ?line|left of cent(?:er|re))",
    re.IGNORECASE,
)
_INTENDED = re.compile(
    r"\b(?:intend(?:ed|ing|s)? (?:to|on)|planning to|planned to|wanted to|was going to|in order to)\b[^.,;]*",
    re.IGNORECASE,
)


def _number(word: str) -> int:
    return int(word) if word.isdigit() else _NUM[word.lower()]


def extract_environment(text: str) -> Environment:
    low = text.lower()
    weather = tuple(w for w, pattern in _WEATHER if re.search(pattern, low))
    lighting: list[Lighting] = []
    if re.search(_DAYLIGHT, low):  # stated outright, it wins over "the night before" and the like
        lighting.append(Lighting.DAYLIGHT)
    elif re.search(_LIT, low):
        lighting += [Lighting.DARK, Lighting.STREET_LIGHTS]
    elif re.search(_DARK, low):
        lighting.append(Lighting.DARK)
    elif re.search(_DAY, low):
        lighting.append(Lighting.DAYLIGHT)
    return Environment(weather or UNKNOWN, tuple(lighting) or UNKNOWN)


def first_speed(text: str) -> Speed | Unknown:
    """The first speed stated; in km/h when both units are given (the ground truth's convention)."""
    found = [(int(v), u.lower()) for v, u in _SPEED.findall(text)]
    metric = [v for v, u in found if u != "mph"]
    if metric:
        return Speed(metric[0], SpeedUnit.KMH)
    return Speed(found[0][0], SpeedUnit.MPH) if found else UNKNOWN


def extract_speed_limit(text: str) -> Speed | Unknown:
    """The posted limit; with several (a side road, a ramp, a school zone), the lowest, as the ground truth has it."""
    limits: list[Speed] = []
    for sentence in sentences(text):
        if re.search(r"speed limits?|posted|limit", sentence, re.IGNORECASE):
            found = [(int(v), u.lower()) for v, u in _SPEED.findall(sentence)]
            metric = [Speed(v, SpeedUnit.KMH) for v, u in found if u != "mph"]
            limits += metric or [Speed(v, SpeedUnit.MPH) for v, u in found]
    return min(limits, key=Speed.to_mps) if limits else UNKNOWN


def extract_lanes(text: str) -> int | Unknown:
    """Lanes of the widest road, both directions together."""
    low = text.lower()
    counts: list[int] = []
    each = r"(?: of travel)? (?:in )?(?:each|either|per|both)(?: the \w+ and \w+)? directions?"
    for m in re.finditer(_NUMBER + r"[- ]lanes?" + each, low):
        counts.append(2 * _number(m.group(1)))
    for m in re.finditer(_NUMBER + r"[- ]lanes?\b(?!" + each + ")", low):
        tail = low[m.end() : m.end() + 60]
        if re.match(
            r",? ?(?:\(|of travel\b|(?:[\w/-]+,? ){0,4}?(?:two-way|undivided|divided|roadway|road|highway|street|"
            r"t-intersection|intersection|interstate|one-way|avenue|boulevard|arterial|freeway|expressway|route)\b|"
            r"(?:residential|rural|urban|city|county|state))",
            tail,
        ):
            counts.append(_number(m.group(1)))
    return max(counts) if counts else UNKNOWN


def extract_road_kind(text: str) -> RoadKind:
    low = text.lower()
    if re.search(r"\bt[- ]?(?:intersection|junction|type)|three[- ]leg|3[- ]leg|\by[- ]intersection", low):
        return RoadKind.T_JUNCTION
    if re.search(r"\bintersection\b|\bintersecting\b", low):
        return RoadKind.INTERSECTION
    return RoadKind.STRAIGHT


@dataclass
class _Reading:
    heading: Heading | Unknown = UNKNOWN
    lane: int | Unknown = UNKNOWN
    speed: Speed | Unknown = UNKNOWN
    actions: list[tuple[int, Action]] | None = None
    travelling_at: float = float("inf")  # where the text first says it was moving
    crossings: list[int] = field(default_factory=list)  # where it says it crossed the intersection


def _segments(sents: list[str], ids: list[str]) -> dict[str, list[str]]:
    """Text after each mention of a participant, up to the next mention: what it did."""
    out: dict[str, list[str]] = {pid: [] for pid in ids}
    for s in sents:
        marks = [(m.start(), m.group()) for m in re.finditer(r"\b[VP]\d\b", s) if m.group() in out]
        if not marks:
            continue
        ends = [start for start, _ in marks[1:]] + [len(s)]
        for (start, pid), end in zip(marks, ends, strict=True):
            out[pid].append(s[start:end])
    return out


def _read_participant(chunks: list[str], lanes: int | Unknown) -> _Reading:
    reading = _Reading(actions=[])
    offset = 0
    for chunk in chunks:
        done = _INTENDED.sub(" ", chunk)
        if isinstance(reading.heading, Unknown) and (h := _HEADING.search(done)):
            reading.heading = Heading(h.group(1).lower())
        if isinstance(reading.lane, Unknown):
            reading.lane = _lane(done, lanes)
        if isinstance(reading.speed, Unknown) and not re.search(r"\blimit|\bposted", done, re.IGNORECASE):
            reading.speed = first_speed(done)
        for kind, pattern in _ACTION_PATTERNS:
            for m in re.finditer(pattern, done, re.IGNORECASE):
                to: int | Side | None = None
                if kind is ActionKind.CHANGE_LANE:
                    side = re.search(r"\b(left|right)\b", done[m.start() : m.start() + 60], re.IGNORECASE)
                    if side is None:
                        continue
                    to = Side(side.group(1).lower())
                reading.actions.append((offset + m.start(), Action(kind, to)))
        if (m := _TRAVELLING.search(done)) is not None:
            reading.travelling_at = min(reading.travelling_at, offset + m.start())
        for m in _CROSSING_AFTER_STOP.finditer(done):
            reading.crossings.append(offset + m.start())
        offset += len(chunk) + 1
    return reading


def _lane(text: str, lanes: int | Unknown) -> int | Unknown:
    if m := re.search(r"\blane " + _NUMBER + r"\b", text, re.IGNORECASE):
        return _number(m.group(1))
    if m := re.search(r"\b(first|second|third|fourth|fifth) (?:\w+ ){0,2}lane\b", text, re.IGNORECASE):
        return _ORDINAL[m.group(1).lower()]
    if re.search(r"\b(?:right|curb|outside|only) (?:\w+ )?lane\b", text, re.IGNORECASE):
        return 1
    if re.search(r"\b(?:left|inside|passing) (?:\w+ )?lane\b", text, re.IGNORECASE) and isinstance(lanes, int):
        return max(1, lanes // 2)
    return UNKNOWN


def _ordered_actions(reading: _Reading) -> tuple[Action, ...]:
    found = list(reading.actions or [])
    stops = [at for at, a in found if a.kind is ActionKind.STOP]
    if stops and not any(a.kind in _MANOEUVRES for at, a in found if at > stops[0]):
        # stopped at a sign or signal, then drove on across the intersection
        found += [(at, Action(ActionKind.GO_ACROSS)) for at in reading.crossings if at > stops[0]][:1]
    ordered: list[Action] = []
    for _, action in sorted(found, key=lambda item: item[0]):
        if not ordered or ordered[-1] != action:
            ordered.append(action)
    # A vehicle drives in its lane before whatever it does, unless it stood still or came from off the road
    # (the ground truth's convention); one the report first shows moving, then stopping, drove first.
    first_at = min((at for at, _ in found), default=float("inf"))
    standing = ordered and ordered[0].kind in (ActionKind.STOP, ActionKind.DRIVE_INTO)
    if not standing or (ordered[0].kind is ActionKind.STOP and reading.travelling_at < first_at):
        ordered.insert(0, Action(ActionKind.FOLLOW_LANE))
    return tuple(ordered)


_MANOEUVRES = (ActionKind.TURN_LEFT, ActionKind.TURN_RIGHT, ActionKind.GO_ACROSS, ActionKind.U_TURN)


# The part of the struck participant; "the right front side" is a side.
_STRUCK_PART = r"(?:(?:left|right) )?(?:front|rear) (?:(?:left|right) )?side|front|rear|back|side|end"
_STRIKE = re.compile(
    r"front(?: \w+)? of (?P<a>[VP]\d)\b[^.]*?\b(?:struck|impacted|contacted|hit|strik\w+|collided with)\b[^.]*?"
    r"(?P<part>" + _STRUCK_PART + r")\b[^.]*?\b(?P<b>[VP]\d)\b"
    r"|(?P<a2>[VP]\d)\b[^.]*?\b(?:struck|impacted|contacted|hit|rear-ended|collided with)\b(?! by)[^.]*?"
    r"(?P<part2>" + _STRUCK_PART + r")\b[^.]*?\b(?P<b2>[VP]\d)\b"
    r"|(?P<b3>[VP]\d)\b[^.]*?(?P<part3>front|rear|back|side|end)\b[^.]*?\bwas (?:struck|impacted|contacted|hit) by"
    r" (?:the front of )?(?P<a3>[VP]\d)\b",
    re.IGNORECASE,
)
_PART = {
    "front": CrashType.FRONTAL,
    "rear": CrashType.REAR_END,
    "back": CrashType.REAR_END,
    "end": CrashType.REAR_END,
    "side": CrashType.SIDE,
}


def extract_crash(sents: list[str]) -> Crash:
    for s in sents:
        m = _STRIKE.search(s)
        if not m:
            continue
        a = m.group("a") or m.group("a2") or m.group("a3")
        b = m.group("b") or m.group("b2") or m.group("b3")
        part = (m.group("part") or m.group("part2") or m.group("part3")).lower()
        part = "side" if part.endswith("side") else part
        if a != b:
            return Crash(_PART[part], a, b)
    if any(re.search(r"head[- ]on", s, re.IGNORECASE) for s in sents):
        return Crash(CrashType.FRONTAL)
    return Crash()


_BOTH = re.compile(
    r"\b(V\d)\b[^.]*?\band (?:the )?(V\d)\b[^.]*?\bwere (?:both )?(?:\w+ )?(?:traveling|travelling|driving|heading|"
    r"proceeding|going) (?:in an? )?(north|south|east|west)",
    re.IGNORECASE,
)
_SAME_WAY = re.compile(
    r"\b(V\d)\b[^.]*?\b(?:in the same direction|same direction)\b[^.]*?\b(?:behind|ahead of|as|of) (V\d)\b"
    r"|\b(V\d)\b[^.]*?\b(?:behind|following) (V\d)\b[^.]*?\bsame (?:direction|lane)",
    re.IGNORECASE,
)


def _precrash_retrograde(sents: list[str], people: list[Participant]) -> list[Participant]:
    """The database's coded pre-crash event ("travelling over the lane line on the left side"), often written
    after the impact, says a vehicle went into the opposing lane."""
    wrong_way = {m.group(1) for s in sents if (m := _PRECRASH_LEFT.search(s))}
    out = []
    for p in people:
        kinds = [a.kind for a in p.known_actions]
        if p.id in wrong_way and ActionKind.RETROGRADE not in kinds and kinds[:1] == [ActionKind.FOLLOW_LANE]:
            p = replace(p, actions=(*p.known_actions, Action(ActionKind.RETROGRADE)))
        out.append(p)
    return out


_SCENE = re.compile(r"\boccurred (?:in|on|within) the (north|south|east|west)bound (?:travel )?lanes?\b", re.IGNORECASE)


def _scene_heading(text: str, people: list[Participant]) -> list[Participant]:
    """ "The crash occurred in the southbound lanes": when no vehicle's own heading is stated, they all drove so."""
    vehicles = [p for p in people if p.role is Role.VEHICLE]
    m = _SCENE.search(text)
    if m is None or not vehicles or not all(isinstance(p.heading, Unknown) for p in vehicles):
        return people
    return [replace(p, heading=Heading(m.group(1).lower())) if p.role is Role.VEHICLE else p for p in people]


def _shared_headings(sents: list[str], people: list[Participant]) -> list[Participant]:
    """Headings stated once for two vehicles: "V1 and V2 were traveling north", "V1 ... in the same direction
    behind V2"."""
    heading = {p.id: p.heading for p in people}
    for sentence in sents:
        if m := _BOTH.search(sentence):
            for pid in m.group(1, 2):
                if isinstance(heading.get(pid), Unknown):
                    heading[pid] = Heading(m.group(3).lower())
        if m := _SAME_WAY.search(sentence):
            a, b = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
            if a in heading and b in heading:
                if isinstance(heading[a], Unknown):
                    heading[a] = heading[b]
                elif isinstance(heading[b], Unknown):
                    heading[b] = heading[a]
    return [replace(p, heading=heading[p.id]) for p in people]


def extract(text: str, name: str, report_path: str | None = None) -> Scenario:
    """A scenario from a report's text by rules alone."""
    named = normalize_names(text)
    sents = sentences(named)
    ids = participants(named)
    before = up_to_first_impact(sents)
    lanes = extract_lanes(named)
    chunks = _segments(before, ids)
    people = []
    for pid in ids:
        r = _read_participant(chunks[pid], lanes)
        role = Role.PEDESTRIAN if pid.startswith("P") else Role.VEHICLE
        actions = (Action(ActionKind.CROSS),) if role is Role.PEDESTRIAN else _ordered_actions(r)
        people.append(Participant(pid, role, r.heading, r.lane, r.speed, actions))
    people = _shared_headings(before, people)
    people = _scene_heading(named, people)
    people = _precrash_retrograde(sents, people)
    provenance = Provenance(report_path or UNKNOWN, hashlib.sha256(text.encode("utf-8")).hexdigest(), "rules", UNKNOWN)
    return Scenario(
        name,
        provenance,
        extract_environment(named),
        Road(extract_road_kind(named), lanes, extract_speed_limit(named)),
        tuple(people),
        extract_crash(before if len(before) < len(sents) else sents),
    )
