"""A report's lane on a wider road: a wrong-way driver and the car it meets are read from the centre
line when their lane is the report road's lane by the centre (centre.py); a driveway turn across a
wide road turns a corner of bounded reach, then drives straight over the rest (corridor.py)."""

from __future__ import annotations

import numpy as np
import pytest
from sovarc.compiler.crashes import LINE_TOLERANCE
from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.lower import lower_on
from sovarc.compiler.lower.assume import assume
from sovarc.compiler.lower.corridor import CORNER_REACH, OFF_ROAD, Corridor, Drive, _swing
from sovarc.compiler.maps import Arm, LaneInfo, Site, match_site, scenario_needs
from sovarc.dsl import parse
from sovarc.dsl.ir import RoadKind, Side

from tests.compiler.lower.staging import town

WIDTH = 3.5
MEDIAN = 4.5
LENGTH = 100.0


def _lane(edge: str, k: int, y: float, east: bool) -> LaneInfo:
    shape = ((0.0, y), (LENGTH, y)) if east else ((LENGTH, y), (0.0, y))
    return LaneInfo(f"{edge}_{k}", edge, k, k + 1, WIDTH, LENGTH, 25.0, shape)


def _avenue(each_way: int) -> Site:
    """A straight east-west road of `each_way` lanes each way either side of an open median,
    eastbound on the south side; lanes right-most (kerb) first."""
    inner = MEDIAN / 2.0 + WIDTH / 2.0
    east = tuple(_lane("e", k, -(inner + WIDTH * (each_way - 1 - k)), True) for k in range(each_way))
    west = tuple(_lane("w", k, inner + WIDTH * (each_way - 1 - k), False) for k in range(each_way))
    arms = (Arm("e", 90.0, 1, east, west, LENGTH), Arm("w", 270.0, 3, west, east, LENGTH))
    return Site("road:avenue", RoadKind.STRAIGHT, (LENGTH / 2.0, 0.0), 0.0, arms, median=MEDIAN)


def _wrong_way(lanes: str, lane: int = 1) -> str:
    return f"""scenario wrong_way {{
  road {{
    kind straight
    lanes {lanes}
    speed_limit 64 km/h
  }}
  vehicle V1 {{
    heading east
    lane {lane}
    speed unknown
    actions {{
      follow_lane
      retrograde
    }}
  }}
  vehicle V2 {{
    heading west
    lane {lane}
    speed unknown
    actions {{
      follow_lane
    }}
  }}
  crash {{
    type frontal
    striker V1
    victim V2
  }}
}}
"""


def _lowered(text: str, each_way: int = 3):  # type: ignore[no-untyped-def]
    staged, notes = assume(parse(text, "wrong_way.sov"))
    match = match_site(_avenue(each_way), scenario_needs(staged), clamp=True)
    assert match is not None
    return lower_on(staged, match, town(), notes)


def test_a_wrong_way_driver_on_a_one_lane_road_swerves_from_the_centre_lane_into_the_oncoming_one() -> None:
    lowered = _lowered(_wrong_way("2"))
    striker, victim = lowered.routes["V1"], lowered.routes["V2"]
    # lane 1 of one lane each way is also the lane by the centre line: the swerve crosses one lane
    # line's worth of road and the median, not the whole road kerb to kerb
    assert set(striker.lanes) == {"e_2", "w_2"} and set(victim.lanes) == {"w_2"}
    start, end = striker.line.point(0.0), striker.line.point(striker.line.length)
    assert start[1] == pytest.approx(-(MEDIAN + WIDTH) / 2.0, abs=0.05)
    assert end[1] == pytest.approx((MEDIAN + WIDTH) / 2.0, abs=0.05)
    assert any("planned in lane 3 of 3, by the centre line (V1 crosses the centre line)" in n for n in striker.notes)
    assert any("(V1 comes at it across the centre line)" in n for n in victim.notes)
    assert lowered.contact.angle > 150.0


def test_a_lane_the_report_counts_from_the_kerb_of_a_wider_road_stays_the_kerb_lane() -> None:
    # lane 1 of two each way is the kerb lane, not the one by the centre: read from the right
    striker = _lowered(_wrong_way("4")).routes["V1"]
    assert "e_0" in striker.lanes and "w_0" in striker.lanes and not any("centre line" in n for n in striker.notes)
    # an unknown lane count says nothing of the centre: the lane counts from the right
    assert "e_0" in _lowered(_wrong_way("unknown")).routes["V1"].lanes


def test_the_site_lane_by_the_centre_is_kept_where_the_site_is_no_wider() -> None:
    striker = _lowered(_wrong_way("2"), each_way=1).routes["V1"]
    assert set(striker.lanes) == {"e_0", "w_0"} and not any("centre line" in n for n in striker.notes)


def _leave(each_way: int, side: Side, median: float = MEDIAN) -> Drive:
    site = _avenue(each_way)
    corridor = Corridor.entering(site.arms[0])
    drive = Drive(corridor, corridor.own_line(1), 1, median=median)
    drive.leave(0, 30.0, side)
    return drive


def _sideways_when_turned(drive: Drive, degrees: float) -> float:
    """How far the line has moved off its lane when it first heads `degrees` off the road."""
    for s in np.arange(30.0, drive.line.length, 0.1):
        if abs(angle_diff(drive.line.heading(float(s)), 90.0)) >= degrees:
            return abs(drive.line.point(float(s))[1] - drive.line.point(0.0)[1])
    raise AssertionError("never turned so far")


def test_a_driveway_turn_across_a_wide_road_turns_its_corner_then_drives_straight_across() -> None:
    wide = _leave(3, Side.LEFT)  # from the kerb lane over five lanes and the median
    lateral = WIDTH / 2.0 + 5 * WIDTH + MEDIAN + OFF_ROAD
    assert lateral > CORNER_REACH
    end = wide.line.point(wide.line.length)
    assert end[1] - wide.line.point(0.0)[1] == pytest.approx(lateral + 8.0, abs=0.05)  # 8 m into the driveway
    # the corner is the one a car turns left off a road of one lane each way: as far turned as soon
    narrow = _leave(1, Side.LEFT, median=0.0)
    assert _sideways_when_turned(wide, 50.0) == pytest.approx(_sideways_when_turned(narrow, 50.0), abs=0.3)
    assert _sideways_when_turned(wide, 89.0) <= CORNER_REACH + 0.3
    lo, hi = wide.stretches[0]
    assert hi - lo > lateral  # the stretch runs to the road's edge and beyond, not only round the corner


def test_a_driveway_corner_widens_until_the_trailing_body_keeps_off_the_lane_behind_the_turn() -> None:
    site = _avenue(3)
    corridor = Corridor.entering(site.arms[0])
    from_kerb = Drive(corridor, corridor.own_line(1), 1, median=0.0)
    from_kerb.leave(0, 30.0, Side.LEFT)  # nothing but the kerb behind its turn: the corner as it is
    beside = Drive(corridor, corridor.own_line(3), 3, median=0.0)
    beside.leave(0, 30.0, Side.LEFT)  # lanes 1 and 2 lie on its right, where the rear swings
    lateral = WIDTH / 2.0 + 3 * WIDTH + OFF_ROAD
    assert _sideways_when_turned(from_kerb, 89.0) <= CORNER_REACH + 0.3
    assert CORNER_REACH + 0.5 < _sideways_when_turned(beside, 89.0) < lateral - 1.0  # wider, not the whole road
    # its rear corner stays within lane 3's right-hand line and the oracles' tolerance (the lane runs
    # east, so its left, where it turns, is north: +y); the curve is measured smooth, and its 16 chords
    # (smoothed later, with the whole route) turn a little more abruptly: 0.1 m
    turn = Polyline(beside.line.sub(30.0, beside.line.length).resample(0.1))
    assert _swing(turn, np.array([0.0, 1.0]), beside.body) <= WIDTH / 2.0 + LINE_TOLERANCE + 0.1
    assert _swing(Polyline(from_kerb.line.sub(30.0, 60.0).points), np.array([0.0, 1.0]), from_kerb.body) > 2.1
