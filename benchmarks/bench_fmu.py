"""The FMU target's figures: how fast one test is, and what report-derived tests find against random ones.

Run on demand: `python benchmarks/bench_fmu.py [--repeat N] [--truth DIR | --scenarios PATH...] [--roads N]
[--limit N]`. Prints figures; asserts nothing.
- One test: the tests' hand-made car-following on the town's avenue, stretched to 20 s, so that the
  ego (the follower) drives about 20 s before it reaches its goal. The budget is 1 s of wall time per
  20 s simulated (issue 7).
- The evaluation (`sovarc eval tests`): every scenario on --roads sites of the example town, each vehicle
  the reference ego among the report's participants and among random NPCs; the Table 6 form, the
  failures by check and violation type, and the wall time per test. By default the bundled example
  scenarios; `--truth ../shared/data/nmvccs/truth` runs the 90 labelled reports' ground truth.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # the hand-made plans live with the tests

from sovarc.compiler.evaluation.tests import tests_table  # noqa: E402
from sovarc.compiler.frontend.truth import import_truth_file  # noqa: E402
from sovarc.compiler.maps import load_map  # noqa: E402
from sovarc.compiler.scenario_io import load_scenario  # noqa: E402
from sovarc.targets.fmu import reference_fmu, validate_fmu  # noqa: E402
from sovarc.targets.fmu.driver import Driver  # noqa: E402
from sovarc.targets.fmu.harness import run_test  # noqa: E402
from sovarc.targets.fmu.interface import STEP  # noqa: E402
from sovarc.targets.fmu.oracle import judge  # noqa: E402
from sovarc.targets.fmu.runner import run_tests  # noqa: E402
from sovarc.targets.fmu.world import World  # noqa: E402

from tests.targets.fmu.plans import TOWN, car_following, crossing  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--truth", type=Path, help="SoVAR-style ground truth (<category>/<n>.json) to evaluate")
    parser.add_argument("--scenarios", nargs="*", type=Path, default=[ROOT / "examples" / "scenarios"])
    parser.add_argument("--roads", type=int, default=3)
    parser.add_argument("--limit", type=int, help="only the first N scenarios, for a quick look")
    args = parser.parse_args()

    started = time.perf_counter()
    path = reference_fmu()
    ego = validate_fmu(path)
    print(f"reference FMU ready (built or cached) and validated: {(time.perf_counter() - started) * 1e3:.0f} ms")

    plan = car_following(duration=20.0)
    walls, simulated, steps = [], 0.0, 0
    with Driver(ego) as driver:
        for _ in range(args.repeat):
            start = time.perf_counter()
            with World(TOWN, STEP) as world:
                run = run_test(plan, "V1", driver, world)
            judge(run, plan)
            walls.append(time.perf_counter() - start)
            simulated, steps = float(run.times[-1]), len(run.times)
    wall = statistics.median(walls)
    print(f"one test, ego V1 of car-following: {simulated:.1f} s simulated in {steps} steps of {STEP} s")
    print(f"  wall per test (SUMO start + run + oracle), median of {args.repeat}: {wall * 1e3:.0f} ms")
    print(f"  per 20 s simulated: {wall * 20.0 / simulated * 1e3:.0f} ms (budget 1000 ms)")
    print(f"  per step: {wall / steps * 1e6:.0f} µs")

    for name, make in (("car-following", car_following), ("crossing at x_oak", crossing)):
        for method in ("report", "random"):
            start = time.perf_counter()
            verdicts = run_tests(make(), ego, method=method)
            took = time.perf_counter() - start
            print(f"run_tests({name}, {method}): {len(verdicts)} tests in {took * 1e3:.0f} ms (load FMU, map)")

    scenarios = _scenarios(args)[: args.limit]
    started = time.perf_counter()
    table = tests_table(scenarios, load_map(TOWN), ego, roads=args.roads)
    took = time.perf_counter() - started
    print()
    print(
        table.render(f"Ego failures of the reference ego: {len(scenarios)} scenario(s) x {args.roads} site(s)"), end=""
    )
    print(f"whole evaluation (planning included): {took:.0f} s")


def _scenarios(args: argparse.Namespace) -> list:
    if args.truth is not None:
        return [import_truth_file(p).scenario for p in sorted(args.truth.glob("*/*.json"))]
    files = [p for path in args.scenarios for p in (sorted(path.glob("*.sov")) if path.is_dir() else [path])]
    return [load_scenario(p)[0] for p in files]


if __name__ == "__main__":
    main()
