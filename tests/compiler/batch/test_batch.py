"""`sovarc batch`: the same files however the tasks ran (one process, a pool, Ray), a rerun that runs
exactly the unfinished tasks, and failures recorded without stopping the others."""

from __future__ import annotations

import csv
import io
import json
import os
import signal
import subprocess
import time
from pathlib import Path

import pytest
from sovarc.compiler.batch import BatchOptions, run_batch
from sovarc.compiler.batch.executors import ExecutorError, LocalExecutor, make_executor
from sovarc.compiler.batch.manifest import TAIL
from sovarc.compiler.batch.tasks import RESULT, TIMING
from sovarc.compiler.frontend import FrontEnd

from tests.compiler.cli.test_cli import SOVARC, sovarc
from tests.conftest import EXAMPLES

TOWN = EXAMPLES / "maps" / "town.net.xml"
SCENARIOS = sorted((EXAMPLES / "scenarios").glob("*.sov"))
TIMING_COLUMNS = {"seconds", "cpu_seconds"}


def sumo_city(name: str) -> str:
    import sumo

    return str(Path(sumo.SUMO_HOME) / "tools" / name)


def rules() -> FrontEnd:
    return FrontEnd("none")


def tree(folder: Path) -> dict[str, bytes]:
    """Every file under `folder` by relative path; the timings, which differ between any two runs, left out."""
    files: dict[str, bytes] = {}
    for path in sorted(folder.rglob("*")):
        if not path.is_file() or path.name == TIMING:
            continue
        data = path.read_bytes()
        if path.name == "manifest.json":
            rows = [{k: v for k, v in row.items() if k not in TIMING_COLUMNS} for row in json.loads(data)]
            data = json.dumps(rows).encode()
        elif path.name == "manifest.csv":
            rows = list(csv.DictReader(io.StringIO(data.decode())))
            data = json.dumps([{k: v for k, v in row.items() if k not in TIMING_COLUMNS} for row in rows]).encode()
        files[str(path.relative_to(folder))] = data
    return files


def test_the_local_executor_gives_every_result_once_in_one_process_or_in_a_pool() -> None:
    items = [-3, 1, -4, 1, -5, 9, -2, 6]
    for jobs in (1, 2):
        executor = LocalExecutor(jobs)
        try:
            got = sorted(executor.run(abs, items))
        finally:
            executor.close()
        assert got == [(i, abs(x)) for i, x in enumerate(items)]


def test_an_unknown_executor_and_an_address_without_ray_are_refused() -> None:
    with pytest.raises(ExecutorError, match="no executor named 'slurm'"):
        make_executor("slurm", 1)
    with pytest.raises(ExecutorError, match="--address goes with --executor ray"):
        make_executor("local", 1, "auto")


@pytest.mark.slow  # lowering, synthesis and SUMO replays in two worker processes
def test_a_pool_writes_the_same_files_as_one_process(tmp_path: Path) -> None:
    inputs = [str(p) for p in SCENARIOS[:4]]
    options = {"maps": (str(TOWN),), "roads": 2, "targets": ("sumo",)}
    outs = {}
    for jobs in (1, 2):
        out = tmp_path / f"j{jobs}"
        executor = LocalExecutor(jobs)
        try:
            result = run_batch(inputs, BatchOptions(out=out, **options), executor, rules)
        finally:
            executor.close()
        assert result.ran == 4 and result.reused == 0
        outs[jobs] = tree(out)
    assert outs[1] == outs[2]
    manifest = json.loads(outs[1]["manifest.json"])
    assert [r["input"] for r in manifest] == [i for i in inputs for _ in range(2)]
    assert all(r["sumo"] in ("pass", "fail", "-") for r in manifest)


@pytest.mark.slow  # a Ray local cluster of two workers
def test_ray_writes_the_same_manifest_and_files_as_the_pool(tmp_path: Path) -> None:
    inputs = [str(p) for p in SCENARIOS[4:7]]
    options = {"maps": (str(TOWN),), "roads": 1, "targets": ("sumo",)}
    for name in ("local", "ray"):
        executor = make_executor(name, 2)
        try:
            run_batch(inputs, BatchOptions(out=tmp_path / name, **options), executor, rules)
        finally:
            executor.close()
    assert tree(tmp_path / "local") == tree(tmp_path / "ray")


def batch(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([SOVARC, "batch", *args], capture_output=True, text=True, timeout=900)


def _finished(out: Path) -> int:
    # (pathlib's "*" matches hidden names too: a killed task's ".<name>.<pid>.partial" folder may hold its
    # result.json before it is moved in place, and the batch counts such a folder unfinished)
    return len([p for p in out.glob(f"*/*/{RESULT}") if not p.parent.name.startswith(".")])


@pytest.mark.slow  # 60 tasks staged twice, on two cores
def test_a_batch_killed_midway_reruns_exactly_its_missing_tasks_and_ends_as_an_uninterrupted_one(
    tmp_path: Path,
) -> None:
    inputs = [str(p) for p in SCENARIOS[:20]]
    maps = [str(TOWN), sumo_city("game/DRT/osm.net.xml"), sumo_city("game/grid6/grid6.net.xml")]
    args = [*inputs, *(a for m in maps for a in ("-m", m)), "--roads", "1", "--spare-sites", "0", "-j", "2"]

    whole = tmp_path / "whole"
    done = batch(*args, "--llm", "none", "-o", str(whole))
    assert done.returncode in (0, 1), done.stderr
    assert "60 task(s) run" in done.stderr

    cut = tmp_path / "cut"
    command = [SOVARC, "batch", *args, "--llm", "none", "-o", str(cut)]
    process = subprocess.Popen(command, stderr=subprocess.PIPE, start_new_session=True, text=True)
    deadline = time.monotonic() + 600
    while _finished(cut) < 20 and process.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    os.killpg(process.pid, signal.SIGKILL)
    process.wait()
    before = _finished(cut)
    assert 20 <= before < 60 and not (cut / "manifest.json").exists()

    rerun = batch(*args, "--llm", "none", "-o", str(cut))
    assert rerun.returncode in (0, 1), rerun.stderr
    assert f"{60 - before} task(s) run, {before} reused" in rerun.stderr
    assert tree(cut) == tree(whole)


def test_a_bad_input_is_a_row_with_its_error_and_the_others_still_run(tmp_path: Path) -> None:
    bad = tmp_path / "broken.sov"
    bad.write_text("scenario broken {\n  road { kind nowhere }\n}\n", encoding="utf-8")
    good = EXAMPLES / "scenarios" / "straight_rear_end_stopped_traffic.sov"
    result = sovarc(
        "batch", str(bad), str(good), "-m", str(TOWN), "-j", "1", "--llm", "none", "-o", str(tmp_path / "o")
    )
    assert result.returncode == 1, result.stderr
    rows = json.loads((tmp_path / "o" / "manifest.json").read_text(encoding="utf-8"))
    assert [r["input"] for r in rows] == [str(bad), str(good)]
    assert rows[0]["error"] and not rows[0]["planned"]
    assert rows[1]["planned"] and rows[1]["sumo"] == "pass" and rows[1]["error"] is None
    assert list(rows[0]) == list(rows[1]) and list(rows[0])[-len(TAIL) :] == list(TAIL)


def test_two_reports_that_would_share_a_scenario_file_are_refused_before_anything_runs(tmp_path: Path) -> None:
    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "30.txt").write_text("V1 struck V2.\n", encoding="utf-8")
    out = tmp_path / "out"
    result = sovarc("batch", str(tmp_path / "a" / "30.txt"), str(tmp_path / "b" / "30.txt"), "-o", str(out))
    assert result.returncode == 2
    assert "would both be extracted to scenarios/report_30.sov" in result.stderr
    assert not out.exists()


def test_batch_help_teaches_resuming_and_the_executors() -> None:
    text = sovarc("batch", "--help").stdout
    for words in ("A rerun skips the tasks already finished", "--executor {local,ray}", "manifest.csv", "-j N"):
        assert words in text.replace("\n", " ").replace("  ", " ") or words in text


@pytest.mark.slow  # lowering, synthesis and SUMO replays
def test_eval_srr_gives_the_same_json_with_one_worker_or_two(tmp_path: Path) -> None:
    chosen = [str(p) for p in SCENARIOS[::5]]
    outputs = []
    for jobs in ("1", "2"):
        out = tmp_path / f"srr{jobs}.json"
        result = batch_eval("srr", *chosen, "-m", str(TOWN), "--roads", "2", "-j", jobs, "--json", str(out))
        assert result.returncode == 0, result.stderr
        outputs.append((result.stdout, out.read_bytes()))
    assert outputs[0] == outputs[1]
    assert "SRR on town.net.xml" in outputs[0][0]


def batch_eval(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([SOVARC, "eval", *args], capture_output=True, text=True, timeout=900)
