"""How fast the DSL front of the pipeline is: parse, verify, print, JSON, on every example.

Run on demand: `python benchmarks/bench_dsl.py [--repeat N]`. Prints figures; asserts nothing.
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

from sovarc.dsl import from_json, parse, to_json, to_text, verify
from sovarc.dsl.parser import _lark

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def _time(fn, repeat: int) -> float:
    samples = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        samples.append(time.perf_counter() - start)
    return statistics.median(samples)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeat", type=int, default=20)
    args = parser.parse_args()
    texts = [p.read_text(encoding="utf-8") for p in sorted(EXAMPLES.glob("**/*.sov"))]
    parse(texts[0])  # build the parser once, as a long-running process would
    scenarios = [parse(t) for t in texts]
    data = [to_json(s) for s in scenarios]
    rows = {
        "parse": lambda: [parse(t) for t in texts],
        "verify": lambda: [verify(s) for s in scenarios],
        "print": lambda: [to_text(s) for s in scenarios],
        "to_json": lambda: [to_json(s) for s in scenarios],
        "from_json": lambda: [from_json(d) for d in data],
    }
    n = len(texts)
    size = sum(len(t) for t in texts)
    print(f"{n} example files, {size / 1024:.1f} KiB, median of {args.repeat} runs")
    print(f"{'step':<10} {'per file (ms)':>14} {'files/s':>10}")
    for name, fn in rows.items():
        per_file = _time(fn, args.repeat) / n
        print(f"{name:<10} {per_file * 1e3:>14.3f} {1 / per_file:>10.0f}")
    start = time.perf_counter()
    _lark.cache_clear()
    _lark()
    print(f"parser build (once per process): {(time.perf_counter() - start) * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
