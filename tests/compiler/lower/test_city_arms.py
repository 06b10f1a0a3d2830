"""Short arms of a real city network: moves squeezed before the junction, never a crash."""

from __future__ import annotations

from pathlib import Path

import sumo
from sovarc.compiler.lower import lower_on, sites_for
from sovarc.compiler.maps import load_map
from sovarc.dsl import parse
from sovarc.dsl.errors import SovarcError

CITY = Path(sumo.SUMO_HOME) / "tools" / "game" / "DRT" / "osm.net.xml"
PULL_OUT = """scenario pull_out_then_left {
  road {
    kind intersection
    lanes 4
    speed_limit 50 km/h
  }
  vehicle V1 {
    heading west
    lane 1
    speed unknown
    actions {
      drive_into
      turn_left
    }
  }
  vehicle V2 {
    heading north
    lane 2
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


def test_a_pull_out_before_a_turn_stages_on_city_junctions_or_says_why() -> None:
    road_map = load_map(CITY)
    staged, notes, matches = sites_for(parse(PULL_OUT, "pull_out.sov"), road_map, roads=6)
    assert len(matches) == 6
    lowered = 0
    for match in matches:
        try:
            result = lower_on(staged, match, road_map, notes)
        except SovarcError as error:  # a clear reason, never a crash
            assert error.diagnostics and match.site.id in error.diagnostics[0].message
            continue
        lowered += 1
        v1 = result.routes["V1"]
        assert v1.starts_at_rest and v1.line.length > 10.0
    assert lowered >= 4
