"""Who did what when one party backs, and impacts said as a move into the other: each reading on narratives
written for these tests (fleet style: the automated vehicle and the road user it met, named in words)."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.crash import read_sentence
from sovarc.compiler.frontend.text import describes_impact
from sovarc.dsl.ir import ActionKind, CrashType, Scenario, Unknown
from sovarc.dsl.span import Source

OPENING = (
    "On March [XXX], 2025 at 4:05 PM PT a Waymo Autonomous Vehicle (Waymo AV) was in a collision involving a sedan. "
)


def read(text: str) -> Scenario:
    return FrontEnd("none").extract(Source("sgo.txt", text)).scenario


def kinds(s: Scenario, pid: str) -> list[ActionKind]:
    p = next(p for p in s.participants if p.id == pid)
    return [] if isinstance(p.actions, Unknown) else [a.kind for a in p.actions]


@pytest.mark.parametrize(
    ("impact", "crash"),
    [
        # its rear into the other's front: rear_end with the backing one the striker (the IR's convention)
        ("the sedan reversed and made contact with the front of the Waymo AV", CrashType.REAR_END),
        (
            "the sedan began to back up, and the rear of the sedan made contact with the front of the Waymo AV",
            CrashType.REAR_END,
        ),
        (
            "the sedan began backing up and its rear bumper made contact with the front bumper of the Waymo AV",
            CrashType.REAR_END,
        ),
        # its rear into the other's rear: back to back
        ("the sedan reversed slowly into the rear bumper of the Waymo AV", CrashType.FRONTAL),
        # its rear into a side
        ("the sedan backed into the driver side door of the Waymo AV", CrashType.SIDE),
    ],
)
def test_a_backing_party_leads_with_its_rear(impact: str, crash: CrashType) -> None:
    s = read(OPENING + f"The Waymo AV was stopped at a red light on [XXX] when {impact}.")
    assert kinds(s, "V2")[-1] is ActionKind.REVERSE
    assert (s.crash.striker, s.crash.victim, s.crash.type) == ("V2", "V1", crash)


def test_a_party_driving_forward_into_the_objects_front_is_struck() -> None:
    """The contrast: with nobody backing, the only part named being the object's front says the object's
    front met the subject (which came across its path)."""
    s = read(
        OPENING + "The Waymo AV was traveling north on [XXX] when the sedan pulled across its lane and made contact "
        "with the front of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V1", "V2")


def test_in_front_of_is_a_place_not_a_part() -> None:
    crash = read_sentence(
        "V2 in front of V1 began to roll backwards, and the rear of V2 made contact with the front of V1.",
        backing=frozenset({"V2"}),
    )
    assert crash is not None and (crash.striker, crash.type) == ("V2", CrashType.REAR_END)
    crash = read_sentence("V2 directly in front of V1 reversed and made contact with the front of V1.")
    assert crash is not None and crash.striker == "V2"  # "front of V1" after "in" names no owner of the strike


@pytest.mark.parametrize(
    "sentence",
    [
        "V2 reversed at a low speed from an adjacent driveway into the right rear bumper of V1.",
        "V2 backed into V1.",
        "V2 riding on the wrong side of the street rode into the front bumper of V1.",
        "V2 approaching in the adjacent lane collided into the passenger side doors of V1.",
        "V1 braked hard but was unable to avoid contact with V2.",
    ],
)
def test_a_move_into_the_other_is_an_impact(sentence: str) -> None:
    assert describes_impact(sentence)


@pytest.mark.parametrize(
    "sentence",
    [
        "V2 drove into the intersection behind V1.",
        "V2 drifted into V1's lane.",
        "V2 began reversing into the path of V1.",
        "V1 braked to avoid contact with V2.",
    ],
)
def test_a_move_into_a_place_is_no_impact(sentence: str) -> None:
    assert not describes_impact(sentence)


def test_an_unavoidable_contact_ends_what_each_did_before() -> None:
    s = read(
        OPENING + "The Waymo AV was traveling west on [XXX] and entered the intersection to proceed straight. The "
        "sedan traveling east made a sharp left turn in front of the Waymo AV. The Waymo AV detected the sedan and "
        "braked, but was unable to avoid contact with the sedan."
    )
    assert kinds(s, "V2")[-1] is ActionKind.TURN_LEFT


def test_a_participant_after_a_preposition_is_an_object() -> None:
    """ "parked perpendicular to V1 moved backward": what follows is the parked vehicle's doing, not V1's."""
    s = read(
        OPENING + "The Waymo AV stopped in a parking lot to let a passenger out. The sedan, parked perpendicular "
        "to the Waymo AV, moved backward and its rear bumper made contact with the passenger side of the "
        "Waymo AV."
    )
    assert kinds(s, "V1") == [ActionKind.STOP]
    assert kinds(s, "V2")[-1] is ActionKind.REVERSE
    assert (s.crash.striker, s.crash.type) == ("V2", CrashType.SIDE)
