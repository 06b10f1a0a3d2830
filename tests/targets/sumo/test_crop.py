"""A big map travels cropped to the scenario's roads, with the kept lanes exactly as in the map."""

from __future__ import annotations

import itertools
import subprocess
from pathlib import Path

import pytest
import sumo
from lxml import etree
from sovarc.compiler.lower import lower_on, sites_for
from sovarc.compiler.maps import load_map
from sovarc.compiler.synth import synthesize
from sovarc.dsl import parse
from sovarc.targets.sumo import check, emit
from sovarc.targets.sumo.crop import Box, crop, needs_crop
from sovarc.targets.sumo.network import read_network
from sovarc.targets.sumo.schemas import validate

CITY = Path(sumo.SUMO_HOME) / "tools" / "game" / "DRT" / "osm.net.xml"
TOWN = Path(__file__).resolve().parents[3] / "examples" / "maps" / "town.net.xml"
SCENARIOS = Path(__file__).resolve().parents[3] / "examples" / "scenarios"
BOX = Box(1000.0, 1000.0, 1400.0, 1400.0)


@pytest.fixture(scope="module")
def cropped(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("crop") / "city.net.xml"
    path.write_bytes(crop(CITY.read_bytes(), BOX))
    return path


def test_only_big_maps_are_cropped() -> None:
    assert needs_crop(CITY.read_bytes())
    assert not needs_crop(TOWN.read_bytes())


def test_kept_lanes_are_the_maps_own_and_every_lane_in_the_box_is_kept(cropped: Path) -> None:
    whole, part = read_network(CITY), read_network(cropped)
    assert 0 < len(part.lanes) < len(whole.lanes) / 2
    for lane in part.lanes.values():
        assert lane == whole.lanes[lane.id]  # same shape, width, length and ends: nothing recomputed
    inside = {
        lane.id
        for lane in whole.lanes.values()
        if not lane.internal and any(BOX.meets(p, q) for p, q in itertools.pairwise(lane.shape))
    }
    assert inside and inside <= set(part.lanes)


def test_the_cropped_network_is_valid_and_sumo_loads_it(cropped: Path) -> None:
    assert validate(cropped) == []
    binary = Path(sumo.SUMO_HOME) / "bin" / "sumo"
    done = subprocess.run([str(binary), "-n", str(cropped), "--end", "1"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "Error" not in done.stderr


def test_a_box_only_grows_to_its_grid_and_holds_its_points() -> None:
    box = Box.around([(1012.0, 1190.0), (1130.0, 1250.0)])
    assert box == Box(900.0, 1100.0, 1200.0, 1400.0)
    assert box.holds(1012.0, 1190.0) and box.holds(1130.0, 1250.0)
    assert box.meets((800.0, 1200.0), (1300.0, 1200.0))  # a segment through the box
    assert not box.meets((800.0, 1000.0), (1300.0, 1050.0))  # one passing below it


def test_a_city_plan_emits_a_cropped_network_and_replays_the_crash(tmp_path: Path) -> None:
    road_map = load_map(CITY)
    source = SCENARIOS / "intersection_red_light_runner_side.sov"
    staged, notes, matches = sites_for(parse(source.read_text(encoding="utf-8"), str(source)), road_map, roads=1)
    plan = synthesize(lower_on(staged, matches[0], road_map, notes))
    config = emit(plan, tmp_path)
    net = tmp_path / "osm.net.xml"
    assert net.stat().st_size < CITY.stat().st_size / 3
    verdict = check(plan, tmp_path)
    assert verdict.passed, verdict.findings
    again = tmp_path / "again"
    emit(plan, again)
    assert (again / "osm.net.xml").read_bytes() == net.read_bytes()
    assert config.is_file()


def test_a_route_running_past_the_box_keeps_its_edges_and_the_junction_between_them() -> None:
    whole = etree.fromstring(CITY.read_bytes(), etree.XMLParser(huge_tree=True))
    junctions = {j.get("id"): j for j in whole.iter("junction")}
    ends = {e.get("id"): e.get("to") for e in whole.iter("edge") if not e.get("function")}
    # a turn between two normal edges at a junction well outside BOX
    link = next(
        c
        for c in whole.iter("connection")
        if c.get("from") in ends
        and c.get("to") in ends
        and c.get("via")
        and float(junctions[ends[c.get("from")]].get("x")) > BOX.x1 + 500.0
    )
    route = frozenset({link.get("from"), link.get("to")})
    part = etree.fromstring(crop(CITY.read_bytes(), BOX, route))
    kept = {e.get("id") for e in part.iter("edge")}
    assert route <= kept
    assert any(c.get("from") == link.get("from") and c.get("to") == link.get("to") for c in part.iter("connection"))
    plain = etree.fromstring(crop(CITY.read_bytes(), BOX))
    assert not route <= {e.get("id") for e in plain.iter("edge")}  # without the route, both are cut
