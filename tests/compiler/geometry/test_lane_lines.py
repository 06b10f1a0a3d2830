"""The lane-line test and the lane lookup it rests on, on a road written here: a two-way road
between junctions a and b running east, two lanes each way 3.2 m wide and a sidewalk on each side,
and a junction lane at b. The SUMO oracle and lowering both ask these questions of it.
"""

from __future__ import annotations

import pytest
from sovarc.compiler.geometry.bodies import Box
from sovarc.compiler.geometry.lane_lines import crossed_lane
from sovarc.compiler.geometry.lanes import Lane, LaneMap
from sovarc.compiler.vehicles import CAR

WIDTH = 3.2


def _lane(lane_id: str, y: float, east: bool, *, sidewalk: bool = False, width: float = WIDTH) -> Lane:
    edge, index = lane_id.rsplit("_", 1)
    shape = ((0.0, y), (100.0, y)) if east else ((100.0, y), (0.0, y))
    ends = ("a", "b") if east else ("b", "a")
    return Lane(lane_id, edge, int(index), width, 100.0, shape, False, sidewalk, ends)


# east: ab_1 (inner, y = -1.6), ab_0 (outer, y = -4.8), sidewalk ab_9 (y = -7.4); west: ba_1, ba_0 mirrored
ROAD = LaneMap(
    [
        _lane("ab_0", -4.8, True),
        _lane("ab_1", -1.6, True),
        _lane("ab_9", -7.4, True, sidewalk=True, width=2.0),
        _lane("ba_0", 4.8, False),
        _lane("ba_1", 1.6, False),
        Lane(":b_0_0", ":b_0", 0, WIDTH, 10.0, ((100.0, -1.6), (110.0, -1.6)), True, False),
    ]
)


def _corners(x: float, y: float, heading: float) -> list[tuple[float, float]]:
    return Box.of(CAR, x, y, heading).corners(shrink=0.25)


def test_a_car_inside_its_lane_crosses_nothing() -> None:
    lane = ROAD.lanes["ab_1"]
    assert crossed_lane(ROAD, lane, {"ab_1"}, _corners(50.0, -1.6, 90.0)) is None


def test_a_body_over_the_line_enters_the_lane_beside_unless_its_route_may_use_it() -> None:
    lane = ROAD.lanes["ab_1"]
    over = _corners(50.0, -0.6, 90.0)  # its left side over the centre line
    assert crossed_lane(ROAD, lane, {"ab_1"}, over) == "ba_1"
    assert crossed_lane(ROAD, lane, {"ab_1", "ba_1"}, over) is None
    towards = _corners(50.0, -2.9, 90.0)  # its right side over the line between its road's lanes
    assert crossed_lane(ROAD, lane, {"ab_1"}, towards) == "ab_0"


def test_a_vehicle_on_a_lane_it_may_not_use_enters_that_lane() -> None:
    lane = ROAD.lanes["ab_0"]
    assert crossed_lane(ROAD, lane, {"ab_1"}, _corners(50.0, -4.8, 90.0)) == "ab_0"


def test_junction_lanes_have_no_lines() -> None:
    junction = ROAD.lanes[":b_0_0"]
    assert crossed_lane(ROAD, junction, set(), _corners(105.0, 1.0, 90.0)) is None


def test_the_sidewalk_is_open_to_walkers_and_to_a_car_crossing_it_by_a_driveway() -> None:
    lane = ROAD.lanes["ab_0"]
    onto = _corners(50.0, -6.3, 90.0)  # its right side over the kerb line, onto the sidewalk
    assert crossed_lane(ROAD, lane, {"ab_0"}, onto) == "ab_9"
    assert crossed_lane(ROAD, lane, {"ab_0"}, onto, kerb=True) is None
    sidewalk = ROAD.lanes["ab_9"]
    walker = Box(50.0, -7.4, 90.0, 0.5, 0.6, front_ref=False).corners(shrink=0.25)
    assert crossed_lane(ROAD, sidewalk, {"ab_0"}, walker, pedestrian=True) is None


@pytest.mark.parametrize(
    ("y", "heading", "expected"), [(-1.6, 90.0, "ab_1"), (1.6, 270.0, "ba_1"), (-1.6, 270.0, "ab_1")]
)
def test_the_lookup_takes_a_lane_that_holds_the_point_running_its_way_first(
    y: float, heading: float, expected: str
) -> None:
    among = [ROAD.lanes[i] for i in ("ab_1", "ba_1")]
    assert ROAD.holding(50.0, y, heading, among).id == expected
    assert ROAD.locate(50.0, y, heading, frozenset()).lane.id == expected


def test_where_two_lanes_hold_the_point_the_one_running_its_way_is_taken() -> None:
    # on the centre line both inner lanes hold the point: the heading decides
    among = [ROAD.lanes[i] for i in ("ab_1", "ba_1")]
    assert ROAD.holding(50.0, 0.0, 90.0, among).id == "ab_1"
    assert ROAD.holding(50.0, 0.0, 270.0, among).id == "ba_1"
    assert ROAD.holding(50.0, 9.0, 90.0, among) is None  # off both


def test_the_lanes_beside_are_its_road_and_the_road_the_other_way() -> None:
    beside = {lane.id for lane in ROAD.alongside(ROAD.lanes["ab_1"])}
    assert beside == {"ab_0", "ab_9", "ba_0", "ba_1"}
    assert ROAD.alongside(ROAD.lanes[":b_0_0"]) == []
