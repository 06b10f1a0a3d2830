"""End-to-end back-end time per scenario-site: lower, synthesize, emit and check (SUMO).

    .venv/bin/python benchmarks/bench_backend.py TRUTH_DIR [-m MAP] [--roads 3]

TRUTH_DIR holds .sov files (e.g. `sovarc import-truth ../shared/data/nmvccs/truth -o truth`).
Each scenario is staged on --roads sites of the map (default: the example town); every site
is timed on its own, from lowering to the SUMO oracle's verdict. Site search is timed once
per scenario and reported apart. Prints the median, p90 and total, and the pass rate.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path

from sovarc.compiler.lower import lower_on, sites_for
from sovarc.compiler.maps import load_map
from sovarc.compiler.synth import synthesize
from sovarc.dsl import parse
from sovarc.dsl.errors import SovarcError
from sovarc.targets.sumo import check, emit
from timing import percentile

ROOT = Path(__file__).resolve().parent.parent


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("truth", type=Path)
    parser.add_argument("-m", "--map", type=Path, default=ROOT / "examples" / "maps" / "town.net.xml")
    parser.add_argument("--roads", type=int, default=3)
    args = parser.parse_args()
    road_map = load_map(args.map)
    seconds, searches, passed, attempted = [], [], 0, 0
    start_all = time.perf_counter()
    for path in sorted(args.truth.glob("*.sov")):
        scenario = parse(path.read_text(encoding="utf-8"), str(path))
        start = time.perf_counter()
        try:
            staged, notes, matches = sites_for(scenario, road_map, roads=args.roads)
        except SovarcError:
            attempted += args.roads
            continue
        searches.append(time.perf_counter() - start)
        attempted += args.roads
        for match in matches:
            start = time.perf_counter()
            try:
                plan = synthesize(lower_on(staged, match, road_map, notes))
                with tempfile.TemporaryDirectory(prefix="bench-backend-") as tmp:
                    emit(plan, tmp)
                    passed += check(plan, tmp).passed
            except SovarcError:
                pass
            seconds.append(time.perf_counter() - start)
    total = time.perf_counter() - start_all
    print(f"map {args.map.name}: {attempted} scenario-sites, {passed} pass the SUMO oracle")
    print(f"per scenario-site (lower + synthesize + emit + check): median {statistics.median(seconds):.3f} s, "
          f"p90 {percentile(seconds, 0.9):.3f} s, max {max(seconds):.3f} s")  # fmt: skip
    print(f"site search per scenario: median {statistics.median(searches) * 1e3:.1f} ms")
    print(f"whole run: {total:.1f} s")


if __name__ == "__main__":
    main()
