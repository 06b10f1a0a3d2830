"""What the emit and check stages write for one planned site: the plan's files, and each target's.

`run_target` is the one place the compiler calls a target (emit it, check it, write its verdict).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.maps import RoadMap
from sovarc.compiler.plan import Plan, dump_plan
from sovarc.compiler.plan_picture import draw_plan
from sovarc.compiler.plan_text import render_plan

TARGETS = ("sumo", "openscenario", "fmu")


def write_plan_files(plan: Plan, road_map: RoadMap, folder: Path) -> None:
    """plan.txt (readable), plan.json and plan.png in the site's folder."""
    write_atomic(folder / "plan.txt", render_plan(plan))
    write_atomic(folder / "plan.json", dump_plan(plan))
    write_atomic(folder / "plan.png", draw_plan(plan, road_map))


def run_target(
    target: str, plan: Plan, folder: Path, *, seed: int = 0, ego: str | None = None, osc_version: str | None = None
) -> Any:
    """Emit and check one target; `osc_version` is the OpenSCENARIO version (None: the target's default)."""
    if target == "sumo":
        from sovarc.targets import sumo

        sumo.emit(plan, folder / "sumo")
        verdict = sumo.check(plan, folder / "sumo")
        write_atomic(folder / "verdict-sumo.json", verdict.dumps())
        return verdict
    if target == "openscenario":
        from sovarc.targets import openscenario

        xosc = openscenario.emit(plan, folder / "openscenario", osc_version or openscenario.DEFAULT_VERSION)
        verdict = openscenario.check(xosc, plan)
        write_atomic(folder / "verdict-openscenario.json", verdict.dumps())
        return verdict
    if target == "fmu":
        from sovarc.targets.fmu import run_target as run_fmu

        return run_fmu(plan, folder / "fmu", ego_fmu=ego, seed=seed)
    raise ValueError(f"unknown target {target!r}")
