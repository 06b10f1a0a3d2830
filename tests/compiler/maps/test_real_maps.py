"""Sites on networks we did not draw: esmini's OpenDRIVE files and SUMO's DRT demo city (OpenStreetMap)."""

from __future__ import annotations

from collections import Counter

import pytest
from sovarc.compiler.maps import RoadMap, find_sites, match_sites
from sovarc.dsl.ir import RoadKind

from tests.compiler.maps.conftest import scenario

pytestmark = pytest.mark.slow  # needs SUMO

X, T, S = RoadKind.INTERSECTION, RoadKind.T_JUNCTION, RoadKind.STRAIGHT

# What each OpenDRIVE file holds, as converted by netconvert.
OPENDRIVE_SITES = {
    # a 1.4 km gently curved motorway, four lanes each way: a 5 m median with a guardrail along each
    # edge (the file's railings) makes one-way sites, five stretches each
    "e6mini": {S: 10},
    "fabriksgatan": {X: 1, S: 3},  # one crossing; one of its arms is 17 m long, too short for a straight site
    "jolengatan": {S: 2},  # an 800 m curving street, single lanes: two stretches straight enough
    "multi_intersections": {X: 2, T: 3, S: 13},  # its roads run on through the bends' lane sections
    "straight_500m": {S: 2},  # a long road offers a site on each half
    "two_plus_one": {S: 3},  # a 2+1 road: short lane-change sections between three long ones
}


def test_opendrive_sites(opendrive: dict[str, RoadMap]) -> None:
    found = {name: dict(Counter(s.kind for s in find_sites(m))) for name, m in opendrive.items()}
    assert found == OPENDRIVE_SITES


def test_opendrive_lane_widths_survive_conversion(opendrive: dict[str, RoadMap]) -> None:
    motorway = find_sites(opendrive["e6mini"])[0]
    assert motorway.id == "road:-0@0" and motorway.lanes == 4
    widths = [lane.width for lane in motorway.arms[0].incoming]
    assert widths == pytest.approx([2.85, 3.9, 3.5, 3.65])  # right-most first, as the file gives them
    halves = find_sites(opendrive["straight_500m"])
    assert [s.min_length for s in halves] == pytest.approx([250.0, 250.0], abs=1.0)
    assert all({round(a.heading) for a in s.arms} == {90, 270} for s in halves)


def test_opendrive_junction_arms_form_a_cross(opendrive: dict[str, RoadMap]) -> None:
    for site in find_sites(opendrive["multi_intersections"], X):
        assert [a.slot for a in site.arms] == [0, 1, 2, 3]
        assert site.control == "traffic_light" and site.connections  # the file's signals
    for site in find_sites(opendrive["multi_intersections"], T):
        assert len(site.arms) == 3 and len({a.slot for a in site.arms}) == 3


def test_osm_city_site_counts(osm: RoadMap) -> None:
    # regression figures for the DRT network shipped with eclipse-sumo 1.x
    counts = Counter(s.kind for s in find_sites(osm))
    # T: two three-way nodes whose arms make no T (a fork); S: roads run on through the nodes that
    # split OSM ways and through junctions where they have the right of way; long ones offer a site per stretch.
    # One T is a side road whose two directions meet a one-way road at two nodes 10 m apart: one junction.
    # Three three-way nodes of one-way roads only merge or diverge (a carriageway forking): no T.
    assert counts == {X: 21, T: 57, S: 99}


def test_a_divided_road_is_staged_one_way_at_a_time(osm: RoadMap) -> None:
    # Ernst-Ruska-Ufer: a 12 m median, with other ways on it, between the two directions
    for half in ("320741894#0", "320741895#0"):
        (site,) = [
            s for s in find_sites(osm, S) if half in {e for a in s.arms for lane in a.incoming for e in lane.edges}
        ]
        assert len(site.arms) == 1 and not site.arms[0].outgoing
    paired = [s for s in find_sites(osm, S) if len(s.arms) == 2]
    assert paired and all(s.arms[0].outgoing and s.arms[1].outgoing for s in paired)


def test_osm_sites_use_car_lanes_only(osm: RoadMap) -> None:
    sites = find_sites(osm)
    edges = {e.getID(): e for e in osm.net.getEdges()}
    for site in sites:
        for arm in site.arms:
            for lane in arm.incoming + arm.outgoing:
                assert edges[lane.edge].getLane(lane.index).allows("passenger")
                assert not lane.edge.startswith(":")
    # OSM roads with sidewalks: car lane 1 is not SUMO lane 0
    assert any(lane.index != lane.number - 1 for s in sites for a in s.arms for lane in a.incoming)
    for site in find_sites(osm, X):
        assert max(abs(((a.heading - site.orientation - 90 * a.slot + 180) % 360) - 180) for a in site.arms) <= 35


def test_search_works_on_the_osm_city(osm: RoadMap) -> None:
    matches = match_sites(scenario("intersection_left_turn_across_path_side"), osm, n=5, seed=1)
    assert len({m.site.id for m in matches}) == 5
    assert all(m.site.kind is X and m.exact for m in matches)
    u_turn = match_sites(scenario("t_junction_u_turn_side"), osm, n=3)
    assert all(m.site.kind is T for m in u_turn)
