"""Compass headings and angle differences, and helpers on plain shapes (no SUMO needed)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from sovarc.compiler.geometry.angles import angle_diff, compass
from sovarc.compiler.geometry.polyline import (
    distances_to,
    end_heading,
    max_kink,
    max_offset_from_chord,
    point_at,
    start_heading,
)
from sovarc.targets.openscenario.kinematics import turn


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


def test_distance_to_a_polyline_is_to_its_nearest_segment_or_end() -> None:
    line = np.array([(0.0, 0.0), (10.0, 0.0), (10.0, 10.0)])
    points = np.array([(5.0, 3.0), (13.0, 5.0), (-3.0, -4.0)])
    # above the first segment; beside the second; past the start, to the end point
    assert distances_to(line, points) == pytest.approx([3.0, 3.0, 5.0])


angle = st.floats(-720.0, 720.0, allow_nan=False)


@given(angle, angle)
def test_the_openscenario_oracle_turns_by_the_kernels_angle_diff(a: float, b: float) -> None:
    """OpenSCENARIO's frame is radians counter-clockwise; its turn from a to b is angle_diff(b, a)."""
    got = math.degrees(turn(math.radians(a), math.radians(b)))
    assert -180.0 < got <= 180.0 + 1e-9
    assert got == pytest.approx(angle_diff(b, a), abs=1e-9)
