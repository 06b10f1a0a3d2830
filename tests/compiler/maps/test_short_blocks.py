"""Streets of short blocks: straight stretches shorter than 80 m between junctions are sites of last resort.

A European grid's blocks are 50-70 m long between junctions. The search keeps such stretches, down
to SHORT_MIN_LENGTH (two cars and a two-second gap at 30 km/h), and tries them only after every fit on
a straight site of 80 m or more: a map of short blocks hosts the crashes that fit in a block, and a map
with long roads is staged as it was.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.compiler.maps import RoadMap, find_sites, match_sites, short_sites
from sovarc.compiler.maps.sites import DEFAULT_MIN_LENGTH, SHORT_MIN_LENGTH
from sovarc.compiler.maps.survey import missing, survey
from sovarc.compiler.pipeline import Options, stage_sites
from sovarc.dsl import parse
from sovarc.dsl.ir import RoadKind

from tests.compiler.maps.test_roads import build

pytestmark = pytest.mark.slow  # needs SUMO

S = RoadKind.STRAIGHT

# a town rear-end: V1 follows V2 along a street and runs into it as it stops
REAR_END = """\
scenario city_rear_end {
  road {
    kind straight
    lanes 2
    speed_limit 25 mph
  }
  vehicle V1 {
    heading east
    lane 1
    speed 20 mph
    actions {
      follow_lane
    }
  }
  vehicle V2 {
    heading east
    lane 1
    speed 0 mph
    actions {
      stop
    }
  }
  crash {
    type rear_end
    striker V1
    victim V2
  }
}
"""


def blocks(tmp_path: Path, long_road: bool = False, lanes: int = 1) -> RoadMap:
    """A two-way street of four 60 m blocks of `lanes` lanes each way, side streets crossing it between
    them (40 m each way, one stub of 25 m); with `long_road`, also a 300 m road of its own, one lane
    each way."""
    nodes = {f"c{k}": (60.0 * k, 0.0) for k in range(5)}
    nodes |= {f"n{k}": (60.0 * k, 40.0) for k in range(1, 4)} | {f"s{k}": (60.0 * k, -40.0) for k in range(1, 3)}
    nodes["s3"] = (180.0, -25.0)
    edges = [f"m{k} c{k} c{k + 1} {lanes}" for k in range(4)]
    edges += [f"n{k} c{k} n{k} 1" for k in range(1, 4)] + [f"s{k} c{k} s{k} 1" for k in range(1, 4)]
    if long_road:
        nodes |= {"la": (0.0, 300.0), "lb": (300.0, 300.0)}
        edges.append("long la lb 1")
    return build(tmp_path, nodes, edges)


def test_a_street_of_short_blocks_gives_short_sites_above_the_floor(tmp_path: Path) -> None:
    road_map = blocks(tmp_path)
    assert find_sites(road_map, S) == []  # no block is 80 m long
    short = short_sites(road_map)
    assert short and all(s.kind is S and len(s.arms) == 2 for s in short)
    assert all(SHORT_MIN_LENGTH <= s.min_length < DEFAULT_MIN_LENGTH for s in short)
    # the four blocks of the street and the 40 m side streets; the 25 m stub is too short for two cars
    assert not any("s3" in s.id for s in short)
    assert {f"m{k}" for k in range(4)} <= {part.lstrip("-") for s in short for part in s.id[5:].split("|")}
    # `sovarc sites` lists them last, under their own heading; the counts are of the other sites
    text = survey(road_map).text()
    assert text.splitlines()[0].endswith(", 0 straight roads")
    assert f"straight roads shorter than 80 m, tried last ({len(short)}):" in text
    said = f"0 straight roads; {len(short)} straight roads shorter than 80 m, tried last"
    assert str(missing(road_map, S)).endswith(said)  # `sovarc sites --kind straight` says why it has none


def test_a_straight_crash_plans_on_a_street_of_short_blocks(tmp_path: Path) -> None:
    road_map = blocks(tmp_path)
    results = stage_sites(parse(REAR_END), Options(map=road_map, roads=3, spare=0))
    assert len(results) == 3
    for result in results:
        assert result.plan is not None, result.error
        assert result.site in {s.id for s in short_sites(road_map)}


def test_a_site_of_last_resort_is_not_chosen_when_a_long_one_fits(tmp_path: Path) -> None:
    road_map = blocks(tmp_path, long_road=True)
    (long,) = find_sites(road_map, S)
    scenario = parse(REAR_END)
    assert [m.site.id for m in match_sites(scenario, road_map, n=1)] == [long.id]
    # asked for more than the long roads give, the short blocks follow them
    every = match_sites(scenario, road_map, n=20)
    assert every[0].site.id == long.id
    assert {m.site.id for m in every[1:]} == {s.id for s in short_sites(road_map)}


def test_an_exact_fit_on_a_short_block_goes_before_a_clamped_one_on_a_long_road(tmp_path: Path) -> None:
    # both cars in lane 2: the street's blocks have two lanes each way, the long road one
    road_map = blocks(tmp_path, long_road=True, lanes=2)
    (long,) = find_sites(road_map, S)
    two_lanes = parse(REAR_END.replace("lane 1", "lane 2"))
    matches = match_sites(two_lanes, road_map, n=20, clamp=True)
    streets = {s.id for s in short_sites(road_map) if s.lanes == 2}
    assert len(streets) == 4 and {m.site.id for m in matches[:4]} == streets
    assert all(m.exact for m in matches[:4])
    assert matches[4].site.id == long.id and not matches[4].exact  # then the long road, clamped to its lane
