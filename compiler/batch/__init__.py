"""`sovarc batch`: many reports and scenarios, on several maps, as independent tasks on an executor.

1. Read: each crash report is extracted once (the front end's answers are cached on disk), in this
   process, and kept as `OUT/scenarios/<name>.sov`; a `.sov` input is parsed and verified. An input
   that cannot be read is a manifest row with its error; the others go on.
2. Tasks: every scenario x map is one task (tasks.py): staged on `--roads` sites, emitted for the
   targets and checked, in its own content-addressed folder. Sites of one scenario on one map are
   one task because a failed site's slot is filled from the spare sites the others share
   (slots.py), in the search's order; splitting them would change which spare fills which slot.
3. Run: the tasks a previous run did not finish go to the executor (executors.py: a process pool by
   default, or Ray); a progress bar with ETA counts them.
4. Record: `manifest.csv` / `manifest.json`, one row per scenario-site, in input order, and
   `report.html` (compiler/report) for a person to look at.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from sovarc.compiler.batch.executors import Executor
from sovarc.compiler.batch.manifest import rows_of, write_manifest
from sovarc.compiler.batch.tasks import Task, clear_unfinished, finished, run_task
from sovarc.compiler.frontend import FrontEnd, scenario_name
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.maps import load_map
from sovarc.compiler.report import write_batch_report
from sovarc.compiler.scenario_io import load_scenario
from sovarc.compiler.slots import first_message
from sovarc.dsl import read_source, to_text, verify_or_raise
from sovarc.dsl.errors import SovarcError
from sovarc.dsl.ir import Scenario
from tqdm import tqdm


@dataclass(frozen=True)
class BatchOptions:
    maps: tuple[str, ...]
    out: Path
    roads: int = 1
    seed: int = 0
    spare: int | None = None
    targets: tuple[str, ...] = ("sumo",)
    target_values: dict[str, Any] = field(default_factory=dict)


@dataclass
class BatchResult:
    rows: list[dict[str, Any]]
    ran: int  # tasks run now
    reused: int  # tasks a previous run had finished
    failed_inputs: int
    manifest: tuple[Path, Path]


def read_inputs(
    inputs: Sequence[str], front_end: Callable[[], FrontEnd], out: Path
) -> tuple[list[tuple[str, Scenario]], list[dict[str, Any]]]:
    """Each input's scenario (reports extracted once into OUT/scenarios/), and a row for each that failed."""
    scenarios: list[tuple[str, Scenario]] = []
    failures: list[dict[str, Any]] = []
    reports = [name for name in inputs if Path(name).suffix.lower() == ".txt"]
    reader = front_end() if reports else None
    try:
        for name in tqdm(inputs, desc="read", unit="input", disable=None, leave=False):
            try:
                if Path(name).suffix.lower() == ".txt":
                    assert reader is not None
                    scenario = reader.extract(read_source(name, "crash report")).scenario
                    write_atomic(out / "scenarios" / f"{scenario_name(name)}.sov", to_text(scenario))
                else:
                    scenario, _ = load_scenario(name)
                verify_or_raise(scenario)
                scenarios.append((name, scenario))
            except SovarcError as exc:
                failures.append({"input": name, "error": first_message(exc)})
    finally:
        if reader is not None:
            reader.close()
    return scenarios, failures


def plan_tasks(scenarios: Sequence[tuple[str, Scenario]], options: BatchOptions) -> list[Task]:
    """Every scenario x map, in input order then map order."""
    digests = {m: load_map(m).sha256 for m in options.maps}
    return [
        Task(
            input=name,
            scenario_name=scenario.name,
            scenario_text=to_text(scenario),
            map_path=m,
            map_sha256=digests[m],
            roads=options.roads,
            seed=options.seed,
            spare=options.spare,
            targets=options.targets,
            target_values=dict(options.target_values),
            out_root=str(options.out),
        )
        for name, scenario in scenarios
        for m in options.maps
    ]


def run_tasks(tasks: Sequence[Task], executor: Executor, label: str = "batch") -> tuple[list[dict[str, Any]], int]:
    """Each task's result in task order: a finished one read back, the rest run on the executor."""
    results: list[dict[str, Any] | None] = [finished(t) for t in tasks]
    todo = [i for i, r in enumerate(results) if r is None]
    with tqdm(total=len(tasks), initial=len(tasks) - len(todo), desc=label, unit="task", disable=None) as bar:
        for index, result in executor.run(run_task, [tasks[i] for i in todo]):
            results[todo[index]] = result
            bar.update(1)
    return [r for r in results if r is not None], len(todo)


def run_batch(
    inputs: Sequence[str], options: BatchOptions, executor: Executor, front_end: Callable[[], FrontEnd]
) -> BatchResult:
    """Read the inputs, run every scenario x map task not yet done, and write the manifest."""
    options.out.mkdir(parents=True, exist_ok=True)
    stale = clear_unfinished(options.out)
    if stale:
        print(f"note: removed {stale} unfinished task folder(s) a previous run left; they run again", file=sys.stderr)
    scenarios, failures = read_inputs(inputs, front_end, options.out)
    tasks = plan_tasks(scenarios, options)
    results, ran = run_tasks(tasks, executor)
    by_input: dict[str, list[dict[str, Any]]] = {}
    for task, result in zip(tasks, results, strict=True):
        folder = str(task.folder.relative_to(options.out))
        by_input.setdefault(task.input, []).extend(rows_of(result, options.targets, folder))
    for failure in failures:
        by_input[failure["input"]] = rows_of(failure, options.targets, "")
    rows = [row for name in inputs for row in by_input.get(name, [])]
    manifest = write_manifest(options.out, rows, options.targets)
    write_batch_report(options.out, rows, options.targets)
    return BatchResult(rows, ran, len(tasks) - ran, len(failures), manifest)
