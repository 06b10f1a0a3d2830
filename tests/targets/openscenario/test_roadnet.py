"""The road network written beside the scenario, and the bundled schemas."""

from __future__ import annotations

import hashlib
from dataclasses import replace
from pathlib import Path

import pytest
from lxml import etree
from sovarc.compiler.maps import network_of, with_opendrive
from sovarc.compiler.maps.networks import as_opendrive_14
from sovarc.compiler.plan import Network
from sovarc.dsl.errors import InputError, UnsupportedError
from sovarc.targets.openscenario import emit_files
from sovarc.targets.openscenario.oracle import judge
from sovarc.targets.openscenario.readback import read_scenario
from sovarc.targets.openscenario.roadnet import write_road_network
from sovarc.targets.openscenario.schema import (
    OPENDRIVE_SCHEMAS,
    SCHEMAS,
    opendrive_schema,
    openscenario_schema,
    schema_errors,
)
from sovarc.targets.openscenario.validation import xodr_finding
from sovarc.targets.openscenario.versions import VERSIONS, dialect

from tests.conftest import SHARED, requires_shared
from tests.targets.openscenario.conftest import Emitter
from tests.targets.openscenario.plans import CASES, TOWN

ESMINI_MAP = SHARED / "data" / "opendrive" / "straight_500m.xodr"

# What netconvert writes for a network with a geographic offset and a crosswalk (trimmed): OpenDRIVE
# 1.4 in its header, a 1.5 header <offset> and 1.5 outline attributes in its body.
NETCONVERT_15_MARKUP = """<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE>
    <header revMajor="1" revMinor="4" name="" version="1.00" north="10.00" south="0.00" east="10.00" west="0.00">
        <geoReference><![CDATA[+proj=utm +zone=33 +ellps=WGS84 +datum=WGS84 +units=m +no_defs]]></geoReference>
        <offset x="398790.46" y="5809246.45" z="-0.00" hdg="0"/>
    </header>
    <road name="" length="10.0" id="1" junction="-1">
        <planView><geometry s="0" x="0" y="5" hdg="0" length="10.0"><line/></geometry></planView>
        <lanes><laneSection s="0"><center><lane id="0" type="none" level="false"/></center></laneSection></lanes>
        <objects>
            <object id="c1" type="crosswalk" s="0" t="0" hdg="0" length="4" width="6">
                <outline id="0" fillType="concrete" outer="true" closed="false" laneType="border">
                    <cornerLocal u="2" v="-3" z="0" height="0" id="0"/>
                    <cornerLocal u="2" v="3" z="0" height="0" id="1"/>
                </outline>
            </object>
        </objects>
    </road>
</OpenDRIVE>
"""


def opendrive_map(xodr: Path) -> Network:
    """An OpenDRIVE map's network as its plans carry it (this target reads only the .xodr)."""
    sha256 = hashlib.sha256(xodr.read_bytes()).hexdigest()
    return Network(str(xodr), sha256, sumo="(the SUMO conversion, not read here)", opendrive=str(xodr))


def test_every_bundled_schema_loads_and_has_its_notice() -> None:
    for version in VERSIONS:
        assert openscenario_schema(dialect(version)) is not None
    for rev_minor in OPENDRIVE_SCHEMAS:
        assert opendrive_schema(rev_minor) is not None
    assert opendrive_schema(8) is None  # XML Schema 1.1: lxml cannot load it
    notice = (SCHEMAS / "NOTICE.md").read_text(encoding="utf-8")
    assert "ASAM license terms" in notice and "www.asam.net/license.html" in notice


def test_a_file_that_is_not_a_map_is_an_input_error(tmp_path: Path) -> None:
    bogus = tmp_path / "roads.txt"
    bogus.write_text("no roads here", encoding="utf-8")
    with pytest.raises(InputError, match=r"expected a \.net\.xml or \.xodr file"):
        network_of(bogus)
    with pytest.raises(InputError, match=r"expected a \.net\.xml or \.xodr file"):
        write_road_network(Network(str(bogus), "0" * 64, str(bogus), str(bogus)), tmp_path / "out")


def test_a_sumo_map_without_its_opendrive_file_is_not_converted_here(tmp_path: Path) -> None:
    with pytest.raises(UnsupportedError, match=r"carries no OpenDRIVE file: the compiler provides it"):
        write_road_network(Network(str(TOWN), "0" * 64, str(TOWN)), tmp_path)
    assert not list(tmp_path.iterdir())


@requires_shared
def test_an_opendrive_map_is_copied_byte_for_byte(tmp_path: Path) -> None:
    written = write_road_network(opendrive_map(ESMINI_MAP), tmp_path)
    assert written.name == "straight_500m.xodr"
    assert written.read_bytes() == ESMINI_MAP.read_bytes()


def test_netconverts_opendrive_15_markup_is_made_the_14_it_declares() -> None:
    before = etree.fromstring(NETCONVERT_15_MARKUP.encode()).getroottree()
    errors = " ".join(schema_errors(opendrive_schema(4), before))
    assert "Element 'offset': This element is not expected" in errors
    assert "Element 'outline', attribute 'fillType'" in errors
    text = as_opendrive_14(NETCONVERT_15_MARKUP)
    after = etree.fromstring(text.encode()).getroottree()
    assert schema_errors(opendrive_schema(4), after) == []
    offset = after.getroot().find("header/userData[@code='offset']/offset")
    assert (offset.get("x"), offset.get("y"), offset.get("hdg")) == ("398790.46", "5809246.45", "0")
    assert "<outline>" in text and '<cornerLocal u="2" v="3" z="0" height="0"/>' in text
    geometry = "road/planView/geometry"
    assert after.getroot().find(geometry).attrib == before.getroot().find(geometry).attrib
    assert as_opendrive_14(text) == text


@pytest.mark.slow  # needs SUMO
class TestSumoNetworkConverted:
    def test_valid_opendrive_without_a_date(self, emitted: Emitter) -> None:
        _, files = emitted("t_bone")
        assert files.xodr.name == "town.xodr"
        doc = etree.parse(str(files.xodr))
        header = doc.getroot().find("header")
        assert (header.get("revMajor"), header.get("revMinor")) == ("1", "4")
        assert header.get("date") is None
        text = files.xodr.read_text(encoding="utf-8")
        assert "generated on" not in text and "from town.net.xml (sovarc)" in text
        assert schema_errors(opendrive_schema(4), doc) == []

    def test_the_same_network_gives_the_same_bytes(self, emitted: Emitter, tmp_path: Path) -> None:
        _, files = emitted("t_bone")
        again = write_road_network(with_opendrive(network_of(TOWN)), tmp_path)
        assert again.read_bytes() == files.xodr.read_bytes()

    def test_coordinates_are_the_networks_own(self, emitted: Emitter) -> None:
        """netconvert keeps the SUMO coordinates (no offset), so plan points are OpenDRIVE points."""
        _, files = emitted("t_bone")
        header = etree.parse(str(files.xodr)).getroot().find("header")
        bounds = [float(header.get(k)) for k in ("west", "south", "east", "north")]
        location = etree.parse(str(TOWN)).getroot().find("location")
        assert location.get("netOffset") == "0.00,0.00"
        assert bounds == pytest.approx([float(v) for v in location.get("convBoundary").split(",")], abs=0.01)

    def test_the_oracle_names_an_invalid_road_network(self, emitted: Emitter, tmp_path: Path) -> None:
        _, files = emitted("t_bone")
        (tmp_path / "scenario.xosc").write_bytes(files.xosc.read_bytes())
        text = files.xodr.read_text(encoding="utf-8").replace('<road name="" length=', '<road name="" lenght=', 1)
        (tmp_path / "town.xodr").write_text(text, encoding="utf-8")
        finding, _ = xodr_finding(read_scenario(tmp_path / "scenario.xosc"))
        assert not finding.passed
        assert finding.message.startswith("town.xodr is not valid OpenDRIVE 1.4: line ")
        assert "lenght" in finding.message

    def test_a_users_own_invalid_map_is_reported_not_judged(self, emitted: Emitter, tmp_path: Path) -> None:
        """A user's .xodr travels unchanged: its schema errors are its own (CARLA's Town04 has some), named in
        the finding, which passes; sovarc's conversion of a SUMO map is held to the schema (above)."""
        _, files = emitted("t_bone")
        (tmp_path / "scenario.xosc").write_bytes(files.xosc.read_bytes())
        text = files.xodr.read_text(encoding="utf-8").replace('<road name="" length=', '<road name="" lenght=', 1)
        (tmp_path / "town.xodr").write_text(text, encoding="utf-8")
        scenario = read_scenario(tmp_path / "scenario.xosc")
        theirs = next(f for f in judge(scenario, users_map=True)[0] if f.check == "xodr")
        ours = next(f for f in judge(scenario)[0] if f.check == "xodr")
        assert theirs.passed and theirs.message.startswith("the user's map, copied unchanged; town.xodr is not valid")
        assert not ours.passed


@requires_shared
@pytest.mark.parametrize("xodr", sorted(p.name for p in (SHARED / "data" / "opendrive").glob("*.xodr")))
def test_an_opendrive_map_travels_with_the_scenario_and_validates(xodr: str, tmp_path: Path) -> None:
    plan = replace(CASES["rear_end"](), network=opendrive_map(SHARED / "data" / "opendrive" / xodr))
    files = emit_files(plan, tmp_path)
    assert files.xodr.name == xodr
    finding, _ = xodr_finding(read_scenario(files.xosc))
    assert finding.passed and finding.message.startswith(f"{xodr} valid against the OpenDRIVE 1.")


@pytest.mark.slow  # netconvert on SUMO's DRT city (OpenStreetMap, about 8 s)
def test_a_city_with_a_geographic_offset_and_crosswalks_converts_to_valid_opendrive(tmp_path: Path) -> None:
    import sumo

    city = Path(sumo.SUMO_HOME) / "tools" / "game" / "DRT" / "osm.net.xml"
    doc = etree.parse(str(write_road_network(with_opendrive(network_of(city)), tmp_path)))
    assert schema_errors(opendrive_schema(4), doc) == []
    header = doc.getroot().find("header")
    assert header.find("userData[@code='offset']/offset").get("x") == "398790.46"  # the net's -netOffset
    assert len(doc.getroot().findall(".//object[@type='crosswalk']/outline")) > 100
    location = etree.parse(str(city)).getroot().find("location")
    bounds = [float(header.get(k)) for k in ("west", "south", "east", "north")]
    assert bounds == pytest.approx([float(v) for v in location.get("convBoundary").split(",")], abs=0.01)
