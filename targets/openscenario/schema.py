"""The bundled ASAM schemas (see schemas/NOTICE.md) and validation against them with lxml."""

from __future__ import annotations

import functools
from pathlib import Path

from lxml import etree
from sovarc.targets.openscenario.versions import Dialect

SCHEMAS = Path(__file__).resolve().parent / "schemas"

# OpenDRIVE header revMinor -> the schema file that validates it.
OPENDRIVE_SCHEMAS: dict[int, str] = {
    4: "1.4/OpenDRIVE_1.4H.xsd",
    5: "1.5/OpenDRIVE_1.5.xsd",
    6: "1.6/opendrive_16_core.xsd",
    7: "1.7/opendrive_17_core.xsd",
}
MAX_ERRORS = 5


@functools.cache
def _load(path: Path) -> etree.XMLSchema:
    return etree.XMLSchema(etree.parse(str(path)))


def openscenario_schema(dialect: Dialect) -> etree.XMLSchema:
    return _load(SCHEMAS / "openscenario" / dialect.schema_folder / "OpenSCENARIO.xsd")


def opendrive_schema(rev_minor: int) -> etree.XMLSchema | None:
    """The schema of OpenDRIVE 1.<rev_minor>, or None when none is bundled (1.8 needs XML Schema 1.1)."""
    name = OPENDRIVE_SCHEMAS.get(rev_minor)
    return None if name is None else _load(SCHEMAS / "opendrive" / name)


def schema_errors(schema: etree.XMLSchema, doc: etree._ElementTree) -> list[str]:
    """The first few validation errors as 'line N: message', or [] when the document is valid."""
    if schema.validate(doc):
        return []
    return [f"line {e.line}: {e.message}" for e in list(schema.error_log)[:MAX_ERRORS]]
