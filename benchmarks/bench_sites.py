"""How fast the map layer is: load, find_sites and match_sites, on the example town and a real city.

Run on demand: `python benchmarks/bench_sites.py [--repeat N]`. Prints figures; asserts nothing.
The city is SUMO's DRT demo network (OpenStreetMap), shipped with the eclipse-sumo wheel.
"""

from __future__ import annotations

import argparse
import contextlib
from collections import Counter
from pathlib import Path
from typing import Any

from maps import DRT, ROOT, TOWN
from sovarc.compiler.maps import find_sites, load_map, match_sites
from sovarc.dsl import parse
from sovarc.dsl.errors import LoweringError
from timing import median_ms


def _maps() -> dict[str, Path]:
    return {"town": TOWN, "DRT osm": DRT}


def _match_all(scenarios: list[Any], road_map: Any, n: int) -> int:
    fitted = 0
    for scenario in scenarios:
        with contextlib.suppress(LoweringError):  # a scenario that fits nowhere is counted, not fatal
            fitted += bool(match_sites(scenario, road_map, n=n, seed=0))
    return fitted


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("-n", type=int, default=3, help="sites per scenario")
    args = parser.parse_args()
    scenarios = [parse(p.read_text(encoding="utf-8")) for p in sorted((ROOT / "examples" / "scenarios").glob("*.sov"))]
    print(f"median of {args.repeat} runs; match_sites: {len(scenarios)} example scenarios, n={args.n}")
    header = ("map", "junctions", "edges", "intersections", "t_junctions", "straights", "load", "find", "match")
    print(f"{header[0]:<8} {header[1]:>9} {header[2]:>6} {header[3]:>13} {header[4]:>11} {header[5]:>9}", end="")
    print(f" {header[6] + ' ms':>8} {header[7] + ' ms':>8} {header[8] + ' ms':>9}  fitted")
    for name, path in _maps().items():
        load_ms = median_ms(lambda path=path: load_map(path), args.repeat)
        road_map = load_map(path)
        find_ms = median_ms(lambda m=road_map: (m.cache.clear(), find_sites(m)), args.repeat)
        counts = Counter(site.kind.value for site in find_sites(road_map))
        match_ms = median_ms(lambda m=road_map: _match_all(scenarios, m, args.n), args.repeat)
        fitted = _match_all(scenarios, road_map, args.n)
        nodes = road_map.net.getNodes()
        junctions = sum(1 for node in nodes if node.getType() != "internal")
        edges = sum(1 for edge in road_map.net.getEdges() if not edge.isSpecial())
        print(
            f"{name:<8} {junctions:>9} {edges:>6} {counts['intersection']:>13} {counts['t_junction']:>11}"
            f" {counts['straight']:>9} {load_ms:>8.1f} {find_ms:>8.1f} {match_ms:>9.1f}  {fitted}/{len(scenarios)}"
        )


if __name__ == "__main__":
    main()
