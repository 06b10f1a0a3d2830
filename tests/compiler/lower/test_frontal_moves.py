"""A frontal crash at a T where the report names no junction moves: the cars are staged turning
across each other's paths, so that fronts meet at the angle every oracle calls frontal."""

from __future__ import annotations

from sovarc.compiler.lower import lower_on, sites_for
from sovarc.dsl import parse
from sovarc.targets.verdict import CRASH_ANGLES

from tests.compiler.lower.staging import town

# both drive on; the report says how they met, not which way each went at the junction
T_FRONTAL = """scenario t_frontal {
  road {
    kind t_junction
    lanes 2
    speed_limit 40 km/h
  }
  vehicle V1 {
    heading north
    lane 1
    speed unknown
    actions {
      follow_lane
    }
  }
  vehicle V2 {
    heading west
    lane 1
    speed unknown
    actions {
      follow_lane
    }
  }
  crash {
    type frontal
    striker V2
    victim V1
  }
}
"""


def test_unnamed_moves_are_chosen_so_fronts_meet_wide_of_a_right_angle() -> None:
    staged, notes, matches = sites_for(parse(T_FRONTAL, "t_frontal.sov"), town(), roads=3)
    lowered = [lower_on(staged, match, town(), notes) for match in matches]
    assert len(lowered) == 3
    for plan in lowered:
        assert plan.contact.angle >= CRASH_ANGLES["frontal"][0], plan.match.site.id
    chosen = [n for plan in lowered for n in plan.notes if "front to front" in n]
    assert chosen  # at least one site needed a move the meeting rule alone would not pick
    assert all("names no manoeuvre at the junction: planned to" in n for n in chosen)
