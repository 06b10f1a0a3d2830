"""The crash database's own coded variables as labels for extracted IR: a held-out set with labels.

NMVCCS codes every case (`coded_variables.csv`, one row per case, values per vehicle joined by " | ", in
vehicle number order). Those codes were made by the crash investigators, not by the SoVAR labellers and not
for this project, so they label the 25 `other` reports no rule was tuned on. This module is the project's
mapping from the codes to IR facts, and a scorer in the form of `extraction.score_case`.

The codes say less than the IR, so each is mapped to what it does say:
- pre-event movement, crash type and critical event of a vehicle say whether it turned (and which way),
  went the wrong way (an opposite-direction "lateral move"), changed lanes, left a parking place or ran off
  the road; a vehicle coded as moving straight with no turn anywhere in its codes did not turn. The IR's
  actions must contain what the codes need and nothing they deny (an action set, not a sequence: the codes
  keep no order);
- the crash type family gives the IR crash type: rear-end, head-on (frontal), and the angle families
  (turn across path, turn into path, straight paths), which strike a side;
- travel lane ("Lane one (right curb lane)") is the IR lane, counted from the right, where the IR states one;
- natural lighting, atmospheric condition, speed limit (km/h), relation to junction, vehicle count.
A code with no IR counterpart (a ramp, "Other (specify)", "No statutory limit") is not scored.
"""

from __future__ import annotations

import csv
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from sovarc.dsl.ir import ActionKind, CrashType, Lighting, Participant, RoadKind, Role, Scenario, Unknown, Weather

ATTRIBUTES: tuple[str, ...] = (
    "Weather",
    "Light",
    "SpeedLimit",
    "CollisionLocation",
    "DrivingActions",
    "CrashType",
    "RunningLanes",
    "ParticipantsNumber",
)

_LIGHT = {
    "Daylight": (Lighting.DAYLIGHT,),
    "Dark, but lighted": (Lighting.DARK, Lighting.STREET_LIGHTS),
    "Dark": (Lighting.DARK,),
    "Dusk": (Lighting.TWILIGHT,),
    "Dawn": (Lighting.TWILIGHT,),
}
_WEATHER = {
    "Clear--No adverse conditions": Weather.CLEAR,
    "Cloudy": Weather.CLOUDY,
    "Rain": Weather.RAINY,
    "Snow": Weather.SNOWY,
    "Fog, smog, smoke": Weather.FOGGY,
}
_LANE = {"Lane one (right curb lane)": 1, "Lane two": 2, "Lane three": 3, "Lane four": 4, "Lane five": 5}
_TURNS = frozenset((ActionKind.TURN_LEFT, ActionKind.TURN_RIGHT, ActionKind.U_TURN))


@dataclass(frozen=True)
class Coded:
    """One case's codes, per vehicle where the database codes them per vehicle."""

    name: str  # "kind/n", as the report's path under reports/
    vehicles: int
    weather: tuple[str, ...]
    lighting: tuple[str, ...]
    speed_limit: tuple[str, ...]
    junction: tuple[str, ...]
    crash_type: tuple[str, ...]
    movement: tuple[str, ...]
    event: tuple[str, ...]
    lane: tuple[str, ...]


@dataclass(frozen=True)
class Moves:
    """What a vehicle's codes say about its actions: each set in `need` must meet its actions; `deny` none."""

    need: tuple[frozenset[ActionKind], ...] = ()
    deny: frozenset[ActionKind] = frozenset()

    def fits(self, kinds: set[ActionKind]) -> bool:
        return all(kinds & need for need in self.need) and not kinds & self.deny

    def __str__(self) -> str:
        need = " and ".join("/".join(sorted(k.value for k in n)) for n in self.need)
        deny = "/".join(sorted(k.value for k in self.deny))
        return ", ".join(x for x in (need and f"needs {need}", deny and f"no {deny}") if x) or "anything"


def load(path: Path) -> dict[str, Coded]:
    """ "kind/n" -> the case's codes."""

    def each(value: str) -> tuple[str, ...]:
        return tuple(v.strip() for v in value.split(" | "))

    out: dict[str, Coded] = {}
    with path.open(encoding="utf-8", newline="") as f:
        for row in csv.DictReader(f):
            name = f"{row['category']}/{row['index']}"
            out[name] = Coded(
                name,
                int(row["NumOfVehicle"]),
                each(row["ATMOSPHERICCONDITION"]),
                each(row["NATURAL_LIGHTING"]),
                each(row["SPEED_LIMIT"]),
                each(row["RELATION_TO_JUNCTION"]),
                each(row["CRASH_TYPE"]),
                each(row["PRE_EVENT_MOVEMENT"]),
                each(row["CRITICAL_EVENT"]),
                each(row["TRAVEL_LANE"]),
            )
    return out


def moves(movement: str, crash_type: str, event: str) -> Moves:
    """What one vehicle's pre-event movement, crash type and critical event say it did (see the module's note)."""
    left = movement == "Turning left" or event == "Turning left at intersection" or "(Turning Left)" in crash_type
    right = movement == "Turning right" or event == "Turning right at intersection" or "(Turning Right)" in crash_type
    need: list[frozenset[ActionKind]] = []
    if left and right:  # the codes disagree on the side: a turn either way
        need.append(frozenset((ActionKind.TURN_LEFT, ActionKind.TURN_RIGHT)))
    elif left:
        need.append(frozenset((ActionKind.TURN_LEFT,)))
    elif right:
        need.append(frozenset((ActionKind.TURN_RIGHT,)))
    elif crash_type.startswith(("Turn Across Path", "Turn Into")) and "(Left/Right)" in crash_type:
        need.append(_TURNS)
    if movement == "Making a U-turn":
        need.append(frozenset((ActionKind.U_TURN,)))
    # An opposite-direction lateral move is a vehicle leaving its side of the road into the other's.
    if crash_type.startswith(("Head-On: Lateral Move (Left/Right)", "Sideswipe/Angle: Lateral Move (Left/Right)")):
        need.append(frozenset((ActionKind.RETROGRADE,)))
    if crash_type.startswith("Sideswipe/Angle: Changing Lanes") or movement == "Merging":
        need.append(frozenset((ActionKind.CHANGE_LANE,)))
    if movement == "Leaving a parking position":
        need.append(frozenset((ActionKind.DRIVE_INTO,)))
    if crash_type.startswith("Right roadside departure"):
        need.append(frozenset((ActionKind.DRIVE_OFF,)))
    if crash_type.startswith("Left roadside departure"):  # across the other direction's lanes first
        need.append(frozenset((ActionKind.RETROGRADE, ActionKind.DRIVE_OFF)))
    if movement == "Stopped in traffic lane" and crash_type.startswith("Rear-end") and ", " in crash_type:
        need.append(frozenset((ActionKind.STOP,)))  # the struck one, standing in its lane
    turned = left or right or any(n & _TURNS for n in need)
    straight = movement in ("Going straight", "Negotiating a curve", "Decelerating in traffic lane") or (
        movement in ("Stopped in traffic lane", "Starting in traffic lane", "Accelerating in traffic lane")
    )
    return Moves(tuple(need), _TURNS if straight and not turned else frozenset())


def _kinds(p: Participant) -> set[ActionKind]:
    return set() if isinstance(p.actions, Unknown) else {a.kind for a in p.actions}


def _crash_type(code: str) -> frozenset[CrashType] | None:
    """The IR crash types a coded crash type allows. The IR's type is the struck vehicle's part hit; a turn
    across or into an oncoming vehicle's path hits its side or, as often, its front, so both are allowed."""
    if code.startswith("Rear-end"):
        return frozenset((CrashType.REAR_END,))
    if code.startswith("Head-On"):
        return frozenset((CrashType.FRONTAL,))
    if code.startswith(("Turn Across Path: Initial Opposite", "Turn Into Opposite")):
        return frozenset((CrashType.SIDE, CrashType.FRONTAL))
    if code.startswith(("Turn Across Path", "Turn Into", "Straight Paths")):
        return frozenset((CrashType.SIDE,))
    return None


def _speed_kmh(codes: tuple[str, ...]) -> int | None:
    """The lowest posted limit coded, as the ground truth takes the lowest of several."""
    values = [int(c) for c in codes if c.isdigit()]
    return min(values) if values else None


Result = tuple[bool, str] | None  # None: the codes say nothing the IR can be held to


def score(got: Scenario, coded: Coded) -> dict[str, Result]:
    """attribute -> (right?, what differed), or None where the codes do not score it."""
    vehicles = [p for p in got.participants if p.role is Role.VEHICLE]
    by_id = {p.id: p for p in vehicles}
    out: dict[str, Result] = {}

    weather = {_WEATHER[w] for w in coded.weather if w in _WEATHER}
    mine = set() if isinstance(got.environment.weather, Unknown) else set(got.environment.weather)
    mine = {Weather.CLEAR if w is Weather.SUNNY else w for w in mine}  # sunny is clear to the database
    out["Weather"] = (mine == weather, f"{sorted(mine)} ≠ {sorted(weather)}") if weather else None

    light = _LIGHT.get(coded.lighting[0])
    lit = got.environment.lighting
    out["Light"] = (
        None if light is None else (not isinstance(lit, Unknown) and set(lit) == set(light), f"{lit} ≠ {light}")
    )

    kmh = _speed_kmh(coded.speed_limit)
    limit = got.road.speed_limit
    out["SpeedLimit"] = (
        None
        if kmh is None
        else (not isinstance(limit, Unknown) and abs(limit.to_mps() * 3.6 - kmh) < 1.5, f"{limit} ≠ {kmh} km/h")
    )

    junction = coded.junction[0]
    want = {"Intersection": True, "Intersection related": True, "Non-junction": False}.get(junction)
    kind = got.road.kind
    at = kind in (RoadKind.INTERSECTION, RoadKind.T_JUNCTION)
    out["CollisionLocation"] = None if want is None else (at == want, f"{kind} ≠ {junction}")

    out["ParticipantsNumber"] = (len(vehicles) == coded.vehicles, f"{len(vehicles)} ≠ {coded.vehicles} vehicles")

    crash = _crash_type(coded.crash_type[0])
    shown = "/".join(sorted(crash or ()))
    out["CrashType"] = None if crash is None else (got.crash.type in crash, f"{got.crash.type} ≠ {shown}")

    out["DrivingActions"] = _per_vehicle(coded, by_id, _actions)
    out["RunningLanes"] = _per_vehicle(coded, by_id, _lane)
    return out


def _actions(p: Participant, coded: Coded, i: int) -> Result:
    want = moves(coded.movement[i], coded.crash_type[i], coded.event[i])
    kinds = _kinds(p)
    return want.fits(kinds), f"{p.id}: [{', '.join(sorted(k.value for k in kinds))}] ≠ {want}"


def _lane(p: Participant, coded: Coded, i: int) -> Result:
    """A lane the IR states must be the coded one. The investigators code every vehicle's lane, while a report
    (and the ground truth's convention) leaves an unstated lane unknown, so an unknown lane is not scored: the
    count of cases scored shows how many lanes were stated."""
    want = _LANE.get(coded.lane[i])
    if want is None or isinstance(p.lane, Unknown):
        return None
    return p.lane == want, f"{p.id}: lane {p.lane} ≠ {want}"


def _per_vehicle(
    coded: Coded, by_id: dict[str, Participant], fact: Callable[[Participant, Coded, int], Result]
) -> Result:
    """Right when every coded vehicle is right; vehicle i of the codes is the report's V(i+1)."""
    results: list[tuple[bool, str]] = []
    for i in range(min(coded.vehicles, len(coded.movement))):
        p = by_id.get(f"V{i + 1}")
        if p is None:
            results.append((False, f"V{i + 1}: missing"))
        elif (r := fact(p, coded, i)) is not None:
            results.append(r)
    if not results:
        return None
    return all(ok for ok, _ in results), "; ".join(why for ok, why in results if not ok)


@dataclass
class CodedReport:
    cases: dict[str, dict[str, Result]]

    def accuracy(self, attribute: str) -> tuple[float, int]:
        """(percent right, cases scored)."""
        scored = [r[0] for c in self.cases.values() if (r := c.get(attribute)) is not None]
        return (100.0 * sum(scored) / len(scored) if scored else 0.0), len(scored)

    def failures(self, attribute: str) -> list[tuple[str, str]]:
        return [(n, r[1]) for n, c in sorted(self.cases.items()) if (r := c.get(attribute)) is not None and not r[0]]
