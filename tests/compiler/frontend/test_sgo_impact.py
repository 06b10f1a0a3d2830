"""How fleet narratives say the impact (issue 18, sgo6), each on sentences written for these tests: a part
named in the plural, a contact its subject could not avoid, an opened door, the damage a vehicle took."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.crash import read_sentence
from sovarc.compiler.frontend.damage import damaged_part
from sovarc.compiler.frontend.doors import door_met
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


@pytest.mark.parametrize(
    ("sents", "crash"),
    [
        # the door's vehicle is the subject, the one passing is met by it: the one passing struck
        (
            ["V1 passed V2, which was parked at the curb.", "The rear door of V2 opened and struck the side of V1."],
            Crash(CrashType.SIDE, "V1", "V2"),
        ),
        (
            ["V1 was stopped when its passenger opened the door.", "V1's rear left door made contact with V2."],
            Crash(CrashType.SIDE, "V2", "V1"),
        ),
        (
            ["V2 was parked at the curb.", "The open driver door of V2 made contact with the right side of V1."],
            Crash(CrashType.SIDE, "V1", "V2"),
        ),
        # a door not tied to its vehicle is the door the narrative said was opened
        (
            [
                "V1 drove past V2 as the passengers inside V2 opened the front and rear right side doors.",
                "The rear right side door made contact with the front right side of V1.",
            ],
            Crash(CrashType.SIDE, "V1", "V2"),
        ),
    ],
)
def test_an_opened_door_is_met_by_the_one_passing(sents: list[str], crash: Crash) -> None:
    read = read_sentence(sents[-1], "V1")
    assert door_met(read if read is not None else Crash(), sents, len(sents) - 1) == crash


def test_a_door_no_one_opened_is_a_part_struck_as_any_other() -> None:
    sents = ["The front of V2 struck the left rear door of V1."]
    assert door_met(Crash(CrashType.SIDE, "V2", "V1"), sents, 0) == Crash(CrashType.SIDE, "V2", "V1")
    # and the door's vehicle moving into the other names its own door opened nowhere: nothing changes
    sents = ["V1 turned right and its front struck the door of V2."]
    assert door_met(Crash(CrashType.SIDE, "V1", "V2"), sents, 0) == Crash(CrashType.SIDE, "V1", "V2")


@pytest.mark.parametrize(
    "text",
    [
        "A Waymo Autonomous Vehicle was stopped at the curb on Elm Street for a passenger drop-off. As a pickup "
        "truck drove by on the left, the rider opened the rear left door. The Waymo AV's rear left door made "
        "contact with the right side of the pickup truck.",
        "A Waymo Autonomous Vehicle was traveling north on Oak Avenue when it approached a passenger car stopped in "
        "the center of the road. The Waymo AV began to pass the passenger car on the right, and the passengers "
        "inside the passenger car opened the right side doors. The rear right side door made contact with the "
        "front left side of the Waymo AV.",
    ],
)
def test_a_narrative_with_a_door_opened_into_a_passing_car(text: str) -> None:
    s = read(text)
    door = "V1" if "AV's rear left door" in text else "V2"
    passing = "V2" if door == "V1" else "V1"
    assert (s.crash.type, s.crash.striker, s.crash.victim) == (CrashType.SIDE, passing, door)


@pytest.mark.parametrize(
    ("said", "backing", "kind"),
    [
        ("V1 sustained minor damage to the driver's side rear door.", frozenset(), CrashType.SIDE),
        ("V1 suffered scratches on its rear bumper.", frozenset(), CrashType.REAR_END),
        ("The collision caused damage to the left rear of V1.", frozenset(), CrashType.REAR_END),
        ("There was damage to V1's right side.", frozenset(), CrashType.SIDE),
        ("V1's rear bumper was slightly damaged.", frozenset(), CrashType.REAR_END),
        ("It left, damaging the left side of V1.", frozenset(), CrashType.SIDE),
        # one backing leads with its rear: into the victim's front is the IR's rear_end
        ("V1 sustained damage to its front bumper.", frozenset(("V2",)), CrashType.REAR_END),
    ],
)
def test_the_victims_damage_says_where_it_was_met(said: str, backing: frozenset[str], kind: CrashType) -> None:
    sents = ["V2 moved into V1 in the parking lot.", said, "No one was hurt."]
    assert damaged_part(Crash(striker="V2", victim="V1"), sents, 0, backing) == (Crash(kind, "V2", "V1"), 1)


@pytest.mark.parametrize(
    ("crash", "said"),
    [
        # the striker's damage is not where the victim was met
        (Crash(striker="V2", victim="V1"), "V2 sustained damage to its front bumper."),
        # a part the impact sentence named stands
        (Crash(CrashType.REAR_END, "V2", "V1"), "V1 sustained damage to its left door."),
        # damage said too far from the impact is about something else
        (Crash(striker="V2", victim="V1"), "It was towed. The driver left. V1 had damage to its left door."),
    ],
)
def test_other_damage_leaves_the_crash_as_read(crash: Crash, said: str) -> None:
    sents = ["V2 moved into V1.", *said.split(". ")]
    assert damaged_part(crash, sents, 0, frozenset()) == (crash, 0)


def test_a_narrative_that_says_where_the_damage_was() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was parked in a lot on 2nd Street when a pickup truck reversed into the "
        "Waymo AV. The Waymo AV sustained minor damage to the right side rear door. There were no injuries."
    )
    assert (s.crash.type, s.crash.striker, s.crash.victim) == (CrashType.SIDE, "V2", "V1")
