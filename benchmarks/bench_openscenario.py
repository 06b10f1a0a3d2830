"""How fast the OpenSCENARIO target is: emit (with and without the road network) and check.

Run on demand: `python benchmarks/bench_openscenario.py [--repeat N]`. Prints figures; asserts nothing.
Plans are the hand-made ones of the tests (examples/maps/town.net.xml), plus a long T-bone
(impact at 60 s, so about 600 vertices per participant).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # the hand-made plans live with the tests

from sovarc.compiler.plan import CAR, Plan  # noqa: E402
from sovarc.targets.openscenario import check, choose_ego, emit_files  # noqa: E402
from sovarc.targets.openscenario.emit import build_document  # noqa: E402
from sovarc.targets.openscenario.provenance import Options  # noqa: E402
from sovarc.targets.openscenario.roadnet import write_road_network  # noqa: E402
from sovarc.targets.openscenario.versions import dialect  # noqa: E402

from tests.targets.openscenario.plans import CASES, make_plan, straight  # noqa: E402


def long_t_bone(t_hit: float = 60.0) -> Plan:
    y2, point = -8.25, (4.5, -8.25 - CAR.width / 2)
    motions = {
        "V1": straight(4.5, point[1], 0.0, 1.0, t_hit),
        "V2": straight(4.5 + CAR.length / 2, y2, 90.0, 1.0, t_hit),
    }
    return make_plan("intersection_red_light_runner_side", "junction:x_main", t_hit, point, motions)


def _median_ms(fn: Callable[[], Any], repeat: int) -> float:
    samples = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        samples.append(time.perf_counter() - start)
    return statistics.median(samples) * 1e3


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--version", default="1.3")
    args = parser.parse_args()
    plans = {name: make() for name, make in CASES.items()} | {"long_t_bone": long_t_bone()}
    d = dialect(args.version)
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        town = next(iter(plans.values())).map
        start = time.perf_counter()
        write_road_network(town, out / "cold")
        cold = (time.perf_counter() - start) * 1e3
        print(
            f"OpenSCENARIO {d.version}; median of {args.repeat} runs; netconvert to .xodr (cold, once): {cold:.0f} ms"
        )
        header = ("plan", "vertices", "xosc KB", "document ms", "emit ms", "check ms", "verdict")
        print(
            f"{header[0]:<12} {header[1]:>8} {header[2]:>8} {header[3]:>12} {header[4]:>8} {header[5]:>9}  {header[6]}"
        )
        for name, plan in plans.items():
            options = Options(d.version, choose_ego(plan))
            folder = out / name
            document = _median_ms(lambda p=plan, o=options: build_document(p, "town.xodr", o, d), args.repeat)
            emitted = emit_files(plan, folder, d.version)
            emit = _median_ms(lambda p=plan, f=folder: emit_files(p, f, d.version), args.repeat)
            checking = _median_ms(lambda x=emitted.xosc, p=plan: check(x, p), args.repeat)
            verdict = check(emitted.xosc, plan)
            vertices = sum(len(t.samples) for t in plan.trajectories)
            size = emitted.xosc.stat().st_size / 1024
            status = "pass" if verdict.passed else "FAIL " + ", ".join(f.check for f in verdict.failures)
            print(f"{name:<12} {vertices:>8} {size:>8.1f} {document:>12.1f} {emit:>8.1f} {checking:>9.1f}  {status}")


if __name__ == "__main__":
    main()
