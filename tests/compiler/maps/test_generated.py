"""Networks as SUMO's netgenerate makes them, built here: junctions that are not right-angled.

A spider network (arms from a centre, rings round it, the centre node left out) has junctions
where a road bends through a T, three roads meet as a Y, and four roads cross askew: the shapes of
roundabout-like centres and skewed crossings a user's town has, which grids never show.
"""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest
from sovarc.compiler.lower import lower
from sovarc.compiler.maps import RoadMap, find_sites
from sovarc.compiler.maps.sites import TURNS
from sovarc.compiler.synth import synthesize
from sovarc.dsl.ir import RoadKind

from tests.compiler.maps.conftest import generate, scenario

pytestmark = pytest.mark.slow  # needs SUMO

X, T, S = RoadKind.INTERSECTION, RoadKind.T_JUNCTION, RoadKind.STRAIGHT


def spider(tmp_path: Path, arms: int, circles: int = 2) -> RoadMap:
    options = ("--spider.arm-number", str(arms), "--spider.circle-number", str(circles))
    return generate(tmp_path, "--spider", *options, "--spider.space-radius", "90", "--spider.omit-center")


def test_a_junction_names_each_turn_by_its_place_in_the_cross(tmp_path: Path) -> None:
    # the inner ring's junctions of a five-armed spider: the ring bends by 72 degrees at each and a
    # spoke comes in between, 126 degrees from both ring roads: SUMO calls every way through a
    # left or a right. The cross the search lays over them has a road through, and its way across
    # must be a straight on, or no scenario can go straight over a T there. (The outer ring's
    # junctions, where the spokes end, are T's of the same shape.)
    road_map = spider(tmp_path, 5)
    tees = find_sites(road_map, T)
    assert len(tees) == 10
    for tee in tees:
        for c in tee.connections:
            entry, exit_ = tee.arm_of_lane(c.from_lane), tee.arm_of_lane(c.to_lane)
            assert entry is not None and exit_ is not None
            assert c.direction == TURNS[(exit_.slot - entry.slot) % 4]
        assert any(c.direction == "s" for c in tee.connections)  # the road through the T


def test_a_side_crash_across_a_bent_t_is_staged_on_every_one(tmp_path: Path) -> None:
    # V1 turns left out of the stem across V2, who goes straight on along the road through
    road_map = spider(tmp_path, 5)
    lowered = lower(scenario("t_junction_left_turn_out_side"), road_map, roads=5, seed=0)
    assert len(lowered) == 5
    for one in lowered:
        moves = {t.participant: t for t in synthesize(one, seed=0).trajectories}
        assert set(moves) == {"V1", "V2"}


def test_a_ring_road_gives_its_straight_sides(tmp_path: Path) -> None:
    # a grid's perimeter is one road round the block, on through its T's: a ring has no first
    # edge, and where its walk began decided which of its two directions staged it, each deferring
    # to the other. Each of its four sides is a straight road.
    road_map = generate(tmp_path, "--grid", "--grid.number", "3", "--grid.length", "200", "-L", "2")
    straights = find_sites(road_map, S)
    sides = [s for s in straights if s.min_length > 300.0]
    assert len(sides) == 4 and all(s.arms[0].two_way and s.lanes == 2 for s in sides)
    assert sorted(round(s.arms[0].heading) % 180 for s in sides) == [0, 0, 90, 90]
    assert len(straights) == 4 + 4  # and the four roads inside, from the middle junction out


def test_roads_crossing_askew_are_a_cross(tmp_path: Path) -> None:
    # the middle ring of a five-armed spider bends by 72 degrees where each spoke crosses it: the
    # ring's roads meet the spoke at 54 degrees, a crossing askew; on the outer ring, where the
    # spoke ends, a T whose through road bends by as much
    road_map = spider(tmp_path, 5, circles=3)
    crosses, tees = find_sites(road_map, X), find_sites(road_map, T)
    assert len(crosses) == 5 and len(tees) == 10
    for cross in crosses:
        ring = [*cross.arms, cross.arms[0]]  # the arms clockwise, by their places in the cross
        gaps = sorted(round((b.heading - a.heading) % 360) for a, b in itertools.pairwise(ring))
        assert gaps == [54, 54, 126, 126]
    lowered = lower(scenario("intersection_left_turn_across_path_side"), road_map, roads=5, seed=0)
    assert len(lowered) == 5 and {one.match.site.id for one in lowered} == {c.id for c in crosses}
    for one in lowered:
        assert {t.participant for t in synthesize(one, seed=0).trajectories} == {"V1", "V2"}
