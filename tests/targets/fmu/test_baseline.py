"""Random NPCs: on the site's lanes, deterministic for a seed, the ego's task untouched."""

from __future__ import annotations

from dataclasses import replace

import pytest
import sumolib
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.targets.fmu import random_npcs

from tests.targets.fmu.plans import TOWN, crossing, cut_in

pytestmark = pytest.mark.slow  # loads the map with sumolib


@pytest.fixture(scope="module")
def net() -> sumolib.net.Net:
    return sumolib.net.readNet(str(TOWN), withInternal=True)


def _on_lanes(trajectory, net) -> float:
    """How far the trajectory's samples stray from the centre lines of its lanes (m)."""
    line = Polyline([p for lane in trajectory.lanes for p in net.getLane(lane).getShape()])
    return max(
        line.project_within((s.x, s.y))[1]
        for s in trajectory.samples
        if line.project_within((s.x, s.y))[0] < line.length
    )


def test_same_seed_same_npcs_other_seed_other_npcs() -> None:
    plan = crossing()
    assert random_npcs(plan, "V1", 7) == random_npcs(plan, "V1", 7)
    assert random_npcs(plan, "V1", 7).trajectory("V2") != random_npcs(plan, "V1", 8).trajectory("V2")


def test_each_scenario_on_a_site_gets_its_own_draw() -> None:
    """Scenarios staged on one site often give the same ego task: the same NPCs for all of them would
    count one draw once per scenario."""
    plan = crossing()
    other = replace(plan, scenario=replace(plan.scenario, name="another_report"))
    assert random_npcs(plan, "V1", 7).trajectory("V2") != random_npcs(other, "V1", 7).trajectory("V2")


@pytest.mark.parametrize("make", [crossing, cut_in])
def test_npcs_drive_the_sites_lanes_and_the_ego_keeps_its_task(make, net) -> None:
    plan = make()
    for seed in range(5):
        random = random_npcs(plan, "V1", seed)
        assert random.trajectory("V1") == plan.trajectory("V1")
        npc = random.trajectory("V2")
        assert npc.body == plan.trajectory("V2").body
        assert len(npc.samples) == len(plan.trajectory("V2").samples)
        assert _on_lanes(npc, net) < 0.5
        if plan.site == "junction:x_oak":
            assert any(lane.startswith(":x_oak_") for lane in npc.lanes)  # it drives through the junction
        assert "random baseline" in random.notes[-1]
