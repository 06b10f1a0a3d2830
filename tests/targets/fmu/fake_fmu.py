"""FMU files that only carry a modelDescription.xml: enough for interface validation, which reads
nothing else. Variables come from the real interface table, then are dropped or altered."""

from __future__ import annotations

import zipfile
from pathlib import Path
from xml.sax.saxutils import quoteattr

from sovarc.targets.fmu.interface import VARIABLES, Variable


def variable_xml(v: Variable, vr: int, *, causality: str | None = None, kind: str | None = None, unit: str = "") -> str:
    kind = kind or v.kind.value
    start = ' start="0"' if (causality or v.causality.value) in ("input", "parameter") else ""
    unit_attr = f" unit={quoteattr(unit)}" if unit else ""
    tunable = ' variability="tunable"' if (causality or v.causality.value) == "parameter" else ""
    return (
        f'<ScalarVariable name="{v.name}" valueReference="{vr}" causality="{causality or v.causality.value}"{tunable}>'
        f"<{kind}{start}{unit_attr}/></ScalarVariable>"
    )


def write_fmu(
    path: Path,
    *,
    drop: tuple[str, ...] = (),
    change: dict[str, dict[str, str]] | None = None,
    fmi_version: str = "2.0",
) -> Path:
    """An FMU whose variables are the interface's, without `drop`, with `change[name]` attributes."""
    change = change or {}
    rows = [variable_xml(v, vr, **change.get(v.name, {})) for vr, v in enumerate(VARIABLES) if v.name not in drop]
    description = (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        f'<fmiModelDescription fmiVersion="{fmi_version}" modelName="Fake" guid="{{fake}}">'
        '<CoSimulation modelIdentifier="Fake"/>'
        f"<ModelVariables>{''.join(rows)}</ModelVariables>"
        "<ModelStructure/></fmiModelDescription>\n"
    )
    with zipfile.ZipFile(path, "w") as archive:
        archive.writestr("modelDescription.xml", description)
    return path
