"""The side of a lane change the report does not give is chosen by lowering's assume pass, with a note: into the
partner's lane for a lane changer in a side-swipe or rear-end with a partner going its way, else toward a lane
that surely exists; the choice stages on the example town."""

from __future__ import annotations

from sovarc.compiler.lower import lower
from sovarc.compiler.lower.assume import assume
from sovarc.compiler.maps import load_map
from sovarc.dsl import parse
from sovarc.dsl.ir import ActionKind, Participant, Scenario, Side

from tests.conftest import EXAMPLES

TOWN = EXAMPLES / "maps" / "town.net.xml"


def sov(v1: str, v2: str, crash: str = "side", heading2: str = "north") -> str:
    return f"""scenario sideless {{
  road {{
    kind straight
  }}
  vehicle V1 {{
    heading north
    lane {v1}
    actions {{
      follow_lane
    }}
  }}
  vehicle V2 {{
    heading {heading2}
    lane {v2}
    actions {{
      follow_lane
      change_lane
    }}
  }}
  crash {{
    type {crash}
    striker V2
    victim V1
  }}
}}
"""


def _who(s: Scenario, pid: str) -> Participant:
    p = s.participant(pid)
    assert p is not None
    return p


def _side(s: Scenario) -> object:
    return next(a.to for a in _who(s, "V2").known_actions if a.kind is ActionKind.CHANGE_LANE)


def test_into_the_partners_known_lane() -> None:
    filled, notes = assume(parse(sov("2", "1")))
    assert _side(filled) is Side.LEFT
    assert (
        "V2 change_lane side unknown: planned to the left (into V1's lane: it strikes V1, both going north, "
        in (notes[-1])
    )
    filled, _ = assume(parse(sov("1", "2", crash="rear_end")))
    assert _side(filled) is Side.RIGHT


def test_neither_lane_known_places_the_pair_in_neighbour_lanes() -> None:
    filled, notes = assume(parse(sov("unknown", "unknown")))
    assert _side(filled) is Side.LEFT
    assert _who(filled, "V2").lane == 1 and _who(filled, "V1").lane == 2
    assert "V1 lane unknown: planned in lane 2 (the lane V2 changes into)" in notes
    assert any("neither lane is known" in n for n in notes)


def test_one_lane_known_places_the_other_beside_it() -> None:
    filled, _ = assume(parse(sov("1", "unknown")))  # the partner in lane 1: from lane 2 to the right
    assert _side(filled) is Side.RIGHT and _who(filled, "V2").lane == 2
    filled, _ = assume(parse(sov("unknown", "3")))  # the changer in lane 3: down into lane 2
    assert _side(filled) is Side.RIGHT and _who(filled, "V1").lane == 2


def test_with_no_partner_going_its_way_toward_a_lane_that_exists() -> None:
    filled, notes = assume(parse(sov("1", "unknown", crash="frontal", heading2="south")))
    assert _side(filled) is Side.LEFT and _who(filled, "V2").lane == 1
    assert any("V2 change_lane side unknown: planned to the left (from lane 1, the right-most" in n for n in notes)
    filled, notes = assume(parse(sov("1", "3", crash="frontal", heading2="south")))
    assert _side(filled) is Side.RIGHT
    assert any("from lane 3 the lane below it is one of its direction" in n for n in notes)


def test_a_known_side_is_kept() -> None:
    text = sov("unknown", "unknown").replace("      change_lane\n", "      change_lane(to: right)\n")
    filled, notes = assume(parse(text))
    assert _side(filled) is Side.RIGHT and not any("change_lane side" in n for n in notes)


def test_a_side_less_lane_change_stages_on_the_town_into_its_partners_lane() -> None:
    lowered = lower(parse(sov("unknown", "unknown")), load_map(TOWN))[0]
    assert any("V2 change_lane side unknown: planned to the left" in n for n in lowered.notes)
    v1, v2 = lowered.routes["V1"], lowered.routes["V2"]
    assert set(v1.lanes) <= set(v2.lanes) and len(v2.lanes) > len(v1.lanes)  # it moved over into V1's lane


def test_a_sided_lane_change_places_a_pair_of_unknown_lanes_beside_each_other() -> None:
    """With its side known, the changer starts on that side's far side of its partner's lane."""
    for side, mine, theirs in (("left", 1, 2), ("right", 2, 1)):
        text = sov("unknown", "unknown").replace("      change_lane\n", f"      change_lane(to: {side})\n")
        filled, notes = assume(parse(text))
        assert (_who(filled, "V2").lane, _who(filled, "V1").lane) == (mine, theirs)
        assert f"V2 lane unknown: planned in lane {mine} (changing {side} into V1's lane)" in notes
    filled, _ = assume(parse(sov("unknown", "3").replace("      change_lane\n", "      change_lane(to: right)\n")))
    assert _who(filled, "V1").lane == 2
    filled, _ = assume(parse(sov("1", "unknown").replace("      change_lane\n", "      change_lane(to: left)\n")))
    assert _who(filled, "V1").lane == 1 and _who(filled, "V2").lane == 1  # none right of lane 1


def test_a_sided_lane_change_with_unknown_lanes_stages_on_the_town() -> None:
    text = sov("unknown", "unknown").replace("      change_lane\n", "      change_lane(to: right)\n")
    lowered = lower(parse(text), load_map(TOWN))[0]
    v1, v2 = lowered.routes["V1"], lowered.routes["V2"]
    assert set(v1.lanes) <= set(v2.lanes) and len(v2.lanes) > len(v1.lanes)
