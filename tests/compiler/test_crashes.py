"""What each crash type accepts at the first touch (compiler/crashes.py): faces and the angle between
headings, as synthesis and the SUMO oracle both judge it."""

from __future__ import annotations

from dataclasses import replace

import pytest
from hypothesis import assume, given
from hypothesis import strategies as st
from sovarc.compiler.crashes import REAR_END_MAX_ANGLE, fits, struck_face, victim_face
from sovarc.compiler.geometry.angles import heading_vector
from sovarc.compiler.geometry.bodies import Box, Contact, first_touch
from sovarc.dsl.ir import CrashType
from sovarc.targets.sumo.oracle import _angle_finding

from tests.targets.sumo.plans import SCENES


def _verdict(kind: CrashType, striker_zone: tuple[str, ...], victim_zone: tuple[str, ...], angle: float) -> bool:
    plan = SCENES["head_on"]()
    plan = replace(plan, impact=replace(plan.impact, type=kind))
    contact = Contact(3.0, (0.0, 0.0), ("front", "front"), (striker_zone, victim_zone), angle)
    passed = _angle_finding(plan, contact).passed
    assert fits(kind, contact) is passed  # the SUMO oracle judges by the crash definitions, as synthesis does
    return passed


@pytest.mark.parametrize(
    ("striker", "victim", "angle", "passed"),
    [
        (("front",), ("front",), 178.0, True),  # head-on
        (("front", "left"), ("front", "right"), 115.0, True),  # a left turner met by an oncoming car
        (("front", "left"), ("front", "right"), 95.0, False),  # fronts at right angles: not approaching
        (("front",), ("left",), 170.0, False),  # a sideswipe of oncoming cars is not frontal
    ],
)
def test_frontal_is_front_into_front_while_approaching(
    striker: tuple[str, ...], victim: tuple[str, ...], angle: float, passed: bool
) -> None:
    assert _verdict(CrashType.FRONTAL, striker, victim, angle) is passed


@pytest.mark.parametrize(("angle", "passed"), [(10.0, True), (44.0, True), (50.0, False)])
def test_rear_end_needs_headings_within_45_degrees(angle: float, passed: bool) -> None:
    assert _verdict(CrashType.REAR_END, ("front",), ("rear",), angle) is passed


def test_side_is_decided_by_the_faces_not_the_angle() -> None:
    assert _verdict(CrashType.SIDE, ("front",), ("left",), 20.0)
    assert not _verdict(CrashType.SIDE, ("front",), ("rear",), 90.0)


# --- which face of a corner is struck (crashes.struck_face), from bodies that touch -------------------

CAR_L, CAR_W = 4.6, 1.8


def _car(x: float, y: float, heading: float) -> Box:
    return Box(x, y, heading, CAR_L, CAR_W, front_ref=True)


def _turned_victim(turned: float) -> tuple[Box, tuple[float, float]]:
    """A car turned `turned` degrees left off an eastbound lane (0 < turned < 90), standing with its
    rear-left corner, the westmost point of its body, at the origin: the body and that corner."""
    heading = 90.0 - turned
    (fx, fy), (lx, ly) = heading_vector(heading), heading_vector(heading - 90.0)
    front = (CAR_L * fx - CAR_W / 2 * lx, CAR_L * fy - CAR_W / 2 * ly)
    return _car(*front, heading), (0.0, 0.0)


def _follower_touch(turned: float, beside: float) -> Contact:
    """An eastbound follower driving in its lane into the rear-left corner of the turned car, the
    corner `beside` m to the left of the middle of its front (inside its width): its front face is
    what the corner meets."""
    victim, _ = _turned_victim(turned)
    start, end = _car(-3.0, -beside, 90.0), _car(0.5, -beside, 90.0)
    return first_touch(0.0, 1.0, (start, end), (victim, victim))


@pytest.mark.parametrize("turned", [1.0, 8.0, 13.0, 22.0, 30.0, 40.0, 44.0, 46.0, 55.0, 60.0, 75.0, 85.0])
@pytest.mark.parametrize("beside", [-0.6, 0.0, 0.45, 0.8])
def test_a_follower_meets_the_rear_of_a_car_turning_off_until_it_has_turned_past_a_rear_end(
    turned: float, beside: float
) -> None:
    # straight_0: V2 turns left off the lane, V1 following in it meets its rear-left corner. Within a
    # rear-end's 45 degrees that is the rear (once, 'rear-left corner at 1 degree' counted as a side)
    contact = _follower_touch(turned, beside)
    assert contact.zones[1] == ("rear", "left")
    assert contact.angle == pytest.approx(turned, abs=1e-6)
    rear = turned <= 45.0
    assert victim_face(contact) == ("rear" if rear else "left")
    assert fits(CrashType.SIDE, contact) is not rear
    assert fits(CrashType.REAR_END, contact) is rear


@given(turned=st.floats(0.5, 89.5), beside=st.floats(-0.85, 0.85))
def test_the_struck_face_of_a_turned_rear_corner_follows_the_rear_end_angle(turned: float, beside: float) -> None:
    assume(abs(turned - REAR_END_MAX_ANGLE) > 1e-6)  # the bound itself is measured to rounding
    contact = _follower_touch(turned, beside)
    assert victim_face(contact) == ("rear" if turned <= REAR_END_MAX_ANGLE else "left")


def test_a_corner_that_enters_the_victims_side_strikes_the_side_even_near_its_rear() -> None:
    # a sideswipe: the striker beside the victim, 10 degrees off its heading, drives its front-left
    # corner into the victim's right side 0.2 m ahead of its rear-right corner. The striker's corner
    # enters the side square, so the side is struck, not the rear (a rear-end's angle or not)
    victim = _car(0.0, 2.3, 0.0)
    (fx, fy), (lx, ly) = heading_vector(350.0), heading_vector(260.0)
    front = (0.9 - 0.9 * lx, -2.1 - 0.9 * ly)
    start, end = _car(front[0] - fx, front[1] - fy, 350.0), _car(front[0] + 0.5 * fx, front[1] + 0.5 * fy, 350.0)
    contact = first_touch(0.0, 1.0, (start, end), (victim, victim))
    assert contact.zones == (("front", "left"), ("rear", "right"))
    assert contact.pressed[1] == "right"
    assert fits(CrashType.SIDE, contact)
    assert not fits(CrashType.REAR_END, contact)


@pytest.mark.parametrize(("angle", "face"), [(95.0, "right"), (100.0, "front"), (150.0, "front")])
def test_a_front_corner_met_by_the_strikers_front_is_the_front_from_a_frontal_angle(angle: float, face: str) -> None:
    # the victim's front-right corner meets the striker's flat front (the striker's face is pressed)
    assert struck_face(("front", "right"), None, angle) == face
    assert struck_face(("front", "right"), "right", 150.0) == "right"  # its side entered square


def test_a_backing_striker_strikes_the_corner_end_its_crash_type_names() -> None:
    # backing, a rear_end is the striker's rear into the victim's front (same headings)
    assert struck_face(("front", "left"), None, 10.0, backing=True) == "front"
    assert struck_face(("rear", "left"), None, 10.0, backing=True) == "left"
    assert struck_face(("rear", "left"), None, 170.0, backing=True) == "rear"


def _crossing_touch(striker_front_y: float, victim_front_x: float) -> Contact:
    """A car heading north (front bumper at x = 0) and one heading west (front bumper at y = 0),
    each moving 2 m in a second from the given positions, until they first touch."""
    striker = (_car(0.0, striker_front_y, 0.0), _car(0.0, striker_front_y + 2.0, 0.0))
    victim = (_car(victim_front_x, 0.0, 270.0), _car(victim_front_x - 2.0, 0.0, 270.0))
    return first_touch(0.0, 1.0, striker, victim)


def test_fronts_met_at_right_angles_are_frontal_only_where_the_victims_front_face_is_entered() -> None:
    # the striker's front-right corner half a metre into the victim's way when the victim's front
    # reaches it: the victim's front face is struck square, a frontal crash at 90 degrees
    corner = _crossing_touch(-1.4, CAR_W / 2 + 1.0)
    assert corner.angle == pytest.approx(90.0)
    assert corner.pressed[1] == "front" and "front" in corner.zones[0]
    assert fits(CrashType.FRONTAL, corner)
    # the victim a little earlier: the striker's front runs into its left side, a side crash
    side = _crossing_touch(-2.0, -0.5)
    assert victim_face(side) == "left"
    assert not fits(CrashType.FRONTAL, side)
    assert fits(CrashType.SIDE, side)
