"""Left-hand traffic: a map whose traffic keeps left is planned on as its mirror image.

The reports sovarc reads are written for right-hand traffic (US police and fleet reports), and every
stage of lowering and synthesis reads lanes as right-hand traffic has them: lane 1 at the kerb on the
right, the oncoming lanes on the left, a U-turn swinging left, a parked car at the right-hand kerb. The
same crash in a left-hand-traffic country is the report's mirror image: there a left turn across the
oncoming lanes is a right turn, and a car drifting over the centre line drifts right. So a map whose
SUMO network keeps left (`<net lefthand="true">`: netconvert and netgenerate with --lefthand, an OSM
city of a left-hand country, an OpenDRIVE map netconvert converted as one) is planned on in its mirror
image across the x axis, y negated: a right-hand network with the same edge, lane and junction ids, in
which a turn SUMO calls left is a right turn. Each plan is then mirrored back onto the map as given
(`mirror_plan`), so the targets replay it on the user's own network: the lane ids match, and the poses
are the map's own.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from lxml import etree
from sovarc.compiler.plan import Plan, Sample, Trajectory

MIRROR_VERSION = "2"  # of the mirroring: part of the cached copy's name, so a change makes a new copy
# SUMO's turn directions as a mirror sees them: left and right swap; a turnaround, which a left-hand
# network writes 'T' (turning the other way round), is a right-hand one's 't' (a 't' stays one)
_MIRRORED_DIRS = {"l": "r", "r": "l", "L": "R", "R": "L", "T": "t"}
_SHAPES = ("shape", "customShape")


def keeps_left(net_file: Path) -> bool:
    """Whether the SUMO network's traffic keeps left, read from its root element alone."""
    for _event, element in etree.iterparse(str(net_file), events=("start",)):
        return element.get("lefthand") == "true"
    return False


def opendrive_keeps_left(xodr: Path) -> bool:
    """Whether an OpenDRIVE map's roads keep left: most of its roads (outside junctions) say `rule="LHT"`
    (OpenDRIVE 1.5; a road without the attribute keeps right). netconvert does not read the attribute, and
    converts such a map as a left-hand one only when told (`--lefthand`)."""
    left = right = 0
    for _event, element in etree.iterparse(str(xodr), events=("end",), tag="road"):
        if element.get("junction", "-1") == "-1":
            if element.get("rule") == "LHT":
                left += 1
            else:
                right += 1
        element.clear()
    return left > right


def mirror_point(x: float, y: float) -> tuple[float, float]:
    return x, -y


def mirror_heading(heading: float) -> float:
    """A compass heading's image when y is negated: north and south swap, east and west stay."""
    return (180.0 - heading) % 360.0


def mirror_bytes(net_file: Path) -> bytes:
    """The SUMO network in `net_file` as its mirror image across the x axis, keeping right."""
    tree = etree.parse(str(net_file), etree.XMLParser(remove_comments=True, huge_tree=True))
    root = tree.getroot()
    root.attrib.pop("lefthand", None)  # the image keeps right
    for element in root.iter():
        if not isinstance(element.tag, str):
            continue
        for name in _SHAPES:
            if (value := element.get(name)) is not None:
                element.set(name, _mirror_shape(value))
        if element.tag == "junction" and (value := element.get("y")) is not None:
            element.set("y", _negated(value))
        if element.tag == "connection" and (direction := element.get("dir")) in _MIRRORED_DIRS:
            element.set("dir", _MIRRORED_DIRS[direction])
        if element.tag == "location" and (box := element.get("convBoundary")) is not None:
            x0, y0, x1, y1 = box.split(",")
            element.set("convBoundary", f"{x0},{_negated(y1)},{x1},{_negated(y0)}")
    return etree.tostring(tree, xml_declaration=True, encoding="UTF-8")


def _negated(value: str) -> str:
    return value[1:] if value.startswith("-") else ("0.00" if float(value) == 0.0 else f"-{value}")


def _mirror_shape(shape: str) -> str:
    points = []
    for point in shape.split():
        x, y, *z = point.split(",")
        points.append(",".join([x, _negated(y), *z]))
    return " ".join(points)


def mirror_plan(plan: Plan) -> Plan:
    """A plan made on a map's mirror image, mirrored back onto the map: the same lanes and edges, each
    pose's y negated and its heading mirrored, and a note saying so."""
    impact = replace(plan.impact, point=mirror_point(*plan.impact.point))
    trajectories = tuple(_mirror_trajectory(t) for t in plan.trajectories)
    note = (
        "the map keeps left: planned on its mirror image, so the report's left and right are swapped "
        "(its left turns across the oncoming lanes are right turns here), as is its compass's north and south"
    )
    return replace(plan, impact=impact, trajectories=trajectories, notes=(*plan.notes, note))


def _mirror_trajectory(trajectory: Trajectory) -> Trajectory:
    samples = tuple(
        Sample(s.t, *mirror_point(s.x, s.y), mirror_heading(s.heading), s.speed) for s in trajectory.samples
    )
    return replace(trajectory, samples=samples)
