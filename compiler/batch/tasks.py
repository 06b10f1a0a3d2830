"""One batch task: a scenario staged on one map's sites, emitted and checked, in a folder of its own.

A task is plain data (picklable, so any executor can ship it) and names its output by the hash of
everything its result depends on: the scenario's canonical text, the map's bytes, the options and
sovarc's version. So a rerun finds a finished task's folder and skips it, and a task whose inputs
changed gets a new folder instead of mixing old and new files.

A task writes into a hidden folder beside its final one and renames it into place when it is done,
with `result.json` inside: a task killed midway leaves only the hidden folder, which the next run
removes and redoes. A task that fails records its error in its result; it never raises, so one bad
scenario or map never stops the others.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import time
from dataclasses import asdict, dataclass, field
from functools import lru_cache
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Any

from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.maps import RoadMap, load_map
from sovarc.compiler.pipeline import Options, run_pipeline
from sovarc.compiler.slots import first_message, folder_name, passed, summary
from sovarc.dsl import parse_source
from sovarc.dsl.errors import SovarcError
from sovarc.dsl.span import Source

RESULT = "result.json"  # written last: a folder without it is unfinished
TIMING = "timing.json"  # how long the task took; the only file that differs between two runs


def sovarc_version() -> str:
    try:
        return version("sovarc")
    except PackageNotFoundError:  # run from a source tree
        return "0+unknown"


@dataclass(frozen=True)
class Task:
    """A scenario (by its canonical text) on a map (by path and content hash), with the run's options."""

    input: str  # the report or .sov file the scenario came from, as the user named it
    scenario_name: str
    scenario_text: str
    map_path: str
    map_sha256: str
    roads: int
    seed: int
    spare: int | None
    targets: tuple[str, ...]
    target_values: dict[str, Any] = field(default_factory=dict)
    out_root: str = ""

    @property
    def key(self) -> str:
        """The content address: the same inputs and options give the same key, anywhere."""
        identity = {k: v for k, v in asdict(self).items() if k not in ("input", "map_path", "out_root")}
        identity["sovarc"] = sovarc_version()
        blob = json.dumps(identity, sort_keys=True, default=list).encode("utf-8")
        return hashlib.sha256(blob).hexdigest()

    @property
    def folder(self) -> Path:
        """`OUT/<scenario>/<map>-<key>`: readable, and distinct for distinct inputs."""
        stem = Path(self.map_path).name.split(".")[0]
        return Path(self.out_root) / folder_name(self.scenario_name) / f"{folder_name(stem)}-{self.key[:10]}"


@lru_cache(maxsize=4)
def worker_map(path: str) -> RoadMap:
    """Each worker process loads a map once, however many of its tasks use it."""
    return load_map(path)


def finished(task: Task) -> dict[str, Any] | None:
    """The result of a task a previous run finished, or None."""
    path = task.folder / RESULT
    if not path.is_file():
        return None
    result: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
    timing = task.folder / TIMING
    result["timing"] = json.loads(timing.read_text(encoding="utf-8")) if timing.is_file() else {}
    return result


def run_task(task: Task) -> dict[str, Any]:
    """Stage, emit and check the task's scenario on its map; its folder holds every file and result.json."""
    start_wall, start_cpu = time.perf_counter(), time.process_time()
    final = task.folder
    work = final.with_name(f".{final.name}.{os.getpid()}.partial")
    shutil.rmtree(work, ignore_errors=True)
    result: dict[str, Any] = {"task": task.key, "input": task.input, "scenario": task.scenario_name,
                              "map": task.map_path, "slots": [], "error": None}  # fmt: skip
    try:
        scenario = parse_source(Source(f"{task.scenario_name}.sov", task.scenario_text))
        options = Options(seed=task.seed, map=worker_map(task.map_path), roads=task.roads, spare=task.spare,
                          targets=task.targets, out_dir=work, target_values=dict(task.target_values))  # fmt: skip
        slots, _ = run_pipeline(scenario, start="verify", stop="check", options=options)
        write_atomic(work / "summary.txt", summary(slots.results, task.targets))
        result["slots"] = [_slot(r, task.targets) for r in slots.results]
    except SovarcError as exc:
        result["error"] = first_message(exc)
    except Exception as exc:  # a defect: recorded for this task, the batch goes on
        result["error"] = f"internal error: {type(exc).__name__}: {exc}"
    write_atomic(work / RESULT, json.dumps(result, indent=2, ensure_ascii=False) + "\n")
    timing = {
        "seconds": round(time.perf_counter() - start_wall, 3),
        "cpu_seconds": round(time.process_time() - start_cpu, 3),
    }
    write_atomic(work / TIMING, json.dumps(timing) + "\n")
    shutil.rmtree(final, ignore_errors=True)
    final.parent.mkdir(parents=True, exist_ok=True)
    os.replace(work, final)
    result["timing"] = timing
    return result


def _slot(r: Any, targets: tuple[str, ...]) -> dict[str, Any]:
    verdicts: dict[str, str] = {}
    for target in targets:
        verdict = r.verdicts.get(target)
        verdicts[target] = "-" if verdict is None else ("pass" if passed(verdict) else "fail")
    return {
        "site": r.site,
        "planned": r.plan is not None,
        "impact_s": round(r.plan.impact.time, 3) if r.plan is not None else None,
        "verdicts": verdicts,
        "folder": folder_name(r.site) if r.plan is not None else None,
        "error": None if r.plan is not None else first_message(r.error),
    }


def clear_unfinished(out_root: Path) -> int:
    """Remove the hidden folders of tasks a killed run left half-done; how many there were."""
    stale = list(out_root.glob("*/.*.partial")) if out_root.is_dir() else []
    for folder in stale:
        shutil.rmtree(folder, ignore_errors=True)
    return len(stale)
