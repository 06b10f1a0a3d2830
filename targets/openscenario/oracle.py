"""The OpenSCENARIO oracle: read the emitted file back and judge it.

    check(xosc_path, plan=None) -> Verdict

Schema validity (the .xosc and its .xodr), ASAM's Quality Checker rules (asam_qc.py), then a
kinematic re-check of the trajectories as the file encodes them (see motion.py and crash.py).
The plan, when given, only names the scenario and site in the verdict; every judgement comes
from the file.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

from lxml import etree
from sovarc.compiler.plan import Plan
from sovarc.targets.openscenario import provenance as p
from sovarc.targets.openscenario.asam_qc import qc_finding
from sovarc.targets.openscenario.crash import Crash, crash_findings
from sovarc.targets.openscenario.motion import single_trajectories, speed_findings, teleport_findings, timing_findings
from sovarc.targets.openscenario.readback import ScenarioFile, read_scenario
from sovarc.targets.openscenario.validation import xodr_finding, xsd_finding
from sovarc.targets.verdict import Finding, Verdict

TARGET = "openscenario"
STOP_WITHIN = 10.0  # s after the impact


def check(xosc_path: str | Path, plan: Plan | None = None) -> Verdict:
    path = Path(xosc_path)
    names = (plan.scenario.name, plan.site) if plan else (path.stem, "unknown")
    try:
        scenario = read_scenario(path)
    except OSError as e:
        return Verdict(TARGET, *names, (Finding("xml", False, f"cannot read {path}: {e.strerror}"),))
    except etree.XMLSyntaxError as e:
        return Verdict(TARGET, *names, (Finding("xml", False, f"{path.name} is not well-formed XML: {e}"),))
    except ValueError as e:
        message = f"{path.name} is not a readable OpenSCENARIO file: {e}"
        return Verdict(TARGET, *names, (Finding("xml", False, message),))
    if plan is None:
        names = (scenario.parameters.get(p.SCENARIO, path.stem), scenario.parameters.get(p.SITE, "unknown"))
    users_map = plan is not None and str(plan.network.map).lower().endswith(".xodr")
    findings, facts = judge(scenario, users_map)
    return Verdict(TARGET, *names, tuple(findings), facts)


def _crash(scenario: ScenarioFile) -> Crash | str:
    """The crash the file declares, or why it cannot be read."""
    params = scenario.parameters
    missing = [n for n in p.ORACLE_PARAMETERS if n not in params]
    if missing:
        return f"the file does not declare {', '.join(missing)}"
    try:
        crash = Crash(
            params[p.CRASH_TYPE],
            params[p.STRIKER],
            params[p.VICTIM],
            float(params[p.IMPACT_TIME]),
            (float(params[p.IMPACT_X]), float(params[p.IMPACT_Y])),
            float(params[p.IMPACT_RADIUS]),
        )
    except ValueError as e:
        return f"an impact parameter is not a number: {e}"
    unknown = [n for n in (crash.striker, crash.victim) if n not in scenario.entities]
    if unknown:
        return f"striker or victim {', '.join(unknown)} is not an entity of the file"
    return crash


def judge(scenario: ScenarioFile, users_map: bool = False) -> tuple[list[Finding], dict[str, Any]]:
    """`users_map`: the .xodr beside the file is the user's own map, copied unchanged. Its schema errors are
    the map's, not the scenario's (CARLA's towns have some): they are reported, and the players judge
    whether it can be driven. sovarc's own conversion of a SUMO map must be valid."""
    findings = [xsd_finding(scenario), qc_finding(scenario.path, scenario.doc)]
    xodr, xodr_path = xodr_finding(scenario)
    if users_map and not xodr.passed and xodr_path is not None and xodr_path.is_file():
        xodr = replace(xodr, passed=True, message=f"the user's map, copied unchanged; {xodr.message}")
    findings.append(xodr)
    facts: dict[str, Any] = {
        "version": ".".join(map(str, scenario.rev)),
        "road_network": xodr_path.name if xodr_path else None,
        "ego": scenario.parameters.get(p.EGO),
    }
    crash = _crash(scenario)
    if isinstance(crash, str):
        findings.append(Finding("pair", False, crash))
        return findings, facts
    facts.update(crash_type=crash.type, striker=crash.striker, victim=crash.victim, impact_time=crash.time)
    findings.append(Finding("pair", True, f"{crash.striker} strikes {crash.victim} ({crash.type})"))

    trajectory_findings, paths = single_trajectories(scenario)
    findings += trajectory_findings
    findings += teleport_findings(scenario, paths)
    timing = list(timing_findings(paths))
    findings += timing
    if not all(f.passed for f in timing + trajectory_findings):
        return findings, facts  # the motion cannot be interpolated
    speeds, peaks = speed_findings(scenario, paths)
    findings += speeds
    facts["peak_speeds"] = peaks
    crash_list, crash_facts = crash_findings(scenario, paths, crash)
    findings += crash_list
    facts.update(crash_facts)
    findings.append(_stop_finding(scenario, crash))
    return findings, facts


def _stop_finding(scenario: ScenarioFile, crash: Crash) -> Finding:
    stop = scenario.stop_time
    if stop is None:
        return Finding("stop_trigger", False, "no simulation-time StopTrigger: a player may run forever")
    if not crash.time < stop <= crash.time + STOP_WITHIN:
        message = (
            f"the run stops at t={stop:g} s; it must stop after the impact ({crash.time:g} s)"
            f" and within {STOP_WITHIN:g} s of it"
        )
        return Finding("stop_trigger", False, message, stop)
    return Finding("stop_trigger", True, f"the run stops at t={stop:g} s, after the impact", stop)
