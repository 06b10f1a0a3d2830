"""U-turns that fit the road: the body stays between its edges, the line has no kink."""

from __future__ import annotations

import numpy as np
import pytest
from sovarc.compiler.geometry.frame import Band
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.lower.corridor import Corridor, Drive
from sovarc.compiler.lower.uturn import choose, footprint, layout, u_turn_line
from sovarc.compiler.maps import LaneInfo
from sovarc.compiler.vehicles import CAR, CAR_MODEL
from sovarc.dsl.errors import UnsatError

LENGTH = 200.0


def _road(lanes: int, width: float) -> Corridor:
    """A straight road running east, `lanes` lanes each way (lane 1 right-most of its direction)."""

    def lane(edge: str, k: int, y: float, reverse: bool) -> LaneInfo:
        shape = ((LENGTH, y), (0.0, y)) if reverse else ((0.0, y), (LENGTH, y))
        return LaneInfo(f"{edge}_{k}", edge, k, k + 1, width, LENGTH, 13.9, shape)

    east = tuple(lane("e", k, -(lanes - k - 0.5) * width, False) for k in range(lanes))
    west = tuple(lane("w", k, (lanes - k - 0.5) * width, True) for k in range(lanes))
    return Corridor(east, west)


def _turn(corridor: Corridor, to: int) -> tuple[Band, Polyline]:
    band = Band.across(corridor.own, corridor.other)
    start = corridor.own_line(1).point(60.0)
    lanes = [(lane.number, Polyline(lane.shape)) for lane in corridor.other]  # running the new way
    number, d_to, plan = choose(band, start, [lanes[to - 1]], CAR)
    assert number == to and plan.fits
    turn, _, _ = u_turn_line(band, start, lanes[to - 1][1], d_to, plan)
    return band, turn


@pytest.mark.parametrize(("width", "to"), [(3.2, 2), (3.2, 1), (3.75, 2), (3.5, 1)])
def test_a_u_turn_on_a_two_lane_road_keeps_the_body_on_it(width: float, to: int) -> None:
    band, turn = _turn(_road(2, width), to)
    low, high = footprint(turn, band, CAR)
    assert band.right <= low and high <= band.left
    assert band.place(turn.point(turn.length))[1] == pytest.approx((4 - to) * width, abs=0.05)


@pytest.mark.parametrize("width", [3.2, 3.5, 3.75])
def test_a_tight_u_turn_is_a_round_curve_not_a_kink(width: float) -> None:
    _, turn = _turn(_road(2, width), 2)
    radii = turn.curvature_radius(window=2.0)
    assert radii.min() >= 0.95 * CAR_MODEL.front_radius
    turns = np.abs((np.diff(turn.headings(turn.s[:-1] + 1e-6)) + 180.0) % 360.0 - 180.0)
    assert turns.max() < 10.0  # degrees between neighbouring segments


def test_a_wide_road_turns_straight_into_the_lane() -> None:
    corridor = _road(4, 3.6)
    band = Band.across(corridor.own, corridor.other)
    plan = layout(band, 0.0, 5 * 3.6, CAR)  # from lane 1 to the other way's lane 3
    assert plan.fits and plan.d1 == pytest.approx(5 * 3.6)  # no move across after the half circle
    assert 0.0 < plan.d0 < 0.5 and plan.radius > 8.5  # moved over a little: the rear swings out


def test_a_road_too_narrow_even_for_a_turn_in_legs_is_unsatisfiable() -> None:
    corridor = _road(1, 2.6)  # 5.2 m: one sweep needs 11.6 m, five legs 5.6 m (test_kturn.py)
    band = Band.across(corridor.own, corridor.other)
    assert not layout(band, 0.0, 2.6, CAR).fits
    drive = Drive(corridor, corridor.own_line(1), 1, site="road:test")
    with pytest.raises(UnsatError, match=r"road:test.*5\.2 m wide, too narrow for a U-turn even in 5 legs"):
        drive.u_turn(1, 60.0, None)


def test_a_u_turn_without_a_lane_ends_where_the_narrow_road_lets_it() -> None:
    corridor = _road(2, 3.75)
    drive = Drive(corridor, corridor.own_line(2), 2)  # from the lane by the centre line
    drive.u_turn(0, 60.0, None)
    assert drive.lane == 1  # the far lane: the one by the centre line is too close to turn into
    assert {lane.id for lane in corridor.own + corridor.other} <= drive.lanes
