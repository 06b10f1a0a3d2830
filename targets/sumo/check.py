"""`check`: replay an emitted SUMO scenario folder and judge it (the SUMO target's oracle)."""

from __future__ import annotations

import os
import tempfile
from dataclasses import replace
from pathlib import Path
from xml.etree import ElementTree

from sovarc.compiler.plan import Plan
from sovarc.dsl.errors import OracleError
from sovarc.targets.sumo.documents import CONFIG
from sovarc.targets.sumo.emit import emit
from sovarc.targets.sumo.network import read_network
from sovarc.targets.sumo.oracle import judge
from sovarc.targets.sumo.replay import replay
from sovarc.targets.sumo.schemas import validate_folder
from sovarc.targets.verdict import Finding, Verdict


def check(plan: Plan, folder: str | os.PathLike[str] | None = None, *, fresh_process: bool = False) -> Verdict:
    """Replay `folder` (emitted from `plan`; emitted to a temporary folder when None) in SUMO and judge it.

    `fresh_process` runs SUMO in a child process (it does so anyway when this process
    already has a libsumo simulation loaded).
    """
    if folder is None:
        with tempfile.TemporaryDirectory(prefix="sovarc-sumo-") as tmp:
            return _check(plan, emit(plan, tmp), fresh_process)
    config = Path(folder) / CONFIG
    if not config.is_file():
        raise OracleError(f"{folder} has no {CONFIG}: emit the scenario there first")
    return _check(plan, config, fresh_process)


def _check(plan: Plan, config: Path, fresh_process: bool) -> Verdict:
    people = [t.participant for t in plan.trajectories if t.body.vclass == "pedestrian"]
    vehicles = [t.participant for t in plan.trajectories if t.body.vclass != "pedestrian"]
    trace = replay(config, people, vehicles, fresh_process=fresh_process)
    net = ElementTree.parse(config).getroot().find("./input/net-file")
    if net is None:
        raise OracleError(f"{config} names no network")
    verdict = judge(plan, trace, read_network(config.parent / net.get("value", "")))
    return replace(verdict, findings=(_schema_finding(config.parent), *verdict.findings))


def _schema_finding(folder: Path) -> Finding:
    errors = validate_folder(folder)
    if errors:
        return Finding("xsd", False, f"{len(errors)} error(s) against SUMO's schemas, first: {errors[0]}")
    return Finding("xsd", True, "the scenario files are valid against SUMO's XSD schemas")
