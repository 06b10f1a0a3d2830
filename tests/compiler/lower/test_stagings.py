"""Stagings tried when the report's own facts do not make the crash on a site: each changes only
what a report leaves open, or holds least firmly, and says so in a note."""

from __future__ import annotations

from sovarc.compiler.crashes import CRASH_ANGLES
from sovarc.compiler.lower import lower_on, sites_for
from sovarc.dsl import parse

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


# V1 turns left out of the stem into lane 2; V2 goes by in lane 1: as named, they never meet
TURN_INTO_LANE_2 = """scenario turn_into_lane_2 {
  road {
    kind t_junction
    lanes 4
    speed_limit 50 km/h
  }
  vehicle V1 {
    heading south
    lane 1
    speed unknown
    actions {
      stop
      turn_left(to: 2)
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


def test_a_turn_into_the_lane_beside_its_partner_ends_in_the_partners_lane_for_a_side_crash() -> None:
    staged, notes, matches = sites_for(parse(TURN_INTO_LANE_2, "turn.sov"), town(), roads=2)
    for match in matches:
        plan = lower_on(staged, match, town(), notes)
        assert any("V1's turn ends in its partner's lane" in n for n in plan.notes), match.site.id
        assert plan.contact.angle < 45.0  # V1 moves over into V2's lane ahead of it: a shallow side hit
