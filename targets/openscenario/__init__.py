"""The OpenSCENARIO target: a plan as an ASAM OpenSCENARIO XML scenario with its OpenDRIVE road network.

emit(plan, out_dir, version="1.3") -> Path     writes scenario.xosc and the .xodr beside it; returns the .xosc
emit_files(plan, out_dir, ...) -> Emitted      the same, with the notes on what the format cannot say
check(xosc_path, plan=None) -> Verdict         the oracle: XSD validation and a kinematic re-check of the file
play(xosc_path, plan=None) -> Verdict          runs it in esmini headless ($ESMINI or PATH), judges the collision
TARGET                                         the target contract's object: its check is the oracle's, and
                                               esmini's findings too when esmini is found

The plan must carry its network's OpenDRIVE file (`plan.network.opendrive`); the compiler fills it
in before this target runs (TARGET.needs_opendrive).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path
from typing import ClassVar

from sovarc.compiler.plan import Plan
from sovarc.targets.contract import Artifacts, option
from sovarc.targets.openscenario.emit import SCENARIO_FILE, Emitted, choose_ego, emit, emit_files
from sovarc.targets.openscenario.oracle import check
from sovarc.targets.openscenario.player import PlayerError, esmini_path, play
from sovarc.targets.openscenario.versions import DEFAULT_VERSION, VERSIONS
from sovarc.targets.verdict import Verdict


@dataclass(frozen=True)
class OpenScenarioOptions:
    version: str = option(
        DEFAULT_VERSION,
        "--osc-version",
        f"with -t openscenario: the OpenSCENARIO XML version written (default {DEFAULT_VERSION})",
        VERSIONS,
    )


class OpenScenarioTarget:
    name = "openscenario"
    Options: ClassVar[type[OpenScenarioOptions]] = OpenScenarioOptions
    needs_opendrive = True
    one_verdict = True

    def emit(self, plan: Plan, folder: Path, options: OpenScenarioOptions) -> Artifacts:
        files = emit_files(plan, folder, options.version)
        return Artifacts(Path(folder), (files.xosc, files.xodr))

    def check(self, plan: Plan, artifacts: Artifacts, options: OpenScenarioOptions) -> list[Verdict]:
        """The oracle's verdict on the file; with esmini's findings added when esmini is found."""
        verdict = check(artifacts.main, plan)
        try:
            esmini = esmini_path()
        except PlayerError:  # esmini is optional: not on PyPI or in Debian
            return [verdict]
        played = play(artifacts.main, plan, esmini)
        facts = {**verdict.facts, "esmini_collisions": played.facts.get("collisions", [])}
        return [replace(verdict, findings=(*verdict.findings, *played.findings), facts=facts)]


TARGET = OpenScenarioTarget()

__all__ = [
    "DEFAULT_VERSION",
    "SCENARIO_FILE",
    "TARGET",
    "VERSIONS",
    "Emitted",
    "OpenScenarioOptions",
    "OpenScenarioTarget",
    "check",
    "choose_ego",
    "emit",
    "emit_files",
    "play",
]
