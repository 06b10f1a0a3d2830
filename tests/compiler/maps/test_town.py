"""The example town: reproducible build, and the sites found on it."""

from __future__ import annotations

import subprocess
import sys
from collections import Counter

import pytest
from sovarc.compiler.maps import RoadMap, find_sites, load_map
from sovarc.dsl.ir import RoadKind

from tests.compiler.maps.conftest import TOWN
from tests.conftest import EXAMPLES

pytestmark = pytest.mark.slow  # needs SUMO


def test_rebuilding_the_town_gives_the_same_bytes() -> None:
    done = subprocess.run(
        [sys.executable, str(EXAMPLES / "maps" / "build_town.py"), "--check"], capture_output=True, text=True
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert b"generated on" not in TOWN.read_bytes()[:2000]  # no date in the checked-in file


def test_site_counts_per_kind(town: RoadMap) -> None:
    counts = Counter(site.kind for site in find_sites(town))
    assert counts == {RoadKind.INTERSECTION: 5, RoadKind.T_JUNCTION: 4, RoadKind.STRAIGHT: 21}
    assert [s.id for s in find_sites(town, RoadKind.T_JUNCTION)] == [
        "junction:t_mill_s",
        "junction:t_north",
        "junction:t_oak_s",
        "junction:t_river",
    ]
    assert find_sites(town, "intersection") == find_sites(town, RoadKind.INTERSECTION)


def test_lane_widths_counts_and_lengths_are_in_the_designed_ranges(town: RoadMap) -> None:
    sites = find_sites(town)
    car_lanes = {lane.id: lane for s in sites for a in s.arms for lane in a.incoming + a.outgoing}
    widths = {lane.width for lane in car_lanes.values()}
    assert min(widths) == pytest.approx(2.8) and max(widths) == pytest.approx(4.0)
    assert len(widths) >= 8
    assert {s.lanes for s in sites} == {1, 2, 3, 4}
    assert min(s.min_length for s in sites if s.kind is RoadKind.STRAIGHT) >= 150.0
    assert {s.control for s in sites if s.junction} == {"priority", "traffic_light"}


def test_a_road_rotated_twenty_degrees_has_rotated_headings(town: RoadMap) -> None:
    (road,) = [s for s in find_sites(town, RoadKind.STRAIGHT) if s.id == "road:-river1@0|river1@14"]
    assert road.orientation == pytest.approx(20.0, abs=0.1)
    assert {a.id: round(a.heading, 1) for a in road.arms} == {"river1": 110.0, "-river1": 290.0}
    assert [len(a.incoming) for a in road.arms] == [2, 2] and [len(a.outgoing) for a in road.arms] == [2, 2]
    river = next(s for s in find_sites(town) if s.id == "junction:x_river")
    # arms are named by their incoming edge; headings are those of traffic entering the junction
    assert {a.id: round(a.heading) for a in river.arms} == {"mill2": 15, "river1": 110, "-rivn": 200, "-rive1": 290}
    assert [a.slot for a in river.arms] == [0, 1, 2, 3]
    assert river.orientation == pytest.approx(18.85, abs=0.1)


def test_lanes_are_numbered_from_the_rightmost_car_lane(town: RoadMap) -> None:
    x_main = next(s for s in find_sites(town) if s.id == "junction:x_main")
    main1 = next(a for a in x_main.arms if a.id == "main1")  # Main Street has a sidewalk at SUMO index 0
    assert [(lane.index, lane.number) for lane in main1.incoming] == [(1, 1), (2, 2)]
    assert [lane.id for lane in main1.outgoing] == ["-main1_1", "-main1_2"]
    assert all(lane.width == pytest.approx(3.0) and 250 < lane.length < 300 for lane in main1.incoming)
    right, left = main1.incoming
    assert right.shape[0][1] < right.shape[-1][1] < 0.0  # northbound, stopping short of the junction at y = 0
    assert right.shape[0][0] > left.shape[0][0]  # the right-most lane is the eastern one


def test_connections_through_a_junction(town: RoadMap) -> None:
    x_main = next(s for s in find_sites(town) if s.id == "junction:x_main")
    west_bound = next(a for a in x_main.arms if a.id == "-ave2")
    links = x_main.connections_from(west_bound)
    assert {c.direction for c in links} >= {"s", "l", "r"}
    lefts = [c for c in links if c.direction == "l"]
    # westbound traffic turning left drives south, onto the outgoing lanes of the southern arm
    assert {x_main.arm_of_lane(c.to_lane).id for c in lefts} == {"main1"}
    assert all(c.via and c.via.startswith(":x_main_") for c in links)
    assert list(x_main.connections) == sorted(x_main.connections, key=lambda c: (c.from_lane, c.to_lane, c.direction))


def test_one_way_roads(town: RoadMap) -> None:
    x_north = next(s for s in find_sites(town) if s.id == "junction:x_north")
    exit_only = next(a for a in x_north.arms if a.id == "oak_n")
    assert (len(exit_only.incoming), len(exit_only.outgoing), exit_only.heading) == (0, 2, 180.0)
    (one_way,) = [s for s in find_sites(town) if s.id == "road:oak_n"]
    assert len(one_way.arms) == 1 and one_way.arms[0].heading == pytest.approx(0.0)


def test_sites_are_deterministic_and_sorted(town: RoadMap) -> None:
    again = find_sites(load_map(TOWN))
    assert again == find_sites(town)
    assert [s.id for s in again] == sorted(s.id for s in again)
    assert find_sites(town, min_length=300.0) != find_sites(town)
    assert all(s.min_length >= 300.0 for s in find_sites(town, RoadKind.STRAIGHT, min_length=300.0))
