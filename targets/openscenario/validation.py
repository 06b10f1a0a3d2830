"""Schema findings: the .xosc against the OpenSCENARIO XSD its header names, the road network
against the OpenDRIVE XSD of its header's revision."""

from __future__ import annotations

from pathlib import Path

from lxml import etree
from sovarc.targets.openscenario.readback import ScenarioFile
from sovarc.targets.openscenario.schema import opendrive_schema, openscenario_schema, schema_errors
from sovarc.targets.openscenario.versions import VERSIONS, dialect_of_revision
from sovarc.targets.verdict import Finding


def xsd_finding(scenario: ScenarioFile) -> Finding:
    d = dialect_of_revision(*scenario.rev)
    if d is None:
        version = ".".join(map(str, scenario.rev))
        known = ", ".join(VERSIONS)
        return Finding("xsd", False, f"OpenSCENARIO {version} is not a version the oracle knows ({known})")
    errors = schema_errors(openscenario_schema(d), scenario.doc)
    if errors:
        return Finding("xsd", False, f"not valid OpenSCENARIO {d.version}: " + "; ".join(errors))
    return Finding("xsd", True, f"valid against the ASAM OpenSCENARIO {d.version} schema")


def xodr_finding(scenario: ScenarioFile) -> tuple[Finding, Path | None]:
    if not scenario.logic_file:
        return Finding("xodr", False, "no RoadNetwork/LogicFile: the scenario names no road network"), None
    path = (scenario.path.parent / scenario.logic_file).resolve()
    if not path.is_file():
        return Finding("xodr", False, f"road network {scenario.logic_file} not found beside the scenario"), None
    try:
        doc = etree.parse(str(path))
    except etree.XMLSyntaxError as e:
        return Finding("xodr", False, f"{path.name} is not XML: {e}"), path
    header = doc.getroot().find("header")
    if doc.getroot().tag != "OpenDRIVE" or header is None:
        return Finding("xodr", False, f"{path.name} is not OpenDRIVE (no <OpenDRIVE><header>)"), path
    rev_major, rev_minor = header.get("revMajor", "?"), header.get("revMinor", "?")
    schema = opendrive_schema(int(rev_minor)) if rev_major == "1" and rev_minor.isdigit() else None
    if schema is None:
        message = f"{path.name}: OpenDRIVE {rev_major}.{rev_minor} not validated: no schema for it that lxml can load"
        return Finding("xodr", True, message), path
    errors = schema_errors(schema, doc)
    if errors:
        return Finding("xodr", False, f"{path.name} is not valid OpenDRIVE 1.{rev_minor}: " + "; ".join(errors)), path
    return Finding("xodr", True, f"{path.name} valid against the OpenDRIVE 1.{rev_minor} schema"), path
