"""End-to-end back-end time per scenario-site: lower, synthesize, emit and check (SUMO), per stage.

    .venv/bin/python benchmarks/bench_backend.py TRUTH_DIR [-m MAP ...] [--roads 3]

TRUTH_DIR holds .sov files (e.g. `sovarc import-truth ../shared/data/nmvccs/truth/*/*.json -o truth`).
Each scenario is staged on --roads sites of each map (default: the example town); every site is
timed on its own, from lowering to the SUMO oracle's verdict. As in `sovarc`, a site that cannot
host the crash is replaced by the next one (up to --spare more tries per scenario); a site's time
includes the tries it replaced. Site search is timed once per scenario and reported apart.

The machine may be shared, so each stage is measured in CPU time (`time.process_time`, this
process only) beside wall time, and the load average is printed with the figures. Lowering and
synthesis are told apart by timing the staging search's two calls (`stagings_on`, whose every
step lowers one staging, and `synthesize`) where `staging.py` makes them; nothing else changes.
Prints, per map, the median and p90 of each stage and of their sum, and the pass rate.
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from collections import defaultdict
from collections.abc import Iterator
from contextlib import contextmanager
from functools import partial
from pathlib import Path
from types import SimpleNamespace
from typing import Any

from maps import TOWN, add_map_argument
from sovarc.compiler import staging, synth
from sovarc.compiler.maps import SiteMatch, load_map
from sovarc.compiler.pipeline import Options, RunLog, SiteJob, Sites, run_pipeline, stage_named
from sovarc.compiler.slots import SiteResult, default_spare, fill_slots
from sovarc.dsl import parse
from sovarc.dsl.errors import SovarcError
from sovarc.targets.sumo import check, emit
from timing import percentile

STAGES = ("lower", "synthesize", "emit", "check")

Spent = dict[str, list[float]]  # stage -> [cpu s, wall s]


class Clock:
    """CPU and wall seconds per stage, added up until `take` hands them over and starts afresh."""

    def __init__(self) -> None:
        self.spent: Spent = defaultdict(lambda: [0.0, 0.0])

    @contextmanager
    def stage(self, name: str) -> Iterator[None]:
        cpu, wall = time.process_time(), time.perf_counter()
        try:
            yield
        finally:
            self.spent[name][0] += time.process_time() - cpu
            self.spent[name][1] += time.perf_counter() - wall

    def take(self) -> Spent:
        spent, self.spent = dict(self.spent), defaultdict(lambda: [0.0, 0.0])
        return spent


def _instrument(clock: Clock) -> None:
    """Time the staging search's lowering steps and synthesis calls in place (see the docstring)."""
    stagings_on = staging.stagings_on

    def timed_stagings(*args: Any, **kwargs: Any) -> Iterator[Any]:
        found = stagings_on(*args, **kwargs)
        while True:
            with clock.stage("lower"):
                item = next(found, None)
            if item is None:
                return
            yield item

    def timed_synthesize(*args: Any, **kwargs: Any) -> Any:
        with clock.stage("synthesize"):
            return synth.synthesize(*args, **kwargs)

    staging.stagings_on = timed_stagings  # type: ignore[assignment]
    staging.synth = SimpleNamespace(synthesize=timed_synthesize)  # type: ignore[assignment]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("truth", type=Path)
    add_map_argument(parser, "the example town")
    parser.add_argument("--roads", type=int, default=3)
    parser.add_argument("--spare", type=int, help="extra sites tried per scenario (default: three times --roads)")
    args = parser.parse_args()
    clock = Clock()
    _instrument(clock)
    for path in args.map or [TOWN]:
        _bench_map(path, args, clock)


def _bench_map(map_path: Path, args: argparse.Namespace, clock: Clock) -> None:
    spare = default_spare(args.roads) if args.spare is None else args.spare
    load_before = os.getloadavg()[0]
    cpu, wall = time.process_time(), time.perf_counter()
    road_map = load_map(map_path)
    loaded = (time.process_time() - cpu, time.perf_counter() - wall)
    options = Options(map=road_map, roads=args.roads, spare=spare)
    per_site: list[Spent] = []
    searches: list[float] = []
    passed = attempted = replaced = 0
    cpu_all, wall_all = time.process_time(), time.perf_counter()
    for path in sorted(args.truth.glob("*.sov")):
        scenario = parse(path.read_text(encoding="utf-8"), str(path))
        attempted += args.roads
        start = time.process_time()
        try:
            sites, _ = run_pipeline(scenario, start="assume", stop="sites", options=options)
        except SovarcError:
            continue
        searches.append(time.process_time() - start)
        tried: dict[str, Spent] = {}
        for slot in fill_slots(sites.candidates, args.roads, partial(_timed_plan, sites, options, clock, tried)):
            if slot.plan is not None:
                with tempfile.TemporaryDirectory(prefix="bench-backend-") as tmp:
                    with clock.stage("emit"):
                        emit(slot.plan, tmp)
                    with clock.stage("check"):
                        passed += check(slot.plan, tmp).passed
            spent = clock.take()
            for given_up in (tried[s.site] for s in [slot, *slot.skipped]):
                for stage, (c, w) in given_up.items():
                    spent.setdefault(stage, [0.0, 0.0])
                    spent[stage][0] += c
                    spent[stage][1] += w
            per_site.append(spent)
            replaced += bool(slot.skipped)
    cpu_all, wall_all = time.process_time() - cpu_all, time.perf_counter() - wall_all
    if not per_site:
        print(f"map {map_path.name}: no scenario has a fitting site")
        return
    print(f"map {map_path.name}: {attempted} scenario-sites, {len(per_site)} staged or tried, "
          f"{passed} pass the SUMO oracle; load average {load_before:.1f} -> {os.getloadavg()[0]:.1f}")  # fmt: skip
    print(f"  load_map: {loaded[0]:.2f} s CPU, {loaded[1]:.2f} s wall; "
          f"site search per scenario: median {statistics.median(searches) * 1e3:.1f} ms CPU")  # fmt: skip
    print(f"  sites that took the place of one that could not host the crash: {replaced} (up to {spare} spare tries)")
    print(f"  {'per scenario-site':<18} {'CPU median':>10} {'CPU p90':>8} {'wall median':>11} {'wall p90':>8}")
    for stage in (*STAGES, "total"):
        cpus = [_seconds(s, stage, 0) for s in per_site]
        walls = [_seconds(s, stage, 1) for s in per_site]
        print(f"  {stage:<18} {statistics.median(cpus):>10.3f} {percentile(cpus, 0.9):>8.3f} "
              f"{statistics.median(walls):>11.3f} {percentile(walls, 0.9):>8.3f}")  # fmt: skip
    print(f"  whole run: {cpu_all:.1f} s CPU, {wall_all:.1f} s wall")


def _seconds(spent: Spent, stage: str, which: int) -> float:
    if stage == "total":
        return sum(v[which] for v in spent.values())
    return spent.get(stage, [0.0, 0.0])[which]


def _timed_plan(sites: Sites, options: Options, clock: Clock, tried: dict[str, Spent], match: SiteMatch) -> SiteResult:
    """The pipeline's stage stage on one site (lower and synthesize), its seconds kept in `tried`."""
    result = stage_named("stage").run(SiteJob(sites, match), options, RunLog())
    tried[match.site.id] = clock.take()
    return result


if __name__ == "__main__":
    main()
