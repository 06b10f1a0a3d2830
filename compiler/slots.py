"""Filling several sites: the wrapper around the pipeline's per-site stages.

The sites stage lists candidate sites in the search's order; `fill` runs the per-site stages
(stage, emit, check) on the first `roads` of them, and on the next while a slot has failed. A site
that cannot be staged (unsat, synthesis) is a result with its error, not an exception: the other
sites still run. A chosen site that cannot host the crash (a frontal crash where the site's roads
cross at right angles, an arm too short to change lanes on) is replaced by the next candidate, up
to `spare` extra tries per run; the sites given up are kept on the result that replaced them
(`SiteResult.skipped`), so every output says where the crash could not be staged and why.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from sovarc.compiler.emit import Emitted
from sovarc.compiler.maps import RoadMap, SiteMatch
from sovarc.compiler.plan import Plan
from sovarc.dsl.errors import SovarcError


@dataclass
class SiteResult:
    """One site's way through the per-site stages: its plan or error, folder and verdicts."""

    site: str
    plan: Plan | None = None
    error: SovarcError | None = None
    verdicts: dict[str, Any] = field(default_factory=dict)  # target -> Verdict (fmu: a list of them)
    folder: Path | None = None
    skipped: list[SiteResult] = field(default_factory=list)  # sites tried first for this slot, which failed
    road_map: RoadMap | None = field(default=None, repr=False)  # the map it was planned on
    emitted: dict[str, Emitted] = field(default_factory=dict, repr=False)  # target -> its files, for the check


def default_spare(roads: int) -> int:
    """Extra sites tried per run when chosen ones cannot host the crash, three times the sites asked
    for: a frontal crash on a city grid may find its oblique junction only after seven right-angled ones."""
    return 3 * roads


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


def folder_name(site: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", site).strip("_")


def passed(verdict: Any) -> bool:
    if isinstance(verdict, list):
        return all(v.passed for v in verdict)
    return bool(verdict.passed)


def summary(results: Sequence[SiteResult], targets: tuple[str, ...]) -> str:
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


def skipped_lines(results: Sequence[SiteResult]) -> list[str]:
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
