"""Scenario-sites a map has no site of the needed shape for are their own class (srr.NO_SHAPE)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest
from sovarc.compiler.evaluation.srr import NO_SHAPE, _lacking, _row, reconstruct, srr_table
from sovarc.compiler.maps import find_sites
from sovarc.compiler.pipeline import Assumed, Sites, Slots, _fewer
from sovarc.compiler.slots import SiteResult

from tests.compiler.maps.conftest import scenario
from tests.compiler.maps.test_roads import build

pytestmark = pytest.mark.slow  # needs SUMO's netconvert


def _failed(site: str, reason: str) -> dict:
    return _row(Path("straight_double_yellow_pass_frontal.sov"), "straight", site, "planning failed", reason)


def test_a_map_with_fewer_sites_of_the_shape_than_asked_says_so(tmp_path: Path) -> None:
    # one two-way road and two one-way carriageways: a pass over the centre line fits the first alone
    nodes = {"a": (0, 0), "b": (200, 0), "c": (0, 100), "d": (200, 100), "e": (200, 120), "f": (0, 120)}
    road_map = build(tmp_path, nodes, ["two a b 1", "east c d 2 oneway", "west e f 2 oneway"])
    passing = scenario("straight_double_yellow_pass_frontal")
    (two_way,) = [s.id for s in find_sites(road_map) if len(s.arms) == 2]
    rows = [_failed(two_way, "cannot strike"), _failed("-", "fewer fitting sites than asked")]
    rows.append(_failed("-", "fewer fitting sites than asked"))
    out = _lacking(passing, road_map, [dict(r) for r in rows], roads=3)
    # two of three asked have no site: those rows, not the one on the road that has the shape
    assert [r["failure"] for r in out] == ["planning failed", NO_SHAPE, NO_SHAPE]
    assert out[1]["reason"].startswith("the map has no site of the shape this scenario needs: 1 of its 3 straight")
    assert out[0]["reason"] == "cannot strike"
    table = srr_table("m", out)
    assert "  all               0.0%  0/3          0.0%  0/1" in table
    assert "no site of its shape 2" in table


def test_a_map_with_enough_sites_of_the_shape_keeps_its_failures(tmp_path: Path) -> None:
    nodes = {"a": (0, 0), "b": (200, 0), "c": (0, 100), "d": (200, 100), "e": (0, 200), "f": (200, 200)}
    road_map = build(tmp_path, nodes, ["r1 a b 1", "r2 c d 1", "r3 e f 1"])
    rows = [_failed(f"road:{k}", "cannot strike") for k in range(3)]
    out = _lacking(scenario("straight_double_yellow_pass_frontal"), road_map, [dict(r) for r in rows], roads=3)
    assert [r["failure"] for r in out] == ["planning failed"] * 3


def test_a_scenario_no_site_fits_at_all_has_every_row_said_so(tmp_path: Path) -> None:
    # two one-way carriageways: a pass over the centre line has no road here, on any of 3 sites
    nodes = {"a": (0, 0), "b": (200, 0), "c": (200, 20), "d": (0, 20)}
    road_map = build(tmp_path, nodes, ["east a b 2 oneway", "west c d 2 oneway"])
    name = "straight_double_yellow_pass_frontal"
    rows = reconstruct(scenario(name), Path(f"{name}.sov"), road_map, roads=3)
    assert [r["failure"] for r in rows] == [NO_SHAPE] * 3
    assert all(r["reason"].startswith("the map has no site of the shape this scenario needs: 0 of its 2") for r in rows)


def test_the_pipeline_says_when_the_map_has_fewer_sites_of_the_shape_than_asked(tmp_path: Path) -> None:
    nodes = {"a": (0, 0), "b": (200, 0), "c": (0, 100), "d": (200, 100), "e": (200, 120), "f": (0, 120)}
    road_map = build(tmp_path, nodes, ["two a b 1", "east c d 2 oneway", "west e f 2 oneway"])
    sites = Sites(Assumed(scenario("straight_double_yellow_pass_frontal"), ()), road_map, (), 3)
    note = _fewer(Slots(sites, [SiteResult("road:two")], ()))
    assert note == (
        f"note: {road_map.name} has 1 site this scenario fits, 3 asked: "
        "it has no other site of the shape the scenario needs\n"
    )
    assert _fewer(Slots(replace(sites, roads=1), [SiteResult("road:two")], ())) == ""
