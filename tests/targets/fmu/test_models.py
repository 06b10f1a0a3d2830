"""The pieces the harness is made of: bicycle model, body geometry, routes and ego tasks."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
import sumolib
from sovarc.compiler.geometry.bodies import Box, overlap
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.vehicles import CAR, PEDESTRIAN
from sovarc.targets.fmu.bicycle import MAX_BRAKE, Geometry, State, advance
from sovarc.targets.fmu.geometry import TICK, straight_on, time_to_collision
from sovarc.targets.fmu.task import GOAL_MARGIN, MIN_CRUISE, extended, make_task, to_ego_frame

from tests.targets.fmu.plans import TOWN, car_following, eastbound

CAR_GEOMETRY = Geometry.of(CAR)


def test_bicycle_goes_straight_turns_left_and_never_reverses() -> None:
    state = State(0.0, 0.0, 90.0, 10.0)  # heading east
    for _ in range(20):
        state = advance(state, 0.0, 0.0, 0.05, CAR_GEOMETRY)
    assert (state.x, state.y, state.heading) == pytest.approx((10.0, 0.0, 90.0))
    left = State(0.0, 0.0, 0.0, 10.0)  # heading north, positive steer is to the left: heading decreases
    for _ in range(10):
        left = advance(left, 0.0, 0.2, 0.05, CAR_GEOMETRY)
    assert 300.0 < left.heading < 360.0 and left.x < 0.0
    stopped = advance(State(0.0, 0.0, 0.0, 0.1), -20.0, 0.0, 0.05, CAR_GEOMETRY)
    assert stopped.speed == 0.0 and stopped.accel == pytest.approx(-2.0)  # clamped braking, then rest
    hard = advance(State(0.0, 0.0, 0.0, 20.0), -20.0, 0.0, 0.05, CAR_GEOMETRY)
    assert hard.accel == pytest.approx(-MAX_BRAKE)


def test_boxes_overlap_and_the_front_bumper_is_the_reference_point() -> None:
    ego = Box.of(CAR, 10.0, 0.0, 90.0)  # front bumper at x = 10, body back to x = 5.4
    xs = [x for x, _ in ego.corners()]
    assert min(xs) == pytest.approx(5.4) and max(xs) == pytest.approx(10.0)
    assert overlap(ego, Box.of(CAR, 14.0, 0.0, 90.0))  # its back at 9.4
    assert not overlap(ego, Box.of(CAR, 14.7, 0.0, 90.0))
    assert not overlap(ego, Box.of(CAR, 10.0, 2.0, 90.0))  # side by side, 0.2 m apart
    assert overlap(Box.of(PEDESTRIAN, 0.0, 0.0, 0.0), Box.of(PEDESTRIAN, 0.2, 0.2, 45.0))


def test_time_to_collision_head_on_and_apart() -> None:
    def ahead(*values: float) -> tuple[np.ndarray, ...]:
        return straight_on(*(np.array([v]) for v in values))

    # fronts 20 m apart, closing at 20 m/s; the three-disc cover touches a little before the boxes do
    ttc = time_to_collision(ahead(0.0, 0.0, 90.0, 10.0), CAR, ahead(20.0, 0.0, 270.0, 10.0), CAR)
    assert 0.8 - TICK < float(ttc[0]) <= 1.0
    apart = time_to_collision(ahead(0.0, 0.0, 90.0, 10.0), CAR, ahead(0.0, 3.5, 90.0, 10.0), CAR)
    assert math.isinf(float(apart[0]))  # the next lane over, same speed
    touching = time_to_collision(ahead(0.0, 0.0, 90.0, 0.0), CAR, ahead(4.0, 0.0, 90.0, 0.0), CAR)
    assert float(touching[0]) == 0.0


def test_polyline_projection_and_extension() -> None:
    line = Polyline([(0.0, 0.0), (10.0, 0.0), (10.0, 10.0)])
    assert line.length == pytest.approx(20.0)
    assert line.project_within((12.0, 4.0)) == pytest.approx((14.0, 2.0))
    assert line.heading(5.0) == pytest.approx(90.0) and line.heading(15.0) == pytest.approx(0.0)
    longer = extended(line, 5.0, towards=[(10.0, 12.0)])
    assert longer.length == pytest.approx(27.0) and longer.point_at(27.0) == pytest.approx((10.0, 17.0))
    assert to_ego_frame(0.0, 10.0, 0.0, 0.0, 90.0) == pytest.approx((0.0, 10.0))  # facing east, north is left


def test_an_ego_task_follows_the_planned_path_and_speeds() -> None:
    plan = car_following()
    task = make_task(plan, "V1")
    trajectory = plan.trajectory("V1")
    assert (task.start.x, task.start.y) == (trajectory.samples[0].x, trajectory.samples[0].y)
    assert task.goal == pytest.approx(task.path_end + GOAL_MARGIN)
    assert task.target_speed(1.0) == pytest.approx(14.0)
    assert task.target_speed(task.path_end - 1.0) == pytest.approx(9.0, abs=0.1)
    assert task.target_speed(task.path_end + 5.0) == task.cruise >= MIN_CRUISE
    ahead = task.path_points(0.0, task.start.x, task.start.y, task.start.heading)
    assert ahead[0] == pytest.approx((4.0, 0.0)) and ahead[-1] == pytest.approx((48.0, 0.0))
    assert task.budget > plan.duration


def test_a_wrong_way_route_goes_on_straight_and_its_goal_stays_ahead() -> None:
    """A driver on the wrong side of the road ends on the other direction's edge: following that
    edge's lanes would turn the route back on itself and put the goal out of reach."""
    net = sumolib.net.readNet(str(TOWN))
    lanes = lambda edge: [(lane.getID(), lane.getShape()) for lane in net.getEdge(edge).getLanes()]  # noqa: E731
    plan = car_following()
    v1 = plan.trajectory("V1")
    on_wrong_side = eastbound("V1", 20.0, 1, lambda t: 14.0, 10.0, lateral=lambda t: 9.9)  # in -ave2_3, east
    wrong_way = replace(on_wrong_side, edges=("ave2", "-ave2"), lanes=("ave2_1", "-ave2_3"))
    assert wrong_way.samples[-1].y == pytest.approx(1.65) and v1.samples[-1].y == pytest.approx(-8.25)
    plan = replace(plan, trajectories=(wrong_way, plan.trajectory("V2")))
    task = make_task(plan, "V1", lanes)
    end = task.route.point_at(task.path_end)
    assert task.route.heading(task.path_end + 1.0) == pytest.approx(90.0, abs=1.0)
    assert task.route.point_at(task.goal) == pytest.approx((end[0] + GOAL_MARGIN, 1.65), abs=0.1)
    right_way = make_task(car_following(), "V1", lanes)  # its own lane goes on east
    assert right_way.route.point_at(right_way.goal)[1] == pytest.approx(-8.25, abs=0.1)
