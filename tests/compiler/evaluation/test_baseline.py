"""The random baseline: NPCs on the site's lanes, deterministic for a seed, the ego's task untouched."""

from __future__ import annotations

from dataclasses import replace

import pytest
import sumolib
from sovarc.compiler.evaluation.baseline import random_npcs, random_tests
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.maps import RoadMap
from sovarc.targets.fmu import EgoFmu, egos, run_test_results

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


def test_same_seed_same_npcs_other_seed_other_npcs(town: RoadMap) -> None:
    plan = crossing()
    assert random_npcs(plan, town, "V1", 7) == random_npcs(plan, town, "V1", 7)
    assert random_npcs(plan, town, "V1", 7).trajectory("V2") != random_npcs(plan, town, "V1", 8).trajectory("V2")


def test_each_scenario_on_a_site_gets_its_own_draw(town: RoadMap) -> None:
    """Scenarios staged on one site often give the same ego task: the same NPCs for all of them would
    count one draw once per scenario."""
    plan = crossing()
    other = replace(plan, scenario=replace(plan.scenario, name="another_report"))
    assert random_npcs(plan, town, "V1", 7).trajectory("V2") != random_npcs(other, town, "V1", 7).trajectory("V2")


@pytest.mark.parametrize("make", [crossing, cut_in])
def test_npcs_drive_the_sites_lanes_and_the_ego_keeps_its_task(make, net, town: RoadMap) -> None:
    plan = make()
    for seed in range(5):
        random = random_npcs(plan, town, "V1", seed)
        assert random.trajectory("V1") == plan.trajectory("V1")
        npc = random.trajectory("V2")
        assert npc.body == plan.trajectory("V2").body
        assert len(npc.samples) == len(plan.trajectory("V2").samples)
        assert _on_lanes(npc, net) < 0.5
        if plan.site == "junction:x_oak":
            assert any(lane.startswith(":x_oak_") for lane in npc.lanes)  # it drives through the junction
        assert "random baseline" in random.notes[-1]


def test_the_fmu_target_runs_the_random_plans_it_is_given(reference: EgoFmu, town: RoadMap) -> None:
    plan = crossing()
    report = run_test_results(plan, reference, seed=1)
    random = run_test_results(plan, reference, seed=1, method="random", tests=random_tests(plan, town, 1, egos(plan)))
    assert [r.run.ego for r in random] == [r.run.ego for r in report]
    for a, b in zip(report, random, strict=True):
        assert a.plan.trajectory(a.run.ego) == b.plan.trajectory(b.run.ego)  # the ego's task is unchanged
        assert b.plan == random_npcs(plan, town, b.run.ego, 1)  # the NPCs it was given
        assert b.verdict.facts["method"] == "random"
