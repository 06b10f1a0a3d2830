"""Loading a map and finding its sites, cold (netconvert converts the OpenDRIVE file) and warm
(its conversion is in the content-addressed cache): issue 17's target is 1 s on a CARLA town.

    .venv/bin/python benchmarks/bench_map_load.py MAP [MAP ...] [--repeat 5]

Cold: the conversion cache is an empty temporary folder, so an .xodr map is converted by
netconvert (a child process, whose CPU time is counted too); once per map. Warm: the median of
--repeat runs with the conversion cached; each run loads the map afresh (sumolib) and finds its
sites. A .net.xml map needs no conversion, so its cold and warm runs differ only by the disk
cache. Times are CPU (this process and its children) and wall, with the load average, since
the machine may be shared.
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from collections import Counter
from pathlib import Path

from maps import resolve
from sovarc.compiler.maps import find_sites, load_map


def _cpu() -> float:
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def _load_and_find(path: Path) -> tuple[float, float, Counter[str]]:
    cpu, wall = _cpu(), time.perf_counter()
    kinds = Counter(site.kind.value for site in find_sites(load_map(path)))
    return _cpu() - cpu, time.perf_counter() - wall, kinds


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("maps", type=resolve, nargs="+", help="files or maps' names (Town04, town, DRT, ...)")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    print(f"load + find_sites, s; warm: median of {args.repeat}; load average {os.getloadavg()[0]:.1f}")
    print(f"{'map':<14} {'cold CPU':>8} {'cold wall':>9} {'warm CPU':>8} {'warm wall':>9}  sites (4-way/T/straight)")
    saved = os.environ.get("XDG_CACHE_HOME")
    for path in args.maps:
        with tempfile.TemporaryDirectory(prefix="bench-map-cache-") as empty:
            os.environ["XDG_CACHE_HOME"] = empty
            try:
                cold_cpu, cold_wall, _ = _load_and_find(path)
            finally:
                if saved is None:
                    del os.environ["XDG_CACHE_HOME"]
                else:
                    os.environ["XDG_CACHE_HOME"] = saved
        _load_and_find(path)  # the conversion into the usual cache, if it is not there yet
        warm = [_load_and_find(path) for _ in range(args.repeat)]
        kinds = warm[0][2]
        counts = f"{kinds['intersection']}/{kinds['t_junction']}/{kinds['straight']}"
        print(f"{path.name:<14} {cold_cpu:>8.2f} {cold_wall:>9.2f} {statistics.median(w[0] for w in warm):>8.2f} "
              f"{statistics.median(w[1] for w in warm):>9.2f}  {counts}")  # fmt: skip
    print(f"load average at the end {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
