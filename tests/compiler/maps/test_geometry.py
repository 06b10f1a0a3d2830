"""Laying a compass cross over a site's arms (no SUMO needed)."""

from __future__ import annotations

import pytest
from sovarc.compiler.maps.geometry import fit_frame


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
