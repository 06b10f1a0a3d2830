"""Reading an emitted .xosc back into plain data for the oracle: entities, Init teleports,
trajectories in simulation time, the stop time, and the scenario's parameters.

Only what the file says counts; nothing comes from the plan. What the reader cannot interpret
(a position that is not a WorldPosition, a relative timing) is collected in `problems`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree


@dataclass(frozen=True)
class Pose:
    t: float
    x: float
    y: float
    h: float  # rad, counter-clockwise from +x


@dataclass(frozen=True)
class Entity:
    name: str
    pedestrian: bool
    length: float
    width: float
    center_x: float  # bounding-box centre relative to the reference point
    center_y: float
    max_speed: float | None  # m/s: Performance (vehicles) or the sovarc_max_speed property (pedestrians)
    max_acceleration: float | None
    max_deceleration: float | None
    properties: dict[str, str]


@dataclass
class ScenarioFile:
    path: Path
    doc: etree._ElementTree
    rev: tuple[int, int]
    parameters: dict[str, str]
    entities: dict[str, Entity]
    init_teleports: dict[str, list[Pose]] = field(default_factory=dict)
    story_teleports: list[str] = field(default_factory=list)  # entities teleported after the start
    trajectories: dict[str, list[tuple[Pose, ...]]] = field(default_factory=dict)
    stop_time: float | None = None
    logic_file: str | None = None
    problems: list[str] = field(default_factory=list)


class Reader:
    """Resolves `$name` parameter references against the top-level ParameterDeclarations."""

    def __init__(self, parameters: dict[str, str]) -> None:
        self.parameters = parameters

    def text(self, node: etree._Element, name: str) -> str:
        value = node.get(name)
        if value is None:
            raise ValueError(f"<{node.tag}> line {node.sourceline} has no {name}")
        if value.startswith("$") and not value.startswith("${"):
            if value[1:] not in self.parameters:
                raise ValueError(f"<{node.tag}> line {node.sourceline}: unknown parameter {value}")
            return self.parameters[value[1:]]
        return value

    def number(self, node: etree._Element, name: str, default: float | None = None) -> float:
        if node.get(name) is None and default is not None:
            return default
        text = self.text(node, name)
        try:
            return float(text)
        except ValueError:
            raise ValueError(f"<{node.tag}> line {node.sourceline}: {name}={text!r} is not a number") from None


def read_scenario(path: Path) -> ScenarioFile:
    """Parse the file; raises etree.XMLSyntaxError (not XML) or ValueError (not OpenSCENARIO)."""
    doc = etree.parse(str(path))
    root = doc.getroot()
    if root.tag != "OpenSCENARIO":
        raise ValueError(f"root element is <{root.tag}>, not <OpenSCENARIO>")
    header = root.find("FileHeader")
    if header is None:
        raise ValueError("no FileHeader")
    parameters = {
        d.get("name", ""): d.get("value", "") for d in root.findall("ParameterDeclarations/ParameterDeclaration")
    }
    reader = Reader(parameters)
    rev = (int(reader.number(header, "revMajor")), int(reader.number(header, "revMinor")))
    entities = {}
    for obj in root.findall("Entities/ScenarioObject"):
        entity = _entity(reader, obj)
        entities[entity.name] = entity
    scenario = ScenarioFile(path, doc, rev, parameters, entities)
    logic = root.find("RoadNetwork/LogicFile")
    scenario.logic_file = None if logic is None else logic.get("filepath")
    _read_storyboard(reader, root, scenario)
    return scenario


def _entity(reader: Reader, obj: etree._Element) -> Entity:
    name = reader.text(obj, "name")
    body = obj.find("Vehicle")
    pedestrian = body is None
    if body is None:
        body = obj.find("Pedestrian")
    if body is None:
        raise ValueError(f"entity {name}: only Vehicle and Pedestrian entities are read")
    center, dims = body.find("BoundingBox/Center"), body.find("BoundingBox/Dimensions")
    if center is None or dims is None:
        raise ValueError(f"entity {name}: no BoundingBox")
    properties = {p.get("name", ""): p.get("value", "") for p in body.findall("Properties/Property")}
    performance = body.find("Performance")
    if performance is not None:
        limits = tuple(reader.number(performance, a) for a in ("maxSpeed", "maxAcceleration", "maxDeceleration"))
    else:
        speed = properties.get("sovarc_max_speed")
        limits = (float(speed) if speed else None, None, None)
    return Entity(
        name,
        pedestrian,
        reader.number(dims, "length"),
        reader.number(dims, "width"),
        reader.number(center, "x"),
        reader.number(center, "y"),
        *limits,
        properties,
    )


def _world_pose(reader: Reader, position: etree._Element | None, t: float) -> Pose:
    world = None if position is None else position.find("WorldPosition")
    if world is None:
        raise ValueError(f"line {position.sourceline if position is not None else '?'}: not a WorldPosition")
    return Pose(t, reader.number(world, "x"), reader.number(world, "y"), reader.number(world, "h", 0.0))


def _actors_of(reader: Reader, node: etree._Element) -> list[str]:
    """The entities a Private (Init) or an Action (story) applies to."""
    if node.tag == "Private":
        return [reader.text(node, "entityRef")]
    group = next((a for a in node.iterancestors() if a.tag == "ManeuverGroup"), None)
    if group is None:
        return []
    return [reader.text(e, "entityRef") for e in group.findall("Actors/EntityRef")]


def _read_storyboard(reader: Reader, root: etree._Element, scenario: ScenarioFile) -> None:
    for private in root.findall("Storyboard/Init/Actions/Private"):
        (name,) = _actors_of(reader, private)
        for teleport in private.findall("PrivateAction/TeleportAction"):
            try:
                scenario.init_teleports.setdefault(name, []).append(_world_pose(reader, teleport.find("Position"), 0.0))
            except ValueError as e:
                scenario.problems.append(f"{name}: Init TeleportAction {e}")
    for story in root.findall("Storyboard/Story"):
        for teleport in story.iter("TeleportAction"):
            scenario.story_teleports.extend(_actors_of(reader, teleport.getparent().getparent()))
        for follow in story.iter("FollowTrajectoryAction"):
            names = _actors_of(reader, follow.getparent().getparent().getparent())
            try:
                poses = _trajectory(reader, follow)
            except ValueError as e:
                scenario.problems.append(f"{', '.join(names)}: FollowTrajectoryAction {e}")
                continue
            for name in names:
                scenario.trajectories.setdefault(name, []).append(poses)
    if root.find("Storyboard/Init/Actions/Private/PrivateAction/RoutingAction/FollowTrajectoryAction") is not None:
        scenario.problems.append("a FollowTrajectoryAction in Init is not read: the oracle expects it in the Story")
    scenario.stop_time = _stop_time(reader, root)


def _trajectory(reader: Reader, follow: etree._Element) -> tuple[Pose, ...]:
    trajectory = follow.find("TrajectoryRef/Trajectory")
    if trajectory is None:
        trajectory = follow.find("Trajectory")
    if trajectory is None:
        raise ValueError("has no inline Trajectory (catalog references are not read)")
    timing = follow.find("TimeReference/Timing")
    if timing is None or reader.text(timing, "domainAbsoluteRelative") != "absolute":
        raise ValueError("has no absolute Timing: its vertices are not bound to simulation time")
    scale, offset = reader.number(timing, "scale"), reader.number(timing, "offset")
    vertices = trajectory.findall("Shape/Polyline/Vertex")
    if not vertices:
        raise ValueError("has no Polyline vertices")
    return tuple(_world_pose(reader, v.find("Position"), reader.number(v, "time") * scale + offset) for v in vertices)


def _stop_time(reader: Reader, root: etree._Element) -> float | None:
    """The earliest simulation time at which the storyboard's StopTrigger fires, if it is a time trigger."""
    path = "Storyboard/StopTrigger/ConditionGroup/Condition/ByValueCondition/SimulationTimeCondition"
    times = [
        reader.number(c, "value")
        for c in root.findall(path)
        if c.get("rule") in ("greaterThan", "greaterOrEqual", "equalTo")
    ]
    return min(times) if times else None
