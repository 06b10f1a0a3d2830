"""Compass headings of polylines, and laying a compass cross over a site's arms (no SUMO needed)."""

from __future__ import annotations

import numpy as np
import pytest
from sovarc.compiler.maps.geometry import (
    angle_diff,
    compass,
    distances_to,
    end_heading,
    fit_frame,
    max_kink,
    max_offset_from_chord,
    point_at,
    start_heading,
)


@pytest.mark.parametrize(("dx", "dy", "expected"), [(0, 1, 0), (1, 0, 90), (0, -1, 180), (-1, 0, 270), (1, 1, 45)])
def test_compass_has_north_up_and_turns_clockwise(dx: float, dy: float, expected: float) -> None:
    assert compass(dx, dy) == pytest.approx(expected)


def test_angle_diff_takes_the_short_way_round() -> None:
    assert angle_diff(10, 350) == pytest.approx(20)
    assert angle_diff(350, 10) == pytest.approx(-20)
    assert angle_diff(180, 0) == pytest.approx(180)


def test_headings_at_the_ends_of_a_bent_line() -> None:
    bent = ((0.0, 0.0), (0.0, 100.0), (100.0, 100.0))  # north, then east
    assert start_heading(bent) == pytest.approx(0)
    assert end_heading(bent) == pytest.approx(90)
    assert point_at(bent, 150.0) == pytest.approx((50.0, 100.0))
    assert point_at(bent, 500.0) == (100.0, 100.0)
    assert max_kink(bent) == pytest.approx(90)
    assert max_offset_from_chord(bent) == pytest.approx(100 / 2**0.5)


def test_a_cross_rotated_twenty_degrees() -> None:
    frame = fit_frame([110.0, 20.0, 290.0, 200.0])
    assert frame.orientation == pytest.approx(20)
    assert frame.slots == (1, 0, 3, 2)
    assert frame.error == pytest.approx(0)


def test_orientation_is_kept_within_45_degrees_of_north() -> None:
    frame = fit_frame([80.0, 170.0, 260.0, 350.0])
    assert frame.orientation == pytest.approx(-10)
    assert frame.slots == (1, 2, 3, 0)


def test_a_t_junction_leaves_one_slot_empty() -> None:
    frame = fit_frame([90.0, 180.0, 270.0])  # bar east-west, stem entering southwards
    assert frame.slots == (1, 2, 3)


def test_a_y_junction_gets_three_distinct_slots_in_clockwise_order() -> None:
    frame = fit_frame([0.0, 120.0, 240.0])
    assert len(set(frame.slots)) == 3
    assert frame.error <= 45


def test_a_straight_road_sits_on_opposite_slots() -> None:
    frame = fit_frame([110.0, 290.0])
    assert frame.orientation == pytest.approx(20)
    assert frame.slots == (1, 3)
    assert fit_frame([0.0]).slots == (0,)


def test_a_skewed_four_way_has_a_large_error() -> None:
    assert fit_frame([0.0, 40.0, 180.0, 270.0]).error > 20


def test_more_than_four_arms_is_refused() -> None:
    with pytest.raises(ValueError, match="1 to 4 arms"):
        fit_frame([0.0, 72.0, 144.0, 216.0, 288.0])


def test_distance_to_a_polyline_is_to_its_nearest_segment_or_end() -> None:
    line = np.array([(0.0, 0.0), (10.0, 0.0), (10.0, 10.0)])
    points = np.array([(5.0, 3.0), (13.0, 5.0), (-3.0, -4.0)])
    # above the first segment; beside the second; past the start, to the end point
    assert distances_to(line, points) == pytest.approx([3.0, 3.0, 5.0])
