"""Junctions netconvert builds as several nodes are read as one junction (clusters.py).

The networks are written here as plain XML: a divided road (two one-way carriageways 10 m
apart, each through its own node) met by side roads, joined across the median by a short
two-way edge. netconvert keeps one node per carriageway, as it does for OSM's dual
carriageways and for many OpenDRIVE junctions.
"""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest
from sovarc.compiler.lower import lower
from sovarc.compiler.maps import RoadMap, find_sites
from sovarc.compiler.synth import synthesize
from sovarc.dsl.ir import RoadKind

from tests.compiler.maps.conftest import scenario
from tests.compiler.maps.test_roads import build, kinds

pytestmark = pytest.mark.slow  # needs SUMO

X, T, S = RoadKind.INTERSECTION, RoadKind.T_JUNCTION, RoadKind.STRAIGHT
CARRIAGEWAYS = ["eb1 w1 a 2 oneway", "eb2 a e1 2 oneway", "wb1 e2 b 2 oneway", "wb2 b w2 2 oneway", "med a b 1"]


def divided(tmp_path: Path, *sides: str, gap: float = 10.0) -> RoadMap:
    """Eastbound through node a (y=0), westbound through node b (y=gap), the median crossed
    between them; side roads to the south (from a) and to the north (from b)."""
    nodes = {"w1": (-200, 0), "a": (0, 0), "e1": (200, 0), "e2": (200, gap), "b": (0, gap), "w2": (-200, gap)}
    nodes |= {"s": (0, -200), "n": (0, 200 + gap)}
    roads = {"south": "south a s 1", "north": "north b n 1"}
    return build(tmp_path, nodes, CARRIAGEWAYS + [roads[side] for side in sides])


def test_a_divided_road_and_a_side_road_are_one_t(tmp_path: Path) -> None:
    road_map = divided(tmp_path, "south")
    (tee,) = find_sites(road_map, T)
    assert kinds(road_map)[T] == 1 and X not in kinds(road_map)  # not a one-way 'cross' at a and a 'T' at b
    assert tee.id == "junction:a+b" and all(arm.two_way for arm in tee.arms)
    west = next(arm for arm in tee.arms if round(arm.heading) == 90)  # traffic entering eastbound
    assert west.incoming[0].edge == "eb1" and west.outgoing[0].edge == "wb2"  # the two carriageways, paired
    # the left turn out of the side road crosses the median: its way runs on the edge between the nodes
    south = next(arm for arm in tee.arms if round(arm.heading) == 0)
    (left,) = [c for c in tee.connections_from(south) if c.direction == "l"]
    assert left.to_lane.startswith("wb2_") and left.edges == ("med",) and "med_0" in left.path
    assert {c.direction for c in tee.connections} == {"l", "r", "s", "t"}


def test_a_divided_road_crossed_by_a_road_is_one_cross(tmp_path: Path) -> None:
    road_map = divided(tmp_path, "south", "north")
    (cross,) = find_sites(road_map, X)
    assert T not in kinds(road_map) and len(cross.arms) == 4 and all(arm.two_way for arm in cross.arms)
    assert [arm.slot for arm in cross.arms] == [0, 1, 2, 3]
    north = next(arm for arm in cross.arms if round(arm.heading) == 180)  # traffic entering southbound
    across = {(c.to_lane.split("_")[0], c.edges) for c in cross.connections_from(north) if c.direction == "s"}
    assert across == {("south", ("-med",))}  # straight over both carriageways, through the median


def test_side_roads_with_no_gap_in_the_median_are_two_ts(tmp_path: Path) -> None:
    # the same roads with no edge across the median: no traffic goes from one carriageway's node
    # to the other's, so each side road meets its carriageway at a T of its own (right in, right out)
    nodes = {"w1": (-200, 0), "a": (0, 0), "e1": (200, 0), "e2": (200, 10), "b": (0, 10), "w2": (-200, 10)}
    nodes |= {"s": (0, -200), "n": (0, 210)}
    road_map = build(tmp_path, nodes, [*CARRIAGEWAYS[:4], "south a s 1", "north b n 1"])
    assert kinds(road_map).get(X) is None and kinds(road_map)[T] == 2
    assert sorted(site.id for site in find_sites(road_map, T)) == ["junction:a", "junction:b"]


def test_nodes_far_apart_stay_two_junctions(tmp_path: Path) -> None:
    # the same roads with the carriageways 60 m apart: two T's, not one junction
    road_map = divided(tmp_path, "south", "north", gap=60.0)
    assert not any("+" in site.id for site in find_sites(road_map))


def test_a_scenario_turns_across_the_median_of_a_clustered_t(tmp_path: Path) -> None:
    road_map = divided(tmp_path, "south")
    (lowered,) = lower(scenario("t_junction_left_turn_out_side"), road_map, seed=0)
    plan = synthesize(lowered, seed=0)
    edges = {t.participant: t.edges for t in plan.trajectories}
    assert edges["V1"] == ("-south", "med", "wb2")  # stem, the median's edge, the far carriageway
    lanes = next(t.lanes for t in plan.trajectories if t.participant == "V1")
    assert "med_0" in lanes and any(lane.startswith(":b_") for lane in lanes)
    samples = next(t.samples for t in plan.trajectories if t.participant == "V1")
    steps = [((p.x - q.x) ** 2 + (p.y - q.y) ** 2) ** 0.5 for p, q in itertools.pairwise(samples)]
    assert max(steps) < 5.0  # a continuous path through both nodes


def test_two_divided_roads_crossing_are_one_cross(tmp_path: Path) -> None:
    # four nodes at the corners of the square where the carriageways cross, 12 m apart
    g = 12
    nodes = {"a": (0, 0), "b": (g, 0), "c": (g, g), "d": (0, g), "W1": (-200, 0), "E1": (200, 0), "E2": (200, g)}
    nodes |= {"W2": (-200, g), "S1": (0, -200), "S2": (g, -200), "N1": (g, 200), "N2": (0, 200)}
    ways = ["eb W1 a b E1", "wb E2 c d W2", "nb S2 b c N1", "sb N2 d a S1"]  # each carriageway through two corners
    edges = [
        f"{w}{k} {a} {b} 2 oneway"
        for w, *path in (s.split() for s in ways)
        for k, (a, b) in enumerate(itertools.pairwise(path))
    ]
    road_map = build(tmp_path, nodes, edges)
    (cross,) = find_sites(road_map, X)
    assert T not in kinds(road_map) and cross.id == "junction:a+b+c+d"
    assert all(arm.two_way and len(arm.incoming) == 2 for arm in cross.arms)
    moves = {(c.from_lane, c.direction): c.edges for c in cross.connections}
    assert moves[("eb0_1", "l")] == ("eb1", "nb1")  # a left turn runs on two of the square's sides
    assert moves[("eb0_0", "s")] == ("eb1",) and moves[("eb0_0", "r")] == ()
