"""The timed plan: what lowering and synthesis produce, and what every target consumes.

Conventions, shared by all targets and oracles:
- Coordinates are the map file's own (SUMO network coordinates; for an OpenDRIVE map,
  those of the network netconvert made from it, with --offset.disable-normalization).
- Headings are compass degrees: 0 = north (+y), 90 = east (+x), clockwise. This is
  SUMO's vehicle angle. A heading is the direction the body FACES: the direction of travel
  while driving forward, its opposite while reversing (the legs of a three-point turn).
- A sample's (x, y) is the FRONT-BUMPER CENTRE of a vehicle, as in SUMO, and the body
  centre of a pedestrian. `body.length` runs back from it along the heading, whichever way
  it moves.
- A sample's speed is signed: negative while reversing. A vehicle stands (speed 0) at every
  change between forward and reverse.
- Every trajectory is sampled at the plan's `step` from t = 0; all end at the same time.
- At `impact.time` the striker and the victim touch at the faces the crash type names;
  the trajectories go on for a short while after it, so that simulators see the overlap.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

from sovarc.compiler.vehicles import Body
from sovarc.dsl.ir import CrashType, RoadKind, Role, Scenario
from sovarc.dsl.jsonform import from_json, to_json

PLAN_FORMAT = "sovarc-plan-1"


@dataclass(frozen=True)
class Sample:
    t: float  # s
    x: float  # m
    y: float  # m
    heading: float  # compass degrees, [0, 360)
    speed: float  # m/s along the heading; negative while reversing (a three-point turn)


@dataclass(frozen=True)
class Segment:
    """One action of a participant, as lowering placed and timed it."""

    action: str  # the IR action (or 'approach' / 'after' around them)
    start_s: float  # m along the participant's path
    end_s: float
    start_t: float  # s
    end_t: float
    speed: float  # m/s planned cruise speed over the segment (0 while stopped)


@dataclass(frozen=True)
class Trajectory:
    participant: str
    role: Role
    body: Body
    samples: tuple[Sample, ...]
    lanes: tuple[str, ...]  # SUMO lane ids its actions allow it to occupy (junction lanes included)
    edges: tuple[str, ...]  # SUMO edges it drives along, in order (a route for SUMO); may be empty
    segments: tuple[Segment, ...]
    impact_s: float | None  # m along its path where it is at impact; None for a bystander

    def at(self, t: float) -> Sample:
        """The sample at time t, interpolated linearly (clamped to the ends)."""
        samples = self.samples
        if t <= samples[0].t:
            return samples[0]
        if t >= samples[-1].t:
            return samples[-1]
        step = samples[1].t - samples[0].t
        k = min(int((t - samples[0].t) / step), len(samples) - 2)
        a, b = samples[k], samples[k + 1]
        u = (t - a.t) / (b.t - a.t)
        turn = ((b.heading - a.heading + 180.0) % 360.0) - 180.0
        return Sample(
            t,
            a.x + u * (b.x - a.x),
            a.y + u * (b.y - a.y),
            (a.heading + u * turn) % 360.0,
            a.speed + u * (b.speed - a.speed),
        )


@dataclass(frozen=True)
class Impact:
    time: float  # s
    point: tuple[float, float]  # centre of the collision area C_A
    radius: float  # m: C_A is the disc of this radius
    striker: str
    victim: str
    type: CrashType


@dataclass(frozen=True)
class Network:
    """The road network a plan was planned on, in the formats its targets read; nothing here converts.

    The map layer (compiler/maps) fills it: `sumo` is the user's `.net.xml`, or for an OpenDRIVE map
    netconvert's conversion of it, kept in a content-addressed cache; `opendrive` is the user's
    `.xodr`, or for a SUMO map its conversion to OpenDRIVE, filled in before a target that reads
    OpenDRIVE runs (None until then). Targets read these files; they never load maps or run netconvert.
    """

    map: str  # path of the map file as given
    sha256: str  # of the map file
    sumo: str  # the SUMO network (.net.xml) the plan's lanes and edges name
    opendrive: str | None = None  # the OpenDRIVE file (.xodr), when there is one yet


@dataclass(frozen=True)
class Plan:
    scenario: Scenario
    network: Network
    site: str  # site id, e.g. 'junction:J3'
    kind: RoadKind
    rotation: int  # degrees the report's compass was turned onto the site
    seed: int
    step: float  # s between samples
    impact: Impact
    trajectories: tuple[Trajectory, ...]
    notes: tuple[str, ...]  # what lowering assumed or clamped, one line each

    @property
    def map(self) -> str:
        """Path of the map file as given."""
        return self.network.map

    @property
    def map_sha256(self) -> str:
        return self.network.sha256

    def trajectory(self, participant: str) -> Trajectory:
        return next(t for t in self.trajectories if t.participant == participant)

    @property
    def duration(self) -> float:
        return self.trajectories[0].samples[-1].t


# --- JSON form: plain data, rounded so that output is byte-stable -------------------


def _r(value: float, digits: int = 3) -> float:
    rounded = round(value, digits)
    return 0.0 if rounded == 0 else rounded  # no '-0.0' in files


def plan_to_json(plan: Plan) -> dict[str, Any]:
    return {
        "format": PLAN_FORMAT,
        "scenario": to_json(plan.scenario),
        "map": plan.map,
        "map_sha256": plan.map_sha256,
        "network": {"sumo": plan.network.sumo, "opendrive": plan.network.opendrive},
        "site": plan.site,
        "kind": plan.kind.value,
        "rotation": plan.rotation,
        "seed": plan.seed,
        "step": plan.step,
        "impact": {
            "time": _r(plan.impact.time),
            "point": [_r(v) for v in plan.impact.point],
            "radius": _r(plan.impact.radius),
            "striker": plan.impact.striker,
            "victim": plan.impact.victim,
            "type": plan.impact.type.value,
        },
        "trajectories": [_trajectory_json(t) for t in plan.trajectories],
        "notes": list(plan.notes),
    }


def _trajectory_json(t: Trajectory) -> dict[str, Any]:
    return {
        "participant": t.participant,
        "role": t.role.value,
        "body": {"length": t.body.length, "width": t.body.width, "vclass": t.body.vclass},
        "lanes": list(t.lanes),
        "edges": list(t.edges),
        "impact_s": None if t.impact_s is None else _r(t.impact_s),
        "segments": [
            [s.action, _r(s.start_s), _r(s.end_s), _r(s.start_t), _r(s.end_t), _r(s.speed)] for s in t.segments
        ],
        # columns: t, x, y, heading, speed
        "samples": [[_r(s.t, 2), _r(s.x), _r(s.y), _r(s.heading % 360.0, 2), _r(s.speed)] for s in t.samples],
    }


def plan_from_json(data: dict[str, Any], origin: str = "plan") -> Plan:
    if data.get("format") != PLAN_FORMAT:
        raise ValueError(f"{origin}: not a sovarc plan (format {data.get('format')!r}, expected {PLAN_FORMAT!r})")
    impact = data["impact"]
    return Plan(
        scenario=from_json(data["scenario"], origin),
        network=_network_from_json(data, origin),
        site=data["site"],
        kind=RoadKind(data["kind"]),
        rotation=int(data["rotation"]),
        seed=int(data["seed"]),
        step=float(data["step"]),
        impact=Impact(
            float(impact["time"]),
            (float(impact["point"][0]), float(impact["point"][1])),
            float(impact["radius"]),
            impact["striker"],
            impact["victim"],
            CrashType(impact["type"]),
        ),
        trajectories=tuple(
            Trajectory(
                participant=t["participant"],
                role=Role(t["role"]),
                body=Body(**t["body"]),
                samples=tuple(Sample(*map(float, row)) for row in t["samples"]),
                lanes=tuple(t["lanes"]),
                edges=tuple(t["edges"]),
                segments=tuple(Segment(row[0], *map(float, row[1:])) for row in t["segments"]),
                impact_s=t["impact_s"],
            )
            for t in data["trajectories"]
        ),
        notes=tuple(data["notes"]),
    )


def _network_from_json(data: dict[str, Any], origin: str) -> Network:
    files = data.get("network")
    if files is None:  # a plan written before plans carried their network: a SUMO map is its own network
        if not data["map"].lower().endswith(".net.xml"):
            raise ValueError(f"{origin}: the plan does not name the SUMO network it was planned on; plan again")
        files = {"sumo": data["map"], "opendrive": None}
    return Network(data["map"], data["map_sha256"], files["sumo"], files.get("opendrive"))


def dump_plan(plan: Plan) -> str:
    return json.dumps(plan_to_json(plan), separators=(",", ":"), ensure_ascii=False) + "\n"
