"""The batch manifest: one row per scenario-site (and one per task or report that failed before any
site), as `manifest.csv` and `manifest.json`, in the order of the inputs, maps and slots, however the
tasks were scheduled.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from sovarc.compiler.fsutil import write_atomic

FIXED = ("task", "input", "scenario", "map", "slot", "site", "planned", "impact_s")
TAIL = ("folder", "error", "seconds", "cpu_seconds")


def rows_of(result: dict[str, Any], targets: Sequence[str], folder: str) -> list[dict[str, Any]]:
    """A task's result as manifest rows: one per slot, or one carrying the task's error."""
    timing = result.get("timing") or {}
    base = {"task": result.get("task", ""), "input": result["input"], "scenario": result.get("scenario", ""),
            "map": result.get("map", ""), "seconds": timing.get("seconds"),
            "cpu_seconds": timing.get("cpu_seconds")}  # fmt: skip
    slots = result.get("slots") or []
    if not slots:
        empty = {t: "-" for t in targets}
        return [{**base, "slot": "", "site": "", "planned": False, "impact_s": None, **empty, "folder": folder,
                 "error": result.get("error") or "no site"}]  # fmt: skip
    rows = []
    for index, slot in enumerate(slots, 1):
        site_folder = f"{folder}/{slot['folder']}" if slot.get("folder") else folder
        rows.append({**base, "slot": index, "site": slot["site"], "planned": slot["planned"],
                     "impact_s": slot["impact_s"], **{t: slot["verdicts"].get(t, "-") for t in targets},
                     "folder": site_folder, "error": slot["error"] or result.get("error")})  # fmt: skip
    return rows


def columns(targets: Sequence[str]) -> list[str]:
    return [*FIXED, *targets, *TAIL]


def write_manifest(out: Path, rows: list[dict[str, Any]], targets: Sequence[str]) -> tuple[Path, Path]:
    """manifest.csv and manifest.json in `out`, each written atomically."""
    names = columns(targets)
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=names, lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: "" if row.get(k) is None else row.get(k) for k in names})
    csv_path, json_path = out / "manifest.csv", out / "manifest.json"
    write_atomic(csv_path, text.getvalue())
    ordered = [{k: row.get(k) for k in names} for row in rows]
    write_atomic(json_path, json.dumps(ordered, indent=2, ensure_ascii=False) + "\n")
    return csv_path, json_path
