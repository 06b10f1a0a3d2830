"""The back end of the main job: stage a scenario on N sites, synthesize, emit and check each target.

results = compile_sites(scenario, "town.net.xml", roads=3, seed=0, targets=("sumo",), out_dir="out")

Per site it writes `out/<site>/plan.txt`, `plan.json` and `plan.png`, then each target's
files and `verdict-<target>.json`. A site that cannot be staged (unsat, synthesis) is a
result with its error, not an exception: the other sites still run.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.maps import RoadMap, load_map
from sovarc.compiler.plan import Plan, dump_plan
from sovarc.dsl.errors import SovarcError
from sovarc.dsl.ir import Scenario

TARGETS = ("sumo", "openscenario", "fmu")
DEFAULT_MAP = Path(__file__).resolve().parents[1] / "examples" / "maps" / "town.net.xml"


@dataclass
class SiteResult:
    site: str
    plan: Plan | None = None
    error: SovarcError | None = None
    verdicts: dict[str, Any] = field(default_factory=dict)  # target -> Verdict (fmu: a list of them)
    folder: Path | None = None


def default_map() -> Path:
    if not DEFAULT_MAP.is_file():
        raise SovarcError("no bundled example map in this installation; give a map with -m MAP (.net.xml or .xodr)")
    return DEFAULT_MAP


def plans_for(scenario: Scenario, road_map: RoadMap, roads: int, seed: int) -> list[SiteResult]:
    """Lower and synthesize on up to `roads` sites; a site's failure is kept as its result."""
    from sovarc.compiler.lower import lower_on, sites_for
    from sovarc.compiler.synth import synthesize

    staged, notes, matches = sites_for(scenario, road_map, roads=roads, seed=seed)
    results = []
    for match in matches:
        result = SiteResult(match.site.id)
        try:
            result.plan = synthesize(lower_on(staged, match, road_map, notes), seed=seed)
        except SovarcError as exc:
            result.error = exc
        results.append(result)
    return results


def compile_sites(
    scenario: Scenario,
    map_path: str | Path | None,
    *,
    roads: int = 1,
    seed: int = 0,
    targets: tuple[str, ...] = (),
    out_dir: str | Path | None = None,
    ego: str | None = None,
    osc_version: str | None = None,
) -> list[SiteResult]:
    road_map = load_map(map_path or default_map())
    results = plans_for(scenario, road_map, roads, seed)
    for result in results:
        if out_dir is None:
            continue
        folder = Path(out_dir) / folder_name(result.site)
        result.folder = folder
        if result.plan is None:
            write_atomic(folder / "error.txt", result.error.render() + "\n" if result.error else "")
            continue
        write_plan_files(result.plan, road_map, folder)
        for target in targets:
            result.verdicts[target] = run_target(
                target, result.plan, folder, seed=seed, ego=ego, osc_version=osc_version
            )
    return results


def write_plan_files(plan: Plan, road_map: RoadMap, folder: Path) -> None:
    from sovarc.compiler.plan_picture import draw_plan
    from sovarc.compiler.plan_text import render_plan

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


def folder_name(site: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", site).strip("_")


def passed(verdict: Any) -> bool:
    if isinstance(verdict, list):
        return all(v.passed for v in verdict)
    return bool(verdict.passed)


def summary(results: list[SiteResult], targets: tuple[str, ...]) -> str:
    """A short table: one row per site, the impact time and each target's verdict."""
    header = ["site", "impact", *targets]
    rows = [header]
    for r in results:
        if r.plan is None:
            reason = r.error.diagnostics[0].message if r.error else "failed"
            rows.append([r.site, "planning failed: " + reason[:70]] + ["-"] * len(targets))
            continue
        cells = [r.site, f"{r.plan.impact.time:.1f} s"]
        for t in targets:
            verdict = r.verdicts.get(t)
            if isinstance(verdict, list):  # fmu: one test per participant as ego; a failure is a finding
                cells.append(f"ego failed {sum(not v.passed for v in verdict)}/{len(verdict)}")
            else:
                cells.append("-" if verdict is None else ("pass" if passed(verdict) else "FAIL"))
        rows.append(cells)
    widths = [max(len(row[i]) for row in rows) for i in range(len(header))]
    return "\n".join("  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)).rstrip() for row in rows) + "\n"
