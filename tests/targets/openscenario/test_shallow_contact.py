"""Side hits, planned and synthesized for real, first touch inside C_A: at the planned impact the
striker's leading front corner is only a little into the victim's side (SIDE_OVERLAP, more the
steeper the angle), so a shallow or slow approach does not touch metres before it."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.compiler.lower import lower_on, sites_for
from sovarc.compiler.maps import load_map
from sovarc.compiler.slots import folder_name
from sovarc.compiler.synth import synthesize
from sovarc.dsl import parse
from sovarc.targets.openscenario import check
from sovarc.targets.verdict import Verdict

from tests.targets.openscenario.plans import TOWN, emit_files

pytestmark = pytest.mark.slow  # netconvert writes the .xodr


def verdicts(text: str, tmp_path: Path) -> list[tuple[str, Verdict]]:
    """The OpenSCENARIO oracle's verdict on each of the 3 town sites the scenario is staged on."""
    town = load_map(TOWN)
    staged, notes, matches = sites_for(parse(text, "shallow.sov"), town, roads=3)
    out = []
    for match in matches:
        plan = synthesize(lower_on(staged, match, town, notes))
        out.append((match.site.id, check(emit_files(plan, tmp_path / folder_name(match.site.id)).xosc, plan)))
    return out


# V1 stops at a T's stem, then turns left into lane 2; V2, in lane 1 of the road it turns onto,
# strikes it as it drifts over at about 6 degrees (NMVCCS t_0, rewritten)
DRIFT = """scenario drift_into_lane_2 {
  road { kind t_junction lanes 6 speed_limit 72 km/h }
  vehicle V1 { heading south lane unknown actions { follow_lane stop turn_left(to: 2) } }
  vehicle V2 { heading east lane 1 actions unknown }
  crash { type side striker V2 victim V1 }
}
"""


def test_a_turn_into_the_partners_lane_first_touches_in_the_collision_area(tmp_path: Path) -> None:
    for site, verdict in verdicts(DRIFT, tmp_path):
        assert verdict.passed, (site, verdict.dumps())
        assert verdict.facts["relative_heading"] < 15.0  # a drift into the lane, not a crossing


# V1 U-turns from lane 1 across V2, which drives on beside it in lane 2 at the same pace: V1's
# front corner reaches V2's side well before its bumper's middle crosses V2's line (NMVCCS straight_22)
U_TURN_ACROSS = """scenario u_turn_across {
  road { kind straight lanes 4 speed_limit 48 km/h }
  vehicle V1 { heading east lane unknown actions { follow_lane u_turn(to: 2) } }
  vehicle V2 { heading east lane 2 actions { follow_lane } }
  crash { type side striker V1 victim V2 }
}
"""


def test_a_slow_u_turn_across_the_car_beside_first_touches_in_the_collision_area(tmp_path: Path) -> None:
    for site, verdict in verdicts(U_TURN_ACROSS, tmp_path):
        assert verdict.passed, (site, verdict.dumps())
