"""A crash on an earlier leg of a three-point turn (lower/midturn.py): on a street of one lane each
way (built with netconvert) a car that starts to turn in legs swings across the oncoming lane on
its first forward leg, and meets the car coming the other way there."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.compiler.lower import sites_for, stagings_on
from sovarc.compiler.maps import load_map
from sovarc.compiler.plan import Plan
from sovarc.compiler.staging import stage_on_site
from sovarc.targets import openscenario
from sovarc.targets.sumo import check

from tests.compiler.synth.street import STRUCK_TURNING, scenario, street
from tests.targets.openscenario.plans import emit_files

pytestmark = pytest.mark.slow  # netconvert builds the street

# V1 starts its U-turn and its front strikes the side of V2, coming the other way.
ONCOMING = STRUCK_TURNING.replace("striker V2\n    victim V1", "striker V1\n    victim V2").replace(
    "vehicle V2 {\n    heading east", "vehicle V2 {\n    heading west"
)


def _plan(text: str) -> Plan:
    road_map = load_map(street())
    staged, notes, matches = sites_for(scenario(text), road_map, roads=1)
    return stage_on_site(staged, notes, road_map, matches[0])


def test_the_turner_strikes_an_oncoming_car_on_its_first_forward_leg() -> None:
    assert ONCOMING != STRUCK_TURNING
    plan = _plan(ONCOMING)
    assert any("met on leg 1 of its 3-leg turn (forward)" in note for note in plan.notes)
    turner = plan.trajectory("V1")
    before = [s for s in turner.samples if s.t <= plan.impact.time]
    assert min(s.speed for s in before) >= 0.0  # never reversed before the crash
    assert turner.at(plan.impact.time).speed > 0.0
    assert 20.0 < turner.at(plan.impact.time).heading < 90.0  # swinging across, not yet facing back
    verdict = check(plan)
    assert verdict.passed, verdict.dumps()
    impact = verdict.facts["impact"]
    assert impact["striker_face"].startswith("front") and "left" in impact["victim_face"]


def test_the_crash_on_the_first_leg_passes_the_openscenario_oracle(tmp_path: Path) -> None:
    plan = _plan(ONCOMING)
    verdict = openscenario.check(emit_files(plan, tmp_path).xosc, plan)
    assert verdict.passed, verdict.dumps()
    assert verdict.facts["striker"] == "V1" and "left" in verdict.facts["victim_face"]


def test_the_turner_stands_where_its_leg_ends_after_the_crash() -> None:
    plan = _plan(ONCOMING)
    last = plan.trajectory("V1").samples[-1]
    assert last.speed == 0.0  # the crash ends the turn: no reverse leg is driven after it


def test_a_turn_met_on_its_last_leg_is_staged_as_before() -> None:
    # V2 coming up behind strikes V1 on its last leg: the earlier legs are never tried
    road_map = load_map(street())
    staged, notes, matches = sites_for(scenario(), road_map, roads=1)
    lowered = next(stagings_on(staged, matches[0], road_map, notes))
    assert not any("met on leg" in note for note in lowered.notes)
    assert lowered.routes["V1"].manoeuvres[0].gears == (1, -1, 1)
