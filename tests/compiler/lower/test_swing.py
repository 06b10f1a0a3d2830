"""A junction move keeps the car's body between its approach lane's lines up to the stop line.

SUMO's junction lanes start 12-19 degrees off the approach lane; smoothing the route rounded
that bend from a few metres before the stop line, and the rear of a car whose front was still
on its approach lane swung over the lane's far line (ground truth t/18 on the town's T junction
t_north, t/19 on the DRT city's junction 1560223462: the SUMO oracle's line crossings).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import sumo
from sovarc.compiler.crashes import LINE_TOLERANCE
from sovarc.compiler.frontend.truth import import_truth_file
from sovarc.compiler.geometry.bodies import Box
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.lower import lower_on, sites_for
from sovarc.compiler.lower.swing import MARGIN, Approach, keep_in_lane
from sovarc.compiler.maps import RoadMap, load_map
from sovarc.compiler.plan import Plan
from sovarc.compiler.synth import synthesize
from sovarc.compiler.vehicles import CAR

from tests.compiler.lower.staging import town
from tests.conftest import SHARED, requires_shared

TRUTH = SHARED / "data" / "nmvccs" / "truth" / "t"
CITY = Path(sumo.SUMO_HOME) / "tools" / "game" / "DRT" / "osm.net.xml"


def _plan(number: int, road_map: RoadMap, site: str) -> Plan:
    staged, notes, matches = sites_for(import_truth_file(TRUTH / f"{number}.json").scenario, road_map, roads=3)
    match = next(m for m in matches if m.site.id == site)
    return synthesize(lower_on(staged, match, road_map, notes))


def _worst_reach(plan: Plan, participant: str, road_map: RoadMap, lane_id: str) -> float:
    """How far the body's corners (moved in by the SUMO oracle's tolerance) reach beyond the lane's
    lines, over the plan's samples whose body lies along the lane, its front not yet past the
    lane's end (the stop line)."""
    lane = road_map.net.getLane(lane_id)
    centre = Polyline([p[:2] for p in lane.getShape()])
    (ex, ey), (px, py) = centre.points[-1], centre.points[-2]
    trajectory = plan.trajectory(participant)
    worst = -math.inf
    for s in trajectory.samples:
        if (s.x - ex) * (ex - px) + (s.y - ey) * (ey - py) >= 0.0:
            continue  # past the stop line
        if centre.project((s.x, s.y))[0] < trajectory.body.length:
            continue  # the rear is still on the lane before this one
        body = Box.of(trajectory.body, s.x, s.y, s.heading)
        corners = np.asarray(body.corners(shrink=LINE_TOLERANCE))
        worst = max(worst, float(centre.distances(corners).max()) - lane.getWidth() / 2.0)
    return worst


@requires_shared
def test_a_right_turn_from_the_stop_line_keeps_the_rear_in_its_lane() -> None:
    """t/18 on t_north: V1 waits at the stop line, then turns right onto an exit lane 3.45 m away."""
    plan = _plan(18, town(), "junction:t_north")
    assert _worst_reach(plan, "V1", town(), "main2_1") < 0.0


@requires_shared
@pytest.mark.slow  # loads the DRT city network (about 2 s)
def test_a_left_turn_and_a_bent_approach_keep_the_rear_in_the_lane_on_the_city() -> None:
    """t/19 on the city's junction 1560223462: V1's left turn starts 19 degrees off its lane, and
    V2's approach lane itself bends 43 degrees in its last 2 m; both rears swung onto the sidewalk."""
    city = load_map(CITY)
    plan = _plan(19, city, "junction:1560223462")
    assert _worst_reach(plan, "V1", city, "38160000_1") < 0.0
    assert _worst_reach(plan, "V2", city, "172013798#3_1") < 0.0


@requires_shared
@pytest.mark.slow  # replays in SUMO
def test_the_sumo_oracle_sees_no_line_crossing_on_t_north() -> None:
    from sovarc.targets.sumo import check

    verdict = check(_plan(18, town(), "junction:t_north"))
    lanes = next(f for f in verdict.findings if f.check == "lane_lines")
    assert lanes.passed, lanes.message


# A SUMO-like right turn: the approach lane runs north to its stop line at y = 30; the junction
# lane starts 13 degrees off it and reaches the exit lane, running east, 3.5 m further north.
LANE = Polyline([(0.0, 0.0), (0.0, 30.0)])
RAW = Polyline([(0.0, 0.0), (0.0, 30.0), (0.35, 31.5), (1.4, 32.6), (3.15, 33.25), (5.6, 33.5), (40.0, 33.5)])


def test_a_bend_that_swings_the_body_out_is_reshaped_and_the_stop_line_carries_over() -> None:
    smooth, from_s = RAW.smoothing()
    approach = Approach(float(np.interp(30.0, from_s, smooth.s)), ((LANE, 1.6),))
    assert approach.line_overreach(smooth, CAR) > -MARGIN  # smoothing alone swings the rear out
    line, carried, moved = keep_in_lane(smooth, from_s, approach, CAR)
    assert moved.line_overreach(line, CAR) <= -MARGIN
    assert len(carried) == len(line.s) and np.all(np.diff(carried) > 0.0)
    assert np.interp(30.0, carried, line.s) == pytest.approx(moved.stop, abs=0.05)  # the stop line carries over
    assert abs(line.point(moved.stop)[1] - 30.0) < 0.1
    assert line.curvature_radius(window=2.0).min() >= min(smooth.curvature_radius(window=2.0).min(), 3.0)


def test_a_line_that_keeps_the_body_in_is_left_as_it_is() -> None:
    straight = Polyline([(0.0, 0.0), (0.0, 30.0), (0.0, 60.0)])
    smooth, from_s = straight.smoothing()
    approach = Approach(30.0, ((LANE, 1.6),))
    line, carried, moved = keep_in_lane(smooth, from_s, approach, CAR)
    assert line is smooth and carried is from_s and moved is approach
