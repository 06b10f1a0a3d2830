"""Every new participant kind compiled to all targets: its example on the bundled town and on a CARLA town.

One example per kind (examples/scenarios): each staged with `-t all`, the SUMO and OpenSCENARIO verdicts
(esmini included, where it is found) must pass and the FMU tests must run; the emitted files must carry
the kind (SUMO's vClass and size, OpenSCENARIO's vehicleCategory and BoundingBox). On the CARLA towns:
Town01 has no four-way junction, so the intersection examples run on Town06 (Town04's OpenDRIVE file
does not validate against the ASAM schema, whatever the scenario).
"""

from __future__ import annotations

import json
from pathlib import Path
from xml.etree import ElementTree

import pytest
from sovarc.compiler.cli import main
from sovarc.compiler.vehicles import MODELS
from sovarc.dsl import parse

from tests.conftest import EXAMPLES, SHARED, requires_shared
from tests.targets.openscenario.test_player import real_esmini

pytestmark = pytest.mark.slow  # lowering, synthesis, SUMO, esmini and the FMU per example

# kind -> its example
EXAMPLE = {
    "bus": "intersection_bus_left_turn_cyclist_side",
    "bicycle": "intersection_cyclist_go_across_side",
    "truck": "intersection_truck_left_turn_side",
    "motorcycle": "straight_motorcycle_rear_ended",
    "van": "straight_van_lane_change_rear_end",
    "pickup": "t_junction_pickup_left_turn_out_side",
}
CARLA = SHARED / "data" / "opendrive" / "carla"
# OpenSCENARIO's word for a kind where it is not the IR's
CATEGORY = {"pickup": "car", "motorcycle": "motorbike"}


@pytest.fixture(autouse=True)
def _esmini(monkeypatch: pytest.MonkeyPatch) -> None:
    found = real_esmini()
    if found:
        monkeypatch.setenv("ESMINI", found)


def _compile(kind: str, out: Path, road_map: Path | None = None) -> list[Path]:
    """The example of `kind` through every target on one site; returns its site folders."""
    source = EXAMPLES / "scenarios" / f"{EXAMPLE[kind]}.sov"
    args = [str(source), "-t", "all", "--roads", "1", "-o", str(out)]
    main([*args, *(["-m", str(road_map)] if road_map else [])])
    sites = [p for p in out.iterdir() if p.is_dir()]
    assert sites, f"{kind}: nothing staged"
    return sites


def _check(kind: str, site: Path) -> None:
    for target in ("sumo", "openscenario"):
        verdict = json.loads((site / f"verdict-{target}.json").read_text(encoding="utf-8"))
        failed = [f["message"] for f in verdict["findings"] if not f["passed"]]
        assert verdict["passed"], f"{kind} on {site.name}, {target}: {failed}"
    fmu = json.loads((site / "verdict-fmu.json").read_text(encoding="utf-8"))
    assert len(fmu) == 2 and all(v["findings"] for v in fmu)  # each vehicle took its turn as the ego
    body = MODELS[kind].body
    scenario = parse((EXAMPLES / "scenarios" / f"{EXAMPLE[kind]}.sov").read_text(encoding="utf-8"))
    pid = next(p.id for p in scenario.participants if str(getattr(p.kind, "value", "")) == kind)
    types = ElementTree.parse(site / "sumo" / "scenario.add.xml").getroot()
    vtype = next(t for t in types.iter("vType") if t.get("id") == f"{pid}.type")
    assert vtype.get("vClass") == body.vclass and vtype.get("guiShape") == body.gui_shape
    assert float(vtype.get("length", 0)) == body.length and float(vtype.get("width", 0)) == body.width
    assert float(vtype.get("accel", 0)) == MODELS[kind].drive_accel
    xosc = ElementTree.parse(site / "openscenario" / "scenario.xosc").getroot()
    vehicle = next(v for v in xosc.iter("Vehicle") if v.get("name") == pid)
    assert vehicle.get("vehicleCategory") == CATEGORY.get(kind, kind)
    dimensions = vehicle.find("BoundingBox/Dimensions")
    assert dimensions is not None
    assert float(dimensions.get("length", 0)) == body.length and float(dimensions.get("width", 0)) == body.width


@pytest.mark.parametrize("kind", sorted(EXAMPLE))
def test_each_kind_compiles_to_every_target_on_the_town(kind: str, tmp_path: Path) -> None:
    for site in _compile(kind, tmp_path):
        _check(kind, site)


@requires_shared
@pytest.mark.parametrize("kind", sorted(EXAMPLE))
def test_each_kind_compiles_to_every_target_on_a_carla_town(kind: str, tmp_path: Path) -> None:
    town = "Town06" if EXAMPLE[kind].startswith("intersection") else "Town01"
    for site in _compile(kind, tmp_path, CARLA / f"{town}.xodr"):
        _check(kind, site)
