"""The scenario reconstruction rate (SRR) in SUMO, per road kind: the paper's Tables 4 and 5.

Each scenario is staged on --roads sites of a map (the pipeline's assume, sites and stage), and each
plan replayed by the SUMO target's oracle; a scenario-site counts as reconstructed when the oracle
passes it. A failure is sorted into the paper's classes: planning failed, crash type mismatch, line
crossing (and replay error, when SUMO refused the scenario). A scenario-site the map has no site
for is not a planning failure: where fewer of the map's sites have the shape the scenario needs
(its kind, the lanes each participant needs, an arm where each move leads) than were asked, that
many of its failed rows are "no site of its shape", and the SRR is also given over the rest.
Planning failures are split by what their reasons say (`planning_class`), and the SRR is given
once more without the scenarios whose record contradicts itself (no road can stage it): a
failure of the ground truth, on every map, not of the map or the compiler.
"""

from __future__ import annotations

import tempfile
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import sovarc.targets.registry as registry
from sovarc.compiler.batch.tasks import worker_map
from sovarc.compiler.lower.assume import assume
from sovarc.compiler.maps import RoadMap, find_sites, has_shape, planning_map, scenario_needs
from sovarc.compiler.maps.search import KIND_NAMES
from sovarc.compiler.pipeline import Options, stage_sites
from sovarc.compiler.plan import Plan
from sovarc.compiler.scenario_io import load_scenario
from sovarc.compiler.slots import first_message
from sovarc.dsl.errors import SovarcError
from sovarc.dsl.ir import RoadKind, Scenario
from sovarc.targets.verdict import Verdict

NO_SHAPE = "no site of its shape"
FAILURE_CLASSES = ("planning failed", "crash type mismatch", "line crossing", "replay error", NO_SHAPE)

Row = dict[str, Any]

CONTRADICTS = "record contradicts itself"
# Why a scenario-site failed to plan, by what its reason says, first match: the map lacks the kind or a
# site that fits (a truthful miss), the record contradicts itself (lower/consistency.py), a site that
# fits only clamped (too few lanes, a move with no connection) cannot host it, or a site that fits
# cannot host the crash.
PLANNING = (
    ("map lacks the kind", ("has no ",)),
    ("no site fits", ("no site of ", "fewer fitting sites than asked", "none of its")),
    (CONTRADICTS, ("no road can stage it",)),
    ("site fits only clamped", ("the site fits only clamped",)),
    ("site cannot host it", ("",)),
)


def classify(verdict: Any) -> str | None:
    """The paper's Table 5 classes for a SUMO verdict; None when it passed."""
    failed = {f.check for f in verdict.failures}
    if not failed:
        return None
    if failed & {"collision", "pair", "impact_angle"}:
        return "crash type mismatch"
    if "lane_lines" in failed:
        return "line crossing"
    return "replay error"


def planning_class(row: Row, first: dict[str, str]) -> str:
    """The class of a planning failure (PLANNING); a scenario's follow-up rows ('no site') take the
    reason of its first row, `first` (scenario -> reason, `first_reasons`)."""
    reason = _reason(row, first)
    return next(name for name, marks in PLANNING if any(mark in reason for mark in marks))


def first_reasons(rows: list[Row]) -> dict[str, str]:
    """Each scenario's first row's reason, which its follow-up rows ('no site') stand for."""
    first: dict[str, str] = {}
    for row in rows:
        first.setdefault(row["scenario"], row["reason"] or "")
    return first


def planning_split(rows: list[Row]) -> Counter[str]:
    """The planning failures among the rows, by class (PLANNING)."""
    first = first_reasons(rows)
    return Counter(planning_class(r, first) for r in rows if r["failure"] == "planning failed")


def contradicting(rows: list[Row]) -> set[str]:
    """The scenarios whose record contradicts itself: a failed row's reason says no road can stage it,
    whatever class the row was given (a map short of sites of its shape keeps the reason in brackets)."""
    marks = dict(PLANNING)[CONTRADICTS]
    first = first_reasons(rows)
    return {r["scenario"] for r in rows if not r["passed"] and any(m in _reason(r, first) for m in marks)}


def _reason(row: Row, first: dict[str, str]) -> str:
    return row["reason"] if row["reason"] != "no site" else first.get(row["scenario"], "")


def reconstruct(
    scenario: Scenario, path: Path, road_map: RoadMap, *, roads: int, seed: int = 0, spare: int | None = None
) -> list[Row]:
    """One row per scenario-site asked for: staged on the map and replayed in SUMO, or why not."""
    kind = scenario.road.kind.value if hasattr(scenario.road.kind, "value") else "unknown"
    rows: list[Row] = []
    try:
        results = stage_sites(scenario, Options(map=road_map, roads=roads, seed=seed, spare=spare))
    except Exception as exc:  # no fitting site: every requested site failed to plan
        reason = getattr(exc, "diagnostics", None)
        rows += [_row(path, kind, "-", "planning failed", str(reason[0].message if reason else exc))]
        rows += [_row(path, kind, "-", "planning failed", "no site") for _ in range(roads - 1)]
        return _lacking(scenario, road_map, rows, roads)
    for r in results:
        if r.plan is None:
            rows.append(_row(path, kind, r.site, "planning failed", first_message(r.error)))
        else:
            try:
                verdict = replay(r.plan)
                failure = classify(verdict)
                rows.append(_row(path, kind, r.site, failure, "; ".join(f.message for f in verdict.failures)))
            except SovarcError as error:  # SUMO refused the scenario: counted, and the batch goes on
                rows.append(_row(path, kind, r.site, "replay error", str(error)))
        rows[-1]["skipped"] = [{"site": s.site, "reason": first_message(s.error)} for s in r.skipped]
    missing = roads - len(results)
    rows += [_row(path, kind, "-", "planning failed", "fewer fitting sites than asked") for _ in range(missing)]
    return _lacking(scenario, road_map, rows, roads)


def _lacking(scenario: Scenario, road_map: RoadMap, rows: list[Row], roads: int) -> list[Row]:
    """Rows the map has no site for, said so: where only n < `roads` of its sites have the shape
    the scenario needs (`maps.has_shape`), up to roads - n failed rows, those not on such a site
    first, are of class NO_SHAPE, their reason beginning with what the map lacks."""
    if all(row["passed"] for row in rows):
        return rows
    try:
        scenario, _ = assume(scenario)  # the needs of the scenario as the site search saw it
    except SovarcError:
        return rows  # facts no road can reconcile: the record's failure, not the map's
    kind = scenario.road.kind if isinstance(scenario.road.kind, RoadKind) else None
    needs = scenario_needs(scenario)
    sites = find_sites(planning_map(road_map), kind)  # as the search saw it: a left-hand map's mirror
    shaped = {site.id for site in sites if has_shape(site, needs)}
    short = roads - len(shaped)
    if short <= 0:
        return rows
    # rows on no site, then on sites of another shape; a reason of its own (a record that contradicts
    # itself) is kept for the row left a planning failure
    bare = ("no site", "fewer fitting sites than asked")
    failed = sorted((r for r in rows if not r["passed"]), key=lambda r: (r["site"] in shaped, r["reason"] not in bare))
    kinds = KIND_NAMES[kind][1] if kind is not None else "sites"
    asked = "; ".join(n.describe() for n in needs) or "no participants"
    lack = "the map has no site of the shape this scenario needs: "
    lack += f"{len(shaped)} of its {len(sites)} {kinds} fit {asked}" if sites else f"it has no {kinds} ({asked})"
    for row in failed[:short]:
        reason = row["reason"]
        said = reason if reason not in bare else ""
        row.update(failure=NO_SHAPE, reason=lack + (f" ({said})" if said else ""))
    return rows


@dataclass(frozen=True)
class SrrTask:
    """One scenario on one map: plain data, so any executor can run it in another process."""

    scenario: str  # a .sov or .json file
    map: str
    roads: int
    seed: int = 0
    spare: int | None = None


def run_srr_task(task: SrrTask) -> list[Row]:
    """The task's rows; the map is loaded once per worker process."""
    scenario, _ = load_scenario(task.scenario)
    road_map = worker_map(task.map)
    return reconstruct(scenario, Path(task.scenario), road_map, roads=task.roads, seed=task.seed, spare=task.spare)


def replay(plan: Plan) -> Verdict:
    """The SUMO target's verdict on the plan, its files emitted to a folder of their own and thrown away."""
    sumo = registry.get("sumo")
    options = sumo.Options()
    with tempfile.TemporaryDirectory(prefix="sovarc-srr-") as tmp:
        [verdict] = sumo.check(plan, sumo.emit(plan, Path(tmp), options), options)
    return verdict


def map_key(map_path: str, maps: list[str]) -> str:
    """A map's file name, or the path as given when another map has the same name (two cities'
    osm.net.xml), so that no map's rows overwrite another's in the JSON."""
    name = Path(map_path).name
    return name if [Path(m).name for m in maps].count(name) == 1 else map_path


def _row(path: Path, kind: str, site: str, failure: str | None, reason: str) -> Row:
    return {"scenario": path.stem, "kind": kind, "site": site, "passed": failure is None, "failure": failure,
            "reason": reason}  # fmt: skip


def srr_table(name: str, rows: list[Row]) -> str:
    kinds = sorted({str(r["kind"]) for r in rows})
    mixed = contradicting(rows)
    lines = [
        f"SRR on {name} (scenario-sites reconstructed / attempted; then / those the map has a site of the shape for;",
        "  then / those, less the scenarios whose record contradicts itself: the truth's failure, not the map's)",
        f"  {'road kind':<14}{'SRR':>8}  {'n':<9}{'SRR':>8}  {'n':<9}{'SRR':>8}  n",
    ]
    for kind in [*kinds, "all"]:
        chosen = [r for r in rows if kind in ("all", r["kind"])]
        hosted = [r for r in chosen if r["failure"] != NO_SHAPE]
        sound = [r for r in hosted if r["scenario"] not in mixed]
        rates = [_rate(chosen), _rate(hosted), _rate(sound)]
        lines.append(f"  {kind:<14}" + "".join(f"{rate:<19}" for rate in rates).rstrip())
    counts = Counter(str(r["failure"]) for r in rows if not r["passed"])
    lines.append("  failures: " + ", ".join(f"{c} {counts[c]}" for c in FAILURE_CLASSES))
    planning = planning_split(rows)
    if planning:
        lines.append("  planning failed: " + ", ".join(f"{c} {planning[c]}" for c, _ in PLANNING))
    if mixed:
        lines.append(f"  records that contradict themselves: {', '.join(sorted(mixed))}")
    replaced = sum(1 for r in rows if r.get("skipped") and r["failure"] != "planning failed")
    given_up = sum(len(r.get("skipped", ())) for r in rows)
    if given_up:
        lines.append(f"  sites that could not host their crash: {given_up}; slots filled by another site: {replaced}")
    return "\n".join(lines) + "\n"


def _rate(rows: list[Row]) -> str:
    """Reconstructed / attempted over the rows, as a percentage and a fraction."""
    ok = sum(1 for r in rows if r["passed"])
    return f"{100.0 * ok / max(1, len(rows)):7.1f}%  {ok}/{len(rows)}"


def sov_files(path: Path) -> list[Path]:
    return sorted(path.glob("*.sov")) if path.is_dir() else [path]
