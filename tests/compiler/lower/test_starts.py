"""Vehicles that start in one lane start apart: bodies that overlap at the start are a crash
before the crash (a striker begun beside its victim's rear meets it front to rear at once)."""

from __future__ import annotations

from sovarc.compiler.lower import lower_on, sites_for
from sovarc.compiler.lower.solve import START_GAP
from sovarc.dsl import parse
from sovarc.dsl.errors import UnsatError

from tests.compiler.lower.staging import town

# V2 turns left off the road ahead of V1, which follows it in its lane and hits its side
FOLLOWER_HITS_TURNER = """scenario follower_hits_turner {
  road {
    kind straight
    lanes 2
    speed_limit unknown
  }
  vehicle V1 {
    heading east
    lane 1
    speed unknown
    actions {
      follow_lane
    }
  }
  vehicle V2 {
    heading east
    lane 1
    speed unknown
    actions {
      follow_lane
      turn_left(to: 1)
    }
  }
  crash {
    type side
    striker V1
    victim V2
  }
}
"""


def test_a_victim_starting_in_its_strikers_lane_starts_a_body_length_ahead() -> None:
    scenario = parse(FOLLOWER_HITS_TURNER, "follower.sov")
    together = 0
    for seed in (1, 2):  # on road:-stem|stem both lines begin at the road's end
        staged, notes, matches = sites_for(scenario, town(), roads=3, seed=seed)
        for match in matches:
            try:
                lowered = lower_on(staged, match, town(), notes)
            except UnsatError:  # a driveway turn too wide: the follower meets its rear, on no side
                continue
            striker, victim = lowered.routes["V1"], lowered.routes["V2"]
            if striker.line.point(0.0) != victim.line.point(0.0):
                continue
            together += 1
            starts = lowered.solution.starts
            assert starts["V2"] - starts["V1"] >= victim.body.length + START_GAP - 1e-6, match.site.id
    assert together
