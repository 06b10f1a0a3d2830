"""What the emit and check stages write for one planned site: the plan's files, and each target's.

`run_target` is the one place the compiler calls a target (emit it, check it, write its verdict).
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

import sovarc.targets.registry as registry
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.maps import RoadMap, with_opendrive
from sovarc.compiler.plan import Plan, dump_plan
from sovarc.compiler.plan_picture import draw_plan
from sovarc.compiler.plan_text import render_plan
from sovarc.targets.contract import options_from, write_verdicts


def write_plan_files(plan: Plan, road_map: RoadMap, folder: Path) -> None:
    """plan.txt (readable), plan.json and plan.png in the site's folder."""
    write_atomic(folder / "plan.txt", render_plan(plan))
    write_atomic(folder / "plan.json", dump_plan(plan))
    write_atomic(folder / "plan.png", draw_plan(plan, road_map))


def run_target(
    target: str,
    plan: Plan,
    folder: Path,
    *,
    seed: int = 0,
    ego: str | None = None,
    osc_version: str | None = None,
    **values: Any,
) -> Any:
    """Emit and check one registered target into `folder/<target>/`; write its verdicts beside it
    (`folder/verdict-<target>.json`) and return them: the Verdict, or the list for a target with one per test.

    The keywords are command-line values by flag destination (`osc_version` is --osc-version; None:
    the target's default). A target that reads OpenDRIVE gets the plan's network with its .xodr."""
    chosen = registry.get(target)
    options = options_from(chosen, {"seed": seed, "ego": ego, "osc_version": osc_version, **values})
    if chosen.needs_opendrive:
        plan = replace(plan, network=with_opendrive(plan.network))
    artifacts = chosen.emit(plan, folder / chosen.name, options)
    verdicts = chosen.check(plan, artifacts, options)
    write_verdicts(folder, chosen, verdicts)
    return verdicts[0] if chosen.one_verdict else verdicts
