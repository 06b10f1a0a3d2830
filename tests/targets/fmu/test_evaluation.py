"""`eval tests`: failures per road kind, report-derived against random, in the paper's Table 6 form."""

from __future__ import annotations

import pytest
from sovarc.targets.fmu import EgoFmu, evaluate_tests

from tests.targets.fmu.plans import car_following, cut_in

pytestmark = pytest.mark.slow  # runs SUMO and an FMU


def test_table_counts_failures_per_kind_and_method(reference: EgoFmu) -> None:
    table = evaluate_tests([car_following(), cut_in()], reference, seed=0)
    data = table.to_json()
    straight = data["rows"]["straight"]
    assert straight["plans"] == 2
    assert straight["report"] == {"tests": 4, "failed": 2}  # the cut-in fails both its egos
    assert straight["random"]["tests"] == 4
    assert data["rows"]["intersection"] == {
        "plans": 0,
        "report": {"tests": 0, "failed": 0},
        "random": {"tests": 0, "failed": 0},
    }
    assert data["classes"]["report"] == {"rear_end": 1, "struck_from_behind": 1}
    assert len(data["verdicts"]) == 8
    text = table.render()
    assert "straight            2      4               2" in text
    assert "collision: the ego ran into the back of another" in text
