"""What `sovarc REPORT -t fmu` writes: per test, the verdict as JSON and a PNG of the run."""

from __future__ import annotations

import re
from pathlib import Path

from sovarc.compiler.plan import Plan
from sovarc.targets.fmu.interface import EgoFmu
from sovarc.targets.fmu.render import render_run
from sovarc.targets.fmu.runner import Method, TestResult, run_test_results
from sovarc.targets.verdict import Verdict


def run_target(
    plan: Plan,
    out_dir: str | Path,
    ego_fmu: str | Path | EgoFmu | None = None,
    seed: int = 0,
    *,
    method: Method = "report",
    pictures: bool = True,
) -> list[Verdict]:
    """Run every test of the plan and write their verdicts (and pictures) into out_dir."""
    results = run_test_results(plan, ego_fmu, seed, method=method)
    write_results(results, Path(out_dir), pictures=pictures)
    return [r.verdict for r in results]


def test_name(result: TestResult) -> str:
    """`fmu-<scenario>-<site>-ego-<participant>[-random]`, safe as a file name."""
    verdict = result.verdict
    parts = ["fmu", verdict.scenario, verdict.site, "ego", result.run.ego]
    if verdict.facts.get("method") == "random":
        parts.append("random")
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", "-".join(parts))


def write_results(results: list[TestResult], out_dir: Path, *, pictures: bool = True) -> list[Path]:
    """One `<name>.json` verdict per test, and `<name>.png` unless pictures is False. Returns the paths."""
    out_dir.mkdir(parents=True, exist_ok=True)
    written = []
    for result in results:
        name = test_name(result)
        path = out_dir / f"{name}.json"
        path.write_text(result.verdict.dumps(), encoding="utf-8")
        written.append(path)
        if pictures:
            written.append(render_run(result.run, result.verdict, out_dir / f"{name}.png"))
    return written


test_name.__test__ = False  # type: ignore[attr-defined]  # not a pytest test
