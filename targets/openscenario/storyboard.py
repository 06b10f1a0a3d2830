"""The Storyboard: Init places everyone, one Act has each participant follow its timed
trajectory, and a simulation-time StopTrigger ends the run shortly after the impact.

Only constructs that common players support: TeleportAction and SpeedAction in Init,
FollowTrajectoryAction with a Polyline and absolute Timing, SimulationTimeConditions.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from lxml import etree
from sovarc.compiler.plan import Plan
from sovarc.targets.openscenario.bodies import TAU, reference_point
from sovarc.targets.openscenario.entities import Actor
from sovarc.targets.openscenario.versions import Dialect
from sovarc.targets.openscenario.xml import ANGLE_DIGITS, TIME_DIGITS, el, num

STOP_AFTER_IMPACT = 3.0  # s: the run stops at most this long after the impact


def stop_time(plan: Plan) -> float:
    """When the run stops: at the end of the trajectories, but no later than STOP_AFTER_IMPACT past impact."""
    return max(plan.impact.time + plan.step, min(plan.duration, plan.impact.time + STOP_AFTER_IMPACT))


def world_position(x: float, y: float, h: float) -> etree._Element:
    attrs = {"x": num(x), "y": num(y), "z": 0, "h": num(h, ANGLE_DIGITS), "p": 0, "r": 0}
    return el("Position", None, el("WorldPosition", attrs))


def storyboard_element(
    plan: Plan, actors: Sequence[Actor], environment: etree._Element | None, dialect: Dialect
) -> etree._Element:
    init_actions = el("Actions")
    if environment is not None:
        init_actions.append(el("GlobalAction", None, el("EnvironmentAction", None, environment)))
    init_actions.extend(_init_private(a) for a in actors)
    start_rule = ("greaterOrEqual", 0) if dialect.greater_or_equal else ("greaterThan", 0)
    act = el(
        "Act",
        {"name": "sovarc_act"},
        *(_maneuver_group(a, dialect, start_rule) for a in actors),
        _time_trigger("StartTrigger", "sovarc_act_start", *start_rule, edge="none"),
    )
    return el(
        "Storyboard",
        None,
        el("Init", None, init_actions),
        el("Story", {"name": "sovarc_story"}, act),
        _time_trigger("StopTrigger", "sovarc_stop", "greaterThan", stop_time(plan), edge="rising"),
    )


def _init_private(actor: Actor) -> etree._Element:
    first = actor.trajectory.samples[0]
    x, y, h = reference_point(first, actor.body)
    speed = el(
        "SpeedAction",
        None,
        el("SpeedActionDynamics", {"dynamicsShape": "step", "value": 0, "dynamicsDimension": "time"}),
        el("SpeedActionTarget", None, el("AbsoluteTargetSpeed", {"value": num(first.speed)})),
    )
    return el(
        "Private",
        {"entityRef": actor.name},
        el("PrivateAction", None, el("TeleportAction", None, world_position(x, y, h))),
        el("PrivateAction", None, el("LongitudinalAction", None, speed)),
    )


def _trajectory(actor: Actor) -> etree._Element:
    """The Polyline of reference points. Headings are unwrapped (each within pi of the one before, so
    they may leave [0, 2 pi)): a player that interpolates them linearly never spins a body around."""
    vertices = []
    previous: float | None = None
    for sample in actor.trajectory.samples:
        x, y, h = reference_point(sample, actor.body)
        if previous is not None:
            h = previous + (h - previous + math.pi) % TAU - math.pi
        previous = h
        vertices.append(el("Vertex", {"time": num(sample.t, TIME_DIGITS)}, world_position(x, y, h)))
    return el(
        "Trajectory",
        {"name": f"{actor.name}_trajectory", "closed": False},
        el("Shape", None, el("Polyline", None, *vertices)),
    )


def _follow(actor: Actor, dialect: Dialect) -> etree._Element:
    trajectory = _trajectory(actor)
    return el(
        "FollowTrajectoryAction",
        None,
        el("TrajectoryRef", None, trajectory) if dialect.trajectory_ref else trajectory,
        el("TimeReference", None, el("Timing", {"domainAbsoluteRelative": "absolute", "scale": 1, "offset": 0})),
        el("TrajectoryFollowingMode", {"followingMode": "position"}),
    )


def _maneuver_group(actor: Actor, dialect: Dialect, start_rule: tuple[str, float]) -> etree._Element:
    action = el(
        "Action",
        {"name": f"{actor.name}_follow_trajectory"},
        el("PrivateAction", None, el("RoutingAction", None, _follow(actor, dialect))),
    )
    event = el(
        "Event",
        {"name": f"{actor.name}_event", "priority": dialect.priority, "maximumExecutionCount": 1},
        action,
        _time_trigger("StartTrigger", f"{actor.name}_start", *start_rule, edge="none"),
    )
    return el(
        "ManeuverGroup",
        {"name": f"{actor.name}_group", "maximumExecutionCount": 1},
        el("Actors", {"selectTriggeringEntities": False}, el("EntityRef", {"entityRef": actor.name})),
        el("Maneuver", {"name": f"{actor.name}_maneuver"}, event),
    )


def _time_trigger(tag: str, name: str, rule: str, value: float, *, edge: str) -> etree._Element:
    condition = el(
        "Condition",
        {"name": name, "delay": 0, "conditionEdge": edge},
        el("ByValueCondition", None, el("SimulationTimeCondition", {"value": num(value, TIME_DIGITS), "rule": rule})),
    )
    return el(tag, None, el("ConditionGroup", None, condition))
