"""The ego interface: the FMI 2.0 co-simulation variables a driving system under test must have.

The harness steps the FMU every `STEP` seconds. Before each step it sets the inputs (the ego's own
state, its route ahead, the objects around it); after the step it reads the outputs (acceleration and
steering) and drives the ego with them through a kinematic bicycle model. INTERFACE.md documents the
frames and units; this module is their one definition, and `validate_fmu` checks a user's FMU against it.
"""

from __future__ import annotations

import re
import zipfile
from dataclasses import dataclass
from enum import StrEnum
from pathlib import Path
from xml.etree import ElementTree

from sovarc.dsl.errors import Diagnostic, InputError
from sovarc.dsl.span import Span

STEP = 0.05  # s, the communication step: 20 Hz
MAX_OBJECTS = 8  # object slots, nearest first
PATH_POINTS = 12  # route points ahead of the ego
PATH_SPACING = 4.0  # m between route points along the route: 4, 8, ... 48 m ahead
PERCEPTION_RANGE = 100.0  # m: objects farther than this from the ego are not reported


class Causality(StrEnum):
    PARAMETER = "parameter"
    INPUT = "input"
    OUTPUT = "output"


class Kind(StrEnum):
    REAL = "Real"
    INTEGER = "Integer"


@dataclass(frozen=True)
class Variable:
    name: str
    causality: Causality
    kind: Kind
    unit: str  # '' for a count
    description: str
    required: bool = True  # parameters are optional: set when the FMU has them


def _ego() -> list[Variable]:
    p, i = Causality.PARAMETER, Causality.INPUT
    return [
        Variable("ego_length", p, Kind.REAL, "m", "body length", required=False),
        Variable("ego_width", p, Kind.REAL, "m", "body width", required=False),
        Variable("ego_wheelbase", p, Kind.REAL, "m", "distance between the axles", required=False),
        Variable("ego_rear_axle", p, Kind.REAL, "m", "from the front bumper back to the rear axle", required=False),
        Variable("ego_x", i, Kind.REAL, "m", "front-bumper centre, map x"),
        Variable("ego_y", i, Kind.REAL, "m", "front-bumper centre, map y"),
        Variable("ego_heading", i, Kind.REAL, "deg", "compass heading: 0 north, 90 east"),
        Variable("ego_speed", i, Kind.REAL, "m/s", "speed along the heading (never negative)"),
        Variable("target_speed", i, Kind.REAL, "m/s", "the speed the route asks for here"),
        Variable("goal_distance", i, Kind.REAL, "m", "along the route to the goal; negative once past it"),
    ]


def _path() -> list[Variable]:
    found = []
    ahead = f"route point k = 1..{PATH_POINTS}, k·{PATH_SPACING:g} m ahead along the route"
    for k in range(1, PATH_POINTS + 1):
        found.append(Variable(f"path_x_{k}", Causality.INPUT, Kind.REAL, "m", f"{ahead}, ego frame forward"))
        found.append(Variable(f"path_y_{k}", Causality.INPUT, Kind.REAL, "m", f"{ahead}, ego frame left"))
    return found


OBJECT_FIELDS: tuple[tuple[str, str, str], ...] = (
    ("x", "m", "body centre, ego frame forward"),
    ("y", "m", "body centre, ego frame left"),
    ("heading", "deg", "heading relative to the ego's, positive to the left"),
    ("speed", "m/s", "speed along its own heading (negative while it reverses)"),
    ("length", "m", "body length"),
    ("width", "m", "body width"),
)


def _objects() -> list[Variable]:
    found = [Variable("obj_count", Causality.INPUT, Kind.INTEGER, "", f"objects reported, 0..{MAX_OBJECTS}")]
    for k in range(1, MAX_OBJECTS + 1):
        for field, unit, text in OBJECT_FIELDS:
            found.append(
                Variable(
                    f"obj_{k}_{field}",
                    Causality.INPUT,
                    Kind.REAL,
                    unit,
                    f"object k = 1..{MAX_OBJECTS}, nearest first: {text}",
                )
            )
    return found


def _outputs() -> list[Variable]:
    o = Causality.OUTPUT
    return [
        Variable("accel", o, Kind.REAL, "m/s2", "commanded longitudinal acceleration (clamped to [-8, 4])"),
        Variable("steer", o, Kind.REAL, "rad", "front-wheel angle, positive to the left (clamped to ±0.6)"),
    ]


VARIABLES: tuple[Variable, ...] = tuple(_ego() + _path() + _objects() + _outputs())
BY_NAME: dict[str, Variable] = {v.name: v for v in VARIABLES}

# Unit spellings accepted as the same unit, when an FMU declares units at all.
_UNIT_ALIASES = {"m/s2": {"m/s2", "m/s^2", "m/(s.s)", "m.s-2"}, "m/s": {"m/s", "m.s-1"}, "deg": {"deg", "°"}}
# FMI 2.0 types the harness can write or read for each kind.
_FMI2_TYPES = {Kind.REAL: {"Real"}, Kind.INTEGER: {"Integer"}}


class FmuInterfaceError(InputError):
    """A user's FMU does not match the ego interface; one diagnostic per problem."""

    stage = "check"


@dataclass(frozen=True)
class EgoFmu:
    """A validated ego FMU: where it is and the value reference of each interface variable it has."""

    path: Path
    model_name: str
    model_identifier: str
    guid: str
    refs: dict[str, int]  # interface name -> value reference (optional parameters only when present)


def validate_fmu(path: str | Path) -> EgoFmu:
    """Check an FMU's modelDescription.xml against the ego interface; raise FmuInterfaceError listing every problem."""
    from fmpy import read_model_description

    source = Path(path)
    span = Span.whole_file(str(source))

    def fail(messages: list[str]) -> FmuInterfaceError:
        return FmuInterfaceError([Diagnostic(m, span) for m in messages])

    if not source.is_file():
        raise fail(["FMU not found"])
    fmi_version = _fmi_version(source)
    if fmi_version is None:
        raise fail(["not an FMU: a zip archive with a modelDescription.xml was expected"])
    if fmi_version != "2.0":
        raise fail([f"FMI {fmi_version} FMU: the ego harness runs FMI 2.0 co-simulation FMUs"])
    try:
        md = read_model_description(str(source), validate=False)
    except Exception as exc:  # fmpy raises whatever zipfile or lxml raise
        raise fail([f"not a readable FMU: {type(exc).__name__}: {exc}"]) from None
    if md.coSimulation is None:
        raise fail(["the FMU has no CoSimulation interface (model exchange only); export it for co-simulation"])
    problems = _check_variables({v.name: v for v in md.modelVariables})
    if problems:
        raise fail(problems)
    refs = {v.name: v.valueReference for v in md.modelVariables if v.name in BY_NAME}
    return EgoFmu(source, md.modelName, md.coSimulation.modelIdentifier, md.guid, refs)


def _fmi_version(source: Path) -> str | None:
    """The fmiVersion of the archive's modelDescription.xml root, or None when there is none to read."""
    try:
        with zipfile.ZipFile(source) as archive, archive.open("modelDescription.xml") as description:
            for _event, element in ElementTree.iterparse(description, events=("start",)):
                return element.get("fmiVersion", "")
    except (zipfile.BadZipFile, KeyError, ElementTree.ParseError, OSError):
        return None
    return None


def _check_variables(found: dict[str, object]) -> list[str]:
    missing = [v for v in VARIABLES if v.required and v.name not in found]
    problems = []
    if missing:
        listed = ", ".join(f"{v.name} ({v.causality}, {v.kind}{', ' + v.unit if v.unit else ''})" for v in missing)
        problems.append(f"missing {len(missing)} variable(s) of the ego interface: {listed}")
    for spec in VARIABLES:
        var = found.get(spec.name)
        if var is None:
            continue
        causality, kind, unit = getattr(var, "causality", None), getattr(var, "type", None), getattr(var, "unit", None)
        if causality != spec.causality.value:
            problems.append(f"{spec.name} has causality '{causality}', the ego interface needs '{spec.causality}'")
        if kind not in _FMI2_TYPES[spec.kind]:
            problems.append(f"{spec.name} is of type {kind}, the ego interface needs {spec.kind}")
        if unit and spec.unit and unit not in _UNIT_ALIASES.get(spec.unit, {spec.unit}):
            problems.append(f"{spec.name} is declared in '{unit}', the ego interface gives '{spec.unit}'")
    return problems


def interface_table() -> str:
    """The interface as a Markdown table (INTERFACE.md embeds it; a test keeps the two in step)."""
    rows = ["| name | causality | type | unit | meaning |", "|---|---|---|---|---|"]
    for v in VARIABLES:
        name = re.sub(r"_\d+(?=_|$)", "_k", v.name)
        optional = " (optional)" if not v.required else ""
        row = f"| `{name}` | {v.causality}{optional} | {v.kind} | {v.unit or '-'} | {v.description} |"
        if row not in rows:
            rows.append(row)
    return "\n".join(rows) + "\n"
