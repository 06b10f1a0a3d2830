"""The .xosc document alone (no road network, no SUMO): golden files, schema validity for every
version, determinism, environment, ego marker and the reference-point conversion."""

from __future__ import annotations

import itertools
import math
from dataclasses import replace

import pytest
from lxml import etree
from sovarc.compiler.plan import Plan
from sovarc.compiler.vehicles import CAR
from sovarc.dsl.errors import Severity
from sovarc.dsl.ir import Environment, Lighting, Weather
from sovarc.targets.openscenario import VERSIONS, choose_ego
from sovarc.targets.openscenario.bodies import compass_of, osc_body, osc_heading
from sovarc.targets.openscenario.emit import build_document
from sovarc.targets.openscenario.provenance import Options
from sovarc.targets.openscenario.schema import openscenario_schema, schema_errors
from sovarc.targets.openscenario.versions import dialect

from tests.conftest import Golden
from tests.targets.openscenario.conftest import FIXTURES
from tests.targets.openscenario.plans import CASES, with_samples


def document(plan: Plan, version: str = "1.3", ego: str | None = None) -> tuple[bytes, list]:
    d = dialect(version)
    return build_document(plan, "town.xodr", Options(d.version, choose_ego(plan, ego)), d)


def parse(data: bytes) -> etree._Element:
    return etree.fromstring(data)


@pytest.mark.parametrize("case", sorted(CASES))
def test_golden_xosc(case: str, golden: Golden) -> None:
    data, _ = document(CASES[case]())
    golden.check(FIXTURES / f"{case}.xosc", data.decode("utf-8"))


def test_golden_xosc_version_1_0(golden: Golden) -> None:
    data, _ = document(CASES["t_bone"](), "1.0")
    golden.check(FIXTURES / "t_bone_1.0.xosc", data.decode("utf-8"))


@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("case", sorted(CASES))
def test_every_version_validates_against_its_schema(case: str, version: str) -> None:
    data, _ = document(CASES[case](), version)
    root = parse(data)
    assert root.find("FileHeader").get("revMinor") == version.split(".")[1]
    assert schema_errors(openscenario_schema(dialect(version)), etree.ElementTree(root)) == []


def test_the_same_plan_gives_the_same_bytes() -> None:
    assert document(CASES["left_turn"]())[0] == document(CASES["left_turn"]())[0]


def test_an_unknown_version_is_refused_by_name() -> None:
    with pytest.raises(ValueError, match=r"version '2.0' is not supported; choose one of 1.0, 1.1, 1.2, 1.3"):
        dialect("2.0")
    assert dialect("1.1.1").version == "1.1"


def test_version_differences_are_written() -> None:
    old, new = parse(document(CASES["t_bone"](), "1.0")[0]), parse(document(CASES["t_bone"](), "1.3")[0])
    assert old.find(".//FollowTrajectoryAction/Trajectory") is not None
    assert old.find(".//TrajectoryRef") is None
    assert new.find(".//FollowTrajectoryAction/TrajectoryRef/Trajectory") is not None
    assert old.find(".//Event").get("priority") == "overwrite"
    assert new.find(".//Event").get("priority") == "override"
    assert old.find(".//Sun").get("intensity") is not None and new.find(".//Sun").get("illuminance") is not None


def test_provenance_and_impact_are_declared() -> None:
    plan = CASES["t_bone"]()
    root = parse(document(plan)[0])
    params = {p.get("name"): p.get("value") for p in root.iter("ParameterDeclaration")}
    assert params["sovarc_scenario"] == "intersection_red_light_runner_side"
    assert params["sovarc_map"] == "town.net.xml" and params["sovarc_map_sha256"] == plan.map_sha256
    assert len(params["sovarc_ir_sha256"]) == 64
    assert (params["sovarc_striker"], params["sovarc_victim"], params["sovarc_crash_type"]) == ("V1", "V2", "side")
    assert float(params["sovarc_impact_time"]) == plan.impact.time
    assert params["sovarc_osc_version"] == "1.3" and params["sovarc_ego"] == "V1"
    assert "sovarc_speed_limit" in params and params["sovarc_speed_limit"] == "70 km/h"
    assert root.find("FileHeader").get("date") == "2000-01-01T00:00:00"  # fixed: no clock is read
    assert root.find("RoadNetwork/LogicFile").get("filepath") == "town.xodr"


def test_stop_trigger_fires_shortly_after_the_impact() -> None:
    plan = CASES["rear_end"]()
    root = parse(document(plan)[0])
    stop = root.find("Storyboard/StopTrigger//SimulationTimeCondition")
    assert stop.get("rule") == "greaterThan"
    assert plan.impact.time < float(stop.get("value")) <= plan.impact.time + 3.0


def test_ego_is_the_striker_by_default_first_and_marked() -> None:
    plan = CASES["left_turn"]()  # V2 strikes V1
    root = parse(document(plan)[0])
    objects = root.findall("Entities/ScenarioObject")
    assert [o.get("name") for o in objects] == ["V2", "V1"]
    types = {o.get("name"): o.find(".//Property[@name='type']").get("value") for o in objects}
    assert types == {"V2": "ego_vehicle", "V1": "simulation"}
    roles = {o.get("name"): o.find(".//Property[@name='sovarc_crash_role']").get("value") for o in objects}
    assert roles == {"V2": "striker", "V1": "victim"}


def test_ego_can_be_chosen_and_a_wrong_one_is_named() -> None:
    plan = CASES["left_turn"]()
    root = parse(document(plan, ego="V1")[0])
    assert root.find("Entities/ScenarioObject").get("name") == "V1"
    with pytest.raises(ValueError, match=r"ego 'V9' is not a participant of the plan \(V1, V2\)"):
        choose_ego(plan, "V9")


def test_pedestrian_striker_hands_the_ego_to_a_vehicle() -> None:
    plan = CASES["pedestrian"]()
    swapped = replace(plan, impact=replace(plan.impact, striker="P1", victim="V1"))
    assert choose_ego(swapped) == "V1"


def test_headings_turn_compass_into_math_angles() -> None:
    assert osc_heading(0.0) == pytest.approx(math.pi / 2)  # north = +y
    assert osc_heading(90.0) == pytest.approx(0.0)  # east = +x
    assert osc_heading(180.0) == pytest.approx(3 * math.pi / 2)
    assert osc_heading(270.0) == pytest.approx(math.pi)
    for compass in (0.0, 45.0, 123.4, 359.0):
        assert compass_of(osc_heading(compass)) == pytest.approx(compass)


def test_vehicles_are_placed_by_the_rear_axle_not_the_front_bumper() -> None:
    plan = CASES["t_bone"]()  # V1 drives north; its first sample is its front bumper
    first = plan.trajectory("V1").samples[0]
    root = parse(document(plan)[0])
    world = root.find("Storyboard/Init/Actions/Private[@entityRef='V1']//TeleportAction//WorldPosition")
    body, _ = osc_body(CAR)
    assert float(world.get("x")) == pytest.approx(first.x, abs=1e-3)
    assert float(world.get("y")) == pytest.approx(first.y - body.front_offset, abs=1e-3)
    assert float(world.get("h")) == pytest.approx(math.pi / 2, abs=1e-4)
    box = root.find("Entities/ScenarioObject[@name='V1']//BoundingBox")
    # The box reaches exactly from the rear bumper to the front bumper.
    assert float(box.find("Center").get("x")) + CAR.length / 2 == pytest.approx(body.front_offset)
    assert float(box.find("Dimensions").get("length")) == CAR.length


def test_pedestrians_are_placed_by_their_centre() -> None:
    plan = CASES["pedestrian"]()
    first = plan.trajectory("P1").samples[0]
    root = parse(document(plan)[0])
    world = root.find("Storyboard/Init/Actions/Private[@entityRef='P1']//WorldPosition")
    assert (float(world.get("x")), float(world.get("y"))) == pytest.approx((first.x, first.y), abs=1e-3)
    assert root.find("Entities/ScenarioObject[@name='P1']/Pedestrian") is not None


def _with_environment(plan: Plan, environment: Environment) -> Plan:
    return replace(plan, scenario=replace(plan.scenario, environment=environment))


def _messages(notes: list, severity: Severity) -> list[str]:
    return [n.message for n in notes if n.severity is severity]


def test_street_lights_are_reported_as_unsupported_with_their_span() -> None:
    plan = CASES["pedestrian"]()  # lighting dark, street_lights
    data, notes = document(plan)
    (warning,) = [n for n in notes if n.severity is Severity.WARNING]
    assert "street_lights" in warning.message and "no road lighting" in warning.message
    assert warning.span is not None and warning.span.line == 5
    assert b"<!-- sovarc warning: lighting street_lights" in data
    assert parse(data).find(".//TimeOfDay").get("dateTime").endswith("T23:00:00")


def test_weather_the_version_cannot_say_is_reported() -> None:
    env = Environment((Weather.RAINY, Weather.SNOWY, Weather.WINDY), (Lighting.DAYLIGHT,))
    plan = _with_environment(CASES["t_bone"](), env)
    old = _messages(document(plan, "1.0")[1], Severity.WARNING)
    assert any("one precipitation type; rain written" in m for m in old)
    assert any("OpenSCENARIO 1.0 has no wind" in m for m in old)
    data, notes = document(plan, "1.1")
    assert not any("wind" in m for m in _messages(notes, Severity.WARNING))
    weather = parse(data).find(".//Weather")
    assert weather.find("Wind") is not None
    assert weather.find("Precipitation").get("precipitationType") == "rain"


def test_unknown_environment_writes_no_environment_action() -> None:
    plan = _with_environment(CASES["t_bone"](), Environment())
    for version in VERSIONS:
        data, notes = document(plan, version)
        assert parse(data).find(".//EnvironmentAction") is None
        assert any("player's defaults apply" in m for m in _messages(notes, Severity.NOTE))


def test_fog_rain_and_night_become_fog_precipitation_and_a_dark_sun() -> None:
    env = Environment((Weather.FOGGY, Weather.RAINY), (Lighting.DARK,))
    root = parse(document(_with_environment(CASES["t_bone"](), env))[0])
    assert float(root.find(".//Fog").get("visualRange")) <= 200
    assert root.find(".//Precipitation").get("precipitationType") == "rain"
    assert float(root.find(".//Sun").get("elevation")) < 0
    assert root.find(".//RoadCondition").get("wetness") == "wetWithPuddles"


def test_a_participant_without_trajectory_is_reported() -> None:
    plan = CASES["t_bone"]()
    v3 = replace(plan.scenario.participants[0], id="V3")
    scenario = replace(plan.scenario, participants=(*plan.scenario.participants, v3))
    _, notes = document(replace(plan, scenario=scenario))
    assert "V3 has no trajectory in the plan: not in the scenario" in _messages(notes, Severity.WARNING)


def test_headings_along_a_trajectory_never_jump_a_full_turn() -> None:
    """East is h = 0: a car weaving around east must not flip between 0.02 and 6.26 (a player would spin it)."""
    plan = with_samples(CASES["t_bone"](), "V2", lambda s: replace(s, heading=89.0 if round(s.t * 10) % 2 else 91.0))
    root = parse(document(plan)[0])
    headings = [float(w.get("h")) for w in root.findall(".//ManeuverGroup[@name='V2_group']//WorldPosition")]
    assert max(abs(b - a) for a, b in itertools.pairwise(headings)) < 0.04  # 2 degrees, not 358
    assert headings[0] == pytest.approx(osc_heading(91.0), abs=1e-4)
