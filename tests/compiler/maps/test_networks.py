"""The network a plan carries: the map in both formats, each conversion made once and cached."""

from __future__ import annotations

import hashlib
import json
from dataclasses import replace
from pathlib import Path

import pytest
from sovarc.compiler.maps import network_of, networks, with_opendrive
from sovarc.compiler.plan import Network, dump_plan, plan_from_json

from tests.compiler.maps.conftest import OPENDRIVE, TOWN
from tests.conftest import requires_shared
from tests.targets.fmu.plans import car_following


@pytest.fixture
def cache(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> Path:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    return tmp_path / "sovarc" / "networks"


def _no_netconvert(*_: object, **__: object) -> None:
    raise AssertionError("netconvert ran again")


def test_a_sumo_map_is_its_own_network() -> None:
    network = network_of(TOWN)
    assert network == Network(str(TOWN), hashlib.sha256(TOWN.read_bytes()).hexdigest(), str(TOWN), None)


def test_the_plan_json_carries_the_network_and_reads_back() -> None:
    plan = car_following()
    data = json.loads(dump_plan(plan))
    assert data["map"] == plan.map and data["map_sha256"] == plan.map_sha256
    assert data["network"] == {"sumo": plan.network.sumo, "opendrive": None}
    assert plan_from_json(data).network == plan.network
    assert dump_plan(plan_from_json(data)) == dump_plan(plan)
    del data["network"]  # a plan written before plans carried their network: its SUMO map is its network
    assert plan_from_json(data).network == plan.network
    data["map"] = "roads.xodr"
    with pytest.raises(ValueError, match="does not name the SUMO network it was planned on"):
        plan_from_json(data)


@requires_shared
@pytest.mark.slow  # netconvert
def test_an_opendrive_map_is_converted_once_into_the_cache(cache: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    xodr = OPENDRIVE / "straight_500m.xodr"
    network = network_of(xodr)
    sha = hashlib.sha256(xodr.read_bytes()).hexdigest()
    assert (network.map, network.sha256, network.opendrive) == (str(xodr), sha, str(xodr))
    converted = Path(network.sumo)
    assert converted.parent.parent == cache and converted.parent.name.startswith(sha + "-")
    assert converted.name == "straight_500m.net.xml" and converted.read_bytes().lstrip().startswith(b"<?xml")
    monkeypatch.setattr(networks, "convert_opendrive", _no_netconvert)
    assert network_of(xodr) == network
    assert [p.name for p in converted.parent.iterdir()] == ["straight_500m.net.xml"]  # no temp file left


@pytest.mark.slow  # netconvert
def test_a_sumo_map_gets_its_opendrive_file_from_the_cache(cache: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    network = with_opendrive(network_of(TOWN))
    xodr = Path(network.opendrive or "")
    assert xodr.name == "town.xodr" and xodr.parent.parent == cache
    text = xodr.read_text(encoding="utf-8")
    assert "from town.net.xml (sovarc)" in text and "generated on" not in text
    monkeypatch.setattr(networks, "run_netconvert", _no_netconvert)
    assert with_opendrive(network_of(TOWN)) == network
    assert with_opendrive(network) is network
    assert replace(network, opendrive=None) == network_of(TOWN)
