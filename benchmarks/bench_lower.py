"""Feasibility and speed of lowering plus synthesis: the 90 ground-truth scenarios on 3 sites of two maps.

Run on demand: `python benchmarks/bench_lower.py [--limit N] [--json]`. Prints figures; asserts nothing.

The scenarios are converted from `../shared/data/nmvccs/truth` with `sovarc import-truth` into a
temporary folder at run time. Each is staged on 3 sites (`lower(roads=3)` step by step, so that
every site is timed on its own) of the example town and of SUMO's DRT demo city network
(OpenStreetMap, shipped with the eclipse-sumo wheel). A scenario-site succeeds when both lowering
and synthesis succeed; a map with fewer than 3 fitting sites counts the missing ones as failures.
As `sovarc` does, a site that cannot host the crash is replaced by the next one the search offers,
up to `--spare` more tries per scenario (default: the CLI's, three times the sites); `--spare 0` measures
the first choice alone. A slot's time includes the tries it gave up.
Site search (`match_sites`) is timed separately, cold (finding the map's sites) and warm (cached).
"""

from __future__ import annotations

import argparse
import json
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections import Counter, defaultdict
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from maps import DRT, TOWN, TRUTH
from sovarc.compiler.lower.assume import assume
from sovarc.compiler.maps import RoadMap, find_sites, load_map, match_sites
from sovarc.compiler.pipeline import Assumed, Options, RunLog, SiteJob, Sites, stage_named
from sovarc.compiler.slots import SiteResult, default_spare, fill_slots
from sovarc.dsl import parse
from sovarc.dsl.errors import SovarcError
from sovarc.dsl.ir import RoadKind, Scenario
from timing import percentile

ROADS = 3


@dataclass
class Run:
    """One scenario on one site of one map (site is None when no site was found for it)."""

    map: str
    scenario: str
    kind: str
    participants: int
    site: str | None
    ok: bool
    reason: str | None
    seconds: float | None  # lower_on + synthesize for this site, and for the sites it replaced
    given_up: int = 0  # sites tried for this slot that could not host the crash


def _maps() -> dict[str, Path]:
    return {"town": TOWN, "DRT osm": DRT}


def _import_truth(out: Path) -> list[tuple[str, Scenario]]:
    sovarc = shutil.which("sovarc", path=str(Path(sys.executable).parent)) or "sovarc"
    subprocess.run([sovarc, "import-truth", str(TRUTH), "-o", str(out)], check=True, capture_output=True)
    return [(p.stem, parse(p.read_text(encoding="utf-8"), str(p))) for p in sorted(out.rglob("*.sov"))]


def _reason(error: SovarcError) -> str:
    """The error's first message with the specifics (site ids, numbers, participants) taken out."""
    text = error.diagnostics[0].message if error.diagnostics else str(error)
    text = re.sub(r"(junction|road):\S+", "SITE", text)
    text = re.sub(r"scenario '[^']*'", "scenario", text)
    text = re.sub(r"\b[VP]\d+\b", "X", text)
    text = re.sub(r"\d+(\.\d+)?", "N", text)
    text = text.split(": these facts conflict")[0] + (": facts conflict" if "facts conflict" in text else "")
    return f"{type(error).__name__}: {text[:110]}"


def _stage(
    map_name: str, road_map: RoadMap, name: str, scenario: Scenario, seed: int, spare: int
) -> tuple[list[Run], float]:
    kind = scenario.road.kind.value if isinstance(scenario.road.kind, RoadKind) else "unknown"
    base = {"map": map_name, "scenario": name, "kind": kind, "participants": len(scenario.participants)}
    start = time.perf_counter()
    try:
        staged, notes = assume(scenario)
        matches = match_sites(staged, road_map, n=ROADS + spare, seed=seed, clamp=True)
    except SovarcError as error:
        search = time.perf_counter() - start
        return [Run(**base, site=None, ok=False, reason=_reason(error), seconds=None)] * ROADS, search
    except Exception as error:  # a crash: as below
        search = time.perf_counter() - start
        reason = f"CRASH {type(error).__name__}: {error}"
        return [Run(**base, site=None, ok=False, reason=reason, seconds=None)] * ROADS, search
    search = time.perf_counter() - start
    seconds: dict[str, float] = {}
    crashes: dict[str, str] = {}

    def attempt(match: Any) -> SiteResult:
        start = time.perf_counter()
        try:
            job = SiteJob(Sites(Assumed(staged, tuple(notes)), road_map, tuple(matches), ROADS), match)
            result = stage_named("stage").run(job, Options(seed=seed), RunLog())
        except Exception as error:  # a crash is a bug: counted and named
            crashes[match.site.id] = f"CRASH {type(error).__name__}: {error}"
            result = SiteResult(match.site.id, error=SovarcError(crashes[match.site.id]))
        seconds[match.site.id] = time.perf_counter() - start
        return result

    runs = []
    for slot in fill_slots(matches, ROADS, attempt):
        spent = seconds[slot.site] + sum(seconds[s.site] for s in slot.skipped)
        reason = None if slot.plan else crashes.get(slot.site) or _reason(slot.error)  # type: ignore[arg-type]
        runs.append(Run(**base, site=slot.site, ok=slot.plan is not None, reason=reason, seconds=spent,
                        given_up=len(slot.skipped)))  # fmt: skip
    missing = ROADS - len(runs)
    runs += [Run(**base, site=None, ok=False, reason=f"only {len(matches)} fitting sites", seconds=None)] * missing
    return runs, search


def _rate(runs: list[Run]) -> str:
    good = sum(r.ok for r in runs)
    return f"{good}/{len(runs)} ({100.0 * good / len(runs):.1f}%)" if runs else "-"


def _map_facts(road_map: RoadMap) -> dict[str, Any]:
    junctions = sum(1 for node in road_map.net.getNodes() if node.getType() != "internal")
    edges = sum(1 for edge in road_map.net.getEdges() if not edge.isSpecial())
    start = time.perf_counter()
    road_map.cache.clear()
    sites = find_sites(road_map)
    find_s = time.perf_counter() - start
    return {"junctions": junctions, "edges": edges, "sites": len(sites), "find_sites_s": find_s}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--limit", type=int, default=0, help="only the first N scenarios (0: all)")
    parser.add_argument("--spare", type=int, default=default_spare(ROADS), help="extra sites tried per scenario")
    parser.add_argument("--json", action="store_true", help="print the figures and every run as JSON")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="sovarc-truth-") as tmp:
        scenarios = _import_truth(Path(tmp))
    if args.limit:
        scenarios = scenarios[: args.limit]
    runs: list[Run] = []
    searches: dict[str, list[float]] = defaultdict(list)
    facts: dict[str, dict[str, Any]] = {}
    for map_name, path in _maps().items():
        start = time.perf_counter()
        road_map = load_map(path)
        load_s = time.perf_counter() - start
        facts[map_name] = {"load_s": load_s, **_map_facts(road_map)}
        road_map.cache.clear()  # the first search below is a cold one
        for name, scenario in scenarios:
            found, search = _stage(map_name, road_map, name, scenario, args.seed, args.spare)
            runs += found
            searches[map_name].append(search)
        facts[map_name]["search_cold_s"] = searches[map_name][0]
    summary = _summary(runs, searches, facts)
    if args.json:
        print(json.dumps({"summary": summary, "runs": [asdict(r) for r in runs]}, indent=1))
    else:
        _print(summary, len(scenarios), args.spare)


def _summary(runs: list[Run], searches: dict[str, list[float]], facts: dict[str, dict[str, Any]]) -> dict[str, Any]:
    timed = [r.seconds for r in runs if r.seconds is not None]
    out: dict[str, Any] = {
        "overall": _rate(runs),
        "per_kind": {k: _rate([r for r in runs if r.kind == k]) for k in sorted({r.kind for r in runs})},
        "per_map": {},
        "failures": Counter(f"{r.map}: {r.reason}" for r in runs if not r.ok).most_common(),
        "crashes": sorted({f"{r.map}: {r.scenario} on {r.site}" for r in runs if (r.reason or "").startswith("CRASH")}),
        "given_up": sum(r.given_up for r in runs),
        "replaced": sum(1 for r in runs if r.given_up and r.ok),
        "time_median_s": statistics.median(timed) if timed else None,
        "time_p90_s": percentile(timed, 0.9),
        "by_participants": {},
    }
    for map_name, info in facts.items():
        mine = [r for r in runs if r.map == map_name]
        seconds = [r.seconds for r in mine if r.seconds is not None]
        warm = searches[map_name][1:] or searches[map_name]
        out["per_map"][map_name] = {
            **info,
            "success": _rate(mine),
            "per_kind": {k: _rate([r for r in mine if r.kind == k]) for k in sorted({r.kind for r in mine})},
            "median_s": statistics.median(seconds) if seconds else None,
            "p90_s": percentile(seconds, 0.9),
            "search_median_s": statistics.median(warm),
            "search_max_s": max(warm),
        }
    for count in sorted({r.participants for r in runs}):
        for map_name in facts:
            seconds = [r.seconds for r in runs if r.participants == count and r.map == map_name and r.seconds]
            if seconds:
                out["by_participants"][f"{count} on {map_name}"] = {
                    "runs": len(seconds),
                    "median_s": statistics.median(seconds),
                    "p90_s": percentile(seconds, 0.9),
                }
    return out


def _print(summary: dict[str, Any], count: int, spare: int) -> None:
    print(f"{count} ground-truth scenarios x {ROADS} sites per map; time = lower_on + synthesize per scenario-site")
    print(f"up to {spare} spare sites per scenario: {summary['given_up']} sites could not host their crash,")
    print(f"{summary['replaced']} scenario-sites were then staged on another")
    print()
    header = f"{'map':<8} {'junct':>5} {'edges':>5} {'sites':>5} {'load s':>6} {'find s':>6}"
    print(header + f" {'search med/max/cold s':>21} {'success':>16} {'median s':>8} {'p90 s':>6}")
    for name, m in summary["per_map"].items():
        search = f"{m['search_median_s']:.3f}/{m['search_max_s']:.3f}/{m['search_cold_s']:.3f}"
        print(
            f"{name:<8} {m['junctions']:>5} {m['edges']:>5} {m['sites']:>5} {m['load_s']:>6.2f}"
            f" {m['find_sites_s']:>6.2f}"
            f" {search:>21} {m['success']:>16} {m['median_s']:>8.3f} {m['p90_s']:>6.3f}"
        )
    print()
    print(f"{'road kind':<14} " + " ".join(f"{name:>16}" for name in summary["per_map"]) + f" {'overall':>16}")
    for kind, rate in summary["per_kind"].items():
        cells = " ".join(f"{m['per_kind'].get(kind, '-'):>16}" for m in summary["per_map"].values())
        print(f"{kind:<14} {cells} {rate:>16}")
    print(f"{'all':<14} " + " ".join(f"{m['success']:>16}" for m in summary["per_map"].values()), end="")
    print(f" {summary['overall']:>16}")
    print()
    print(f"overall median {summary['time_median_s']:.3f} s, p90 {summary['time_p90_s']:.3f} s per scenario-site")
    print()
    print(f"{'participants':<22} {'runs':>5} {'median s':>8} {'p90 s':>6}")
    for key, row in summary["by_participants"].items():
        print(f"{key:<22} {row['runs']:>5} {row['median_s']:>8.3f} {row['p90_s']:>6.3f}")
    print()
    print("failures by reason (scenario-sites):")
    for reason, n in summary["failures"]:
        print(f"{n:>4}  {reason}")
    if summary["crashes"]:
        print()
        print("crashes (not a SovarcError: bugs):")
        for crash in summary["crashes"]:
            print(f"      {crash}")


if __name__ == "__main__":
    main()
