"""The harness with the real reference FMU (fmpy) and real SUMO (libsumo) on hand-made plans."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from sovarc.compiler.vehicles import MODELS
from sovarc.targets.fmu import EgoFmu, FmuInterfaceError, run_target, run_test_results, run_tests

from tests.targets.fmu.fake_fmu import write_fmu
from tests.targets.fmu.plans import car_following, crossing, cut_in, slow_ahead, stopped_ahead

pytestmark = pytest.mark.slow  # runs SUMO and an FMU


def _by_ego(verdicts: list) -> dict:
    return {v.facts["ego"]: v for v in verdicts}


def test_the_reference_ego_passes_car_following(reference: EgoFmu) -> None:
    verdicts = _by_ego(run_tests(car_following(), reference))
    assert set(verdicts) == {"V1", "V2"}  # every vehicle takes its turn as the ego
    for verdict in verdicts.values():
        assert verdict.passed, verdict.dumps()
        assert [f.check for f in verdict.findings] == ["collision", "goal", "min_ttc", "harsh_braking"]
    follower = verdicts["V1"].facts
    assert follower["ended"] == "goal" and follower["peak_braking"] < 2.5


def test_the_reference_ego_fails_a_planted_cut_in(reference: EgoFmu) -> None:
    verdict = _by_ego(run_tests(cut_in(), reference))["V1"]
    assert not verdict.passed
    collision = next(f for f in verdict.findings if f.check == "collision")
    assert not collision.passed and "collided with V2" in collision.message
    facts = verdict.facts
    assert facts["failure"] == "collision" and facts["violation"] == "rear_end"
    assert facts["collision"]["kind"] == "rear_end"
    assert facts["collision"]["other"] == "V2" and facts["collision"]["ego_speed"] > 5.0
    assert facts["peak_braking"] == pytest.approx(7.0)  # it did brake as hard as it could
    assert 0.8 < facts["collision"]["time"] < 2.0


def test_runs_are_deterministic(reference: EgoFmu) -> None:
    first = run_test_results(crossing(), reference, seed=4)
    second = run_test_results(crossing(), reference, seed=4)
    assert [r.verdict.to_json() for r in first] == [r.verdict.to_json() for r in second]
    for a, b in zip(first, second, strict=True):
        for name, track in a.run.tracks.items():
            other = b.run.tracks[name]
            assert np.array_equal(track.x, other.x) and np.array_equal(track.heading, other.heading)
        assert np.array_equal(a.run.commands, b.run.commands)


def test_run_target_writes_a_verdict_and_a_picture_per_test(tmp_path: Path, reference: EgoFmu) -> None:
    verdicts = run_target(cut_in(), tmp_path, reference)
    written = sorted(p.name for p in tmp_path.iterdir())
    stem = "fmu-straight_rear_end_stopped_traffic-road_-ave2_ave2-ego-"
    assert written == [f"{stem}V1.json", f"{stem}V1.png", f"{stem}V2.json", f"{stem}V2.png"]
    assert json.loads((tmp_path / f"{stem}V1.json").read_text()) == verdicts[0].to_json()
    assert (tmp_path / f"{stem}V1.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_mismatched_fmu_is_refused_before_anything_runs(tmp_path: Path) -> None:
    bad = write_fmu(tmp_path / "bad.fmu", drop=("steer",))
    with pytest.raises(FmuInterfaceError, match="steer"):
        run_tests(car_following(), bad)


def test_a_participant_that_never_moved_holds_and_one_behind_it_waits_without_failing(reference: EgoFmu) -> None:
    verdicts = _by_ego(run_tests(stopped_ahead(), reference))
    holder = verdicts["V2"]
    assert holder.passed, holder.dumps()
    goal = next(f for f in holder.findings if f.check == "goal")
    assert "hold its position" in goal.message and holder.facts["max_speed"] == 0.0
    follower = verdicts["V1"]  # its goal lies past V2, which never moves: waiting behind it is right
    assert follower.passed, follower.dumps()
    assert follower.facts["ended"] == "budget" and follower.facts["blocked_by"] == "V2"
    assert "held up by V2" in next(f for f in follower.findings if f.check == "goal").message


@pytest.mark.parametrize("kind", ["van", "pickup", "bus", "truck", "motorcycle", "bicycle"])
def test_the_reference_ego_sees_every_kind_ahead_and_keeps_behind_it(kind: str, reference: EgoFmu) -> None:
    """A slow road user of each kind ahead in the ego's lane, drawn with its own body, which the plan
    runs into: the ego must see it (a narrow cyclist or motorcycle as surely as a bus) and wait behind."""
    verdict = _by_ego(run_tests(slow_ahead(MODELS[kind].body), reference))["V1"]
    assert verdict.passed, verdict.dumps()
    assert verdict.facts["ended"] == "budget" and verdict.facts["blocked_by"] == "V2"
    assert verdict.facts["peak_braking"] > 1.0  # it slowed for it: the plan's own speed never drops
