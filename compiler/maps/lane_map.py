"""The map's lanes as the geometry kernel's lane map (compiler/geometry/lanes.py), the shapes the
SUMO target reads from the same network file: lowering asks the kernel's lane-line test of them
(compiler/lower/corners.py), as the SUMO oracle asks it of the replayed poses."""

from __future__ import annotations

from typing import Any

from sovarc.compiler.geometry.lanes import Lane, LaneMap
from sovarc.compiler.maps.load import RoadMap


def lane_map(road_map: RoadMap) -> LaneMap:
    """Every lane of the map (its sumolib network, the mirror image for left-hand traffic), built once."""
    found = road_map.cache.get("lane map")
    if found is None:
        lanes = (_lane(lane) for edge in road_map.net.getEdges() for lane in edge.getLanes())
        found = road_map.cache["lane map"] = LaneMap(lanes)
    return found


def _lane(lane: Any) -> Lane:
    """A sumolib lane. Every lane of a junction (its internal lanes, crossings and walking areas) has
    an id that begins with ':' and no painted lines."""
    edge = lane.getEdge()
    internal = lane.getID().startswith(":")
    ends = ("", "") if internal else (edge.getFromNode().getID(), edge.getToNode().getID())
    return Lane(
        id=lane.getID(),
        edge=edge.getID(),
        index=lane.getIndex(),
        width=lane.getWidth(),
        length=lane.getLength(),
        shape=tuple((float(x), float(y)) for x, y in lane.getShape()),
        internal=internal,
        pedestrian_only=set(lane.getPermissions()) == {"pedestrian"},
        ends=ends,
    )
