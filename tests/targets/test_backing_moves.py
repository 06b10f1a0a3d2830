"""The parked and reversing moves through every target: each example compiles to SUMO, OpenSCENARIO
and the FMU harness (`-t all`) on the example town and on a CARLA town, and passes every oracle,
esmini's too when it is found; the reference ego meets the reversing car and sees it."""

from __future__ import annotations

import functools
from pathlib import Path

import pytest
from sovarc.compiler.pipeline import Options, run_pipeline
from sovarc.dsl import parse
from sovarc.targets.openscenario.player import PlayerError, esmini_path

from tests.conftest import EXAMPLES, SHARED, requires_shared

pytestmark = pytest.mark.slow

MOVES = (
    "straight_reverse_into_stopped_rear_end",
    "straight_back_out_of_parking_rear_end",
    "straight_parked_car_struck_rear_end",
)
TOWN = EXAMPLES / "maps" / "town.net.xml"
TOWN01 = SHARED / "data" / "opendrive" / "carla" / "Town01.xodr"
TARGETS = ("sumo", "openscenario", "fmu")


def _esmini() -> bool:
    try:
        esmini_path()
    except PlayerError:
        return False
    return True


@functools.cache
def _results(name: str, map_path: Path, out: Path) -> list:
    scenario = parse((EXAMPLES / "scenarios" / f"{name}.sov").read_text())
    options = Options(map=map_path, roads=1, targets=TARGETS, out_dir=out)
    slots, _ = run_pipeline(scenario, start="assume", options=options)
    return slots.results


def _check(name: str, map_path: Path, out: Path) -> None:
    results = _results(name, map_path, out)
    assert results and all(r.plan is not None for r in results), [r.error for r in results]
    for result in results:
        for target in ("sumo", "openscenario"):
            verdict = result.verdicts[target]
            assert verdict.passed, verdict.dumps()
        checks = {f.check for f in result.verdicts["openscenario"].findings}
        if _esmini():
            assert {"player_run", "player_collision"} <= checks
        sumo_checks = {f.check for f in result.verdicts["sumo"].findings}
        assert ("on_road" in sumo_checks) == (name != "straight_parked_car_struck_rear_end")
        tests = result.verdicts["fmu"]
        assert tests, "every vehicle that never reverses takes a turn as the ego"
        assert "V1" not in {t.facts["ego"] for t in tests} or name.endswith("struck_rear_end")
        for test in tests:  # the ego is never the one at fault: struck standing, or held up
            assert next(f for f in test.findings if f.check == "collision").passed, test.dumps()


@pytest.mark.parametrize("name", MOVES)
def test_on_the_town(name: str, tmp_path_factory: pytest.TempPathFactory) -> None:
    _check(name, TOWN, tmp_path_factory.mktemp(name))


@requires_shared
@pytest.mark.parametrize("name", MOVES)
def test_on_a_carla_town(name: str, tmp_path_factory: pytest.TempPathFactory) -> None:
    _check(name, TOWN01, tmp_path_factory.mktemp(name))


def test_the_reference_ego_sees_a_car_backing_out_in_front_of_it(tmp_path: Path) -> None:
    """The ego drives along the lane a car backs into: it brakes for it and stands before it is struck."""
    (result,) = _results("straight_back_out_of_parking_rear_end", TOWN, tmp_path)
    (test,) = result.verdicts["fmu"]
    assert test.facts["ego"] == "V2"
    assert test.facts["collision"]["other"] == "V1" and test.facts["collision"]["other_speed"] < 0.0
    assert test.facts["collision"]["ego_speed"] < 0.5  # it stopped for the reversing car
    assert test.facts["peak_braking"] > 1.0  # it braked for it: it saw it
