"""A car that drives into or off the road by a driveway may cross the sidewalk; others may not."""

from __future__ import annotations

import math
from pathlib import Path

import sumo
from sovarc.compiler.plan import Trajectory
from sovarc.compiler.vehicles import CAR
from sovarc.dsl.ir import Role
from sovarc.targets.sumo.network import read_network
from sovarc.targets.sumo.oracle import lane_violation
from sovarc.targets.sumo.replay import Pose

CITY = Path(sumo.SUMO_HOME) / "tools" / "game" / "DRT" / "osm.net.xml"
CAR_LANE, SIDEWALK = "190083616_1", "190083616_0"  # an OpenStreetMap street with its sidewalk at index 0


def _over_the_kerb() -> tuple[Trajectory, Pose]:
    """A car on the street's car lane, 2.5 m towards the sidewalk: its right side is on it."""
    network = read_network(CITY)
    lane, sidewalk = network.lanes[CAR_LANE], network.lanes[SIDEWALK]
    (ax, ay), (bx, by) = lane.shape[0], lane.shape[1]
    (cx, cy) = sidewalk.shape[0]
    length = ((bx - ax) ** 2 + (by - ay) ** 2) ** 0.5
    ux, uy = (bx - ax) / length, (by - ay) / length
    side = 1.0 if (cx - ax) * -uy + (cy - ay) * ux > 0 else -1.0  # which side the sidewalk lies on
    x, y = ax + 8.0 * ux - side * 2.5 * uy, ay + 8.0 * uy + side * 2.5 * ux
    heading = math.degrees(math.atan2(ux, uy)) % 360.0
    trajectory = Trajectory("V1", Role.VEHICLE, CAR, (), (CAR_LANE,), ("190083616",), (), None)
    return trajectory, Pose(x, y, heading, CAR_LANE)


def test_a_car_on_the_sidewalk_crosses_a_line_unless_it_uses_a_driveway() -> None:
    network = read_network(CITY)
    trajectory, pose = _over_the_kerb()
    assert network.lanes[SIDEWALK].pedestrian_only
    assert lane_violation(network, trajectory, pose) == SIDEWALK
    assert lane_violation(network, trajectory, pose, kerb=True) is None
