"""How fleet narratives say the impact (issue 18, sgo6), each on sentences written for these tests: a part
named in the plural, a contact its subject could not avoid."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.crash import read_sentence
from sovarc.dsl.ir import Crash, CrashType, Scenario
from sovarc.dsl.span import Source


def read(text: str) -> Scenario:
    return FrontEnd("none").extract(Source("sgo.txt", text)).scenario


@pytest.mark.parametrize(
    ("sentence", "crash"),
    [
        ("The front of V2 struck the rear doors of V1.", Crash(CrashType.SIDE, "V2", "V1")),
        ("V1's front bumper hit the left fenders of V2.", Crash(CrashType.SIDE, "V1", "V2")),
        ("The front of V2 made contact with the side mirrors of V1.", Crash(CrashType.SIDE, "V2", "V1")),
        ("V2's front contacted V1's rear corners.", Crash(CrashType.REAR_END, "V2", "V1")),
    ],
)
def test_a_part_named_in_the_plural_is_that_part(sentence: str, crash: Crash) -> None:
    assert read_sentence(sentence) == crash


@pytest.mark.parametrize(
    "sentence",
    [
        "V1 braked hard but was unable to avoid contact with V2.",
        "V1 slowed, but could not avoid striking V2 as it turned.",
        "V1 failed to avoid a collision with V2.",
        "V1 braked and swerved, yet did not avoid hitting V2.",
    ],
)
def test_a_contact_its_subject_could_not_avoid_is_one_it_made(sentence: str) -> None:
    crash = read_sentence(sentence)
    assert crash is not None and (crash.striker, crash.victim) == ("V1", "V2")


def test_a_contact_avoided_is_none() -> None:
    assert read_sentence("V1 braked to avoid contact with V2.") is None


def test_a_narrative_whose_impact_could_not_be_avoided_names_its_striker() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was traveling north on Pine Street. A cyclist riding on the sidewalk entered "
        "the roadway ahead of the Waymo AV. The Waymo AV braked firmly but was unable to avoid contact with the "
        "cyclist."
    )
    assert (s.crash.striker, s.crash.victim) == ("V1", "V2")
