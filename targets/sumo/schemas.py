"""Validate emitted files against SUMO's own XSD schemas, shipped with SUMO in `data/xsd`.

SUMO_HOME is found as sumolib and SUMO's tools find it: the SUMO_HOME environment variable,
else the `eclipse-sumo` wheel's `sumo` package.
"""

from __future__ import annotations

import functools
import os
from pathlib import Path

from lxml import etree
from sovarc.dsl.errors import OracleError

# document root -> its schema file
SCHEMAS = {
    "sumoConfiguration": "sumoConfiguration.xsd",
    "additional": "additional_file.xsd",
    "routes": "routes_file.xsd",
    "fcd-export": "fcd_file.xsd",
    "net": "net_file.xsd",
}


@functools.cache
def xsd_folder() -> Path:
    candidates = []
    if home := os.environ.get("SUMO_HOME"):
        candidates.append(Path(home))
    try:
        import sumo  # the eclipse-sumo wheel, asked only where SUMO_HOME does not say

        candidates.append(Path(sumo.SUMO_HOME))
    except ImportError:
        pass
    for home in candidates:
        if (home / "data" / "xsd" / "fcd_file.xsd").is_file():
            return home / "data" / "xsd"
    raise OracleError("SUMO's XSD schemas not found: install SUMO (`pip install eclipse-sumo`) or set SUMO_HOME")


@functools.cache
def _schema(name: str) -> etree.XMLSchema:
    return etree.XMLSchema(etree.parse(str(xsd_folder() / name)))


def validate(path: Path) -> list[str]:
    """Schema errors of one SUMO file (empty when valid), each as 'file:line: message'."""
    try:
        document = etree.parse(str(path))
    except etree.XMLSyntaxError as exc:
        return [f"{path.name}: not well-formed XML: {exc}"]
    root = etree.QName(document.getroot()).localname
    if root not in SCHEMAS:
        return [f"{path.name}: no SUMO schema for a <{root}> document"]
    schema = _schema(SCHEMAS[root])
    if schema.validate(document):
        return []
    return [f"{path.name}:{e.line}: {e.message}" for e in schema.error_log]


def validate_folder(folder: Path, network: bool = False) -> list[str]:
    """Schema errors of every SUMO file the target wrote in `folder` (the network too, if asked)."""
    errors: list[str] = []
    for path in sorted(folder.iterdir()):
        if path.name.startswith("scenario.") or (network and path.name.endswith(".net.xml")):
            errors += validate(path)
    return errors
