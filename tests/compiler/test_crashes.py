"""What each crash type accepts at the first touch (compiler/crashes.py): faces and the angle between
headings, as synthesis and the SUMO oracle both judge it."""

from __future__ import annotations

from dataclasses import replace

import pytest
from sovarc.compiler.crashes import fits
from sovarc.compiler.geometry.bodies import Contact
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
