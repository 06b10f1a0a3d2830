"""Filling unknown facts: each unknown gets a choice and a note; known facts are kept but for the one
contradiction no site can stage (two cars straight across a T from crossing directions)."""

from __future__ import annotations

from sovarc.compiler.lower.assume import assume
from sovarc.dsl import parse
from sovarc.dsl.ir import ActionKind, CrashType, Heading, Unknown

from tests.compiler.lower.staging import NAMES, scenario

UNKNOWNS = """scenario unknowns {
  road {
    kind intersection
    lanes 4
    speed_limit unknown
  }
  vehicle V1 {
    heading north
    lane 2
    speed 30 km/h
    actions {
      turn_left
    }
  }
  vehicle V2 {
    heading unknown
    lane unknown
    speed unknown
    actions unknown
  }
  crash {
    type unknown
    striker unknown
    victim V1
  }
}
"""


def test_every_unknown_is_filled_with_a_note() -> None:
    original = parse(UNKNOWNS)
    filled, notes = assume(original)
    v1, v2 = filled.participant("V1"), filled.participant("V2")
    assert v1 is not None and v2 is not None
    assert filled.crash.striker == "V2"
    assert filled.crash.type is CrashType.SIDE  # V2's heading was unknown: a side impact is the default
    assert [a.kind for a in v2.known_actions] == [ActionKind.FOLLOW_LANE]
    assert v2.heading is Heading.EAST  # crossing V1's path at an intersection
    assert v2.lane == 1
    assert notes == [
        "striker unknown: planned as V2",
        "crash type unknown: planned as side, from the headings",
        "V2 actions unknown: planned as follow_lane",
        "V2 heading unknown: planned east (crossing V1's path)",
        "V2 lane unknown: planned in lane 1",
    ]
    # what the report said stays as it said it; what lowering does not need stays unknown
    assert v1 == original.participant("V1")
    assert filled.crash.victim == "V1"
    assert isinstance(v2.speed, Unknown) and isinstance(filled.road.speed_limit, Unknown)
    assert filled.road == original.road and filled.environment == original.environment


def test_a_rear_end_partner_gets_the_same_heading_and_lane() -> None:
    text = UNKNOWNS.replace("type unknown", "type rear_end").replace("striker unknown", "striker V2")
    filled, notes = assume(parse(text))
    v2 = filled.participant("V2")
    assert v2 is not None and (v2.heading, v2.lane) == (Heading.NORTH, 2)
    assert "V2 heading unknown: planned north (same as V1, for a rear_end crash)" in notes


def test_a_head_on_partner_comes_the_other_way_unless_one_turns_back() -> None:
    text = UNKNOWNS.replace("type unknown", "type frontal").replace("striker unknown", "striker V2")
    head_on = assume(parse(text))[0].participant("V2")
    assert head_on is not None and head_on.heading is Heading.SOUTH
    wrong_way = assume(parse(text.replace("turn_left", "retrograde")))[0].participant("V2")
    assert wrong_way is not None and wrong_way.heading is Heading.SOUTH  # V1 keeps its heading in V2's lane
    turned = assume(parse(text.replace("turn_left", "u_turn")))[0].participant("V2")
    assert turned is not None and turned.heading is Heading.NORTH  # V1 comes back towards V2


def test_the_crash_type_follows_from_known_headings() -> None:
    text = UNKNOWNS.replace("heading unknown", "heading south").replace("striker unknown", "striker V2")
    filled, notes = assume(parse(text))
    assert filled.crash.type is CrashType.FRONTAL
    assert "crash type unknown: planned as frontal, from the headings" in notes


def test_a_fully_known_scenario_is_left_as_it_is() -> None:
    checked = 0
    for name in NAMES:
        original = scenario(name)
        if any(isinstance(p.heading, Unknown) or isinstance(p.lane, Unknown) for p in original.participants):
            continue
        if isinstance(original.crash.type, Unknown) or any(
            isinstance(p.actions, Unknown) or not p.actions for p in original.participants
        ):
            continue
        filled, notes = assume(original)
        assert filled == original, name
        assert notes == [], name
        checked += 1
    assert checked >= 10


def test_a_pedestrian_without_actions_crosses_and_keeps_its_unknown_heading() -> None:
    text = UNKNOWNS.replace("vehicle V2", "pedestrian V2").replace("    lane unknown\n", "", 1)
    filled, notes = assume(parse(text))
    v2 = filled.participant("V2")
    assert v2 is not None
    assert [a.kind for a in v2.known_actions] == [ActionKind.CROSS]
    assert isinstance(v2.heading, Unknown)  # a pedestrian is laid against its vehicle, not on a heading
    assert "V2 actions unknown: planned as cross" in notes


def test_two_cars_turning_the_same_way_into_a_side_crash_turn_side_by_side() -> None:
    text = (
        UNKNOWNS.replace("type unknown", "type side")
        .replace("striker unknown", "striker V2")
        .replace("heading unknown", "heading north")
        .replace("lane 2", "lane 1")
        .replace("actions unknown", "actions {\n      turn_left\n    }")
    )
    filled, notes = assume(parse(text))
    v2 = filled.participant("V2")
    assert v2 is not None and v2.lane == 2  # beside V1, not behind it in its lane
    assert (
        "V2 lane unknown: planned in lane 2 (beside V1, turning the same way: side by side in two turn lanes)" in notes
    )
    right = assume(parse(text.replace("turn_left", "turn_right")))[0].participant("V2")
    assert right is not None and right.lane == 2


def test_a_wrong_way_striker_side_swipes_an_oncoming_car() -> None:
    text = (
        UNKNOWNS.replace("kind intersection", "kind straight")
        .replace("type unknown", "type side")
        .replace("striker unknown", "striker V1")
        .replace("victim V1", "victim V2")
        .replace("turn_left", "retrograde")
        .replace("actions unknown", "actions {\n      stop\n    }")
    )
    filled, notes = assume(parse(text))
    v2 = filled.participant("V2")
    assert v2 is not None and v2.heading is Heading.SOUTH
    assert "V2 heading unknown: planned south (opposite to V1, whose wrong-way drive swerves into its lane)" in notes
    keeps = assume(parse(text.replace("retrograde", "follow_lane")))[0].participant("V2")
    assert keeps is not None and keeps.heading is Heading.NORTH  # no wrong-way drive: same way, as before


ACROSS_A_T = """scenario across_a_t {
  road { kind t_junction lanes 1 speed_limit 72 km/h }
  vehicle V1 { heading south lane 1 actions { follow_lane go_across } }
  vehicle V2 { heading east lane 1 actions { follow_lane go_across } }
  crash { type side striker V1 victim V2 }
}
"""


def test_two_cars_straight_across_a_t_make_the_victim_turn_out_of_the_stem() -> None:
    original = parse(ACROSS_A_T)
    filled, notes = assume(original)
    v2 = filled.participant("V2")
    assert v2 is not None and [a.kind for a in v2.known_actions] == [ActionKind.FOLLOW_LANE, ActionKind.TURN_LEFT]
    assert v2.known_actions[1].meta == original.participant("V2").known_actions[1].meta  # its source span stays
    assert filled.participant("V1") == original.participant("V1")
    assert any(n.startswith("V2 go_across: planned as turn_left") for n in notes)


def test_straight_across_stays_where_the_road_or_headings_allow_it() -> None:
    for text in (
        ACROSS_A_T.replace("kind t_junction", "kind intersection"),  # a 4-way junction has both roads through
        ACROSS_A_T.replace("heading east", "heading north"),  # opposite directions: both on the through road
    ):
        original = parse(text)
        filled, notes = assume(original)
        assert filled.participants == original.participants and not notes
