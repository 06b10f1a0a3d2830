"""The SUMO target's emitted folder: golden files, byte-stable, valid against SUMO's own schemas."""

from __future__ import annotations

import dataclasses
from pathlib import Path
from xml.etree import ElementTree

import pytest
from sovarc.dsl.errors import InputError, UnsupportedError
from sovarc.targets.sumo import emit
from sovarc.targets.sumo.schemas import validate, validate_folder

from tests.conftest import Golden
from tests.targets.sumo.plans import SCENES, TOWN

FIXTURES = Path(__file__).parent / "fixtures"
WRITTEN = ("scenario.add.xml", "scenario.fcd.xml", "scenario.sumocfg")


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_emitted_files_match_golden(scene: str, tmp_path: Path, golden: Golden) -> None:
    config = emit(SCENES[scene](), tmp_path)
    assert config == tmp_path / "scenario.sumocfg"
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([*WRITTEN, "town.net.xml"])
    assert (tmp_path / "town.net.xml").read_bytes() == TOWN.read_bytes()  # the network travels with it
    (FIXTURES / scene).mkdir(parents=True, exist_ok=True)
    for name in WRITTEN:
        golden.check(FIXTURES / scene / name, (tmp_path / name).read_text(encoding="utf-8"))


def test_same_plan_gives_the_same_bytes(tmp_path: Path) -> None:
    emit(SCENES["t_bone"](), tmp_path / "a")
    emit(SCENES["t_bone"](), tmp_path / "b")
    emit(SCENES["t_bone"](), tmp_path / "b")  # over an earlier emit
    for name in (*WRITTEN, "town.net.xml"):
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes(), name


@pytest.mark.parametrize("scene", sorted(SCENES))
def test_files_are_valid_against_sumo_schemas(scene: str, tmp_path: Path) -> None:
    emit(SCENES[scene](), tmp_path)
    assert validate_folder(tmp_path, network=True) == []


def test_schema_check_reports_an_invalid_file(tmp_path: Path) -> None:
    emit(SCENES["rear_end"](), tmp_path)
    fcd = tmp_path / "scenario.fcd.xml"
    fcd.write_text(fcd.read_text(encoding="utf-8").replace('speed="22.000"', 'speed="-22.000"', 1), encoding="utf-8")
    errors = validate(fcd)
    assert len(errors) == 1 and errors[0].startswith("scenario.fcd.xml:") and "speed" in errors[0]


def _params(path: Path) -> dict[str, str]:
    return {p.get("key", ""): p.get("value", "") for p in ElementTree.parse(path).getroot().iter("param")}


def test_weather_light_and_crash_facts_are_kept_as_params(tmp_path: Path) -> None:
    emit(SCENES["t_bone"](), tmp_path)
    facts = _params(tmp_path / "scenario.add.xml")
    assert facts["sovarc.weather"] == "snowy"
    assert facts["sovarc.lighting"] == "dark"
    assert (facts["sovarc.crash_type"], facts["sovarc.striker"], facts["sovarc.victim"]) == ("side", "V1", "V2")
    assert facts["sovarc.lanes"] == "ave2_1 :x_oak_16_1 ave3_1"  # the last participant's type


def test_types_have_the_participants_real_size(tmp_path: Path) -> None:
    emit(SCENES["pedestrian"](), tmp_path)
    types = {t.get("id"): t.attrib for t in ElementTree.parse(tmp_path / "scenario.add.xml").getroot().iter("vType")}
    assert (types["V1.type"]["vClass"], types["V1.type"]["length"], types["V1.type"]["width"]) == (
        "passenger",
        "4.60",
        "1.80",
    )
    assert (types["P1.type"]["vClass"], types["P1.type"]["length"], types["P1.type"]["width"]) == (
        "pedestrian",
        "0.50",
        "0.60",
    )


def test_config_turns_collision_detection_on_at_the_plan_step(tmp_path: Path) -> None:
    config = ElementTree.parse(emit(SCENES["t_bone"](), tmp_path)).getroot()
    options = {o.tag: o.get("value") for section in config for o in section}
    assert options["collision.check-junctions"] == "true"
    assert options["collision.action"] == "warn"
    assert options["step-length"] == "0.10"
    assert options["device.fcd-replay.files"] == "scenario.fcd.xml"


def test_vehicle_ending_in_a_junction_names_the_lane_it_enters_after_the_run(tmp_path: Path) -> None:
    emit(SCENES["t_bone"](), tmp_path)
    steps = ElementTree.parse(tmp_path / "scenario.fcd.xml").getroot().findall("timestep")
    end = float(ElementTree.parse(tmp_path / "scenario.sumocfg").getroot().find("./time/end").get("value"))
    assert [v.get("lane") for v in steps[-2]] == [":x_oak_12_0", "ave3_1"]  # the last sample
    assert float(steps[-1].get("time")) > end  # never played, but completes V1's route
    assert [(v.get("id"), v.get("lane")) for v in steps[-1]] == [("V1", "oak2_0")]


def test_a_changed_map_is_refused(tmp_path: Path) -> None:
    plan = SCENES["t_bone"]()
    plan = dataclasses.replace(plan, network=dataclasses.replace(plan.network, sha256="0" * 64))
    with pytest.raises(InputError, match="map file changed since the plan was made"):
        emit(plan, tmp_path)


def test_trajectories_sampled_at_different_times_are_refused(tmp_path: Path) -> None:
    plan = SCENES["rear_end"]()
    v1 = plan.trajectory("V1")
    short = dataclasses.replace(v1, samples=v1.samples[:-1])
    plan = dataclasses.replace(plan, trajectories=(short, plan.trajectory("V2")))
    with pytest.raises(UnsupportedError, match="V2 is not sampled at the same times as V1"):
        emit(plan, tmp_path)
