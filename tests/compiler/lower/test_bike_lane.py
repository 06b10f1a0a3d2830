"""A cyclist in the bike lane of a road that has one (SUMO's lane allowing bicycles alone)."""

from __future__ import annotations

import subprocess
from pathlib import Path

import numpy as np
from sovarc.compiler.lower.routes import vehicle_route
from sovarc.compiler.maps import load_map, match_sites
from sovarc.compiler.maps.netconvert import netconvert_path
from sovarc.dsl import parse
from sovarc.dsl.ir import Side

NODES = '<nodes><node id="a" x="0" y="0" type="priority"/><node id="b" x="300" y="0" type="priority"/></nodes>'
ROAD = 'numLanes="2" speed="13.9" bikeLaneWidth="1.5"'
EDGES = f'<edges><edge id="e" from="a" to="b" {ROAD}/><edge id="-e" from="b" to="a" {ROAD}/></edges>'
SCENARIO = """scenario bike_lane {
  road {
    kind straight
    lanes 4
    speed_limit 30 mph
  }
  vehicle V1 {
    kind bicycle
    heading east
    lane 1
    speed 10 mph
    actions {
      follow_lane
    }
  }
  vehicle V2 {
    heading east
    lane 2
    speed 30 mph
    actions {
      follow_lane
    }
  }
  crash {
    type side
    striker V2
    victim V1
  }
}
"""


def test_a_cyclist_rides_in_the_bike_lane_and_a_car_in_its_own(tmp_path: Path) -> None:
    (tmp_path / "n.nod.xml").write_text(NODES)
    (tmp_path / "n.edg.xml").write_text(EDGES)
    args = ["-n", "n.nod.xml", "-e", "n.edg.xml", "-o", "n.net.xml", "--no-turnarounds", "--no-warnings"]
    subprocess.run([netconvert_path(), *args], cwd=tmp_path, check=True, capture_output=True)
    road_map = load_map(tmp_path / "n.net.xml")
    scenario = parse(SCENARIO)
    (match,) = match_sites(scenario, road_map, n=1, seed=0, clamp=True)
    cyclist = vehicle_route(scenario.participant("V1"), match, road_map, 4.0, Side.RIGHT)
    bike = road_map.net.getLane(cyclist.lanes[0])
    assert len(cyclist.lanes) == 1 and bike.allows("bicycle") and not bike.allows("passenger")
    middle = cyclist.line.point(cyclist.line.length / 2.0)
    y = np.interp(middle[0], *np.array(bike.getShape()).T[:2])  # the bike lane runs along x
    assert abs(middle[1] - y) < 0.05
    car = vehicle_route(scenario.participant("V2"), match, road_map, 13.0, Side.RIGHT)
    assert all(road_map.net.getLane(lane).allows("passenger") for lane in car.lanes)
