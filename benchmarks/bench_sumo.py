"""Time the SUMO target per plan: emit (folder) and check (libsumo replay + oracle).

    .venv/bin/python benchmarks/bench_sumo.py [--repeat N] [--synth]

Plans: the hand-made ones of the SUMO target's tests (T-bone, rear-end, head-on,
sideswipe, pedestrian; 3.5 s each at 0.1 s). With --synth, also every example scenario
lowered and synthesized on the example town, where lowering and synthesis succeed.
Prints one row per plan (median of N runs) and the overall median.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # for the tests' plan helper

from maps import TOWN  # noqa: E402
from sovarc.compiler.lower import lower  # noqa: E402
from sovarc.compiler.maps import load_map  # noqa: E402
from sovarc.compiler.plan import Plan  # noqa: E402
from sovarc.compiler.synth import synthesize  # noqa: E402
from sovarc.dsl import parse  # noqa: E402
from sovarc.dsl.errors import SovarcError  # noqa: E402
from sovarc.targets.sumo import check, emit  # noqa: E402

from tests.targets.sumo.plans import SCENES  # noqa: E402


def synthesized() -> dict[str, Plan]:
    town = load_map(TOWN)
    plans = {}
    for path in sorted((ROOT / "examples" / "scenarios").glob("*.sov")):
        try:
            plans[path.stem] = synthesize(lower(parse(path.read_text(encoding="utf-8")), town)[0])
        except SovarcError:
            continue  # lowering or synthesis cannot place it yet: not this benchmark's business
    return plans


def time_plan(plan: Plan, repeat: int) -> tuple[float, float, bool]:
    emits, checks, passed = [], [], True
    for _ in range(repeat):
        with tempfile.TemporaryDirectory(prefix="bench-sumo-") as tmp:
            start = time.perf_counter()
            emit(plan, tmp)
            middle = time.perf_counter()
            passed = check(plan, tmp).passed
            checks.append(time.perf_counter() - middle)
            emits.append(middle - start)
    return statistics.median(emits), statistics.median(checks), passed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--synth", action="store_true", help="also time plans synthesized from the examples")
    args = parser.parse_args()
    plans = {name: make() for name, make in SCENES.items()}
    if args.synth:
        plans.update(synthesized())
    time_plan(next(iter(plans.values())), 1)  # warm up: libsumo, schemas, the network cache
    print(f"{'plan':48} {'steps':>5} {'emit ms':>8} {'check ms':>9} {'total ms':>9}  verdict")
    totals = []
    for name, plan in plans.items():
        e, c, passed = time_plan(plan, args.repeat)
        totals.append(e + c)
        steps = len(plan.trajectories[0].samples)
        verdict = "pass" if passed else "FAIL"
        print(f"{name:48} {steps:5d} {e * 1e3:8.1f} {c * 1e3:9.1f} {(e + c) * 1e3:9.1f}  {verdict}")
    print(f"median emit + check per plan: {statistics.median(totals) * 1e3:.1f} ms over {len(totals)} plans")


if __name__ == "__main__":
    main()
