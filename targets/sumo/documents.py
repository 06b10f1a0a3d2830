"""The three SUMO documents of an emitted scenario, as text.

- `scenario.add.xml`: one vType per participant, of its real size and class, with the
  participant's role and allowed lanes as params; one named route per vehicle (its edges);
  a POI on the collision area C_A carrying the scenario's facts that have no SUMO meaning
  (weather, lighting, crash type, striker, victim, impact time) as params. The types are in
  an additional file, not a route file, because SUMO's replay device builds its vehicles
  before route files are read.
- `scenario.fcd.xml`: the trajectories in SUMO's FCD format, replayed by SUMO's own
  `fcd-replay` device (each step it calls moveToXY with the lane given here).
- `scenario.sumocfg`: ties them together with collision detection on.
"""

from __future__ import annotations

import hashlib
from collections.abc import Sequence

from sovarc.compiler.plan import Plan, Trajectory
from sovarc.compiler.vehicles import CAR_MODEL, model
from sovarc.dsl import to_text
from sovarc.dsl.ir import Unknown
from sovarc.targets.sumo.network import Network, Spot
from sovarc.targets.sumo.xmlwrite import element, empty, num, params, root

ADDITIONAL = "scenario.add.xml"
FCD = "scenario.fcd.xml"
CONFIG = "scenario.sumocfg"
COLLISIONS = "collisions.xml"  # written by SUMO when the scenario runs

COLOURS = {"striker": "1,0,0", "victim": "0,0.4,1", "other": "0.6,0.6,0.6"}
PREFIX = "sovarc."


def role_of(plan: Plan, participant: str) -> str:
    if participant == plan.impact.striker:
        return "striker"
    return "victim" if participant == plan.impact.victim else "other"


def type_id(participant: str) -> str:
    return f"{participant}.type"


def is_person(trajectory: Trajectory) -> bool:
    return trajectory.body.vclass == "pedestrian"


def ir_hash(plan: Plan) -> str:
    return hashlib.sha256(to_text(plan.scenario).encode("utf-8")).hexdigest()


def time_digits(step: float) -> int:
    """Decimals that print every multiple of `step` exactly (at least 2)."""
    return next((d for d in range(2, 7) if abs(round(step, d) - step) < 1e-12), 6)


def note(plan: Plan, what: str) -> str:
    return f"sovarc: {what} (scenario {plan.scenario.name}, site {plan.site})"


# --- scenario.add.xml -------------------------------------------------------------------


def additional(plan: Plan, map_name: str) -> str:
    children = [*_types(plan), _collision_area(plan, map_name)]
    return root("additional", "additional_file.xsd", children, note(plan, f"participants; trajectories in {FCD}"))


def _types(plan: Plan) -> list[str]:
    children: list[str] = []
    for t in plan.trajectories:
        role = role_of(plan, t.participant)
        pairs = [
            ("id", type_id(t.participant)),
            ("vClass", t.body.vclass),
            ("length", num(t.body.length, 2)),
            ("width", num(t.body.width, 2)),
            ("minGap", "0.50" if is_person(t) else "2.50"),
            *_drive(t),
            ("speedDev", "0"),
            ("guiShape", t.body.gui_shape),
            ("color", COLOURS[role]),
        ]
        facts = [
            (PREFIX + "participant", t.participant),
            (PREFIX + "role", role),
            (PREFIX + "lanes", " ".join(t.lanes)),
        ]
        children.append(element("vType", pairs, params(facts, 8), 4))
    for t in plan.trajectories:
        if t.edges and not is_person(t):
            children.append(empty("route", (("id", f"{t.participant}.route"), ("edges", " ".join(t.edges))), 4))
    return children


def _drive(t: Trajectory) -> list[tuple[str, str]]:
    """A kind's own acceleration and braking. The car's (and a walker's) type keeps SUMO's defaults,
    as it always had: the replay places every body on its samples, so these only tell a reader (and
    SUMO's own model, were it to drive the vehicle) what the kind can do."""
    kind = model(t.body)
    if is_person(t) or kind is CAR_MODEL:
        return []
    return [
        ("accel", num(kind.drive_accel, 2)),
        ("decel", num(kind.limits.stop_decel, 2)),
        ("emergencyDecel", num(kind.drive_brake, 2)),
    ]


def _words(value: object) -> str:
    if isinstance(value, Unknown):
        return "unknown"
    if isinstance(value, tuple):
        return " ".join(str(v) for v in value)
    return str(value)


def _collision_area(plan: Plan, map_name: str) -> str:
    env = plan.scenario.environment
    impact = plan.impact
    facts = [
        ("scenario", plan.scenario.name),
        ("ir_sha256", ir_hash(plan)),
        ("site", plan.site),
        ("road_kind", plan.kind.value),
        ("map", map_name),
        ("map_sha256", plan.map_sha256),
        ("rotation", str(plan.rotation)),
        ("seed", str(plan.seed)),
        ("weather", _words(env.weather)),
        ("lighting", _words(env.lighting)),
        ("crash_type", impact.type.value),
        ("striker", impact.striker),
        ("victim", impact.victim),
        ("impact_time", num(impact.time, 3)),
        ("impact_radius", num(impact.radius, 3)),
    ]
    facts += [(f"note.{i}", text) for i, text in enumerate(plan.notes, 1)]
    size = num(2.0 * impact.radius, 2)
    pairs = [
        ("id", "collision_area"),
        ("type", "sovarc.collision_area"),
        ("color", "1,0.8,0"),
        ("layer", "10"),
        ("x", num(impact.point[0], 3)),
        ("y", num(impact.point[1], 3)),
        ("width", size),
        ("height", size),
    ]
    return element("poi", pairs, params([(PREFIX + k, v) for k, v in facts], 8), 4)


# --- scenario.fcd.xml -------------------------------------------------------------------


def fcd(plan: Plan, spots: dict[str, list[Spot]], network: Network) -> str:
    """One <timestep> per sample time: vehicles first, then persons (the schema's order).

    A vehicle whose trajectory ends inside a junction gets one more entry, one step after
    the end of the run, at the start of the lane it would enter: SUMO's replay device builds
    each vehicle's route from the lanes named here, and needs that lane's edge to map the
    vehicle onto the junction lane that leads into it. The run ends before that entry plays.
    """
    digits = time_digits(plan.step)
    ordered = sorted(plan.trajectories, key=is_person)
    steps: list[str] = []
    count = len(plan.trajectories[0].samples)
    for k in range(count):
        rows = [_sample(t, k, spots[t.participant][k]) for t in ordered]
        steps.append(element("timestep", (("time", num(plan.trajectories[0].samples[k].t, digits)),), rows, 4))
    tail = [row for t in ordered if (row := _route_tail(t, spots[t.participant][-1], network))]
    if tail:
        steps.append(element("timestep", (("time", num(plan.duration + 2 * plan.step, digits)),), tail, 4))
    return root("fcd-export", "fcd_file.xsd", steps, note(plan, "trajectories, replayed by SUMO's fcd-replay device"))


def _sample(t: Trajectory, k: int, spot: Spot) -> str:
    s = t.samples[k]
    where = ("edge", spot.lane.edge) if is_person(t) else ("lane", spot.lane.id)
    pairs = [
        ("id", t.participant),
        ("x", num(s.x, 3)),
        ("y", num(s.y, 3)),
        ("angle", num(s.heading % 360.0, 2)),
        ("type", type_id(t.participant)),
        ("speed", num(abs(s.speed), 3)),
        ("pos", num(spot.pos, 3)),
        where,
    ]
    return empty("person" if is_person(t) else "vehicle", pairs, 8)


def _route_tail(t: Trajectory, last: Spot, network: Network) -> str | None:
    if is_person(t) or not last.lane.internal:
        return None
    lane = network.next_normal_lane(last.lane)
    if lane is None:
        return None
    (x0, y0), (x1, y1) = lane.shape[0], lane.shape[1]
    spot, _ = network.spot(lane, x1, y1)
    pairs = [
        ("id", t.participant),
        ("x", num(x0, 3)),
        ("y", num(y0, 3)),
        ("angle", num(spot.heading, 2)),
        ("type", type_id(t.participant)),
        ("speed", num(abs(t.samples[-1].speed), 3)),
        ("pos", "0.000"),
        ("lane", lane.id),
    ]
    return empty("vehicle", pairs, 8)


# --- scenario.sumocfg -------------------------------------------------------------------


def config(plan: Plan, map_name: str, extra: Sequence[tuple[str, str]] = ()) -> str:
    """The run: time span and step of the plan, collision detection on, the replay device."""
    digits = time_digits(plan.step)

    def section(name: str, options: Sequence[tuple[str, str]]) -> str:
        return element(name, (), [empty(key, (("value", value),), 8) for key, value in options], 4)

    processing = [
        ("collision.action", "warn"),  # keep replaying: the trajectories run past the impact
        ("intermodal-collision.action", "warn"),
        ("collision.check-junctions", "true"),
        ("collision.mingap-factor", "0"),  # bodies touching, not minGap, is a collision
        ("emergencydecel.warning-threshold", "1000"),  # replayed vehicles brake as recorded
        *extra,
    ]
    sections = [
        section("input", [("net-file", map_name), ("additional-files", ADDITIONAL)]),
        section("output", [("collision-output", COLLISIONS)]),
        section(
            "time",
            [
                ("begin", num(0.0, digits)),
                ("end", num(plan.duration + plan.step, digits)),  # the last sample plays in the step before
                ("step-length", num(plan.step, digits)),
            ],
        ),
        section("processing", processing),
        section("fcd_replay_device", [("device.fcd-replay.files", FCD)]),
        section("random_number", [("seed", str(plan.seed))]),
    ]
    run = note(plan, "run with `sumo -c` or `sumo-gui -c`")
    return root("sumoConfiguration", "sumoConfiguration.xsd", sections, run)
