"""The SUMO target: emit a plan as a scenario folder that `sumo -c` replays, and check it in SUMO.

cfg = emit(plan, "out/site1")        # -> out/site1/scenario.sumocfg
verdict = check(plan, "out/site1")   # replays it through libsumo; check(plan) emits to a temp folder
TARGET                               # the same, as the target contract's object (targets/contract.py)
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

from sovarc.compiler.plan import Plan
from sovarc.targets.contract import Artifacts
from sovarc.targets.sumo.check import check
from sovarc.targets.sumo.emit import emit, emit_files
from sovarc.targets.verdict import Verdict


@dataclass(frozen=True)
class SumoOptions:
    """The SUMO target takes no options."""


class SumoTarget:
    name = "sumo"
    Options: ClassVar[type[SumoOptions]] = SumoOptions
    needs_opendrive = False
    one_verdict = True

    def emit(self, plan: Plan, folder: Path, options: SumoOptions) -> Artifacts:
        return Artifacts(Path(folder), emit_files(plan, folder))

    def check(self, plan: Plan, artifacts: Artifacts, options: SumoOptions) -> list[Verdict]:
        return [check(plan, artifacts.folder)]


TARGET = SumoTarget()

__all__ = ["TARGET", "SumoOptions", "SumoTarget", "check", "emit", "emit_files"]
