"""Three-point turns: legs at full lock that keep the body on the road, and stop at every change of gear."""

from __future__ import annotations

import math

import numpy as np
import pytest
from sovarc.compiler.crashes import LINE_TOLERANCE
from sovarc.compiler.geometry.frame import Band
from sovarc.compiler.lower.corridor import Drive
from sovarc.compiler.lower.kturn import KERB_OVERHANG, STEP, corners_d, layout
from sovarc.compiler.lower.uturn import corner_span
from sovarc.compiler.vehicles import CAR, CAR_MODEL, REAR_OVERHANG

from tests.compiler.lower.test_uturn import _road

AXLE_RADIUS = CAR_MODEL.axle_radius
EAST, WEST = 90.0, 270.0


def _band(width: float) -> Band:
    corridor = _road(1, width)
    return Band.across(corridor.own, corridor.other)


@pytest.mark.parametrize(("width", "legs"), [(3.2, 3), (3.5, 3), (3.75, 3), (2.8, 5), (3.0, 5)])
def test_a_two_lane_street_takes_a_three_point_turn_a_narrower_one_five(width: float, legs: int) -> None:
    plan = layout(_band(width), 0.0, width, CAR)
    assert plan is not None
    assert plan.count == legs
    assert plan.legs.gears == (1, -1, 1, -1, 1)[:legs]  # forward, reverse, ... and forward to finish
    assert len(plan.legs.stops) == legs  # it stands before the first leg and between every two
    assert plan.legs.poses[-1][2] == pytest.approx(math.pi)  # facing back, straight


@pytest.mark.parametrize("width", [2.8, 3.2, 3.75])
def test_the_body_stays_on_the_road_within_the_oracles_tolerance(width: float) -> None:
    band = _band(width)
    plan = layout(band, 0.0, width, CAR)
    assert plan is not None
    low = min(corners_d(pose, CAR)[0] for pose in plan.legs.poses)
    high = max(corners_d(pose, CAR)[1] for pose in plan.legs.poses)
    assert KERB_OVERHANG < LINE_TOLERANCE  # a bumper over the kerb, inside what the SUMO oracle allows
    assert band.right - KERB_OVERHANG - 1e-9 <= low and high <= band.left + KERB_OVERHANG + 1e-9


def test_the_rear_axle_turns_no_tighter_than_full_lock() -> None:
    plan = layout(_band(3.2), 0.0, 3.2, CAR)
    assert plan is not None
    poses = np.array(plan.legs.poses)
    moved = np.hypot(*np.diff(poses[:, :2], axis=0).T)
    turned = np.abs(np.diff(poses[:, 2]))
    assert (moved <= STEP + 1e-9).all()
    assert (turned <= moved / AXLE_RADIUS * 1.001 + 1e-6).all()  # chords are a hair shorter than arcs


def test_a_street_too_narrow_even_for_five_legs_has_no_layout() -> None:
    assert layout(_band(2.6), 0.0, 2.6, CAR) is None


def _between(a: float, b: float) -> float:
    return abs((a - b + 180.0) % 360.0 - 180.0)


def _turned(width: float) -> Drive:
    corridor = _road(1, width)
    drive = Drive(corridor, corridor.own_line(1), 1, site="road:test")
    drive.u_turn(1, 60.0, None)
    return drive


def test_a_drive_turns_in_legs_where_one_sweep_does_not_fit() -> None:
    drive = _turned(3.2)
    assert len(drive.manoeuvres) == 1
    turn = drive.manoeuvres[0]
    assert turn.index == 1 and turn.gears == (1, -1, 1) and len(turn.stops) == 3
    assert turn.lo >= 100.0  # halfway along the 200 m road at the earliest
    assert any("turns in 3 legs (a three-point turn)" in note for note in drive.notes)
    assert drive.lane == 1 and {lane.id for lane in _road(1, 3.2).own + _road(1, 3.2).other} <= drive.lanes
    line = drive.line
    # at each change of gear the front bumper turns back: it moved along the heading, now against it
    for stop, gear in zip(turn.stops[1:], turn.gears[1:], strict=True):
        facing = float(turn.facing(np.array([stop]))[0])
        before, after = line.heading(stop - 0.05), line.heading(stop + 0.05)
        assert _between(before, facing) < 90.0 if gear == -1 else _between(before, facing) > 90.0
        assert _between(after, facing) > 90.0 if gear == -1 else _between(after, facing) < 90.0
        assert _between(before, after) > 60.0  # a corner where the wheels turn at rest, no curve
    # the heading the body faces turns smoothly from east to west, through the stops too
    assert turn.heading[0] % 360.0 == pytest.approx(EAST, abs=1e-6)
    assert turn.heading[-1] % 360.0 == pytest.approx(WEST, abs=1e-6)
    assert np.abs(np.diff(turn.heading)).max() < 5.0


def test_the_body_placed_from_the_heading_stays_on_the_road() -> None:
    width = 3.2
    drive, band = _turned(width), _band(width)
    turn = drive.manoeuvres[0]
    ahead = CAR.length * (1.0 - REAR_OVERHANG)
    low, high = corner_span(drive.line, turn.s, turn.heading, band, CAR)
    assert band.right - KERB_OVERHANG - 0.01 <= low and high <= band.left + KERB_OVERHANG + 0.01
    # the front bumper moves as the rear axle's arcs say: it leaves the kerb at an angle to the heading
    leaves = drive.line.heading(turn.stops[0] + 0.05)
    assert _between(leaves, EAST) == pytest.approx(math.degrees(math.atan(ahead / AXLE_RADIUS)), abs=3.0)
