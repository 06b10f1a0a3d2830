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
from typing import Any

from sovarc.compiler.frontend.actions import read_actions_at, what_was_done
from sovarc.compiler.frontend.backing import backing, backing_leads
from sovarc.compiler.frontend.clauses import Piece, by_participant, pieces
from sovarc.compiler.frontend.crash import backed_into_follower, read_crash, read_crash_at, sides_met
from sovarc.compiler.frontend.damage import damaged_part
from sovarc.compiler.frontend.doors import door_met
from sovarc.compiler.frontend.evidence import Locator, keep_stated
from sovarc.compiler.frontend.headings import heading_before_turn, read_heading
from sovarc.compiler.frontend.kinds import stated_kinds
from sovarc.compiler.frontend.lanes import per_direction, placed_lane
from sovarc.compiler.frontend.precrash import precrash_wrong_way
from sovarc.compiler.frontend.situation import wrong_side
from sovarc.compiler.frontend.standing import (
    introduced_doing,
    moving_met_standing,
    standing_struck,
    still_at_impact,
    stood_at_impact,
)
from sovarc.compiler.frontend.text import (
    Prepared,
    describes_impact,
    first_impact,
    impact_clause,
    own_impact,
    participants,
    prepare_report,
    sentences,
)
from sovarc.compiler.frontend.words import ORDINALS, number
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
    Speed,
    SpeedUnit,
    Unknown,
    Weather,
)

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
    r"|\bnight(?:time)?\b|\bevening\b"
)
# Dawn and dusk: the sun at or just below the horizon (twilight), neither day nor night.
_TWILIGHT = r"\bdusk\b|\bdawn\b|\btwilight\b|\bsunset\b|\bsunrise\b|\bdaybreak\b"
_LIT = r"\b(?:dark,? but (?:lighted|lit)|lighted|street ?lights?|street lamps?|lit by|illuminated|dark with lights)\b"
_DAYLIGHT = r"\bdaylight\b|\bdaytime\b"
_DAY = r"\b(?:morning|afternoon|noon|midday|mid-day)\b|\bduring the day\b|\bsunny\b"

# a speed's unit abbreviated or said in words: "48 KMPH", "48 km/hr", "30 mi/h", "30 miles per hour"
_SPEED = re.compile(
    r"(\d{2,3})\s*-?\s*(km/?hr?|kmph|kph|kilomet(?:er|re)s? (?:per|an) hour|mph|mi/h|miles (?:per|an) hour)\b",
    re.IGNORECASE,
)


def _miles(unit: str) -> bool:
    return unit.lower().startswith("m")


_HEADING = re.compile(r"\b(north|east|south|west)(?:bound|ward|erly)?\b", re.IGNORECASE)


# A span a reader read a fact from: the fact's path, the text it is in ("named": the prepared report,
# "joined": its sentences joined by one space), start and end. See `evidence.Locator`.
Spot = tuple[str, str, int, int]


def read_environment(text: str) -> tuple[Environment, list[Spot]]:
    """The environment, and the words each fact was read from."""
    low = text.lower()
    weather: list[Weather] = []
    spots: list[Spot] = []
    for w, pattern in _WEATHER:
        if m := re.search(pattern, low):
            weather.append(w)
            spots.append(("environment.weather", "named", *m.span()))
    lighting: list[Lighting] = []
    if m := re.search(_DAYLIGHT, low):  # stated outright, it wins over "the night before" and the like
        lighting.append(Lighting.DAYLIGHT)
    elif m := re.search(_TWILIGHT, low):
        lighting.append(Lighting.TWILIGHT)
    elif m := re.search(_LIT, low):
        lighting += [Lighting.DARK, Lighting.STREET_LIGHTS]
    elif m := re.search(_DARK, low):
        lighting.append(Lighting.DARK)
    elif m := re.search(_DAY, low):
        lighting.append(Lighting.DAYLIGHT)
    if m:
        spots.append(("environment.lighting", "named", *m.span()))
    return Environment(tuple(weather) or UNKNOWN, tuple(lighting) or UNKNOWN), spots


def extract_environment(text: str) -> Environment:
    return read_environment(text)[0]


def first_speed(text: str) -> Speed | Unknown:
    """The first speed stated; in km/h when both units are given (the ground truth's convention)."""
    found = [(int(v), u.lower()) for v, u in _SPEED.findall(text)]
    metric = [v for v, u in found if not _miles(u)]
    if metric:
        return Speed(metric[0], SpeedUnit.KMH)
    return Speed(found[0][0], SpeedUnit.MPH) if found else UNKNOWN


def read_speed_limit(text: str) -> tuple[Speed | Unknown, int]:
    """The posted limit and the index of the sentence that states it (-1 if none); with several (a side road,
    a ramp, a school zone), the lowest, as the ground truth has it."""
    limits: list[tuple[Speed, int]] = []
    for i, sentence in enumerate(sentences(text)):
        if re.search(r"speed limits?|posted|limit|designated", sentence, re.IGNORECASE):  # "designated 104 kmph"
            found = [(int(v), u.lower()) for v, u in _SPEED.findall(sentence)]
            metric = [Speed(v, SpeedUnit.KMH) for v, u in found if not _miles(u)]
            limits += [(limit, i) for limit in metric or [Speed(v, SpeedUnit.MPH) for v, u in found]]
    return min(limits, key=lambda li: li[0].to_mps()) if limits else (UNKNOWN, -1)


def extract_speed_limit(text: str) -> Speed | Unknown:
    return read_speed_limit(text)[0]


def read_lanes(text: str) -> tuple[int | Unknown, tuple[int, int] | None]:
    """Lanes of the widest road, both directions together, and where the count was read."""
    low = text.lower()
    counts: list[tuple[int, tuple[int, int]]] = []
    each = r"(?: of travel)? (?:in )?(?:each|either|per|both)(?: the \w+ and \w+)? directions?"
    for m in re.finditer(_NUMBER + r"[- ]lanes?" + each, low):
        counts.append((2 * number(m.group(1)), m.span()))
    for m in re.finditer(_NUMBER + r"[- ]lanes?\b(?!" + each + ")", low):
        tail = low[m.end() : m.end() + 60]
        if t := re.match(
            r",? ?(?:\(|of travel\b|(?:[\w/-]+,? ){0,4}?(?:two-way|undivided|divided|roadway|road|highway|street|"
            r"t-intersection|intersection|interstate|one-way|avenue|boulevard|arterial|freeway|expressway|route)\b|"
            r"(?:residential|rural|urban|city|county|state))",
            tail,
        ):
            counts.append((number(m.group(1)), (m.start(), m.end() + t.end())))
        # the road said before the count: "the east/west roadway has five lanes", "the approach consists of"
        elif b := re.search(
            r"\b(?:road(?:way)?|street|highway|approach|avenue)\b[^.;]{0,40}?\b(?:has|had|have|consists? of"
            r"|consisted of) $",
            low[max(0, m.start() - 60) : m.start()],
        ):
            counts.append((number(m.group(1)), (m.start() - (min(60, m.start()) - b.start()), m.end())))
    if not counts:
        return UNKNOWN, None
    return max(counts, key=lambda c: c[0])


def extract_lanes(text: str) -> int | Unknown:
    return read_lanes(text)[0]


def read_road_kind(text: str) -> tuple[RoadKind, tuple[int, int] | None]:
    """The kind of road, and the words that say it (none for a straight road: no junction was named)."""
    low = text.lower()
    if m := re.search(r"\b['\"]?[ty]['\"]?[- ]?(?:intersection|junction|type)|three[- ]leg|3[- ]leg", low):
        return RoadKind.T_JUNCTION, m.span()
    # (a "non-intersection" or "non-junction" road is one away from any junction, as crash databases code it)
    if m := re.search(r"(?<!non-)(?<!non )\bintersection\b|\bintersecting\b", low):
        return RoadKind.INTERSECTION, m.span()
    return RoadKind.STRAIGHT, None


def extract_road_kind(text: str) -> RoadKind:
    return read_road_kind(text)[0]


def _lane(text: str, lanes: int | Unknown, each_way: int | Unknown) -> int | Unknown:
    if m := re.search(
        r"\blane (?:#|number |no\.? )?" + _NUMBER + r"\b(?![-/])|\bnumber " + _NUMBER + r" lane", text, re.I
    ):
        return number(m.group(1) or m.group(2))
    if re.search(r"\blane from the (?:left|right|curb|median|cent)", text, re.I):  # "the second lane from the left"
        return placed_lane(text, each_way)
    if m := re.search(r"\b(first|second|third|fourth|fifth) (?:\w+ ){0,2}lane\b", text, re.IGNORECASE):
        return ORDINALS[m.group(1).lower()]
    if re.search(r"\b(?:right|curb|outside|outer|only|slow) (?:\w+ )?lane\b(?! of the \w+bound)", text, re.I):
        return 1
    if not isinstance(placed := placed_lane(text, each_way), Unknown):  # left, inside, middle: see lanes.py
        return placed
    if lanes == 2 and re.search(r"\b(?:in|within) the (?:north|south|east|west)bound (?:travel )?lane\b", text, re.I):
        return 1  # a road with one lane each way
    if _ONE_LANE_ROAD.search(text):  # its own road has one lane its way, whatever the widest road has
        return 1
    return UNKNOWN


_ONE_LANE_ROAD = re.compile(
    # (a course between the verb and the road: "north", "in a northerly direction")
    r"\b(?:travel\w*|driv\w*|head\w*|was|were|proceed\w*) (?:(?:in an? \w+ direction|\w+) ){0,2}(?:on|along) (?:a|the) "
    r"(?:[\w-]+,? ){0,3}?"
    r"(?:roadway|road|street|highway) with one lane (?:of travel )?(?:in each|each|per|in either) direction"
    r"|\b(?:on|along) (?:a|the) one-way (?:roadway|road|street) with one lane\b",
    re.I,
)


def _lane_of(pieces: list[Piece], lanes: int | Unknown, each_way: int | Unknown) -> tuple[int | Unknown, Piece | None]:
    """The lane a vehicle started in: not one it turned into, nor one it came to rest in after the impact."""
    for piece in pieces:
        text = re.sub(r"\b(?:turn|turned|turning) (?:\w+ ){0,3}into (?:the )?[^.,;]*", " ", piece.text)
        text = re.sub(r"[^.,;]*\b(?:rest|pushed|spun|rotated)\b[^.,;]*", " ", text)
        if not isinstance(lane := _lane(text, lanes, each_way), Unknown):
            return lane, piece
    return UNKNOWN, None


def _speed(pieces: list[Piece]) -> tuple[Speed | Unknown, Piece | None]:
    for piece in pieces:
        speed = first_speed(piece.text)
        if not re.search(r"\blimit|\bposted", piece.text, re.IGNORECASE) and not isinstance(speed, Unknown):
            return speed, piece
    return UNKNOWN, None


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


def _shared_headings(sents: list[str], people: list[Participant], spots: list[Spot]) -> list[Participant]:
    """Headings and lanes stated once for two vehicles: "V1 and V2 were traveling north", "V1 ... behind V2",
    "V2 was stopped in the same lane ahead of V1". The sentence is the evidence of each fact it fills."""
    heading = {p.id: p.heading for p in people}
    lane = {p.id: p.lane for p in people}
    people_by = {p.id: p for p in people}

    def fill(table: dict[str, Any], pid: str, value: Any, i: int) -> None:
        if isinstance(table[pid], Unknown) and not isinstance(value, Unknown):
            table[pid] = value
            spots.append((f"{pid}.{'heading' if table is heading else 'lane'}", "sentence", i, 0))

    for i, sentence in enumerate(sents):
        if m := _BOTH.search(sentence):
            for pid in m.group(1, 2):
                if pid in heading:
                    fill(heading, pid, Heading(m.group(3).lower()), i)
        if (m := _SAME_LANE.search(sentence)) and m.group(1) != m.group(2):
            a, b = people_by[m.group(1)], people_by[m.group(2)]
            fill(lane, a.id, lane[b.id], i)
            fill(lane, b.id, lane[a.id], i)
        if m := _SAME_WAY.search(sentence):
            a, b = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
            if a in heading and b in heading:
                if isinstance(heading[a], Unknown):
                    fill(heading, a, heading[b], i)
                elif isinstance(heading[b], Unknown):
                    fill(heading, b, heading[a], i)
    return [replace(p, heading=heading[p.id], lane=lane[p.id]) for p in people]


_SCENE = re.compile(
    r"\boccurred (?:in|on|within) the (?:(right|left|curb) lane of the )?(north|south|east|west)bound"
    r" (?:travel )?lanes?\b",
    re.IGNORECASE,
)


def _scene(text: str, people: list[Participant], parked: set[str], spots: list[Spot]) -> list[Participant]:
    """ "The crash occurred in the right lane of the southbound lanes": when no vehicle's own heading is stated,
    the moving ones all drove so (and in that lane)."""
    moving = [p for p in people if p.role is Role.VEHICLE and p.id not in parked]
    m = _SCENE.search(text)
    if m is None or not moving or not all(isinstance(p.heading, Unknown) for p in moving):
        return people
    lane = 1 if m.group(1) and m.group(1).lower() in ("right", "curb") else UNKNOWN
    for p in moving:
        spots.append((f"{p.id}.heading", "named", *m.span()))
        if isinstance(p.lane, Unknown):
            spots.append((f"{p.id}.lane", "named", *m.span()))  # dropped below if it stays unknown
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


def _left_road_to_strike(people: list[Participant], striker: str | Unknown | None) -> bool:
    """Whether the striker's last move before the impact took it off the road."""
    p = next((p for p in people if p.id == striker), None)
    return p is not None and isinstance(p.actions, tuple) and p.actions[-1:] == (Action(ActionKind.DRIVE_OFF),)


def _ending_stopped(actions: tuple[Action, ...]) -> tuple[Action, ...]:
    """The actions up to the last stop, or with a stop added."""
    stops = [i for i, a in enumerate(actions) if a.kind in (ActionKind.STOP, ActionKind.PARKED)]
    return actions[: stops[-1] + 1] if stops else (*actions, Action(ActionKind.STOP))


def extract(text: str, name: str, report_path: str | None = None, prepared: Prepared | None = None) -> Scenario:
    """A scenario from a report's text by rules alone; `prepared` is the report's `prepare_report`, when the
    caller has made it."""
    prepared = prepare_report(text) if prepared is None else prepared
    named = prepared.named
    sents = sentences(named)
    impact = first_impact(sents)
    if prepared.note is not None and "the automated vehicle" in prepared.note:
        impact = own_impact(sents, impact)  # a chain collision: the scenario is the automated vehicle's crash
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
    lanes, lanes_at = read_lanes(named)
    kind, kind_at = read_road_kind(named)
    before = [s for s in sents[: impact + 1]] if impact >= 0 else sents
    carry = next((p.who[0] for p in parts if p.sentence == impact and p.who), None)
    crash, crash_at = read_crash_at(sents, impact, carry)
    # The crash may be read from a later sentence that restates the impact ("The front of V1 then struck a
    # pedestrian"): whoever it names as striker or victim is a party, even if first named there.
    roles = {r for r in (crash.striker, crash.victim) if isinstance(r, str)}
    if not roles <= set(ids):
        ids = [pid for pid in participants(named) if pid in ids or pid in roles]
        parts = pieces(sents, ids)
        mine = by_participant(parts, ids)
    wrong_way = precrash_wrong_way(sents)
    if impact >= 0 and isinstance(crash.striker, str) and crash.striker in mine:
        stood = [p for p in mine[crash.striker] if p.sentence <= impact]
        crash = moving_met_standing(crash, sents[impact], read_actions_at(stood, kind, UNKNOWN, False)[0])
    clauses: dict[str, list[Piece]] = {}
    people = []
    parked: set[str] = set()
    spots: list[Spot] = []
    for pid in ids:
        early = [p for p in mine[pid] if impact < 0 or p.sentence <= impact]
        late = [p for p in mine[pid] if p not in early]
        clauses[pid] = early
        heading, said, at = read_heading(early)
        if isinstance(heading, Unknown):
            heading, said, at = read_heading(late, after_impact=True)
        heading, said, at = heading_before_turn(early) if isinstance(heading, Unknown) else (heading, said, at)
        each_way = per_direction(" ".join(p.text for p in early), named, lanes, kind is RoadKind.STRAIGHT)
        lane, where = _lane_of(early, lanes, each_way)
        lane, where = _lane_of(late, lanes, each_way) if isinstance(lane, Unknown) else (lane, where)
        speed, fast = _speed(early)
        spots += [_clause(f"{pid}.heading", said, at)] if said else []
        spots += [_clause(f"{pid}.{fact}", piece) for fact, piece in _facts(lane=where, speed=fast)]
        if any(_PARKED.search(p.text) for p in early):
            parked.add(pid)
        if pid.startswith("P"):
            walked = next((p for p in early if _WALKING.search(p.text)), None)
            crossed = next((p for p in early if _CROSSING.search(p.text)), None)
            walking = walked is not None and crossed is None
            if walked is None and crossed is None and _left_road_to_strike(people, crash.striker):
                # met where its striker had left the road: not crossing it, and how it moved is not said
                people.append(Participant(pid, Role.PEDESTRIAN, heading, lane, speed, UNKNOWN))
                continue
            action = Action(ActionKind.WALK if walking else ActionKind.CROSS)
            people.append(Participant(pid, Role.PEDESTRIAN, heading, lane, speed, (action,)))
            if (piece := walked if walking else crossed) is not None:
                spots.append(_clause(f"{pid}.actions[1]", piece))
            if not walking and crash.victim == pid and isinstance(crash.type, Unknown):
                crash = replace(crash, type=CrashType.SIDE)  # one crossing the road is struck from its side
                if crossed is not None:
                    spots.append(_clause("crash.type", crossed))
            continue
        behind = crash.type is CrashType.REAR_END and crash.victim == pid
        side = crash.type is CrashType.SIDE
        toward = _moved_toward(sents[impact] if impact >= 0 else "", pid, crash)
        actions, ats = read_actions_at(early, kind, heading, crash.striker == pid, behind, side, toward)
        spots += [
            _clause(f"{pid}.actions[{n}]", p, at - p.at) for n, at in enumerate(ats, 1) if (p := _piece_at(early, at))
        ]
        if isinstance(actions, tuple) and impact >= 0 and still_at_impact(sents[impact], pid):
            actions = _ending_stopped(actions)
        elif isinstance(actions, Unknown) and impact >= 0 and (stood := stood_at_impact(sents[impact], pid)):
            actions = (Action(stood),)  # nothing told before, but "struck the stationary V1": it stood there
        if isinstance(actions, Unknown) and crash.striker == pid and crash.type is CrashType.REAR_END:
            actions = (Action(ActionKind.FOLLOW_LANE),)  # its front drove into the other's rear: it drove along
        if pid in wrong_way and isinstance(actions, tuple) and ActionKind.RETROGRADE not in [a.kind for a in actions]:
            actions = (*actions, Action(ActionKind.RETROGRADE))
            spots.append((f"{pid}.actions[{len(actions)}]", "sentence", wrong_way[pid], 0))
        if isinstance(actions, Unknown) and isinstance(heading, Unknown):
            lane = UNKNOWN  # nothing said about it before the impact: where it was is not known either
        people.append(Participant(pid, Role.VEHICLE, heading, lane, speed, actions))
    people = introduced_doing(people, prepared.words, named, spots)
    people = _with_kinds(people, prepared.words, named, spots)
    people = _shared_headings(before, people, spots)
    people = _scene(named, people, parked, spots)
    if crash_at >= 0 and (backers := backing(people)):
        # read again knowing who backed: its rear is the end it moved with (see `crash.read_sentence`)
        crash, crash_at = read_crash_at(sents, impact, carry, backers)
    people, crash = wrong_side(people, clauses, crash, kind is RoadKind.STRAIGHT)
    crash = backing_leads(people, crash)
    crash = backed_into_follower(crash, backing(people), named)
    crash = door_met(standing_struck(people, crash, sents[impact] if impact >= 0 else ""), sents, crash_at)
    crash, type_at = damaged_part(crash, sents, crash_at, backing(people))
    environment, found = read_environment(named)
    spots += found
    speed_limit, limit_at = read_speed_limit(named)
    spots += [("road.speed_limit", "sentence", limit_at, 0)] if limit_at >= 0 else []
    spots += [("road.lanes", "named", *lanes_at)] if lanes_at else []
    spots += [("road.kind", "named", *kind_at)] if kind_at else []
    said = {"type": type_at, "striker": crash_at, "victim": crash_at}
    spots += [(f"crash.{f}", "sentence", at, 0) for f, at in said.items() if at >= 0]
    locate = Locator(text, named, sents)
    provenance = Provenance(
        report_path or UNKNOWN,
        hashlib.sha256(text.encode("utf-8")).hexdigest(),
        "rules",
        UNKNOWN,
        evidence=tuple(locate.evidence(*spot) for spot in spots),
    )
    scenario = Scenario(name, provenance, environment, Road(kind, lanes, speed_limit), tuple(people), crash)
    return keep_stated(scenario)


def _moved_toward(sentence: str, pid: str, crash: Crash) -> str | None:
    """The side the striker moved to, read from the sides the impact met: two vehicles side by side meet where
    one moved over into the other, so its own side that met is the way it moved, and the other's side that met
    is the side it came from (the other way). None for the victim (the side it was met on says where the striker
    came from, not where it went), when the sentence names no side of either, or when the other is a pedestrian
    (one crossing in front meets a car's front from the side it came from, not alongside)."""
    met = sides_met(sentence)
    other = crash.victim if crash.striker == pid else None
    if not isinstance(other, str) or not other.startswith("V"):
        return None
    if pid in met:
        return met[pid]
    if other in met:
        return "right" if met[other] == "left" else "left"
    return None


def _with_kinds(people: list[Participant], words: dict[str, str], named: str, spots: list[Spot]) -> list[Participant]:
    """Each vehicle with the kind the report names it by (see `kinds`), and where that was read: the noun of
    an appositive, or the participant's first mention, where the words it was named by (`words`) were."""
    kinds = stated_kinds(named, words)
    out = []
    for p in people:
        kind, span = kinds.get(p.id, (None, None))
        first = re.search(rf"\b{p.id}\b", named)
        span = span or (first.span() if first else None)
        if p.role is not Role.VEHICLE or kind is None or span is None:
            out.append(p)
            continue
        spots.append((f"{p.id}.kind", "named", *span))
        out.append(replace(p, kind=kind))
    return out


def _facts(**pieces: Piece | None) -> list[tuple[str, Piece]]:
    return [(fact, piece) for fact, piece in pieces.items() if piece is not None]


# Where one clause of a piece ends and the next begins: "was traveling north in the left lane and proceeded to
# make a left turn".
_CLAUSE_BREAK = re.compile(r"[,;:]| and (?:then )?| then | but | when | as ", re.I)


def _clause(fact: str, piece: Piece, offset: int | None = None) -> Spot:
    """A fact read in a piece of text about a participant: the clause around `offset` (where the reader
    matched), or the whole piece when the match was made in a reworded copy of it (see `what_was_done`)."""
    text = piece.text
    if offset is None or not 0 <= offset < len(text) or what_was_done(text) != text:
        return (fact, "joined", piece.at, piece.at + len(text))
    breaks = list(_CLAUSE_BREAK.finditer(text))
    start = max((m.end() for m in breaks if m.end() <= offset), default=0)
    end = min((m.start() for m in breaks if m.start() > offset), default=len(text))
    return (fact, "joined", piece.at + start, piece.at + end)


def _piece_at(pieces: list[Piece], at: int) -> Piece | None:
    """The piece an action was read in; an action an after-clause puts first, or one inferred right after
    another, sits one character off its piece."""
    for probe in (at, at + 1, at - 1):
        if piece := next((p for p in pieces if p.at <= probe < p.at + len(p.text)), None):
            return piece
    return None
