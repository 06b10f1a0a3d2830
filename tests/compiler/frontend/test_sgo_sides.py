"""Fleet narratives, readings of the third SGO session, each on sentences written for these tests: lanes whose
side of the road their use fixes, one cyclist said as its bicycle."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.lanes import lane_change_side
from sovarc.compiler.frontend.names import label_parties
from sovarc.dsl.ir import Action, ActionKind, Scenario, Side, Unknown
from sovarc.dsl.span import Source


def read(text: str) -> Scenario:
    return FrontEnd("none").extract(Source("sgo.txt", text)).scenario


def actions(s: Scenario, pid: str) -> list[Action]:
    p = next(p for p in s.participants if p.id == pid)
    return [] if isinstance(p.actions, Unknown) else list(p.actions)


@pytest.mark.parametrize(
    ("text", "side"),
    [
        ("changed lanes into the center turn lane", "left"),
        ("began to change lanes into the centre shared turn lane ahead", "left"),
        ("merged into the two-way left turn lane", "left"),
        ("merged into the middle left-turn lane", "left"),
        ("merged out of the bike lane into the travel lane", "left"),
        ("merged from the bicycle lane into traffic", "left"),
        # the side said wins over the lane's use
        ("changed lanes to the right, out of the center turn lane", "right"),
    ],
)
def test_a_lane_whose_use_fixes_its_side_says_where_the_change_went(text: str, side: str) -> None:
    at = next(i for i, w in enumerate(text.split()) if w.startswith(("chang", "merg")))
    start = len(" ".join(text.split()[:at])) + (1 if at else 0)
    end = start + len(text.split()[at])
    assert lane_change_side(text, start, end, "") == side


def test_a_lane_change_said_by_no_side_and_no_lane_stays_unread() -> None:
    text = "began to change lanes behind the bus"
    assert lane_change_side(text, 9, 21, "") is None


def test_a_centre_line_is_no_turn_lane() -> None:
    # "into the center lane line" is the line between directions, not a lane entered
    text = "drifted into the center lane line"
    assert lane_change_side(text, 0, 7, "") is None


def test_a_follower_changing_into_the_centre_turn_lane_changes_left() -> None:
    s = read(
        "The Waymo AV was stopped in a queue of traffic in the left lane. A sedan approached the Waymo AV from "
        "behind and began to change lanes into the center turn lane, and the right side of the sedan made contact "
        "with the rear left corner of the Waymo AV."
    )
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE, Side.LEFT)


def test_a_cyclist_is_the_bicycle_it_rides() -> None:
    named, _ = label_parties(
        "The Waymo AV slowed for traffic when a cyclist left the bike lane, and the front of the bicycle made "
        "contact with the rear of the Waymo AV."
    )
    assert "V2 left the bike lane" in named and "the front of V2 made contact" in named
    assert "V3" not in named


def test_a_cyclist_merging_out_of_the_bike_lane_changes_lanes_left() -> None:
    s = read(
        "As the Waymo AV came to a stop behind traffic, a cyclist merged out of the bike lane into the travel "
        "lane, and the front of the bicycle made contact with the rear right corner of the Waymo AV."
    )
    assert [p.id for p in s.participants] == ["V1", "V2"]
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE, Side.LEFT)
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


@pytest.mark.parametrize(
    ("later", "named"),
    [
        # the brand alone, whatever lowercase word follows it, is the automated vehicle
        ("the pickup struck the rear of the Acme shortly after.", "the rear of V1 shortly after"),
        ("the Acme was struck in the rear by the pickup.", "V1 was struck"),
    ],
)
def test_a_brand_said_alone_is_the_automated_vehicle(later: str, named: str) -> None:
    text, _ = label_parties(f"The subject Acme vehicle was driving in autonomous mode when {later}")
    assert named in text


@pytest.mark.parametrize("noun", ["fleet", "operator", "Roadster"])
def test_a_brand_qualifying_a_noun_or_a_model_is_not_the_vehicle(noun: str) -> None:
    text, _ = label_parties(
        f"The subject Acme vehicle was driving in autonomous mode when a pickup struck it. The Acme {noun} was told."
    )
    assert f"The Acme {noun}" in text


@pytest.mark.parametrize(
    "slowing",
    ["slowed and came to a near stop", "had nearly stopped", "was almost stopped", "slowed to a near stop"],
)
def test_nearly_stopped_is_still_moving(slowing: str) -> None:
    s = read(
        f"The Waymo AV was stopped at a red light. The sedan behind the Waymo AV {slowing} when it made contact "
        "with the rear of the Waymo AV."
    )
    assert [a.kind for a in actions(s, "V2")] == [ActionKind.FOLLOW_LANE]


def test_came_to_a_stop_is_still_a_stop() -> None:
    s = read(
        "The Waymo AV was waiting at a red light. The sedan behind the Waymo AV came to a stop, then rolled "
        "forward and made contact with the rear of the Waymo AV."
    )
    assert ActionKind.STOP in [a.kind for a in actions(s, "V2")]


@pytest.mark.parametrize("head", ["with his head turned left", "while her head was turned left"])
def test_a_head_turned_to_look_is_no_turn(head: str) -> None:
    s = read(
        f"The Waymo AV was stopped at a light. A cyclist was riding behind the Waymo AV {head}, and the cyclist "
        "collided with the rear of the Waymo AV."
    )
    assert ActionKind.TURN_LEFT not in [a.kind for a in actions(s, "V2")]


def test_a_vehicle_turned_left_still_turns() -> None:
    s = read(
        "The Waymo AV was stopped at a light. A cyclist ahead of the Waymo AV turned left, and the front of the "
        "Waymo AV made contact with the cyclist."
    )
    assert ActionKind.TURN_LEFT in [a.kind for a in actions(s, "V2")]


CHAIN = (
    "The Waymo AV was stopped in a queue of traffic in the left lane. The sedan behind the Waymo AV began to change "
    "lanes to the left as a pickup truck was traveling in that lane, and the left side of the sedan made contact "
    "with the right side of the pickup truck. After that, the sedan swerved into the stationary Waymo AV, and the "
    "front of the sedan made contact with the rear of the Waymo AV."
)


def test_a_chain_collision_is_read_at_the_automated_vehicles_own_impact() -> None:
    s = read(CHAIN)
    assert (s.crash.striker, s.crash.victim, s.crash.type.value) == ("V2", "V1", "rear_end")


def test_a_report_numbering_its_own_vehicles_keeps_its_first_impact() -> None:
    # the same chain in police numbering: the first impact is the crash, as NMVCCS codes it
    s = read(
        "V1 was stopped in a queue of traffic in the left lane. V2 behind V1 began to change lanes to the left as "
        "V3 was traveling in that lane, and the left side of V2 made contact with the right side of V3. After "
        "that, V2 swerved into V1, and the front of V2 made contact with the rear of V1."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V3")


def test_a_pronoun_in_the_first_impact_may_be_the_automated_vehicle() -> None:
    s = read(
        "The Waymo AV was in reverse at 2 mph when it made contact with the door of a parked sedan. Later the "
        "sedan's owner struck the Waymo AV with a cart."
    )
    assert s.crash.striker == "V1"


@pytest.mark.parametrize(
    ("where", "crash"),
    [
        # it stood behind the one that then backed into it: rear first into its front
        ("came to a stop behind a stopped box truck", "rear_end"),
        # nothing says where it stood: the part met stays unknown
        ("came to a stop near a stopped box truck", "unknown"),
    ],
)
def test_one_backing_into_the_vehicle_behind_it_meets_its_front(where: str, crash: str) -> None:
    s = read(
        f"The Waymo AV was traveling north in the left lane and {where}. As the Waymo AV waited, the truck began "
        "to reverse and then made contact with the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim, s.crash.type.value) == ("V2", "V1", crash)


@pytest.mark.parametrize(
    "into",
    ["entered the oncoming lanes of Elm Street", "crossed into the opposing lane", "moved into the oncoming lane"],
)
def test_going_around_by_the_other_directions_lanes_is_one_move_there(into: str) -> None:
    s = read(
        f"The Waymo AV was stopped in traffic. A sedan behind the Waymo AV {into} to maneuver around the Waymo AV, "
        "and the right side of the sedan made contact with the rear left corner of the Waymo AV."
    )
    assert [a.kind for a in actions(s, "V2")][-1] is ActionKind.RETROGRADE


def test_going_around_said_alone_is_still_a_lane_change() -> None:
    s = read(
        "The Waymo AV was stopped in traffic. A sedan behind the Waymo AV maneuvered around the left side of the "
        "Waymo AV, and the right side of the sedan made contact with the rear left corner of the Waymo AV."
    )
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE, Side.LEFT)
