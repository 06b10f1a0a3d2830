"""A junction move begins at the stop line: up to it the car keeps its approach lane's heading,
so its body stays between that lane's lines (a turn that bent before the line swung its rear
over them), in the lowered line and in the synthesized path."""

from __future__ import annotations

import numpy as np
from sovarc.compiler.lower import lower_on, sites_for
from sovarc.compiler.lower.polyline import Polyline, unit
from sovarc.compiler.maps.geometry import angle_diff
from sovarc.compiler.plan import CAR, Sample
from sovarc.compiler.synth import synthesize
from sovarc.dsl import parse

from tests.compiler.lower.staging import town

LANE = 3.2  # m: the width of the town's lanes

# V1 waits at the stop line, then turns right; V2 crosses and hits its side
STOP_THEN_TURN = """scenario stop_then_turn {
  road {
    kind t_junction
    lanes 4
    speed_limit 89 km/h
  }
  vehicle V1 {
    heading east
    lane 1
    speed unknown
    actions {
      follow_lane
      stop
      turn_right(to: 1)
    }
  }
  vehicle V2 {
    heading south
    lane 1
    speed unknown
    actions {
      follow_lane
      go_across
    }
  }
  crash {
    type side
    striker V2
    victim V1
  }
}
"""


def test_smoothing_does_not_reach_across_a_pin() -> None:
    corner = Polyline([(0.0, 0.0), (0.0, 30.0), (30.0, 30.0)])  # north, then a right-angle turn east
    line, _ = corner.smoothing(pins=(30.0,))
    assert all(line.heading(s) == 0.0 for s in np.arange(0.0, 29.5, 0.5))  # straight up to the pin
    rounded, _ = corner.smoothing()
    assert rounded.heading(28.0) > 10.0  # unpinned, the corner is rounded off before it


def test_a_turn_keeps_its_approach_heading_up_to_the_stop_line() -> None:
    staged, notes, matches = sites_for(parse(STOP_THEN_TURN, "stop_then_turn.sov"), town(), roads=3)
    assert matches
    for match in matches:
        lowered = lower_on(staged, match, town(), notes)
        route = lowered.routes["V1"]
        assert route.stop_line is not None
        approach = route.line.heading(route.stop_line - 10.0)
        for s in np.arange(route.stop_line - 8.0, route.stop_line - 0.4, 0.5):
            assert abs(angle_diff(route.line.heading(s), approach)) < 2.0, (match.site.id, s)
        samples = next(t for t in synthesize(lowered).trajectories if t.participant == "V1").samples
        approach_lane = route.line.sub(0.0, route.stop_line)
        before = [x for x in samples if route.line.project((x.x, x.y))[0] < route.stop_line - 0.3]
        assert before
        reach = max(float(approach_lane.distances(_rear_corners(x)).max()) for x in before)
        assert reach < LANE / 2.0, match.site.id  # its rear corners are still in its lane


def _rear_corners(x: Sample) -> np.ndarray:
    ahead, left = np.array(unit(x.heading)), np.array(unit(x.heading - 90.0))
    rear = np.array([x.x, x.y]) - CAR.length * ahead
    return np.array([rear + CAR.width / 2.0 * left, rear - CAR.width / 2.0 * left])
