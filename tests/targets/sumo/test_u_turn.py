"""A U-turn on a city street of two lanes each way (12.8 m between the kerbs, sidewalks beside):
planned on one half circle inside the road, it synthesizes and never reaches a sidewalk in SUMO."""

from __future__ import annotations

from pathlib import Path

import pytest
import sumo
from sovarc.compiler.lower import lower_on, sites_for
from sovarc.compiler.maps import load_map
from sovarc.compiler.synth import synthesize
from sovarc.dsl import parse
from sovarc.targets import sumo as sumo_target

pytestmark = pytest.mark.slow

CITY = Path(sumo.SUMO_HOME) / "tools" / "game" / "DRT" / "osm.net.xml"
U_TURN = """scenario u_turn_into_the_near_lane {
  road {
    kind straight
    lanes 4
    speed_limit 48 km/h
  }
  vehicle V1 {
    heading east
    lane 1
    speed unknown
    actions {
      follow_lane
      u_turn(to: 2)
    }
  }
  vehicle V2 {
    heading east
    lane 2
    speed unknown
    actions {
      follow_lane
    }
  }
  crash {
    type side
    striker V1
    victim V2
  }
}
"""


def test_a_u_turn_on_a_narrow_city_street_stays_off_the_sidewalks() -> None:
    road_map = load_map(CITY)
    staged, notes, matches = sites_for(parse(U_TURN, "u_turn.sov"), road_map, roads=3)
    assert len(matches) == 3
    for match in matches:
        plan = synthesize(lower_on(staged, match, road_map, notes))  # TOPP-RA accepts the half circle
        verdict = sumo_target.check(plan)
        lanes = next(f for f in verdict.findings if f.check == "lane_lines")
        assert lanes.passed, f"{match.site.id}: {lanes.message}"
        assert not verdict.failures, f"{match.site.id}: {[f.message for f in verdict.failures]}"
