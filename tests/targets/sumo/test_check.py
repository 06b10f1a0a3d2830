"""The SUMO oracle replays emitted folders in real SUMO and judges them."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.dsl.errors import OracleError
from sovarc.targets.sumo import check, emit

from tests.targets.sumo.plans import BROKEN, SCENES, wrong_way_near_miss

pytestmark = pytest.mark.slow

# scene -> (what saw the collision, striker face, victim face)
EXPECTED = {
    "t_bone": ("sumo", "front-left", "right"),  # V1 arrives at 83 degrees: its front-left corner first
    "rear_end": ("sumo", "front", "rear"),
    "head_on": ("sumo", "front", "front"),
    "sideswipe": ("sumo", "front-left", "right"),
    "pedestrian": ("bodies", "front", "left"),  # SUMO does not see a mid-block pedestrian strike
}


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_good_plans_pass(scene: str) -> None:
    verdict = check(SCENES[scene]())
    assert verdict.passed, verdict.dumps()
    assert [f.check for f in verdict.findings] == ["xsd", "replay", "collision", "pair", "impact_angle", "lane_lines"]
    detected_by, striker_face, victim_face = EXPECTED[scene]
    (crash,) = verdict.facts["collisions"]
    assert crash["detected_by"] == detected_by
    impact = verdict.facts["impact"]
    assert (impact["striker_face"], impact["victim_face"]) == (striker_face, victim_face)
    assert abs(impact["time"] - verdict.facts["planned_impact_time"]) <= 0.5


def test_no_collision_is_caught() -> None:
    verdict = check(BROKEN["no_collision"]())
    assert {f.check for f in verdict.failures} == {"collision", "pair", "impact_angle"}
    assert verdict.failures[0].message == "no collision: V1 and V2 come no closer than 4.00 m (at t=3.50 s)"


def test_wrong_pair_is_caught() -> None:
    verdict = check(BROKEN["wrong_pair"]())
    (failure,) = verdict.failures
    assert failure.check == "pair"
    assert failure.message == "V1 and V3 collide first, before striker V1 and victim V2"
    assert failure.time == pytest.approx(1.7)


def test_wrong_angle_is_caught() -> None:
    verdict = check(BROKEN["wrong_angle"]())
    (failure,) = verdict.failures
    assert failure.check == "impact_angle"
    assert failure.message.startswith("V1's left side meets V2's front")
    assert verdict.facts["impact"]["striker_face"] == "left"


def test_lane_crossing_is_caught() -> None:
    verdict = check(BROKEN["lane_crossing"]())
    (failure,) = verdict.failures
    assert (failure.check, failure.time) == ("lane_lines", 0.0)
    assert failure.message == "V1 enters lane ave2_1, which its actions do not allow"


def test_check_replays_an_emitted_folder_without_changing_it(tmp_path: Path) -> None:
    plan = SCENES["rear_end"]()
    emit(plan, tmp_path)
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    assert check(plan, tmp_path).passed
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before  # SUMO's outputs went elsewhere


def test_check_of_a_folder_without_a_scenario_says_so(tmp_path: Path) -> None:
    with pytest.raises(OracleError, match=r"has no scenario\.sumocfg"):
        check(SCENES["rear_end"](), tmp_path)


def test_verdict_json_names_reasons_and_times() -> None:
    data = check(BROKEN["wrong_pair"]()).to_json()
    assert data["passed"] is False
    pair = data["findings"][3]
    assert (pair["check"], pair["passed"], pair["time"]) == ("pair", False, 1.7)
    assert pair["message"] == "V1 and V3 collide first, before striker V1 and victim V2"


def test_a_sumo_report_without_contact_is_not_a_collision() -> None:
    verdict = check(wrong_way_near_miss())
    assert verdict.facts["sumo_collisions_without_contact"] == [["V1", "V2"]]
    collision = verdict.findings[2]
    assert (collision.check, collision.passed) == ("collision", False)
    assert collision.message.startswith("no collision: V1 and V2 come no closer than 3.00 m")
    assert "SUMO reports one, but its bodies never touch" in collision.message
