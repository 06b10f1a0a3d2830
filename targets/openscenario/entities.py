"""The Entities section: one ScenarioObject per participant, ego first and marked.

Markers, as Properties: `type` is `ego_vehicle` for the ego and `simulation` for the others
(the convention CARLA ScenarioRunner reads); `sovarc_crash_role` is striker, victim or
bystander; `sovarc_actions` lists the IR actions the trajectory performs.

Performance limits are derived from the report (speed limit and stated speeds), never from the
trajectory, so that the oracle's speed check compares the trajectory against the report.
"""

from __future__ import annotations

from dataclasses import dataclass

from lxml import etree
from sovarc.compiler.plan import Plan, Trajectory
from sovarc.compiler.vehicles import CAR_MODEL, model
from sovarc.dsl.ir import Participant, Unknown
from sovarc.targets.openscenario.bodies import OscBody
from sovarc.targets.openscenario.versions import Dialect
from sovarc.targets.openscenario.xml import el, num

# Speed allowance: the larger of the speed limit and the participant's stated speed, plus a margin.
SPEED_MARGIN = 1.1
SPEED_SLACK = 1.0  # m/s
VEHICLE_DEFAULT_SPEED = 150 / 3.6  # neither limit nor speed known
PEDESTRIAN_DEFAULT_SPEED = 3.0  # a brisk run
MAX_ACCELERATION = 6.0  # m/s^2, a strong car
MAX_DECELERATION = 10.0  # m/s^2, emergency braking on dry asphalt
MAX_STEERING = 0.55  # rad
MAX_SPEED_PROPERTY = "sovarc_max_speed"  # pedestrians have no Performance element


@dataclass(frozen=True)
class Actor:
    """A participant as the emitter writes it."""

    trajectory: Trajectory
    participant: Participant | None
    body: OscBody
    ego: bool

    @property
    def name(self) -> str:
        return self.trajectory.participant


def allowed_speed(plan: Plan, actor: Actor) -> float:
    """The highest speed (m/s) the report allows this participant, with a margin."""
    known: list[float] = []
    stated = actor.participant.speed if actor.participant else None
    if stated is not None and not isinstance(stated, Unknown):
        known.append(stated.to_mps())
    limit = plan.scenario.road.speed_limit
    if actor.body.pedestrian:
        known.append(PEDESTRIAN_DEFAULT_SPEED)
    elif not isinstance(limit, Unknown):
        known.append(limit.to_mps())
    base = max(known) if known else VEHICLE_DEFAULT_SPEED
    return base * SPEED_MARGIN + SPEED_SLACK


def crash_role(plan: Plan, name: str) -> str:
    if name == plan.impact.striker:
        return "striker"
    return "victim" if name == plan.impact.victim else "bystander"


def entities_element(plan: Plan, actors: list[Actor], dialect: Dialect) -> etree._Element:
    return el("Entities", None, *(_scenario_object(plan, a, dialect) for a in actors))


def _properties(plan: Plan, actor: Actor) -> etree._Element:
    actions = actor.participant.actions if actor.participant else ()
    rows = [
        ("type", "ego_vehicle" if actor.ego else "simulation"),
        ("sovarc_participant", actor.name),
        ("sovarc_crash_role", crash_role(plan, actor.name)),
        ("sovarc_actions", "unknown" if isinstance(actions, Unknown) else " ".join(_action(a) for a in actions)),
    ]
    if actor.body.pedestrian:
        rows.append((MAX_SPEED_PROPERTY, num(allowed_speed(plan, actor))))
    return el("Properties", None, *(el("Property", {"name": n, "value": v}) for n, v in rows))


def _action(action: object) -> str:
    kind = getattr(action, "kind", action)
    to = getattr(action, "to", None)
    return f"{kind}" if to is None else f"{kind}(to:{to})"


def _bounding_box(body: OscBody) -> etree._Element:
    return el(
        "BoundingBox",
        None,
        el("Center", {"x": num(body.center_x), "y": 0, "z": num(body.height / 2)}),
        el("Dimensions", {"width": num(body.width), "length": num(body.length), "height": num(body.height)}),
    )


def _scenario_object(plan: Plan, actor: Actor, dialect: Dialect) -> etree._Element:
    body = actor.body
    if body.pedestrian:
        attrs: dict[str, str] = {"name": actor.name, "mass": num(body.mass), "pedestrianCategory": body.category}
        if dialect.rev_minor == 0:
            attrs["model"] = "pedestrian"
        entity = el("Pedestrian", attrs, _bounding_box(body), _properties(plan, actor))
    else:
        attrs = {"name": actor.name, "vehicleCategory": body.category}
        if dialect.rev_minor >= 1:
            attrs["mass"] = num(body.mass)
        accel, decel = performance_limits(actor.trajectory)
        performance = {
            "maxSpeed": num(allowed_speed(plan, actor)),
            "maxAcceleration": num(accel),
            "maxDeceleration": num(decel),
        }
        entity = el(
            "Vehicle",
            attrs,
            _bounding_box(body),
            el("Performance", performance),
            _axles(body),
            _properties(plan, actor),
        )
    return el("ScenarioObject", {"name": actor.name}, entity)


def performance_limits(trajectory: Trajectory) -> tuple[float, float]:
    """A vehicle's maxAcceleration and maxDeceleration (m/s^2): a car's as they always were; another
    kind's the most it can do or is planned to (a bus's plan may ask more than it drives with)."""
    kind = model(trajectory.body)
    if kind is CAR_MODEL:
        return MAX_ACCELERATION, MAX_DECELERATION
    return max(kind.drive_accel, kind.limits.plan_accel), max(kind.drive_brake, kind.limits.plan_accel)


def _axles(body: OscBody) -> etree._Element:
    common = {"wheelDiameter": num(body.wheel_diameter), "trackWidth": num(body.track_width)}
    z = {"positionZ": num(body.wheel_diameter / 2)}
    return el(
        "Axles",
        None,
        el("FrontAxle", {"maxSteering": num(MAX_STEERING), **common, "positionX": num(body.wheelbase), **z}),
        el("RearAxle", {"maxSteering": 0, **common, "positionX": 0, **z}),
    )
