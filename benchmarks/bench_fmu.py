"""How fast the FMU target is: one test (20 s of simulated time) with the reference ego FMU.

Run on demand: `python benchmarks/bench_fmu.py [--repeat N]`. Prints figures; asserts nothing.
The plan is the tests' hand-made car-following on the town's avenue, stretched to 20 s, so that the
ego (the follower) drives about 20 s before it reaches its goal. The budget is 1 s of wall time per
20 s simulated (issue 7).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # the hand-made plans live with the tests

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


if __name__ == "__main__":
    main()
