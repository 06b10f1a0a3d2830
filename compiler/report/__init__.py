"""`report.html`: the page a person looks at after a run or a batch.

One card per scenario-site (its plan picture, an animation of the crash, its verdicts and links to
its files), grouped by scenario under the scenario's `.sov` and provenance, after a table of the
verdicts per target and road kind. The page is self-contained: CSS, script and each animation's
scene (JSON) are inline; pictures and files are relative links to files beside it.

Built from data: a run's SiteResults (`cards_from_slots`) or a batch's manifest rows
(`cards_from_rows`), which read each site's plan.json back. Same inputs, same bytes: nothing in it
depends on time, and every list whose order means nothing is sorted.
"""

from __future__ import annotations

import json
import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from sovarc.compiler.frontend import scenario_name
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.maps import RoadMap, load_map
from sovarc.compiler.plan import Plan, plan_from_json
from sovarc.compiler.plan_picture import scene
from sovarc.compiler.report.page import render_page
from sovarc.compiler.slots import SiteResult, first_message, passed
from sovarc.dsl import to_text

REPORT = "report.html"


@dataclass(frozen=True)
class Card:
    """One scenario-site as the page shows it; paths are relative to the report's folder."""

    scenario: str
    site: str
    map: str
    verdicts: dict[str, str]  # target -> 'pass', 'fail' or '-' (not run)
    kind: str = "-"  # the site's road kind; '-' when nothing was planned
    impact_s: float | None = None
    error: str | None = None
    folder: str | None = None  # the site's folder
    files: tuple[str, ...] = ()  # every file in it, sorted
    scene: dict[str, Any] | None = None  # the animation's data (plan_picture.scene)
    crash: str = ""  # e.g. 'side crash: V2 strikes V1'


@dataclass(frozen=True)
class ScenarioInfo:
    """What the page says of a scenario once, above its cards."""

    name: str
    input: str  # the report or .sov as the user named it
    sov: str | None  # link to the scenario text
    provenance: dict[str, str] = field(default_factory=dict)


def verdict_label(verdict: Any) -> str:
    """'pass' or 'fail' (a target with one verdict per test fails when any does), '-' when not run."""
    if verdict is None:
        return "-"
    return "pass" if passed(verdict) else "fail"


def provenance_of(plan: Plan | None) -> dict[str, str]:
    prov = plan.scenario.provenance if plan is not None else None
    if prov is None:
        return {}
    fields = {"report": prov.report, "sha256": prov.sha256, "front end": prov.frontend, "model": prov.model}
    info = {k: str(v) for k, v in fields.items()}
    if prov.assumed:
        info["assumed"] = ", ".join(sorted(prov.assumed))
    return info


def _crash(plan: Plan) -> str:
    return f"{plan.impact.type.value} crash: {plan.impact.striker} strikes {plan.impact.victim}"


def _files(out: Path, folder: Path) -> tuple[str, ...]:
    if not folder.is_dir():
        return ()
    return tuple(sorted(_rel(p, out) for p in folder.rglob("*") if p.is_file()))


def _rel(path: Path | str, out: Path) -> str:
    return Path(os.path.relpath(Path(path).resolve(), out.resolve())).as_posix()


def _card(out: Path, plan: Plan | None, road_map: RoadMap | None, base: dict[str, Any]) -> Card:
    folder = base.pop("folder_path", None)
    if folder is not None and Path(folder).is_dir():
        base.update(folder=_rel(folder, out), files=_files(out, folder))
    if plan is None:
        return Card(**base)
    return Card(
        **base,
        kind=plan.kind.value,
        impact_s=round(plan.impact.time, 2),
        scene=scene(plan, road_map) if road_map is not None else None,
        crash=_crash(plan),
    )


def cards_from_slots(
    out: Path, results: Sequence[SiteResult], targets: Sequence[str], input_path: str
) -> tuple[list[ScenarioInfo], list[Card]]:
    """A run's sites: its one scenario, and a card per slot in slot order."""
    plans = [r.plan for r in results if r.plan is not None]
    name = plans[0].scenario.name if plans else scenario_name(input_path)
    cards = []
    for r in results:
        base: dict[str, Any] = {
            "scenario": name,
            "site": r.site,
            "map": str(r.road_map.path) if r.road_map is not None else "",
            "verdicts": {t: verdict_label(r.verdicts.get(t)) for t in targets},
            "error": None if r.error is None else first_message(r.error),
            "folder_path": r.folder,
        }
        cards.append(_card(out, r.plan, r.road_map, base))
    sov = _rel(input_path, out) if Path(input_path).suffix.lower() == ".sov" else None
    if sov is None and plans:  # a report: keep the scenario extracted from it beside the page
        sov_path = out / f"{name}.sov"
        write_atomic(sov_path, _scenario_text(plans[0]))
        sov = sov_path.name
    return [ScenarioInfo(name, input_path, sov, provenance_of(plans[0] if plans else None))], cards


def _scenario_text(plan: Plan) -> str:
    return to_text(plan.scenario)


def cards_from_rows(
    out: Path, rows: Sequence[dict[str, Any]], targets: Sequence[str]
) -> tuple[list[ScenarioInfo], list[Card]]:
    """A batch's manifest rows (one per scenario-site), each site's plan read back from its folder."""
    maps: dict[str, RoadMap] = {}
    infos: dict[str, ScenarioInfo] = {}
    cards = []
    for row in rows:
        folder = out / row["folder"] if row.get("folder") else None
        plan = None
        if row.get("planned") and folder is not None and (folder / "plan.json").is_file():
            data = json.loads((folder / "plan.json").read_text(encoding="utf-8"))
            plan = plan_from_json(data, str(folder / "plan.json"))
        road_map = None
        if plan is not None:
            network = plan.network.sumo
            if network not in maps:
                maps[network] = load_map(network)
            road_map = maps[network]
        name = row.get("scenario") or scenario_name(row["input"])
        base: dict[str, Any] = {
            "scenario": name,
            "site": row.get("site") or "",
            "map": row.get("map") or "",
            "verdicts": {t: str(row.get(t) or "-") for t in targets},
            "error": row.get("error"),
            "folder_path": folder,
        }
        cards.append(_card(out, plan, road_map, base))
        if name not in infos or (not infos[name].provenance and plan is not None):
            infos[name] = ScenarioInfo(name, row["input"], _batch_sov(out, row["input"], name), provenance_of(plan))
    return list(infos.values()), cards


def _batch_sov(out: Path, input_path: str, name: str) -> str | None:
    """A report's scenario is kept as OUT/scenarios/<name>.sov (batch.read_inputs); a .sov input is its own."""
    if Path(input_path).suffix.lower() == ".txt":
        kept = out / "scenarios" / f"{scenario_name(input_path)}.sov"
        return _rel(kept, out) if kept.is_file() else None
    return _rel(input_path, out) if Path(input_path).is_file() else None


def write_report(
    out: Path, title: str, targets: Sequence[str], infos: Sequence[ScenarioInfo], cards: Sequence[Card]
) -> Path:
    path = out / REPORT
    write_atomic(path, render_page(title, tuple(targets), list(infos), list(cards)))
    return path


def write_run_report(out: Path, results: Sequence[SiteResult], targets: Sequence[str], input_path: str) -> Path:
    """The run's report.html in its output folder (cli/run.py's one call)."""
    infos, cards = cards_from_slots(out, results, targets, input_path)
    return write_report(out, f"sovarc report: {infos[0].name}", targets, infos, cards)


def write_batch_report(out: Path, rows: Sequence[dict[str, Any]], targets: Sequence[str]) -> Path:
    """The batch's report.html beside its manifest (batch.run_batch's one call)."""
    infos, cards = cards_from_rows(out, rows, targets)
    return write_report(out, "sovarc batch report", targets, infos, cards)
