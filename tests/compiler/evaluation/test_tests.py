"""`eval tests`: failures per road kind, report-derived against random, in the paper's Table 6 form."""

from __future__ import annotations

import pytest
from sovarc.compiler.evaluation.tests import TestsTable, evaluate_tests
from sovarc.compiler.maps import RoadMap
from sovarc.targets.fmu import EgoFmu

from tests.targets.fmu.plans import car_following, cut_in

pytestmark = pytest.mark.slow  # runs SUMO and an FMU


def test_table_counts_failures_per_kind_and_method(reference: EgoFmu, town: RoadMap) -> None:
    table = evaluate_tests([car_following(), cut_in()], town, reference, seed=0)
    data = table.to_json()
    straight = data["rows"]["straight"]
    assert straight == {
        "planned": 2,
        "unplanned": 0,
        "report": {"tests": 4, "failed": 2},  # the cut-in fails both its egos
        "random": {"tests": 4, "failed": 0},
    }
    assert data["rows"]["intersection"]["report"] == {"tests": 0, "failed": 0}
    assert data["classes"]["report"] == {"collision": 1, "near_miss": 1}
    assert data["violations"]["report"] == {"cut_in": 1, "rear_end": 1}  # V2 cut in; V1 ran up on it
    assert data["ratio"] is None and len(data["verdicts"]) == 8
    text = table.render()
    assert "straight            2        2      4               2       0" in text
    assert "collision while the ego moved" in text and "moved across into a vehicle going its way" in text
    assert "report-derived / random failures: no random failures" in text
    assert len(table.walls) == 8 and "wall time per test: median" in text


def test_scenario_sites_that_could_not_be_planned_are_counted_not_dropped() -> None:
    table = TestsTable()
    table.add_unplanned("crossing_8", "intersection", "junction:x_north", "unsat", "these facts conflict")
    table.add_unplanned("t_3", "t_junction", "-", "no fitting site", "no T-junction")
    data = table.to_json()
    assert data["rows"]["intersection"] == {
        "planned": 0,
        "unplanned": 1,
        "report": {"tests": 0, "failed": 0},
        "random": {"tests": 0, "failed": 0},
    }
    assert data["unplanned"][1] == {
        "scenario": "t_3",
        "kind": "t_junction",
        "site": "-",
        "why": "no fitting site",
        "reason": "no T-junction",
    }
    text = table.render()
    assert "total               2        0      0               0       0" in text
    assert "not planned: 2 scenario-site(s), no tests (unsat 1, no fitting site 1)" in text
