"""The kernel's polyline: many-point distances agree with one-point projection."""

from __future__ import annotations

import numpy as np
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from sovarc.compiler.geometry.polyline import Polyline

coordinate = st.floats(-200.0, 200.0, allow_nan=False)
point = st.tuples(coordinate, coordinate)


@settings(max_examples=60, deadline=None)
@given(st.lists(point, min_size=2, max_size=8, unique=True), st.lists(point, min_size=1, max_size=30))
def test_distances_match_project_point_by_point(shape: list, points: list) -> None:
    steps = np.hypot(*np.diff(np.asarray(shape), axis=0).T)
    assume(bool((steps > 1e-3).all()))  # a polyline's consecutive points are distinct
    line = Polyline(np.asarray(shape))
    many = line.distances(np.asarray(points))
    one_by_one = [line.project(p)[1] for p in points]
    assert np.allclose(many, one_by_one, atol=1e-6)


def test_distance_is_to_the_segments_not_the_vertices() -> None:
    line = Polyline(np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 10.0]]))
    assert line.distances(np.array([[5.0, 2.0], [12.0, 5.0], [-3.0, 4.0]])).tolist() == [2.0, 2.0, 5.0]


def test_curvature_radius_of_an_arc_and_a_straight() -> None:
    angles = np.radians(np.arange(0.0, 91.0, 1.0))
    arc = Polyline(np.column_stack((20.0 * np.cos(angles), 20.0 * np.sin(angles))))
    radii = arc.curvature_radius(window=6.0)
    assert np.allclose(radii[10:-10], 20.0, rtol=0.08)  # within a segment (1 degree) of the turn, away from the ends
    straight = Polyline(np.array([[0.0, 0.0], [5.0, 0.0], [30.0, 0.0]]))
    assert np.isinf(straight.curvature_radius()).all()
