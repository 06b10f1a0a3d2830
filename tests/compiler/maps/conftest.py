"""Maps shared by the map-layer tests, each loaded once per session (loading needs SUMO)."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from sovarc.compiler.maps import RoadMap, load_map
from sovarc.compiler.maps.netconvert import netconvert_path
from sovarc.dsl import Scenario, parse

from tests.conftest import EXAMPLES, SHARED, requires_shared

TOWN = EXAMPLES / "maps" / "town.net.xml"
OPENDRIVE = SHARED / "data" / "opendrive"
SCENARIOS = sorted((EXAMPLES / "scenarios").glob("*.sov"))


def osm_path() -> Path:
    import sumo

    return Path(sumo.SUMO_HOME) / "tools" / "game" / "DRT" / "osm.net.xml"


def generate(tmp_path: Path, *options: str, seed: int = 1) -> RoadMap:
    """A network SUMO's netgenerate makes (seeded, so the same every run), written to `tmp_path`."""
    netgenerate = Path(netconvert_path()).with_name("netgenerate")
    out = tmp_path / "g.net.xml"
    command = [str(netgenerate), *options, "--seed", str(seed), "--no-warnings", "true", "-o", out.name]
    subprocess.run(command, cwd=tmp_path, check=True, capture_output=True)
    return load_map(out)


def scenario(name: str) -> Scenario:
    return parse((EXAMPLES / "scenarios" / f"{name}.sov").read_text(encoding="utf-8"))


@pytest.fixture(scope="session")
def town() -> RoadMap:
    return load_map(TOWN)


@pytest.fixture(scope="session")
def osm() -> RoadMap:
    return load_map(osm_path())


@pytest.fixture(scope="session")
def opendrive() -> dict[str, RoadMap]:
    if not OPENDRIVE.is_dir():
        pytest.skip(requires_shared.kwargs["reason"])
    return {path.stem: load_map(path) for path in sorted(OPENDRIVE.glob("*.xodr"))}
