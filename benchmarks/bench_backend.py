"""End-to-end back-end time per scenario-site: lower, synthesize, emit and check (SUMO).

    .venv/bin/python benchmarks/bench_backend.py TRUTH_DIR [-m MAP] [--roads 3]

TRUTH_DIR holds .sov files (e.g. `sovarc import-truth ../shared/data/nmvccs/truth -o truth`).
Each scenario is staged on --roads sites of the map (default: the example town); every site
is timed on its own, from lowering to the SUMO oracle's verdict. As in `sovarc`, a site that
cannot host the crash is replaced by the next one (up to --spare more tries per scenario); a
site's time includes the tries it replaced. Site search is timed once per scenario and reported
apart. Prints the median, p90 and total, and the pass rate.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from functools import partial
from pathlib import Path

from sovarc.compiler.maps import SiteMatch, load_map
from sovarc.compiler.pipeline import Options, RunLog, SiteJob, Sites, run_pipeline, stage_named
from sovarc.compiler.slots import SiteResult, default_spare, fill_slots
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
    parser.add_argument("--spare", type=int, help="extra sites tried per scenario (default: three times --roads)")
    args = parser.parse_args()
    spare = default_spare(args.roads) if args.spare is None else args.spare
    road_map = load_map(args.map)
    options = Options(map=road_map, roads=args.roads, spare=spare)
    seconds, searches, passed, attempted, replaced = [], [], 0, 0, 0
    start_all = time.perf_counter()
    for path in sorted(args.truth.glob("*.sov")):
        scenario = parse(path.read_text(encoding="utf-8"), str(path))
        start = time.perf_counter()
        try:
            sites, _ = run_pipeline(scenario, start="assume", stop="sites", options=options)
        except SovarcError:
            attempted += args.roads
            continue
        searches.append(time.perf_counter() - start)
        attempted += args.roads
        spent: dict[str, float] = {}
        attempt = partial(_timed_plan, sites, options, spent)
        for slot in fill_slots(sites.candidates, args.roads, attempt):
            start = time.perf_counter()
            if slot.plan is not None:
                with tempfile.TemporaryDirectory(prefix="bench-backend-") as tmp:
                    emit(slot.plan, tmp)
                    passed += check(slot.plan, tmp).passed
            given_up = sum(spent[s.site] for s in slot.skipped)
            seconds.append(time.perf_counter() - start + spent[slot.site] + given_up)
            replaced += bool(slot.skipped)
    total = time.perf_counter() - start_all
    print(f"map {args.map.name}: {attempted} scenario-sites, {passed} pass the SUMO oracle")
    print(f"sites that took the place of one that could not host the crash: {replaced} (up to {spare} spare tries)")
    print(f"per scenario-site (lower + synthesize + emit + check): median {statistics.median(seconds):.3f} s, "
          f"p90 {percentile(seconds, 0.9):.3f} s, max {max(seconds):.3f} s")  # fmt: skip
    print(f"site search per scenario: median {statistics.median(searches) * 1e3:.1f} ms")
    print(f"whole run: {total:.1f} s")


def _timed_plan(sites: Sites, options: Options, spent: dict[str, float], match: SiteMatch) -> SiteResult:
    """The pipeline's stage stage on one site (lower and synthesize), noting the seconds it took in `spent`."""
    start = time.perf_counter()
    result = stage_named("stage").run(SiteJob(sites, match), options, RunLog())
    spent[match.site.id] = time.perf_counter() - start
    return result


if __name__ == "__main__":
    main()
