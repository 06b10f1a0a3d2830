"""Impacts said in other words (issue 18, sgo7), on sentences written for these tests: a glancing blow is a
strike, "its" after a strike's participle or its object is the object's, and a follower "was traveling behind"."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend.crash import read_sentence
from sovarc.dsl.ir import Crash, CrashType


@pytest.mark.parametrize(
    ("sentence", "crash"),
    [
        ("V2 sideswiped V1.", Crash(CrashType.SIDE, "V2", "V1")),
        ("V1 was sideswiped by V2 as it changed lanes.", Crash(CrashType.SIDE, "V2", "V1")),
        ("The right side of V2 side-swiped the left side of V1.", Crash(CrashType.SIDE, "V2", "V1")),
        ("V2 clipped the rear bumper of V1.", Crash(CrashType.REAR_END, "V2", "V1")),
        ("The front of V2 grazed the left side of V1.", Crash(CrashType.SIDE, "V2", "V1")),
        ("V1 brushed against the right side of V2.", Crash(CrashType.SIDE, "V1", "V2")),
        ("V1 was clipped by V2 in the left side.", Crash(CrashType.SIDE, "V2", "V1")),
        ("V1 was grazed on the left side by the front of V2.", Crash(CrashType.SIDE, "V2", "V1")),
    ],
)
def test_a_glancing_blow_is_a_strike(sentence: str, crash: Crash) -> None:
    assert read_sentence(sentence) == crash


@pytest.mark.parametrize(
    ("sentence", "crash"),
    [
        ("V2 struck V1, striking its rear bumper.", Crash(CrashType.REAR_END, "V2", "V1")),
        ("V2 then hit V1 at its rear bumper.", Crash(CrashType.REAR_END, "V2", "V1")),
        ("V2 struck V1 on its left side.", Crash(CrashType.SIDE, "V2", "V1")),
        # a part the subject puts to the other is its own
        ("V1 tried to pass V2, contacting its front bumper to the left side of V2.", Crash(CrashType.SIDE, "V1", "V2")),
    ],
)
def test_its_after_a_strike_is_the_object_s(sentence: str, crash: Crash) -> None:
    assert read_sentence(sentence) == crash


def test_one_that_was_traveling_behind_struck_the_rear() -> None:
    assert read_sentence("V2 was traveling behind V1 and struck V1.") == Crash(CrashType.REAR_END, "V2", "V1")
