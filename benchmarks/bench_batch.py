"""Batch throughput: `sovarc eval srr` with -j 1 against -j N, and the executor's per-task overhead.

    python benchmarks/bench_batch.py TRUTH_DIR [-m MAP] [--roads 3] [-j 2] [--executor local|ray]

TRUTH_DIR holds .sov files (`sovarc import-truth ../shared/data/nmvccs/truth -o truth`). Prints the
wall time of each run, the speed-up, whether the two JSON outputs are byte-identical, and the
overhead of a task that does nothing (the pool's cost per task: pickling, queueing, the result's
way back), which bounds how small a task can usefully be. Run it on an otherwise idle machine:
`uptime` is printed beside the figures.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from maps import TOWN, add_map_argument
from sovarc.compiler.batch.executors import make_executor

SOVARC = str(Path(sys.executable).with_name("sovarc"))


def srr(truth: str, maps: list[str], roads: int, jobs: int, executor: str, out: Path) -> float:
    command = [SOVARC, "eval", "srr", truth, "--roads", str(roads), "-j", str(jobs), "--executor", executor]
    command += [a for m in maps for a in ("-m", m)] + ["--json", str(out)]
    start = time.perf_counter()
    subprocess.run(command, check=True, capture_output=True, text=True)
    return time.perf_counter() - start


def overhead(jobs: int, executor: str, tasks: int = 2000) -> float:
    """Seconds per task of a pool running a function that does nothing, the pool already started."""
    pool = make_executor(executor, jobs)
    try:
        list(pool.run(abs, list(range(4 * jobs))))  # start the workers
        start = time.perf_counter()
        list(pool.run(abs, list(range(tasks))))
        return (time.perf_counter() - start) / tasks
    finally:
        pool.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("truth")
    add_map_argument(parser, "the example town")
    parser.add_argument("--roads", type=int, default=3)
    parser.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--executor", default="local")
    args = parser.parse_args()
    maps = [str(m) for m in args.map or [TOWN]]
    print("load before:", os.getloadavg())
    with tempfile.TemporaryDirectory() as tmp:
        one, many = Path(tmp) / "j1.json", Path(tmp) / "jn.json"
        t1 = srr(args.truth, maps, args.roads, 1, "local", one)
        tn = srr(args.truth, maps, args.roads, args.jobs, args.executor, many)
        same = one.read_bytes() == many.read_bytes()
    print(f"eval srr -j 1: {t1:.1f} s; -j {args.jobs} ({args.executor}): {tn:.1f} s; speed-up {t1 / tn:.2f}x")
    print(f"JSON byte-identical: {same}")
    per_task = overhead(args.jobs, args.executor)
    print(f"per-task overhead of the {args.executor} executor with {args.jobs} workers: {1000 * per_task:.2f} ms")
    print("load after:", os.getloadavg())


if __name__ == "__main__":
    main()
