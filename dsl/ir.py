"""The scenario IR: what a crash report says, and nothing about any map.

Nodes are frozen dataclasses. Each carries a `meta` (source span, spans of its
fields, attached comments) that equality, hashing and the JSON form ignore, so
two scenarios are equal exactly when they state the same facts.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import Enum, StrEnum
from types import MappingProxyType
from typing import Literal, TypeVar

from sovarc.dsl.span import Span

T = TypeVar("T", bound=str)


class Unknown(Enum):
    """A fact the report does not state. Written `unknown`, never guessed."""

    UNKNOWN = "unknown"

    def __str__(self) -> str:
        return self.value


UNKNOWN = Unknown.UNKNOWN


class Weather(StrEnum):
    CLEAR = "clear"
    CLOUDY = "cloudy"
    FOGGY = "foggy"
    RAINY = "rainy"
    SNOWY = "snowy"
    SUNNY = "sunny"
    WINDY = "windy"


class Lighting(StrEnum):
    DARK = "dark"
    DAYLIGHT = "daylight"
    STREET_LIGHTS = "street_lights"  # road lit by lamps; usually together with dark
    TWILIGHT = "twilight"  # dawn or dusk: the sun at or just below the horizon


class RoadKind(StrEnum):
    INTERSECTION = "intersection"  # four-way crossing
    T_JUNCTION = "t_junction"  # also Y and other three-way junctions
    STRAIGHT = "straight"  # a road segment away from junctions


class SpeedUnit(StrEnum):
    KMH = "km/h"
    MPH = "mph"


class Heading(StrEnum):
    NORTH = "north"
    EAST = "east"
    SOUTH = "south"
    WEST = "west"


class Role(StrEnum):
    VEHICLE = "vehicle"
    PEDESTRIAN = "pedestrian"


class VehicleKind(StrEnum):
    """What a vehicle is; its body and limits are the vehicle model's row of that kind."""

    CAR = "car"
    VAN = "van"  # also minivans
    PICKUP = "pickup"
    BUS = "bus"
    TRUCK = "truck"  # a heavy truck, tractor-trailer or box truck
    MOTORCYCLE = "motorcycle"  # also mopeds and scooters with an engine
    BICYCLE = "bicycle"  # the cyclist and the bicycle, one body


class Side(StrEnum):
    LEFT = "left"
    RIGHT = "right"


class ActionKind(StrEnum):
    FOLLOW_LANE = "follow_lane"
    TURN_LEFT = "turn_left"
    TURN_RIGHT = "turn_right"
    CHANGE_LANE = "change_lane"
    GO_ACROSS = "go_across"
    STOP = "stop"
    U_TURN = "u_turn"
    DRIVE_INTO = "drive_into"
    DRIVE_OFF = "drive_off"
    RETROGRADE = "retrograde"
    CROSS = "cross"
    WALK = "walk"
    REVERSE = "reverse"
    PARKED = "parked"


class CrashType(StrEnum):
    REAR_END = "rear_end"  # striker's front into the victim's rear, same heading
    FRONTAL = "frontal"  # front to front, opposing headings
    SIDE = "side"  # striker's front into the victim's side


@dataclass(frozen=True)
class ActionSpec:
    """What an action means and which arguments it takes; the one table the verifier,
    the JSON Schema and the prompts read."""

    roles: frozenset[Role]
    to: Literal["required", "optional", "none"]
    meaning: str


_VEHICLE = frozenset({Role.VEHICLE})
_PEDESTRIAN = frozenset({Role.PEDESTRIAN})

ACTION_SPECS: Mapping[ActionKind, ActionSpec] = MappingProxyType(
    {
        ActionKind.FOLLOW_LANE: ActionSpec(_VEHICLE, "none", "keep driving in the current lane"),
        ActionKind.TURN_LEFT: ActionSpec(
            _VEHICLE, "optional", "turn left at a junction or into a road; `to` is the lane entered"
        ),
        ActionKind.TURN_RIGHT: ActionSpec(
            _VEHICLE, "optional", "turn right at a junction or into a road; `to` is the lane entered"
        ),
        ActionKind.CHANGE_LANE: ActionSpec(
            _VEHICLE,
            "optional",
            "move to lane `to` (a number, or left/right when only the side is known; none when the report does not "
            "say which way)",
        ),
        ActionKind.GO_ACROSS: ActionSpec(_VEHICLE, "none", "drive straight through a junction"),
        ActionKind.STOP: ActionSpec(_VEHICLE, "none", "slow to a standstill and stay stopped"),
        ActionKind.U_TURN: ActionSpec(
            _VEHICLE, "optional", "turn around into the opposite direction; `to` is the lane entered"
        ),
        ActionKind.DRIVE_INTO: ActionSpec(_VEHICLE, "none", "enter the road from a driveway, parking lot or shoulder"),
        ActionKind.DRIVE_OFF: ActionSpec(_VEHICLE, "none", "leave the road to a driveway, parking lot or shoulder"),
        ActionKind.RETROGRADE: ActionSpec(
            _VEHICLE, "none", "drive in a lane of the opposite direction, e.g. across a double yellow line"
        ),
        ActionKind.REVERSE: ActionSpec(
            _VEHICLE,
            "none",
            "drive backwards along the lane; after `parked`, back out of the parking space into the lane",
        ),
        ActionKind.PARKED: ActionSpec(
            _VEHICLE, "none", "stand parked at the kerb or in a parking lane, off the travel lane (first action only)"
        ),
        ActionKind.CROSS: ActionSpec(_PEDESTRIAN, "none", "walk across the road"),
        ActionKind.WALK: ActionSpec(_PEDESTRIAN, "none", "walk along the road"),
    }
)


def _no_spans() -> Mapping[str, Span]:
    return MappingProxyType({})


@dataclass(frozen=True)
class Trivia:
    """Comments around one printed line: own lines before it, one after it on the line,
    and (for blocks) own lines before the closing brace."""

    leading: tuple[str, ...] = ()
    trailing: str | None = None
    closing: tuple[str, ...] = ()


@dataclass(frozen=True)
class Meta:
    """Where a node came from. Ignored by equality: it is not a fact of the scenario."""

    span: Span | None = None
    fields: Mapping[str, Span] = field(default_factory=_no_spans)
    comments: Mapping[str, Trivia] = field(default_factory=_no_spans)

    def where(self, name: str | None = None) -> Span | None:
        """The span of field `name` if it was written, else of the whole node."""
        return self.fields.get(name, self.span) if name else self.span


def _meta() -> Meta:
    return Meta()


def _as_set(values: tuple[T, ...]) -> tuple[T, ...]:
    return tuple(sorted(set(values)))


META = field(default_factory=_meta, compare=False, repr=False, kw_only=True)


@dataclass(frozen=True)
class Speed:
    value: float
    unit: SpeedUnit

    def to_mps(self) -> float:
        return self.value / 3.6 if self.unit is SpeedUnit.KMH else self.value * 0.44704


class Reader(StrEnum):
    """Which reader of the front end read a fact."""

    RULES = "rules"
    MODEL = "model"
    DEFAULT = "default"


FACT_PATH = re.compile(
    r"(?P<head>[A-Za-z_][A-Za-z0-9_\-]*)\.(?P<field>[A-Za-z_][A-Za-z0-9_]*)(?:\[(?P<index>[0-9]+)\])?"
)
_SECTIONS = {"environment": 0, "road": 1, "crash": 3}
_PARTICIPANT = 2
# Fields of each section in the order the printer writes them (kept in step with it by a test).
FIELD_ORDER: Mapping[int, Mapping[str, int]] = MappingProxyType(
    {
        section: MappingProxyType({f: i for i, f in enumerate(names)})
        for section, names in (
            (0, ("weather", "lighting")),
            (1, ("kind", "lanes", "speed_limit")),
            (_PARTICIPANT, ("role", "kind", "heading", "lane", "speed", "actions")),
            (3, ("type", "striker", "victim")),
        )
    }
)


def fact_key(path: str, order: Mapping[str, int] | None = None) -> tuple[int, int | str, int, str, int]:
    """Where a fact's path sorts: the sections in printed order, participants by `order` (else by name), then
    the field, then the action's number. A path of no known form sorts last, by its text."""
    m = FACT_PATH.fullmatch(path)
    if m is None:
        return (4, path, 0, "", 0)
    head, index = m["head"], int(m["index"] or 0)
    section = _SECTIONS.get(head, _PARTICIPANT)
    rank = FIELD_ORDER[section].get(m["field"], len(FIELD_ORDER[section]))
    if head in _SECTIONS:
        return (section, "", rank, m["field"], index)
    who: int | str = order.get(head, len(order)) if order is not None else head
    return (section, who, rank, m["field"], index)


@dataclass(frozen=True)
class Evidence:
    """Why a fact was read: the report's characters start..end (from 0, end exclusive), quoted.

    `fact` is the fact's path (`environment.weather`, `V2.actions[1]`), `reader` what read it there."""

    fact: str
    reader: Reader
    start: int
    end: int
    quote: str
    meta: Meta = META

    def sort_key(self, order: Mapping[str, int] | None = None) -> tuple[object, ...]:
        return (fact_key(self.fact, order), self.start, self.end, self.reader.value, self.quote)


@dataclass(frozen=True)
class Provenance:
    report: str | Unknown = UNKNOWN
    sha256: str | Unknown = UNKNOWN
    frontend: str | Unknown = UNKNOWN
    model: str | Unknown = UNKNOWN
    assumed: tuple[str, ...] = ()  # dotted paths of facts filled in by the defaults pass
    evidence: tuple[Evidence, ...] = ()  # where in the report each fact was read
    meta: Meta = META

    def __post_init__(self) -> None:
        object.__setattr__(self, "assumed", _as_set(self.assumed))
        # A set of statements, kept in one order so that equality ignores the order they were made in.
        object.__setattr__(self, "evidence", tuple(sorted(set(self.evidence), key=Evidence.sort_key)))

    def evidence_for(self, fact: str) -> tuple[Evidence, ...]:
        return tuple(e for e in self.evidence if e.fact == fact)


@dataclass(frozen=True)
class Environment:
    weather: tuple[Weather, ...] | Unknown = UNKNOWN
    lighting: tuple[Lighting, ...] | Unknown = UNKNOWN
    meta: Meta = META

    def __post_init__(self) -> None:
        # Sets, not sequences: keep them sorted so that equality ignores order.
        for name in ("weather", "lighting"):
            value = getattr(self, name)
            if not isinstance(value, Unknown):
                object.__setattr__(self, name, _as_set(value))


@dataclass(frozen=True)
class Road:
    kind: RoadKind | Unknown = UNKNOWN
    lanes: int | Unknown = UNKNOWN  # widest road, both directions together
    speed_limit: Speed | Unknown = UNKNOWN
    meta: Meta = META


@dataclass(frozen=True)
class Action:
    kind: ActionKind
    to: int | Side | None = None  # target lane, for the actions whose spec allows it
    meta: Meta = META

    @property
    def sideless(self) -> bool:
        """A lane change said without its side: the report left it open, lowering chooses it (lower/sides.py)."""
        return self.kind is ActionKind.CHANGE_LANE and self.to is None


@dataclass(frozen=True)
class Participant:
    id: str
    role: Role
    heading: Heading | Unknown = UNKNOWN
    lane: int | Unknown = UNKNOWN  # counted from the right-most lane of its direction, from 1
    speed: Speed | Unknown = UNKNOWN
    actions: tuple[Action, ...] | Unknown = ()  # unknown: the report does not say what it did
    # A vehicle's kind (unknown: the report does not say; it is staged as a car). Last, so that positional
    # construction and the JSON form of earlier scenarios keep their order.
    kind: VehicleKind | Unknown = UNKNOWN
    meta: Meta = META

    @property
    def known_actions(self) -> tuple[Action, ...]:
        return () if isinstance(self.actions, Unknown) else self.actions


@dataclass(frozen=True)
class Crash:
    type: CrashType | Unknown = UNKNOWN
    striker: str | Unknown = UNKNOWN
    victim: str | Unknown = UNKNOWN
    meta: Meta = META


@dataclass(frozen=True)
class Scenario:
    name: str
    provenance: Provenance | None = None
    environment: Environment = field(default_factory=Environment)
    road: Road = field(default_factory=Road)
    participants: tuple[Participant, ...] = ()
    crash: Crash = field(default_factory=Crash)
    meta: Meta = META

    def participant(self, pid: str) -> Participant | None:
        return next((p for p in self.participants if p.id == pid), None)
