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
from dataclasses import replace

from sovarc.compiler.frontend.actions import precrash_wrong_way, read_actions, what_was_done
from sovarc.compiler.frontend.clauses import Piece, by_participant, pieces
from sovarc.compiler.frontend.crash import read_crash
from sovarc.compiler.frontend.text import (
    describes_impact,
    first_impact,
    impact_clause,
    participants,
    prepare,
    sentences,
)
from sovarc.dsl.ir import (
    UNKNOWN,
    Action,
    ActionKind,
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
# "A dark colored Nissan", "a dark gray SUV": a colour of a vehicle, not the scene's lighting.
_DARK = (
    r"\bdark(?:ness)?\b(?![- ](?:colou?red|gr[ae]y|blue|green|red|brown|silver|tinted|painted|sedan|suv|car))"
    r"|\bnight(?:time)?\b|\bdusk\b|\bdawn\b|\bevening\b"
)
_LIT = r"\b(?:dark,? but lighted|lighted|street ?lights?|street lamps?|lit by|illuminated|dark with lights)\b"
_DAYLIGHT = r"\bdaylight\b|\bdaytime\b"
_DAY = r"\b(?:morning|afternoon|noon|midday|mid-day)\b|\bduring the day\b|\bsunny\b"

_SPEED = re.compile(r"(\d{2,3})\s*-?\s*(km/?h|kmph|kph|mph)\b", re.IGNORECASE)
_HEADING = re.compile(r"\b(north|east|south|west)(?:bound|ward|erly)?\b", re.IGNORECASE)


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
    if re.search(r"\b['\"]?[ty]['\"]?[- ]?(?:intersection|junction|type)|three[- ]leg|3[- ]leg", low):
        return RoadKind.T_JUNCTION
    if re.search(r"\bintersection\b|\bintersecting\b", low):
        return RoadKind.INTERSECTION
    return RoadKind.STRAIGHT


# A heading said with a verb of motion ("traveling west", "was eastbound") is the vehicle's own; a lane's
# direction ("in the westbound lane") is where it was; "to travel westbound", "a westbound left turn",
# "onto a northbound road", "two westbound and two eastbound lanes" and "facing east at rest" are not its heading.
# "northwest" counts as north, as the ground truth reads it
_COMPASS = r"(north|south|east|west)(?:east|west)?(?: ?bound|ward|erly)?(?![a-z/-])"
_MOVING_HEADING = re.compile(
    r"\b(?:travel\w*|driv(?:ing|es|e)|drove|head(?:ed|ing)|going|proceed\w*|moving|was|were|continu\w*|approach\w*"
    r"|walk\w*|runn\w*|jogg\w*|rid(?:ing|e)"
    r"|negotiat\w*|stopped facing|(?:was|were) (?:\w+ )?facing)(?: due| in an?| generally)? " + _COMPASS,
    re.I,
)
_FACING = re.compile(r"(?<!rest )(?<!rest, )\bfacing (?:due |generally )?" + _COMPASS, re.I)
_LANE_HEADING = re.compile(
    r"\b(?:in|on|within|from) (?:the|its|his|her) (?:\w+ )?(north|south|east|west) ?bound\b", re.I
)
_NOT_HEADING = re.compile(
    r"\b(?:to (?:travel|go|head|proceed|turn)|onto|into|toward|towards)\b[^.,;]*?$"
    r"|\b(?:\d|one|two|three|four|five|both) $",
    re.I,
)
_BOUND = re.compile(
    r"\b(north|south|east|west) ?bound\b(?! (?:and|or|/)\b)(?!(?: \w+)? (?:left|right|u)[- ]?turn)", re.I
)


def _heading(pieces: list[Piece], after_impact: bool = False) -> Heading | Unknown:
    """The heading the pieces state, the surest way of saying it first (see above). After the impact only a
    verb of motion counts: vehicles spin, come to rest facing anywhere and end up in other lanes."""
    for pattern in (_MOVING_HEADING,) if after_impact else (_MOVING_HEADING, _LANE_HEADING, _BOUND, _FACING):
        for piece in pieces:
            text = what_was_done(piece.text)
            for m in pattern.finditer(text):
                if pattern is _BOUND and _NOT_HEADING.search(text[: m.start()]):
                    continue
                if re.search(r"\bto $", text[: m.start()]):  # "to travel westbound" is where it was going
                    continue
                if after_impact and re.search(r"\brest\b", text[max(0, m.start() - 20) : m.start()]):
                    continue
                return Heading(m.group(1).lower())
    return UNKNOWN


def _lane(text: str, lanes: int | Unknown) -> int | Unknown:
    if m := re.search(
        r"\blane (?:#|number |no\.? )?" + _NUMBER + r"\b(?![-/])|\bnumber " + _NUMBER + r" lane", text, re.I
    ):
        return _number(m.group(1) or m.group(2))
    if m := re.search(r"\b(first|second|third|fourth|fifth) (?:\w+ ){0,2}lane\b", text, re.IGNORECASE):
        return _ORDINAL[m.group(1).lower()]
    if re.search(r"\b(?:right|curb|outside|only) (?:\w+ )?lane\b(?! of the \w+bound)", text, re.IGNORECASE):
        return 1
    if re.search(r"\b(?:left|inside|passing) (?:\w+ )?lane\b", text, re.IGNORECASE) and isinstance(lanes, int):
        return max(1, lanes // 2)
    if lanes == 2 and re.search(r"\b(?:in|within) the (?:north|south|east|west)bound (?:travel )?lane\b", text, re.I):
        return 1  # a road with one lane each way
    if _ONE_LANE_ROAD.search(text):  # its own road has one lane its way, whatever the widest road has
        return 1
    return UNKNOWN


_ONE_LANE_ROAD = re.compile(
    r"\b(?:travel\w*|driv\w*|head\w*|was|were|proceed\w*) (?:\w+ ){0,2}(?:on|along) (?:a|the) (?:[\w-]+,? ){0,3}?"
    r"(?:roadway|road|street|highway) with one lane (?:of travel )?(?:in each|each|per|in either) direction"
    r"|\b(?:on|along) (?:a|the) one-way (?:roadway|road|street) with one lane\b",
    re.I,
)


def _lane_of(pieces: list[Piece], lanes: int | Unknown) -> int | Unknown:
    """The lane a vehicle started in: not one it turned into, nor one it came to rest in after the impact."""
    for piece in pieces:
        text = re.sub(r"\b(?:turn|turned|turning) (?:\w+ ){0,3}into (?:the )?[^.,;]*", " ", piece.text)
        text = re.sub(r"[^.,;]*\b(?:rest|pushed|spun|rotated)\b[^.,;]*", " ", text)
        if not isinstance(lane := _lane(text, lanes), Unknown):
            return lane
    return UNKNOWN


def _speed(pieces: list[Piece]) -> Speed | Unknown:
    for piece in pieces:
        speed = first_speed(piece.text)
        if not re.search(r"\blimit|\bposted", piece.text, re.IGNORECASE) and not isinstance(speed, Unknown):
            return speed
    return UNKNOWN


_SAME_WAY = re.compile(
    r"\b(V\d)\b[^.]*?\b(?:in the same direction|same direction)\b[^.]*?\b(?:behind|ahead of|as|of) (V\d)\b"
    r"|\b(V\d)\b[^.]*?\b(?:behind|following|ahead of|in back of) (V\d)\b",
    re.IGNORECASE,
)
_SAME_LANE = re.compile(r"\b(V\d)\b[^.]*?\bin the same lane\b[^.]*?\b(V\d)\b", re.IGNORECASE)
_BOTH = re.compile(
    r"\b(V\d)\b[^.]*?\band (?:the )?(V\d)\b[^.]*?\bwere (?:both )?(?:\w+ )?(?:traveling|travelling|driving|heading|"
    r"proceeding|going) (?:in an? )?(north|south|east|west)",
    re.IGNORECASE,
)


def _shared_headings(sents: list[str], people: list[Participant]) -> list[Participant]:
    """Headings and lanes stated once for two vehicles: "V1 and V2 were traveling north", "V1 ... behind V2",
    "V2 was stopped in the same lane ahead of V1"."""
    heading = {p.id: p.heading for p in people}
    lane = {p.id: p.lane for p in people}
    people_by = {p.id: p for p in people}
    for sentence in sents:
        if m := _BOTH.search(sentence):
            for pid in m.group(1, 2):
                if isinstance(heading.get(pid), Unknown):
                    heading[pid] = Heading(m.group(3).lower())
        if (m := _SAME_LANE.search(sentence)) and m.group(1) != m.group(2):
            a, b = people_by[m.group(1)], people_by[m.group(2)]
            lane[a.id] = lane[a.id] if not isinstance(lane[a.id], Unknown) else lane[b.id]
            lane[b.id] = lane[b.id] if not isinstance(lane[b.id], Unknown) else lane[a.id]
        if m := _SAME_WAY.search(sentence):
            a, b = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
            if a in heading and b in heading:
                if isinstance(heading[a], Unknown):
                    heading[a] = heading[b]
                elif isinstance(heading[b], Unknown):
                    heading[b] = heading[a]
    return [replace(p, heading=heading[p.id], lane=lane[p.id]) for p in people]


_SCENE = re.compile(
    r"\boccurred (?:in|on|within) the (?:(right|left|curb) lane of the )?(north|south|east|west)bound"
    r" (?:travel )?lanes?\b",
    re.IGNORECASE,
)


def _scene(text: str, people: list[Participant], parked: set[str]) -> list[Participant]:
    """ "The crash occurred in the right lane of the southbound lanes": when no vehicle's own heading is stated,
    the moving ones all drove so (and in that lane)."""
    moving = [p for p in people if p.role is Role.VEHICLE and p.id not in parked]
    m = _SCENE.search(text)
    if m is None or not moving or not all(isinstance(p.heading, Unknown) for p in moving):
        return people
    lane = 1 if m.group(1) and m.group(1).lower() in ("right", "curb") else UNKNOWN
    return [
        replace(p, heading=Heading(m.group(2).lower()), lane=lane if isinstance(p.lane, Unknown) else p.lane)
        if p in moving
        else p
        for p in people
    ]


_PARKED = re.compile(r"\bparked\b", re.IGNORECASE)
# A pedestrian walking along the road, not across it ("walking northbound in the bike lane").
_WALKING = re.compile(
    r"\bwalk(?:ing|ed|s)?\b(?! (?:in)?to the (?:road|street|roadway|path|travel))|\balong the (?:edge|shoulder|side)\b",
    re.I,
)
_CROSSING = re.compile(r"\bcross|\bacross\b|\bin(?:to)? the crosswalk\b|\bfrom (?:the )?(?:left|right)\b", re.I)


# A vehicle the impact sentence says stood still when it was hit: "the stationary V1", "while V1 remained
# stopped". Its front may have met the other (a car reversing into it), but it had not moved off.
_STILL = r"(?:stationary|stopped|parked|standing still|at a stop|at rest)"


def _still_at_impact(sentence: str, pid: str) -> bool:
    return bool(
        re.search(rf"\b(?:the )?{_STILL} {pid}\b", sentence, re.I)
        or re.search(rf"\b{pid} (?:remained|was still|was|sat|had been|stayed) (?:\w+ )?{_STILL}\b", sentence, re.I)
    )


def _ending_stopped(actions: tuple[Action, ...]) -> tuple[Action, ...]:
    """The actions up to the last stop, or with a stop added."""
    stops = [i for i, a in enumerate(actions) if a.kind is ActionKind.STOP]
    return actions[: stops[-1] + 1] if stops else (*actions, Action(ActionKind.STOP))


def extract(text: str, name: str, report_path: str | None = None) -> Scenario:
    """A scenario from a report's text by rules alone."""
    named = prepare(text)
    sents = sentences(named)
    impact = first_impact(sents)
    # A pedestrian first named after the first impact was met in a later one, which the IR does not hold.
    seen = " ".join(sents[: impact + 1]) if impact >= 0 else named
    ids = [pid for pid in participants(named) if pid.startswith("V") or re.search(rf"\b{pid}\b", seen)]
    if impact >= 0:
        # A pedestrian is a party only when an impact involves it: "yielding to a pedestrian crossing" names a
        # bystander. (Vehicles the report numbers itself all stay: it numbers the vehicles in its crash.)
        carry = next((p.who[0] for p in pieces(sents, ids) if p.sentence == impact and p.who), None)
        crash = read_crash(sents, impact, carry)
        involved = {
            carry,
            crash.striker,
            crash.victim,
            *(p for s in filter(describes_impact, sents) for p in re.findall(r"\bP\d\b", impact_clause(s))),
        }
        ids = [pid for pid in ids if pid.startswith("V") or pid in involved]
    parts = pieces(sents, ids)
    mine = by_participant(parts, ids)
    lanes = extract_lanes(named)
    kind = extract_road_kind(named)
    before = [s for s in sents[: impact + 1]] if impact >= 0 else sents
    carry = next((p.who[0] for p in parts if p.sentence == impact and p.who), None)
    crash = read_crash(sents, impact, carry)
    # The crash may be read from a later sentence that restates the impact ("The front of V1 then struck a
    # pedestrian"): whoever it names as striker or victim is a party, even if first named there.
    roles = {r for r in (crash.striker, crash.victim) if isinstance(r, str)}
    if not roles <= set(ids):
        ids = [pid for pid in participants(named) if pid in ids or pid in roles]
        parts = pieces(sents, ids)
        mine = by_participant(parts, ids)
    wrong_way = precrash_wrong_way(sents)
    people = []
    parked: set[str] = set()
    for pid in ids:
        early = [p for p in mine[pid] if impact < 0 or p.sentence <= impact]
        late = [p for p in mine[pid] if p not in early]
        heading = _heading(early)
        heading = _heading(late, after_impact=True) if isinstance(heading, Unknown) else heading
        lane = _lane_of(early, lanes)
        lane = _lane_of(late, lanes) if isinstance(lane, Unknown) else lane
        if any(_PARKED.search(p.text) for p in early):
            parked.add(pid)
        if pid.startswith("P"):
            walking = any(_WALKING.search(p.text) for p in early) and not any(_CROSSING.search(p.text) for p in early)
            action = Action(ActionKind.WALK if walking else ActionKind.CROSS)
            people.append(Participant(pid, Role.PEDESTRIAN, heading, lane, _speed(early), (action,)))
            if not walking and crash.victim == pid and isinstance(crash.type, Unknown):
                crash = replace(crash, type=CrashType.SIDE)  # one crossing the road is struck from its side
            continue
        actions = read_actions(early, kind, heading, crash.striker == pid)
        if isinstance(actions, tuple) and impact >= 0 and _still_at_impact(sents[impact], pid):
            actions = _ending_stopped(actions)
        if isinstance(actions, Unknown) and crash.striker == pid and crash.type is CrashType.REAR_END:
            actions = (Action(ActionKind.FOLLOW_LANE),)  # its front drove into the other's rear: it drove along
        if pid in wrong_way and isinstance(actions, tuple) and ActionKind.RETROGRADE not in [a.kind for a in actions]:
            actions = (*actions, Action(ActionKind.RETROGRADE))
        if isinstance(actions, Unknown) and isinstance(heading, Unknown):
            lane = UNKNOWN  # nothing said about it before the impact: where it was is not known either
        people.append(Participant(pid, Role.VEHICLE, heading, lane, _speed(early), actions))
    people = _shared_headings(before, people)
    people = _scene(named, people, parked)
    provenance = Provenance(report_path or UNKNOWN, hashlib.sha256(text.encode("utf-8")).hexdigest(), "rules", UNKNOWN)
    return Scenario(
        name,
        provenance,
        extract_environment(named),
        Road(kind, lanes, extract_speed_limit(named)),
        tuple(people),
        crash,
    )
