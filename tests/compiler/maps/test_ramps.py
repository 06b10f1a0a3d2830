"""One-way roads that only merge and diverge make no junction a person would call a T or a cross.
Nor does a two-way road parting into its two directions.

A motorway's ramps leave and join a one-way carriageway; two carriageways may meet in a loop.
Read by its arms' headings alone, such a node is a 'T' (three one-way arms) or a 'cross' (a ramp
out and a ramp in at one node). A junction of one-way arms is one only where two streams of its
traffic cross (two one-way streets crossing); a two-way road at it keeps it a junction.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.compiler.maps import find_sites, match_sites
from sovarc.compiler.maps.roads import LaneInfo
from sovarc.compiler.maps.site import Arm, Connection
from sovarc.compiler.maps.sites import streams_cross
from sovarc.compiler.maps.survey import missing
from sovarc.dsl.errors import LoweringError
from sovarc.dsl.ir import RoadKind

from tests.compiler.maps.conftest import scenario
from tests.compiler.maps.test_roads import build, kinds

pytestmark = pytest.mark.slow  # needs SUMO

X, T, S = RoadKind.INTERSECTION, RoadKind.T_JUNCTION, RoadKind.STRAIGHT
# an eastbound carriageway of three lanes through node m; a ramp leaves or joins it there at 55 degrees
CARRIAGEWAY = {"w": (-300, 0), "m": (0, 0), "e": (300, 0)}
RAMP_OFF = (140, -200)  # south-east of m: the ramp runs away from it heading 145 degrees
RAMP_ON = (-140, -200)  # south-west of m: the ramp arrives at it heading 35 degrees


def test_a_diverge_of_a_motorway_is_no_t(tmp_path: Path) -> None:
    nodes = CARRIAGEWAY | {"off": RAMP_OFF}
    road_map = build(tmp_path, nodes, ["in w m 3 oneway", "on m e 2 oneway", "ramp m off 1 oneway"])
    assert T not in kinds(road_map) and X not in kinds(road_map)
    # a miss says what the map has instead, in the survey and in the site search
    ramp = "1 place where one-way roads only merge or diverge (ramps) are no junction of crossing traffic"
    assert ramp in str(missing(road_map, T))
    with pytest.raises(LoweringError, match=r"1 place where one-way roads only merge or diverge"):
        match_sites(scenario("t_junction_left_turn_out_side"), road_map)
    assert missing(road_map, S) is None


def test_a_merge_onto_a_motorway_is_no_t(tmp_path: Path) -> None:
    nodes = CARRIAGEWAY | {"on": RAMP_ON}
    road_map = build(tmp_path, nodes, ["in w m 2 oneway", "on m e 3 oneway", "ramp on m 1 oneway"])
    assert T not in kinds(road_map) and X not in kinds(road_map)


def test_a_ramp_in_and_a_ramp_out_at_one_node_are_no_cross(tmp_path: Path) -> None:
    # a ramp joins from the right and another leaves to the left at one node (as CARLA's Town06
    # has them); ramp traffic may not drive on across the carriageway, so no streams cross
    nodes = CARRIAGEWAY | {"on": RAMP_ON, "off": (140, 200)}
    edges = ["in w m 3 oneway", "on m e 3 oneway", "rin on m 1 oneway", "rout m off 1 oneway"]
    road_map = build(tmp_path, nodes, edges, forbid=("rin rout",))
    assert X not in kinds(road_map) and T not in kinds(road_map)
    # where ramp traffic may drive straight across the carriageway, the streams cross: a cross
    (tmp_path / "across").mkdir()
    assert kinds(build(tmp_path / "across", nodes, edges))[X] == 1


def test_a_two_way_side_road_on_a_one_way_carriageway_is_one_t(tmp_path: Path) -> None:
    # a divided road's carriageways 60 m apart: the side road meets the eastbound one alone
    nodes = CARRIAGEWAY | {"s": (0, -200), "e2": (300, 60), "w2": (-300, 60)}
    edges = ["in w m 2 oneway", "on m e 2 oneway", "back e2 w2 2 oneway", "side m s 1"]
    road_map = build(tmp_path, nodes, edges)
    (tee,) = find_sites(road_map, T)
    assert tee.junction == "m" and sum(arm.two_way for arm in tee.arms) == 1
    south = next(arm for arm in tee.arms if arm.two_way)
    assert {c.direction for c in tee.connections_from(south)} == {"r"}  # the carriageway is one-way east


def test_two_one_way_streets_crossing_are_one_cross(tmp_path: Path) -> None:
    nodes = {"w": (-200, 0), "m": (0, 0), "e": (200, 0), "s": (0, -200), "n": (0, 200)}
    edges = ["eb1 w m 1 oneway", "eb2 m e 1 oneway", "nb1 s m 1 oneway", "nb2 m n 1 oneway"]
    road_map = build(tmp_path, nodes, edges)
    (cross,) = find_sites(road_map, X)
    assert not any(arm.two_way for arm in cross.arms)


def _arm(name: str, heading: float, incoming: bool) -> Arm:
    """A one-way arm of one lane, the lane's id the arm's name."""
    lane = LaneInfo(name, name, 0, 1, 3.5, 100.0, 13.9, ((0.0, 0.0), (1.0, 0.0)))
    return Arm(name, heading, 0, (lane,) if incoming else (), () if incoming else (lane,), 100.0)


@pytest.mark.parametrize(
    ("streams", "cross"),
    [
        ((("w", "e"), ("s", "n")), True),  # through streams at right angles
        ((("w", "e"), ("s", "e")), False),  # a merge
        ((("w", "e"), ("w", "n")), False),  # a diverge
        ((("w", "n"), ("s", "e")), False),  # two turns that never meet
        ((("s", "e"), ("w", "n")), False),
    ],
)
def test_streams_cross_when_their_ends_alternate_round_the_junction(streams: tuple, cross: bool) -> None:
    # arms where they lie: w entered heading east (90), s heading north (0), e and n left by
    arms = [_arm("w", 90.0, True), _arm("s", 0.0, True), _arm("e", 270.0, False), _arm("n", 180.0, False)]
    connections = tuple(Connection(a, b, "s", None) for a, b in streams)
    assert streams_cross(arms, connections) is cross


def test_a_two_way_road_parting_into_its_two_directions_is_no_t(tmp_path: Path) -> None:
    # a two-way road from the west whose directions part at m, 90 degrees apart, into a one-way pair
    # (a loop, a couplet, a median beginning): no traffic runs from the one into the other, as in an
    # OpenDRIVE map that defines no such link (netconvert alone would add a turn back between them)
    nodes = {"w": (-200, 0), "m": (0, 0), "p": (100, -100), "q": (300, -100), "r": (300, 100), "s": (100, 100)}
    edges = ["road w m 1", "out1 m p 1 oneway", "out2 p q 1 oneway", "in1 r s 1 oneway", "in2 s m 1 oneway"]
    road_map = build(tmp_path, nodes, edges, forbid=("in2 out1",))
    assert T not in kinds(road_map) and X not in kinds(road_map)
    (tmp_path / "linked").mkdir()  # with the turn back between them, a car can go on from one to the other
    assert kinds(build(tmp_path / "linked", nodes, edges))[T] == 1
