"""Loading road networks: SUMO and OpenDRIVE files, and every way a file can be wrong."""

from __future__ import annotations

import hashlib
import shutil
from pathlib import Path

import pytest
from sovarc.compiler.maps import RoadMap, load_map
from sovarc.dsl.errors import InputError

from tests.compiler.maps.conftest import OPENDRIVE, TOWN
from tests.conftest import requires_shared

pytestmark = pytest.mark.slow  # needs SUMO


def test_the_town_loads_with_its_provenance(town: RoadMap) -> None:
    assert town.format == "sumo"
    assert town.made_by.startswith("Eclipse SUMO netconvert ")
    assert town.converted_by is None
    assert town.sha256 == hashlib.sha256(TOWN.read_bytes()).hexdigest()
    assert town.name == "town.net.xml"
    assert len([e for e in town.net.getEdges() if not e.isSpecial()]) == 43


def test_an_old_osm_network_names_the_netconvert_that_wrote_it(osm: RoadMap) -> None:
    assert osm.made_by == "Eclipse SUMO netconvert 1_0_1+0645-93703db"


def test_every_opendrive_file_converts(opendrive: dict[str, RoadMap]) -> None:
    assert sorted(opendrive) == sorted(p.stem for p in OPENDRIVE.glob("*.xodr"))
    assert len(opendrive) >= 6
    for name, road_map in opendrive.items():
        assert road_map.format == "opendrive", name
        assert road_map.made_by.startswith("OpenDRIVE 1."), name
        assert road_map.converted_by and road_map.converted_by.startswith("Eclipse SUMO netconvert"), name
        assert any(not e.isSpecial() for e in road_map.net.getEdges()), name


def test_opendrive_keeps_its_coordinates(opendrive: dict[str, RoadMap]) -> None:
    # --offset.disable-normalization: the network is where the OpenDRIVE file puts it
    net = opendrive["multi_intersections"].net
    assert list(net.getLocationOffset()) == [0.0, 0.0]
    (xmin, ymin), _ = net.getBBoxXY()
    assert xmin == pytest.approx(50.0) and ymin == pytest.approx(-240.0)  # normalizing would give (0, 0)


BAD_FILES: dict[str, tuple[bytes | None, str]] = {
    "missing.net.xml": (None, "map file not found"),
    "empty.net.xml": (b"  \n", "map file is empty"),
    "text.net.xml": (b"hello", "not an XML file"),
    "binary.net.xml": (b"\x00\x01\x02\xff", "not an XML file"),
    "routes.net.xml": (b"<routes/>", "not a SUMO network: its root element is <routes>, expected <net>"),
    "broken.net.xml": (b'<net version="1.20"><edge id="e" from="a"', "not a readable SUMO network"),
    "noversion.net.xml": (b"<net></net>", "not a readable SUMO network: missing attribute"),
    "town.osm": (b"<osm/>", "unknown map format '.osm': expected one of .net.xml, .xodr"),
    "net.xodr": (b"<net/>", "not an OpenDRIVE file: its root element is <net>"),
    "headless.xodr": (b"<OpenDRIVE><header/></OpenDRIVE>", "netconvert failed: Error: Attribute 'revMajor'"),
    "noroads.xodr": (b'<OpenDRIVE><header revMajor="1" revMinor="4"/></OpenDRIVE>', "netconvert failed: Error:"),
}


@pytest.mark.parametrize("name", sorted(BAD_FILES))
def test_a_bad_file_is_an_input_error_naming_it(tmp_path: Path, name: str) -> None:
    content, message = BAD_FILES[name]
    path = tmp_path / name
    if content is not None:
        path.write_bytes(content)
    with pytest.raises(InputError) as caught:
        load_map(path)
    rendered = caught.value.render()
    assert rendered.startswith(f"{path}: error: "), rendered
    assert message in rendered
    assert "\n" not in rendered


def test_a_directory_and_a_truncated_network_are_input_errors(tmp_path: Path) -> None:
    (tmp_path / "dir.net.xml").mkdir()
    with pytest.raises(InputError, match="is a directory"):
        load_map(tmp_path / "dir.net.xml")
    cut = tmp_path / "cut.net.xml"
    cut.write_bytes(TOWN.read_bytes()[:50_000])
    with pytest.raises(InputError, match=r"cut.net.xml: error: not a readable SUMO network: line \d+"):
        load_map(cut)


@requires_shared
def test_an_opendrive_file_converts_from_any_folder(tmp_path: Path) -> None:
    copy = tmp_path / "with space" / "straight.xodr"
    copy.parent.mkdir()
    shutil.copy(OPENDRIVE / "straight_500m.xodr", copy)
    road_map = load_map(copy)
    assert road_map.path == copy and road_map.format == "opendrive"
    assert list(tmp_path.rglob("*.net.xml")) == []  # the converted network lived in a temp dir only
