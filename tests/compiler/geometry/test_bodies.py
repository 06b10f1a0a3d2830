"""The kernel's body boxes and their first touch, on plain geometry (every oracle uses them)."""

from __future__ import annotations

import math

import pytest
from sovarc.compiler.geometry.bodies import Box, Contact, first_touch, overlap
from sovarc.targets.openscenario.kinematics import faces_at
from sovarc.targets.openscenario.readback import Entity, Pose


def car(x: float, y: float, heading: float) -> Box:
    return Box(x, y, heading, 4.6, 1.8, front_ref=True)


def test_front_reference_puts_the_body_behind_the_point() -> None:
    assert car(0.0, 0.0, 90.0).centre == pytest.approx((-2.3, 0.0))
    assert Box(0.0, 0.0, 90.0, 0.5, 0.6, front_ref=False).centre == (0.0, 0.0)


def test_overlap_needs_shared_area() -> None:
    assert overlap(car(0.0, 0.0, 90.0), car(4.0, 0.0, 90.0))
    assert not overlap(car(0.0, 0.0, 90.0), car(4.6, 0.0, 90.0))  # bumpers touching
    assert not overlap(car(0.0, 0.0, 90.0), car(0.0, 1.8, 90.0))  # side by side


@pytest.mark.parametrize(
    ("striker_end", "victim_end", "faces", "angle"),
    [
        # rear-end: striker's front reaches the back of a stopped car ahead
        (car(1.0, 0.0, 90.0), car(5.0, 0.0, 90.0), (("front",), ("rear",)), 0.0),
        # head-on: fronts meet
        (car(1.0, 0.0, 90.0), car(0.0, 0.0, 270.0), (("front",), ("front",)), 180.0),
        # T-bone: northbound front into the middle of an eastbound car's right side
        (car(0.0, 0.5, 0.0), car(2.3, 0.0, 90.0), (("front",), ("right",)), 90.0),
    ],
)
def test_first_touch_names_faces_and_angle(
    striker_end: Box, victim_end: Box, faces: tuple[tuple[str, ...], tuple[str, ...]], angle: float
) -> None:
    back = {0.0: (0.0, -3.0), 90.0: (-3.0, 0.0), 270.0: (3.0, 0.0)}
    dx, dy = back[striker_end.heading]
    striker_start = car(striker_end.x + dx, striker_end.y + dy, striker_end.heading)
    contact = first_touch(0.0, 1.0, (striker_start, striker_end), (victim_end, victim_end))
    assert contact.zones == faces
    assert contact.angle == pytest.approx(angle)
    assert 0.0 < contact.time < 1.0


def test_a_corner_hit_names_both_faces_of_the_corner() -> None:
    # a car drifting left at 10 degrees: its front-left corner reaches the side of the car beside it
    victim = car(12.0, 2.0, 90.0)
    striker_end = car(10.65, 0.30, 80.0)
    striker_start = car(7.69, -0.22, 80.0)
    contact = first_touch(0.0, 1.0, (striker_start, striker_end), (victim, victim))
    assert contact.zones == (("front", "left"), ("right",))


def side_swipe(heading: float, behind: float) -> tuple[Contact, Box, Box]:
    """A northbound victim with its centre at the origin, and a striker on its right driving
    forward at `heading` (compass, west of north) whose front-left corner first meets the victim's
    right side `behind` metres behind its middle: the contact, and both bodies at the touch."""
    victim = car(0.0, 2.3, 0.0)
    r = math.radians(heading)
    (fx, fy), (lx, ly) = (math.sin(r), math.cos(r)), (-math.cos(r), math.sin(r))
    front = (0.9 - 0.9 * lx, -behind - 0.9 * ly)  # the front-bumper centre with its left corner at the touch
    start = car(front[0] - fx, front[1] - fy, heading)
    end = car(front[0] + 0.5 * fx, front[1] + 0.5 * fy, heading)
    return first_touch(0.0, 1.0, (start, end), (victim, victim)), car(*front, heading), victim


def test_a_corner_beside_and_behind_the_victim_meets_its_side() -> None:
    # the striker's centre is further behind the victim's than beside it, yet its corner meets the side
    contact, striker, victim = side_swipe(350.0, 0.3)
    assert striker.centre[1] - victim.centre[1] < -abs(striker.centre[0] - victim.centre[0])
    assert contact.point == pytest.approx((0.9, -0.3), abs=1e-6)
    assert contact.time == pytest.approx(2.0 / 3.0, abs=1e-6)
    assert contact.faces == ("left", "right")
    assert contact.zones == (("front", "left"), ("right",))


def osc_faces(body: Box, point: tuple[float, float]) -> tuple[str, ...]:
    """The OpenSCENARIO oracle's faces of `body` at `point` (its pose at the body centre)."""
    entity = Entity("x", False, body.length, body.width, 0.0, 0.0, None, None, None, {})
    return faces_at(entity, Pose(0.0, *body.centre, math.radians(90.0 - body.heading)), point)


@pytest.mark.parametrize("heading", [340.0, 350.0, 355.0, 358.0])
@pytest.mark.parametrize("behind", [-2.0, -1.0, -0.3, 0.0, 0.3, 1.0, 1.6, 2.0])
def test_first_touch_names_the_faces_the_openscenario_oracle_does(heading: float, behind: float) -> None:
    contact, striker, victim = side_swipe(heading, behind)
    assert contact.point == pytest.approx((0.9, -behind), abs=1e-6)
    assert contact.zones == (osc_faces(striker, contact.point), osc_faces(victim, contact.point))
    assert contact.zones[0] == ("front", "left")
    assert "right" in contact.zones[1]
    assert ("rear" in contact.zones[1]) == (behind >= 4.6 / 4.0)
