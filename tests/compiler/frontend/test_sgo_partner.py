"""The crash partner's move in fleet narratives, each reading on sentences written for these tests: a lane
change said without its side, the move under way at the impact, a move into another's lane."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.names import label_parties
from sovarc.dsl.ir import Action, ActionKind, Scenario, Side, Unknown
from sovarc.dsl.span import Source

OPENING = (
    "On March [XXX], 2025 at 4:05 PM PT a Waymo Autonomous Vehicle (Waymo AV) was in a collision involving a sedan. "
)


def read(text: str) -> Scenario:
    return FrontEnd("none").extract(Source("sgo.txt", OPENING + text)).scenario


def actions(s: Scenario, pid: str) -> list[Action]:
    p = next(p for p in s.participants if p.id == pid)
    return [] if isinstance(p.actions, Unknown) else list(p.actions)


@pytest.mark.parametrize(
    ("text", "side"),
    [
        # the other's side met is the side the striker came from: it moved the other way
        (
            "The Waymo AV was traveling north on [XXX] when a sedan switched lanes and made contact with the driver "
            "side of the Waymo AV.",
            Side.RIGHT,
        ),
        (
            "The Waymo AV was traveling north on [XXX] when a sedan began to change lanes and made contact with the "
            "passenger side of the Waymo AV.",
            Side.LEFT,
        ),
        # its own side met is the way it moved
        (
            "The Waymo AV was traveling north on [XXX]. A sedan traveling beside the Waymo AV moved into the Waymo "
            "AV's lane, and the passenger side of the sedan made contact with the Waymo AV.",
            Side.RIGHT,
        ),
        (
            "The Waymo AV was traveling north on [XXX] when a sedan was changing lanes. The front driver side corner "
            "of the sedan made contact with the rear of the Waymo AV.",
            Side.LEFT,
        ),
    ],
)
def test_a_lane_change_without_its_side_goes_toward_the_side_it_met(text: str, side: Side) -> None:
    s = read(text)
    assert s.crash.striker == "V2"
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE, side)


def test_a_lane_change_with_its_side_keeps_it() -> None:
    """The words win over the sides met: "to the left" with the other's left side met is still left."""
    s = read(
        "The Waymo AV was traveling north on [XXX] when a sedan changed lanes to the left and made contact with "
        "the driver side of the Waymo AV."
    )
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE, Side.LEFT)


def test_the_victims_side_says_nothing_of_its_own_lane_change() -> None:
    """Struck on its right side, the automated vehicle was met from its right: whether it moved left or right is
    not said, so its lane change is read without a side."""
    s = read(
        "The Waymo AV began to change lanes on [XXX] when the front of a sedan made contact with the passenger side "
        "of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")
    assert actions(s, "V1")[-1] == Action(ActionKind.CHANGE_LANE)


def test_no_side_met_no_side_read() -> None:
    s = read("The Waymo AV was traveling north when it was rear-ended by a sedan that was switching lanes.")
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE)


@pytest.mark.parametrize(
    "move",
    [
        "A sedan turned left onto [XXX] and approached the Waymo AV from behind.",
        "A sedan made a right turn onto [XXX] and then approached the stopped Waymo AV quickly from behind.",
        "A sedan that was in the right lane changed lanes to the left and approached the Waymo AV closely from behind.",
    ],
)
def test_closing_from_behind_after_a_manoeuvre_is_driving_on(move: str) -> None:
    """Closing on another from behind puts it in that one's lane, behind it: its turn or lane change was over, and
    at the impact it drove along its lane."""
    s = read(
        f"The Waymo AV was stopped at a red light. {move} The front of the sedan made contact with the rear of "
        "the Waymo AV."
    )
    kinds = [a.kind for a in actions(s, "V2")]
    assert kinds[-1] is ActionKind.FOLLOW_LANE
    assert {ActionKind.TURN_LEFT, ActionKind.TURN_RIGHT, ActionKind.CHANGE_LANE} & set(kinds)


@pytest.mark.parametrize(
    "move",
    [
        "A sedan made a left turn onto [XXX] in front of the stopped Waymo AV. As the sedan passed the Waymo AV, the "
        "driver side of the sedan made contact with the driver side of the Waymo AV.",
        "A sedan behind the Waymo AV changed lanes to the left. As the sedan was passing the Waymo AV, the passenger "
        "side of the sedan made contact with the rear driver side of the Waymo AV.",
    ],
)
def test_a_pass_after_a_manoeuvre_is_the_manoeuvre(move: str) -> None:
    """A pass is often the lane change or the turn itself (NHTSA codes it so): it adds no move of its own."""
    s = read(f"The Waymo AV was stopped at a red light. {move}")
    assert actions(s, "V2")[-1].kind in (ActionKind.TURN_LEFT, ActionKind.CHANGE_LANE)


@pytest.mark.parametrize(
    "words",
    ["an approaching sedan", "an oncoming sedan", "the trailing sedan", "a passing sedan", "a speeding sedan"],
)
def test_introduced_in_motion_it_drove_along_its_lane(words: str) -> None:
    """A road user the report says nothing of before the impact but the words that introduce it: those words
    say what it was doing, as "a parked sedan" does."""
    s = read(f"The Waymo AV was stopped on [XXX] when {words} made contact with the driver side of the Waymo AV.")
    assert [a.kind for a in actions(s, "V2")] == [ActionKind.FOLLOW_LANE]


def test_introduced_with_no_motion_stays_unknown() -> None:
    s = read("The Waymo AV was turning left when a white sedan made contact with the front bumper of the Waymo AV.")
    assert actions(s, "V2") == []


def test_another_of_a_kind_is_not_the_one_named_before() -> None:
    """'another SUV' is a second SUV: the double-parked one named before it is a bystander, and its state is not
    the partner's."""
    s = read(
        "The Waymo AV was traveling east on [XXX] and came to a stop behind an SUV that was double parked. Once the "
        "traffic cleared, another SUV traveling directly behind the Waymo AV began passing the Waymo AV and the "
        "passenger door of the SUV made contact with the rear driver side of the Waymo AV."
    )
    assert [p.id for p in s.participants] == ["V1", "V2"]
    assert ActionKind.PARKED not in [a.kind for a in actions(s, "V2")]
    assert s.crash.striker == "V2"


def test_another_renames_only_what_follows_it() -> None:
    named, _ = label_parties(
        "The Waymo AV was stopped behind a sedan at a red light. Then another sedan made contact with the rear of "
        "the Waymo AV. The sedan left the scene."
    )
    assert "behind a sedan" in named
    assert "Then V2 made contact" in named and "V2 left the scene" in named
