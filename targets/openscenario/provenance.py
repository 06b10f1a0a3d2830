"""FileHeader and the scenario's ParameterDeclarations: where the file came from, and the crash it encodes.

The `sovarc_impact_*`, `sovarc_striker`, `sovarc_victim` and `sovarc_crash_type` parameters are
what the oracle reads back to re-check the kinematics; the others record provenance.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from importlib import metadata
from pathlib import Path

from lxml import etree
from sovarc.compiler.plan import Plan
from sovarc.dsl.ir import Scenario, Unknown
from sovarc.dsl.jsonform import to_json
from sovarc.targets.openscenario.versions import Dialect
from sovarc.targets.openscenario.xml import TIME_DIGITS, el, num

# No clock is read: the same inputs give the same bytes. The header date is fixed.
HEADER_DATE = "2000-01-01T00:00:00"

# Parameters the oracle needs, by name.
IMPACT_TIME = "sovarc_impact_time"
IMPACT_X = "sovarc_impact_x"
IMPACT_Y = "sovarc_impact_y"
IMPACT_RADIUS = "sovarc_impact_radius"
STRIKER = "sovarc_striker"
VICTIM = "sovarc_victim"
CRASH_TYPE = "sovarc_crash_type"
SCENARIO = "sovarc_scenario"
SITE = "sovarc_site"
EGO = "sovarc_ego"
ORACLE_PARAMETERS = (IMPACT_TIME, IMPACT_X, IMPACT_Y, IMPACT_RADIUS, STRIKER, VICTIM, CRASH_TYPE)


@dataclass(frozen=True)
class Options:
    """What the user chose for this emission; recorded in the file."""

    version: str
    ego: str


def sovarc_version() -> str:
    try:
        return metadata.version("sovarc")
    except metadata.PackageNotFoundError:
        return "unknown"


def ir_sha256(scenario: Scenario) -> str:
    """The hash of the scenario's facts: its JSON form, keys sorted (comments and spans do not count)."""
    text = json.dumps(to_json(scenario), sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def file_header(plan: Plan, dialect: Dialect) -> etree._Element:
    crash = plan.impact
    description = (
        f"sovarc scenario {plan.scenario.name}: {crash.type.value} crash, {crash.striker} strikes {crash.victim}"
        f" at t={num(crash.time, TIME_DIGITS)} s, on {Path(plan.map).name} at {plan.site}"
    )
    return el(
        "FileHeader",
        {
            "revMajor": 1,
            "revMinor": dialect.rev_minor,
            "date": HEADER_DATE,
            "description": description,
            "author": f"sovarc {sovarc_version()}",
        },
    )


def _text(value: str | Unknown) -> str:
    return str(value)


def parameter_declarations(plan: Plan, options: Options) -> etree._Element:
    s = plan.scenario
    p = s.provenance
    limit = s.road.speed_limit
    rows: list[tuple[str, str, str]] = [
        ("sovarc_version", "string", sovarc_version()),
        (SCENARIO, "string", s.name),
        ("sovarc_report", "string", _text(p.report) if p else "unknown"),
        ("sovarc_report_sha256", "string", _text(p.sha256) if p else "unknown"),
        ("sovarc_frontend", "string", _text(p.frontend) if p else "unknown"),
        ("sovarc_model", "string", _text(p.model) if p else "unknown"),
        ("sovarc_ir_sha256", "string", ir_sha256(s)),
        ("sovarc_map", "string", Path(plan.map).name),
        ("sovarc_map_sha256", "string", plan.map_sha256),
        (SITE, "string", plan.site),
        ("sovarc_rotation", "integer", str(plan.rotation)),
        ("sovarc_seed", "integer", str(plan.seed)),
        ("sovarc_step", "double", num(plan.step, TIME_DIGITS)),
        ("sovarc_osc_version", "string", options.version),
        (EGO, "string", options.ego),
        ("sovarc_road_kind", "string", str(s.road.kind)),
        ("sovarc_road_lanes", "string", str(s.road.lanes)),
        ("sovarc_speed_limit", "string", str(limit) if isinstance(limit, Unknown) else f"{limit.value:g} {limit.unit}"),
        (CRASH_TYPE, "string", plan.impact.type.value),
        (STRIKER, "string", plan.impact.striker),
        (VICTIM, "string", plan.impact.victim),
        (IMPACT_TIME, "double", num(plan.impact.time, TIME_DIGITS)),
        (IMPACT_X, "double", num(plan.impact.point[0])),
        (IMPACT_Y, "double", num(plan.impact.point[1])),
        (IMPACT_RADIUS, "double", num(plan.impact.radius)),
        ("sovarc_plan_notes", "string", " | ".join(plan.notes)),
    ]
    return el(
        "ParameterDeclarations",
        None,
        *(el("ParameterDeclaration", {"name": n, "parameterType": t, "value": v}) for n, t, v in rows),
    )
