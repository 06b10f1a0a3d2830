"""What a scenario asks of a site (no SUMO needed)."""

from __future__ import annotations

from sovarc.compiler.maps import Need, scenario_needs
from sovarc.compiler.maps.needs import participant_need
from sovarc.dsl import parse
from sovarc.dsl.ir import ActionKind, Heading

from tests.compiler.maps.conftest import SCENARIOS, scenario


def vehicle(body: str, heading: str = "north", lane: str = "2", role: str = "vehicle") -> Need:
    text = f"""scenario s {{
  road {{
    kind intersection
  }}
  {role} V1 {{
    heading {heading}
    lane {lane}
    actions {{
      {body}
    }}
  }}
}}
"""
    return participant_need(parse(text).participants[0])


def test_the_dual_left_turn_needs_four_lanes_and_a_left_turn() -> None:
    v1, v2 = scenario_needs(scenario("intersection_dual_left_turn_side"))
    assert (v1.heading, v1.lane, v1.lanes, v1.move, v1.to_lanes) == (Heading.WEST, 4, 4, ActionKind.TURN_LEFT, 1)
    assert (v2.lane, v2.lanes) == (3, 3)
    assert v1.describe() == "V1 heading west: 4 lanes, turn_left into lane 1"


def test_lane_changes_count_towards_the_lanes_needed() -> None:
    assert vehicle("change_lane(to: 3)").lanes == 3
    assert vehicle("change_lane(to: left)").lanes == 3
    assert vehicle("change_lane(to: left)", lane="unknown").lanes == 2
    assert vehicle("change_lane(to: right)", lane="unknown").lanes == 2
    assert vehicle("change_lane(to: right)", lane="1").lanes == 2


def test_only_the_first_junction_manoeuvre_counts_and_what_follows_is_on_the_road_it_enters() -> None:
    need = vehicle("turn_left(to: 2)\n      retrograde\n      go_across")
    assert need.move is ActionKind.TURN_LEFT and need.to_lanes == 2
    assert need.against_after and not need.against_start
    before = vehicle("follow_lane\n      retrograde\n      go_across")
    assert before.against_start and before.move is ActionKind.GO_ACROSS


def test_unknown_facts_ask_for_nothing() -> None:
    need = vehicle("follow_lane", heading="unknown", lane="unknown")
    assert (need.heading, need.lane, need.lanes, need.placed) == (None, None, 0, False)
    assert need.describe() == "V1 heading unknown: any lane"


def test_pedestrians_are_placed_only_when_walking_in_a_lane() -> None:
    assert vehicle("walk", lane="1", role="pedestrian").placed
    assert not vehicle("cross", lane="unknown", role="pedestrian").placed


def test_every_example_has_needs_for_every_participant() -> None:
    for path in SCENARIOS:
        parsed = parse(path.read_text(encoding="utf-8"))
        needs = scenario_needs(parsed)
        assert [n.participant for n in needs] == [p.id for p in parsed.participants], path.name
