"""The back end of the main job: stage a scenario on N sites, synthesize, emit and check each target.

results = compile_sites(scenario, "town.net.xml", roads=3, seed=0, targets=("sumo",), out_dir="out")

Per site it writes `out/<site>/plan.txt`, `plan.json` and `plan.png`, then each target's
files and `verdict-<target>.json`. A site that cannot be staged (unsat, synthesis) is a
result with its error, not an exception: the other sites still run.

A chosen site that cannot host the crash (a frontal crash where the site's roads cross at right
angles, an arm too short to change lanes on) is replaced by the next site in the search's order,
up to `spare` extra tries per run; the sites given up are kept on the result that replaced them
(`SiteResult.skipped`), so every output says where the crash could not be staged and why.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.maps import RoadMap, SiteMatch, load_map, with_opendrive
from sovarc.compiler.plan import Plan, dump_plan
from sovarc.dsl.errors import LoweringError, SovarcError
from sovarc.dsl.ir import Scenario
from sovarc.targets import registry
from sovarc.targets.contract import options_from, write_verdicts

DEFAULT_MAP = Path(__file__).resolve().parents[1] / "examples" / "maps" / "town.net.xml"


@dataclass
class SiteResult:
    site: str
    plan: Plan | None = None
    error: SovarcError | None = None
    verdicts: dict[str, Any] = field(default_factory=dict)  # target -> Verdict (fmu: a list of them)
    folder: Path | None = None
    skipped: list[SiteResult] = field(default_factory=list)  # sites tried first for this slot, which failed


def default_spare(roads: int) -> int:
    """Extra sites tried per run when chosen ones cannot host the crash, three times the sites asked
    for: a frontal crash on a city grid may find its oblique junction only after seven right-angled ones."""
    return 3 * roads


def default_map() -> Path:
    if not DEFAULT_MAP.is_file():
        raise SovarcError("no bundled example map in this installation; give a map with -m MAP (.net.xml or .xodr)")
    return DEFAULT_MAP


def plans_for(
    scenario: Scenario, road_map: RoadMap, roads: int, seed: int, spare: int | None = None
) -> list[SiteResult]:
    """Lower and synthesize on up to `roads` sites, trying up to `spare` more (default:
    `default_spare`) in place of sites that fail; a slot no site could fill keeps its first failure."""
    from sovarc.compiler.lower import sites_for

    spare = default_spare(roads) if spare is None else spare
    staged, notes, matches = sites_for(scenario, road_map, roads=roads + spare, seed=seed)
    return fill_slots(matches, roads, lambda match: plan_site(staged, notes, road_map, match, seed))


def plan_site(staged: Scenario, notes: list[str], road_map: RoadMap, match: SiteMatch, seed: int = 0) -> SiteResult:
    """Lower and synthesize the staged scenario on one site; a failure is kept as the result's error."""
    from sovarc.compiler.lower import stagings_on
    from sovarc.compiler.synth import synthesize_first

    result = SiteResult(match.site.id)
    try:
        result.plan = synthesize_first(stagings_on(staged, match, road_map, notes), seed=seed)
    except SovarcError as exc:
        result.error = exc
    except Exception as exc:  # a defect met on this site's geometry: said, and the next site is tried
        defect = f"{type(exc).__name__}: {exc}"
        message = f"on {match.site.id}, sovarc failed on this site's geometry ({defect}); please report it"
        result.error = LoweringError(message)
    return result


def fill_slots(
    candidates: Sequence[SiteMatch], roads: int, attempt: Callable[[SiteMatch], SiteResult]
) -> list[SiteResult]:
    """Attempt candidates in order until `roads` slots hold a plan or the candidates run out.

    The first `roads` candidates take the slots; each later one is tried only while a slot has
    failed, and a success takes the first failed slot, keeping what it replaced in `skipped`.
    The order of the slots is the order of their first candidates, so output is deterministic.
    """
    slots: list[SiteResult] = []
    for match in candidates:
        if len(slots) < roads:
            slots.append(attempt(match))
            continue
        failed = next((i for i, slot in enumerate(slots) if slot.plan is None), None)
        if failed is None:
            break
        result = attempt(match)
        held = slots[failed]
        if result.plan is None:
            held.skipped.append(result)
        else:
            result.skipped = [held, *held.skipped]
            held.skipped = []
            slots[failed] = result
    return slots


def compile_sites(
    scenario: Scenario,
    map_path: str | Path | None,
    *,
    roads: int = 1,
    seed: int = 0,
    spare: int | None = None,
    targets: tuple[str, ...] = (),
    out_dir: str | Path | None = None,
    ego: str | None = None,
    osc_version: str | None = None,
) -> list[SiteResult]:
    road_map = load_map(map_path or default_map())
    results = plans_for(scenario, road_map, roads, seed, spare)
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
            rows.append([r.site, "planning failed: " + first_message(r.error)[:70]] + ["-"] * len(targets))
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
    table = "\n".join("  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)).rstrip() for row in rows)
    return table + "\n" + "".join(skipped_lines(results))


def skipped_lines(results: list[SiteResult]) -> list[str]:
    """One line per site given up for another: which, why, and what replaced it."""
    lines = []
    for r in results:
        for s in r.skipped:
            why = first_message(s.error)
            if r.plan is not None:
                lines.append(f"note: {s.site} could not host the crash ({why}); staged on {r.site}\n")
            else:
                lines.append(f"note: {s.site}, tried in place of {r.site}, failed too ({why})\n")
    return lines


def first_message(error: SovarcError | None) -> str:
    return error.diagnostics[0].message if error is not None and error.diagnostics else str(error or "failed")
