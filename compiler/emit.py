"""What the emit and check stages do for one planned site: the plan's files, each target's files
(`emit_target`), and each target's check with its verdicts written (`check_target`).

This is the one place the compiler calls a target, through the registry.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import sovarc.targets.registry as registry
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.maps import RoadMap, with_opendrive
from sovarc.compiler.plan import Plan, dump_plan
from sovarc.compiler.plan_picture import draw_plan
from sovarc.compiler.plan_text import render_plan
from sovarc.targets.contract import Artifacts, Target, options_from, write_verdicts


def write_plan_files(plan: Plan, road_map: RoadMap, folder: Path) -> None:
    """plan.txt (readable), plan.json and plan.png in the site's folder."""
    write_atomic(folder / "plan.txt", render_plan(plan))
    write_atomic(folder / "plan.json", dump_plan(plan))
    write_atomic(folder / "plan.png", draw_plan(plan, road_map))


@dataclass(frozen=True)
class Emitted:
    """One target's files for one plan, and what its check needs to judge them."""

    target: Target
    plan: Plan  # as emitted (with its OpenDRIVE file where the target reads one)
    options: Any
    artifacts: Artifacts


def target_options(target: str, *, seed: int = 0, **values: Any) -> Any:
    """A registered target's Options from command-line values by flag destination (None or absent: its default)."""
    return options_from(registry.get(target), {"seed": seed, **values})


def emit_target(target: str, plan: Plan, folder: Path, options: Any) -> Emitted:
    """Emit one registered target into `folder/<target>/`. A target that reads OpenDRIVE gets the
    plan's network with its .xodr, converted by the map layer (targets never convert maps)."""
    chosen = registry.get(target)
    if chosen.needs_opendrive:
        plan = replace(plan, network=with_opendrive(plan.network))
    return Emitted(chosen, plan, options, chosen.emit(plan, folder / chosen.name, options))


def check_target(emitted: Emitted, folder: Path) -> Any:
    """Check what a target emitted and write its verdicts beside its folder (`folder/verdict-<target>.json`);
    return them: the Verdict, or the list for a target with one per test."""
    target = emitted.target
    verdicts = target.check(emitted.plan, emitted.artifacts, emitted.options)
    write_verdicts(folder, target, verdicts)
    return verdicts[0] if target.one_verdict else verdicts


def run_target(target: str, plan: Plan, folder: Path, **values: Any) -> Any:
    """Emit and check one registered target (the emit and check stages' work for one target).
    The keywords are command-line values by flag destination (`osc_version` is --osc-version)."""
    return check_target(emit_target(target, plan, folder, target_options(target, **values)), folder)
