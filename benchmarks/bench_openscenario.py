"""The OpenSCENARIO target on the ground truth, beside the SUMO oracle; and its speed.

    python benchmarks/bench_openscenario.py --truth TRUTH [--roads 3] [-m MAP] [--plans DIR] [--json OUT]
    python benchmarks/bench_openscenario.py [--repeat N]

With --truth (a folder of .sov files, e.g. from `sovarc import-truth`): every scenario is staged
on --roads sites and synthesized; each plan that synthesizes is checked by the SUMO oracle and
emitted as OpenSCENARIO and checked by its oracle. Prints the OpenSCENARIO pass rate per road
kind, the agreement with the SUMO oracle, every disagreement with the checks that differ and why,
the OpenSCENARIO failures by check, and the time per stage. --plans caches the synthesized plans
as JSON, so that a rerun only re-checks them.

Without --truth: emit and check times of the tests' hand-made plans, plus a long T-bone (impact
at 60 s, about 600 vertices per participant). Prints figures; asserts nothing.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from collections import Counter, defaultdict
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # the hand-made plans live with the tests

from sovarc.compiler.plan import CAR, Plan, dump_plan, plan_from_json  # noqa: E402
from sovarc.targets.openscenario import check, choose_ego, emit_files  # noqa: E402
from sovarc.targets.openscenario.emit import build_document  # noqa: E402
from sovarc.targets.openscenario.provenance import Options  # noqa: E402
from sovarc.targets.openscenario.roadnet import write_road_network  # noqa: E402
from sovarc.targets.openscenario.versions import dialect  # noqa: E402
from sovarc.targets.verdict import Verdict  # noqa: E402
from timing import median_ms  # noqa: E402

from tests.targets.openscenario.plans import CASES, make_plan, straight  # noqa: E402

# --- the ground truth, beside the SUMO oracle -----------------------------------------------

# Checks only one oracle makes: a failure of one of them is a disagreement by design.
SUMO_ONLY = {
    "replay": "SUMO could not follow the trajectory; the OSC oracle reads the file, not a replay",
    "lane_lines": "the OSC oracle does not check lane lines",
}
OSC_ONLY = {
    "speed": "SUMO replays any speed",
    "acceleration": "SUMO replays any acceleration",
    "collision_area": "SUMO's oracle does not look at C_A",
    "stop_trigger": "SUMO runs to the end of the plan",
}


@dataclass
class Row:
    scenario: str
    kind: str
    site: str
    error: str | None = None  # planning or synthesis failed
    sumo: Verdict | None = None
    osc: Verdict | None = None
    seconds: dict[str, float] = field(default_factory=dict)

    @property
    def agree(self) -> bool:
        return self.sumo is not None and self.osc is not None and self.sumo.passed == self.osc.passed


def _plans(path: Path, road_map: Any, args: argparse.Namespace, cache: Path | None) -> list[dict[str, Any]]:
    """[{site, plan | None, error | None, synth_s}] for one scenario, from the cache when it has it."""
    from sovarc.compiler.backend import plans_for
    from sovarc.compiler.scenario_io import load_scenario
    from sovarc.dsl.errors import SovarcError

    stored = cache / f"{path.stem}.json" if cache else None
    if stored is not None and stored.is_file():
        data = json.loads(stored.read_text(encoding="utf-8"))
        for entry in data:
            entry["plan"] = plan_from_json(entry["plan"]) if entry["plan"] else None
        return data
    scenario, _ = load_scenario(path)
    start = time.perf_counter()
    try:
        results = plans_for(scenario, road_map, args.roads, args.seed)
    except SovarcError as exc:  # no site of the kind at all
        results, message = [], exc.diagnostics[0].message if exc.diagnostics else str(exc)
        entries = [{"site": "-", "plan": None, "error": message, "synth_s": 0.0}]
    else:
        each = (time.perf_counter() - start) / max(1, len(results))
        entries = [
            {
                "site": r.site,
                "plan": r.plan,
                "error": None if r.error is None else r.error.diagnostics[0].message,
                "synth_s": each,
            }
            for r in results
        ]
    if stored is not None:
        stored.parent.mkdir(parents=True, exist_ok=True)
        plain = [e | {"plan": json.loads(dump_plan(e["plan"])) if e["plan"] else None} for e in entries]
        stored.write_text(json.dumps(plain) + "\n", encoding="utf-8")
    return entries


def evaluate(args: argparse.Namespace) -> list[Row]:
    from sovarc.compiler.maps import load_map
    from sovarc.compiler.scenario_io import load_scenario
    from sovarc.targets import sumo

    road_map = load_map(args.map)
    files = sorted(Path(args.truth).glob("*.sov"))
    rows: list[Row] = []
    cache = Path(args.plans) if args.plans else None
    with tempfile.TemporaryDirectory(prefix="bench-osc-") as tmp:
        for n, path in enumerate(files, 1):
            scenario, _ = load_scenario(path)
            kind = scenario.road.kind.value
            for entry in _plans(path, road_map, args, cache):
                row = Row(path.stem, kind, entry["site"], entry["error"])
                rows.append(row)
                plan: Plan | None = entry["plan"]
                if plan is None:
                    continue
                row.seconds["synthesize"] = entry["synth_s"]
                start = time.perf_counter()
                row.sumo = sumo.check(plan)
                row.seconds["sumo check"] = time.perf_counter() - start
                folder = Path(tmp) / f"{path.stem}-{len(rows)}"
                start = time.perf_counter()
                files_ = emit_files(plan, folder, args.version)
                row.seconds["osc emit"] = time.perf_counter() - start
                start = time.perf_counter()
                row.osc = check(files_.xosc, plan)
                row.seconds["osc check"] = time.perf_counter() - start
            print(f"\r{n}/{len(files)} scenarios", end="", file=sys.stderr, flush=True)
    print(file=sys.stderr)
    return rows


def _failed(verdict: Verdict | None) -> set[str]:
    return set() if verdict is None else {f.check for f in verdict.failures}


def explain(row: Row) -> str:
    """Why the two oracles disagree on a plan, from the checks that failed on each side."""
    assert row.sumo is not None and row.osc is not None
    sumo, osc = _failed(row.sumo), _failed(row.osc)
    reasons = [f"{c}: {SUMO_ONLY[c]}" for c in sorted(sumo) if c in SUMO_ONLY]
    reasons += [f"{c}: {OSC_ONLY[c]}" for c in sorted(osc) if c in OSC_ONLY]
    if "first_contact" in osc:
        reasons.append(_early_touch(row.osc))
    shared = (sumo - set(SUMO_ONLY)) ^ (osc - set(OSC_ONLY) - {"first_contact"})
    if shared:
        reasons.append("judged differently: " + ", ".join(sorted(shared)))
    return "; ".join(reasons) or "same checks fail on both sides"


def _early_touch(osc: Verdict) -> str:
    """first_contact failed: where the pair really meets, against the plan."""
    first, planned = osc.facts.get("first_contact_time"), osc.facts.get("impact_time")
    if first is None:
        return "first_contact: striker and victim never touch in the file"
    if first == 0.0:
        return (
            "first_contact: striker and victim overlap from the start (plan defect: their start positions"
            " collide); SUMO's oracle takes that for the crash"
        )
    when = f"{abs(planned - first):.2f} s {'before' if first < planned else 'after'} the planned impact"
    return (
        f"first_contact: the pair first touches {when}, outside C_A (plan defect: the crash happens elsewhere "
        "than planned); SUMO's oracle judges the first collision wherever it happens"
    )


def _message(verdict: Verdict, checks: set[str]) -> str:
    return " | ".join(f"{f.check}: {f.message}" for f in verdict.failures if f.check in checks)


def report(rows: list[Row]) -> None:
    checked = [r for r in rows if r.osc is not None and r.sumo is not None]
    print(f"ground truth: {len({r.scenario for r in rows})} scenarios, {len(rows)} scenario-sites")
    print(f"synthesized: {len(checked)}; planning or synthesis failed: {len(rows) - len(checked)}")
    print(f"\n{'road kind':<14}{'plans':>6}{'OSC pass':>14}{'SUMO pass':>14}{'agree':>14}")
    kinds = sorted({r.kind for r in checked})
    for kind in [*kinds, "all"]:
        chosen = [r for r in checked if kind in ("all", r.kind)]
        n = max(1, len(chosen))
        osc = sum(r.osc.passed for r in chosen if r.osc)
        sumo = sum(r.sumo.passed for r in chosen if r.sumo)
        agree = sum(r.agree for r in chosen)
        print(
            f"{kind:<14}{len(chosen):>6}{osc:>6} {100 * osc / n:5.1f}%{sumo:>6} {100 * sumo / n:5.1f}%"
            f"{agree:>6} {100 * agree / n:5.1f}%"
        )
    both = Counter((r.sumo.passed, r.osc.passed) for r in checked if r.sumo and r.osc)
    print(
        f"\nboth pass {both[(True, True)]}, both fail {both[(False, False)]}, "
        f"only SUMO passes {both[(True, False)]}, only OSC passes {both[(False, True)]}"
    )
    print("\ndisagreements (scenario, site, SUMO | OSC failed checks, why):")
    for r in checked:
        if r.agree:
            continue
        assert r.sumo is not None and r.osc is not None
        sumo, osc = _failed(r.sumo), _failed(r.osc)
        print(f"  {r.scenario} {r.site}: SUMO {sorted(sumo) or 'pass'} | OSC {sorted(osc) or 'pass'}")
        print(f"    why: {explain(r)}")
        if sumo:
            print(f"    SUMO: {_message(r.sumo, sumo)}")
        if osc:
            print(f"    OSC: {_message(r.osc, osc)}")
    by_check: dict[str, list[Row]] = defaultdict(list)
    for r in checked:
        for c in sorted(_failed(r.osc)):
            by_check[c].append(r)
    print("\nOpenSCENARIO failures by check (a plan may fail several):")
    for c, chosen in sorted(by_check.items(), key=lambda item: -len(item[1])):
        print(f"  {c} ({len(chosen)}): " + ", ".join(f"{r.scenario}@{r.site}" for r in chosen))
    print("\ntime per scenario-site, median (max):")
    for stage in ("synthesize", "sumo check", "osc emit", "osc check"):
        values = [r.seconds[stage] for r in checked if stage in r.seconds]
        if values:
            print(f"  {stage:<12}{statistics.median(values) * 1e3:9.0f} ms ({max(values) * 1e3:.0f} ms)")


def dump(rows: list[Row], out: str) -> None:
    def side(v: Verdict | None) -> dict[str, Any] | None:
        return None if v is None else {"passed": v.passed, "failures": [[f.check, f.message] for f in v.failures]}

    data = [
        {"scenario": r.scenario, "kind": r.kind, "site": r.site, "error": r.error, "sumo": side(r.sumo),
         "openscenario": side(r.osc), "why": None if r.agree or r.osc is None else explain(r)}
        for r in rows
    ]  # fmt: skip
    Path(out).write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")


# --- speed on hand-made plans ----------------------------------------------------------------


def long_t_bone(t_hit: float = 60.0) -> Plan:
    y2, point = -8.25, (4.5, -8.25 - CAR.width / 2)
    motions = {
        "V1": straight(4.5, point[1], 0.0, 1.0, t_hit),
        "V2": straight(4.5 + CAR.length / 2, y2, 90.0, 1.0, t_hit),
    }
    return make_plan("intersection_red_light_runner_side", "junction:x_main", t_hit, point, motions)


def hand_made(args: argparse.Namespace) -> None:
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
            document = median_ms(lambda p=plan, o=options: build_document(p, "town.xodr", o, d), args.repeat)
            emitted = emit_files(plan, folder, d.version)
            emit = median_ms(lambda p=plan, f=folder: emit_files(p, f, d.version), args.repeat)
            checking = median_ms(lambda x=emitted.xosc, p=plan: check(x, p), args.repeat)
            verdict = check(emitted.xosc, plan)
            vertices = sum(len(t.samples) for t in plan.trajectories)
            size = emitted.xosc.stat().st_size / 1024
            status = "pass" if verdict.passed else "FAIL " + ", ".join(f.check for f in verdict.failures)
            print(f"{name:<12} {vertices:>8} {size:>8.1f} {document:>12.1f} {emit:>8.1f} {checking:>9.1f}  {status}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--truth", help="folder of ground-truth .sov files: compare with the SUMO oracle")
    parser.add_argument("-m", "--map", default=str(ROOT / "examples" / "maps" / "town.net.xml"))
    parser.add_argument("--roads", type=int, default=3, help="sites per scenario (default 3)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--plans", help="folder caching the synthesized plans (read if there, else written)")
    parser.add_argument("--json", help="with --truth: also write every scenario-site's verdicts here")
    parser.add_argument("--repeat", type=int, default=5, help="without --truth: runs per hand-made plan")
    parser.add_argument("--version", default="1.3", help="OpenSCENARIO version (default 1.3)")
    args = parser.parse_args()
    if not args.truth:
        hand_made(args)
        return
    start = time.perf_counter()
    rows = evaluate(args)
    report(rows)
    print(f"  wall time   {time.perf_counter() - start:9.1f} s")
    if args.json:
        dump(rows, args.json)


if __name__ == "__main__":
    main()
