"""A turn the junction's map draws no connection for is laid across it by the arms' geometry
(maps/search.geometric_exit, lower/routes.py): an OpenDRIVE junction holds only the connecting roads
its author drew, and a crossing of two-way roads without them is still one a car turns left across.
Such a site fits after every exact fit, with a note, as a site with too few lanes does."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.compiler.lower import sites_for
from sovarc.compiler.maps import RoadMap, find_sites, match_sites
from sovarc.compiler.maps.search import geometric_exit
from sovarc.compiler.staging import stage_on_site
from sovarc.dsl.errors import LoweringError, SovarcError
from sovarc.dsl.ir import ActionKind, RoadKind
from sovarc.targets.sumo.check import check

from tests.compiler.maps.conftest import scenario
from tests.compiler.maps.test_roads import build

pytestmark = pytest.mark.slow  # netconvert builds the networks, SUMO replays the plan

LEFT_TURN = "intersection_left_turn_across_path_side"


def crosses(tmp_path: Path, without_lefts: tuple[str, ...]) -> RoadMap:
    """Two crossings of two-way roads, two lanes each way, 300 m apart along an east-west road:
    'a' at x = 0 and 'b' at x = 300; each junction named in `without_lefts` has no left turn."""
    nodes = {"w": (-250, 0), "a": (0, 0), "b": (300, 0), "e": (550, 0)}
    nodes |= {"as": (0, -250), "an": (0, 250), "bs": (300, -250), "bn": (300, 250)}
    edges = ["wa w a 2", "ab a b 2", "be b e 2", "sa as a 2", "an a an 2", "sb bs b 2", "bn b bn 2"]
    lefts = {
        "a": ("wa an", "sa -wa", "-ab -sa", "-an ab"),
        "b": ("ab bn", "sb -ab", "-be -sb", "-bn be"),
    }
    return build(tmp_path, nodes, edges, forbid=tuple(pair for j in without_lefts for pair in lefts[j]))


def test_a_crossing_without_left_turns_offers_them_by_its_arms(tmp_path: Path) -> None:
    road_map = crosses(tmp_path, ("a", "b"))
    for site in find_sites(road_map, RoadKind.INTERSECTION):
        for arm in site.arms:
            assert not any(c.direction in ("l", "L") for c in site.connections_from(arm))
            left = geometric_exit(site, arm, ActionKind.TURN_LEFT)
            assert left is not None and left.slot == (arm.slot + 1) % 4
            assert geometric_exit(site, arm, ActionKind.U_TURN) is None  # a U-turn needs no connection


def test_exact_fits_come_first_and_a_left_turn_by_geometry_after_them(tmp_path: Path) -> None:
    road_map = crosses(tmp_path, ("b",))
    matches = match_sites(scenario(LEFT_TURN), road_map, n=2, clamp=True)
    assert [m.site.junction for m in matches] == ["a", "b"]
    assert matches[0].exact
    assert any("has no turn_left connection" in note for note in matches[1].clamped)
    none = tmp_path / "none"
    none.mkdir()
    with pytest.raises(LoweringError, match="no site"):  # not without clamping: it is no exact fit
        match_sites(scenario(LEFT_TURN), crosses(none, ("a", "b")), n=1)


def test_a_left_turn_laid_by_geometry_plans_and_passes_the_sumo_oracle(tmp_path: Path) -> None:
    road_map = crosses(tmp_path, ("a", "b"))
    staged, notes, matches = sites_for(scenario(LEFT_TURN), road_map, roads=1)
    plan = stage_on_site(staged, notes, road_map, matches[0])
    verdict = check(plan)
    assert verdict.passed, verdict.dumps()


def test_a_site_that_fits_only_clamped_names_what_it_lacks_when_it_cannot_host_the_crash(tmp_path: Path) -> None:
    # two cars side by side in two left-turn lanes, on a crossing of one lane each way: clamped into
    # one lane, they cannot be side by side, and the reason says the site lacked the lane
    nodes = {"w": (-250, 0), "a": (0, 0), "e": (250, 0), "s": (0, -250), "n": (0, 250)}
    road_map = build(tmp_path, nodes, ["wa w a 1", "ae a e 1", "sa s a 1", "an a n 1"])
    staged, notes, matches = sites_for(scenario("intersection_dual_left_turn_side"), road_map, roads=1)
    assert matches[0].clamped
    with pytest.raises(SovarcError, match=r"\(the site fits only clamped: .*lanes needed"):
        stage_on_site(staged, notes, road_map, matches[0])
