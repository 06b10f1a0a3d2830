"""A two-lane street built with netconvert (one 3.2 m lane each way, 6.4 m between the kerbs,
sidewalks beside), and a crash with a U-turn on it: too narrow for one sweep, a three-point turn.

Built once per session into a temporary folder; the plan is cached, so the lowering, SUMO and
OpenSCENARIO tests share it.
"""

from __future__ import annotations

import subprocess
import tempfile
from functools import cache
from pathlib import Path

from sovarc.compiler.lower import lower_on, sites_for
from sovarc.compiler.maps import load_map
from sovarc.compiler.maps.netconvert import netconvert_path
from sovarc.compiler.plan import Plan
from sovarc.compiler.synth import synthesize
from sovarc.dsl import parse
from sovarc.dsl.ir import Scenario

NODES = """<nodes>
  <node id="w" x="0" y="0" type="priority"/>
  <node id="e" x="300" y="0" type="priority"/>
</nodes>
"""
LANES = """    <lane index="0" allow="pedestrian" width="2.0"/>
    <lane index="1" disallow="pedestrian" width="3.2"/>
"""
EDGES = f"""<edges>
  <edge id="street" from="w" to="e" priority="1" numLanes="2" speed="13.89">
{LANES}  </edge>
  <edge id="-street" from="e" to="w" priority="1" numLanes="2" speed="13.89">
{LANES}  </edge>
</edges>
"""

# V1 turns back across the street; V2, coming up behind it, runs into its side.
STRUCK_TURNING = """scenario struck_while_turning_in_legs {
  road {
    kind straight
    lanes 2
    speed_limit 30 mph
  }
  vehicle V1 {
    heading east
    lane 1
    speed unknown
    actions {
      follow_lane
      u_turn(to: 1)
    }
  }
  vehicle V2 {
    heading east
    lane 1
    speed unknown
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


@cache
def street() -> Path:
    folder = Path(tempfile.mkdtemp(prefix="sovarc-street-"))
    (folder / "street.nod.xml").write_text(NODES, encoding="utf-8")
    (folder / "street.edg.xml").write_text(EDGES, encoding="utf-8")
    net = folder / "street.net.xml"
    command = [netconvert_path(), "-n", "street.nod.xml", "-e", "street.edg.xml", "-o", net.name]
    subprocess.run([*command, "--no-turnarounds", "true"], cwd=folder, check=True, capture_output=True)
    return net


def scenario(text: str = STRUCK_TURNING) -> Scenario:
    return parse(text, "street.sov")


@cache
def k_turn_plan() -> Plan:
    """The crash staged on the street's one site."""
    road_map = load_map(street())
    staged, notes, matches = sites_for(scenario(), road_map, roads=1)
    return synthesize(lower_on(staged, matches[0], road_map, notes))
