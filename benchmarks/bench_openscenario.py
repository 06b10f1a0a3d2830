"""The OpenSCENARIO target on the ground truth, beside the SUMO oracle; and its speed.

    python benchmarks/bench_openscenario.py --truth TRUTH [--roads 3] [-m MAP] [--plans DIR] [--json OUT]
    python benchmarks/bench_openscenario.py [--repeat N]

With --truth (a folder of .sov files, e.g. from `sovarc import-truth`): every scenario is staged
on --roads sites and synthesized; each plan that synthesizes is checked by the SUMO oracle and
emitted as OpenSCENARIO and checked by its oracle. Prints the pass rates per road kind over two
denominators (every scenario-site, scenarios x --roads, where one not planned counts as not
passed; and the planned ones alone), the agreement with the SUMO oracle, every disagreement with
the checks that differ and why, the disagreements by class, whether both oracles saw the same
first touch, the OpenSCENARIO failures by check, and the time per stage. --plans caches the
synthesized plans as JSON, so that a rerun only re-checks them.

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
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # the hand-made plans live with the tests

from maps import TOWN, resolve  # noqa: E402
from sovarc.compiler.maps import load_map, with_opendrive  # noqa: E402
from sovarc.compiler.pipeline import Options as PipelineOptions  # noqa: E402
from sovarc.compiler.pipeline import stage_sites  # noqa: E402
from sovarc.compiler.plan import Plan, dump_plan, plan_from_json  # noqa: E402
from sovarc.compiler.scenario_io import load_scenario  # noqa: E402
from sovarc.compiler.vehicles import CAR  # noqa: E402
from sovarc.dsl.errors import SovarcError  # noqa: E402
from sovarc.targets import sumo  # noqa: E402
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
    stored = cache / f"{path.stem}.json" if cache else None
    if stored is not None and stored.is_file():
        data = json.loads(stored.read_text(encoding="utf-8"))
        for entry in data:
            entry["plan"] = plan_from_json(entry["plan"]) if entry["plan"] else None
        return data
    scenario, _ = load_scenario(path)
    start = time.perf_counter()
    try:
        results = stage_sites(scenario, PipelineOptions(map=road_map, roads=args.roads, seed=args.seed))
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
                plan = replace(plan, network=with_opendrive(plan.network))  # as compiler.emit gives it the target
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


# Classes of disagreement, each explained once in the summary; a plan's own figures go with it.
REAR_CORNER = "first touch at the victim's rear corner, before C_A"
SIDE_EARLY = "first touch on the victim's side, before C_A"
CLASSES: dict[str, str] = {
    REAR_CORNER: (
        "plan defect (lowering): the striker closes on the victim from behind, a few degrees off its "
        "heading and faster, so its front meets the victim's rear corner before it reaches the middle of the "
        "side planned in C_A: an offset rear-end, earlier and elsewhere than the planned side hit. The OSC "
        "oracle wants the first touch in C_A (a player records the crash at the first touch); SUMO's oracle "
        "judges only the faces and angle at the first touch, where a rear corner counts as a side"
    ),
    SIDE_EARLY: (
        "plan defect (lowering): on a shallow merge or pull-out the striker's sideways move brings its front "
        "against the victim's side before the point planned in C_A, so the pair first touches early and "
        "outside C_A. The OSC oracle wants the first touch in C_A; SUMO's oracle does not look at C_A"
    ),
    "first touch outside C_A": (
        "plan defect: the pair first touches away from the planned crash; SUMO's oracle judges the first "
        "collision wherever it happens"
    ),
    "overlap from the start": (
        "plan defect: striker and victim start inside each other; SUMO's oracle takes that for the crash"
    ),
    "never touch": "striker and victim never touch in the file, yet SUMO's replay saw them collide",
}
CLASSES |= {f"{c} (SUMO only)": why for c, why in SUMO_ONLY.items()}
CLASSES |= {f"{c} (OSC only)": why for c, why in OSC_ONLY.items()}


# Known causes of faces named differently at the same first touch (SUMO's in compiler/geometry/bodies.first_touch).
FACE_CAUSES = {
    "flat contact": (
        "the faces meet flat (headings within 1°): where along the touching stretch the contact lies turns on "
        "sub-millimetre differences in pose (SUMO judges its replayed poses, the OSC oracle the file's) and on "
        "each oracle's rule for the nearest points; the faces are the same up to a corner"
    ),
    "overlapping from the start": "the bodies start inside each other: there is no first touch to read faces at",
}


def _face_cause(sumo: dict[str, Any], osc: dict[str, Any]) -> str:
    """Which of FACE_CAUSES explains faces named differently ('unexplained' if none)."""
    if osc["first_contact_time"] == 0.0:
        return "overlapping from the start"
    if min(sumo["angle"], 180.0 - sumo["angle"]) <= 1.0:
        return "flat contact"
    return "unexplained"


@dataclass(frozen=True)
class Reason:
    kind: str  # a key of CLASSES, or 'judged differently: ...'
    detail: str = ""  # this plan's figures


def explain(row: Row) -> list[Reason]:
    """Why the two oracles disagree on a plan, from the checks that failed on each side."""
    assert row.sumo is not None and row.osc is not None
    sumo, osc = _failed(row.sumo), _failed(row.osc)
    reasons = [Reason(f"{c} (SUMO only)", _message(row.sumo, {c})) for c in sorted(sumo) if c in SUMO_ONLY]
    reasons += [Reason(f"{c} (OSC only)", _message(row.osc, {c})) for c in sorted(osc) if c in OSC_ONLY]
    if "first_contact" in osc:
        reasons.append(_touch_reason(row.osc))
    shared = (sumo - set(SUMO_ONLY)) ^ (osc - set(OSC_ONLY) - {"first_contact"})
    if shared:
        reasons.append(Reason("judged differently: " + ", ".join(sorted(shared))))
    return reasons


def _why(reasons: list[Reason]) -> str:
    return "; ".join(f"{r.kind} ({r.detail})" if r.detail else r.kind for r in reasons) or "same checks fail"


def _touch_reason(osc: Verdict) -> Reason:
    """first_contact failed: where the pair really meets, against the plan."""
    facts = osc.facts
    first, planned = facts.get("first_contact_time"), facts.get("impact_time")
    if first is None:
        return Reason("never touch")
    if first == 0.0:
        return Reason("overlap from the start")
    when = f"{abs(planned - first):.2f} s {'before' if first < planned else 'after'} the planned impact"
    finding = next(f for f in osc.failures if f.check == "first_contact")
    where = finding.message.partition("outside C_A: ")[2]
    meet = (
        f"{facts.get('striker_face')} of {facts.get('striker')} into {facts.get('victim_face')} of "
        f"{facts.get('victim')} at {facts.get('relative_heading')}°"
    )
    detail = f"{when}; {where}; {meet}"
    if facts.get("crash_type") == "side" and first < planned:
        victim = str(facts.get("victim_face", "")).split("-")
        return Reason(REAR_CORNER if "rear" in victim else SIDE_EARLY, detail)
    return Reason("first touch outside C_A", detail)


def _message(verdict: Verdict, checks: set[str]) -> str:
    return " | ".join(f"{f.check}: {f.message}" for f in verdict.failures if f.check in checks)


def _rates(rows: list[Row], roads: int) -> None:
    """Pass rates per road kind: of every scenario-site (scenarios x roads), and of the planned ones."""
    scenarios = {r.scenario: r.kind for r in rows}
    planned = [r for r in rows if r.osc is not None and r.sumo is not None]
    sites = len(scenarios) * roads
    placed = sum(r.site != "-" for r in rows)
    failed = sum(r.site != "-" and r.error is not None for r in rows)
    print(f"ground truth: {len(scenarios)} scenarios x {roads} sites = {sites} scenario-sites")
    print(
        f"  planned (synthesized, judged by both oracles): {len(planned)}; not planned: {sites - len(planned)}"
        f" ({sites - placed} for want of a fitting site on the map, {failed} failed in lowering or synthesis)"
    )
    print("  'of sites' counts a scenario-site that was not planned as not passed; 'of planned' leaves it out")
    head = f"{'pass':>5}{'of sites':>10}{'of planned':>12}"
    print(f"\n{'road kind':<14}{'sites':>6}{'planned':>8} | OSC {head} | SUMO {head} | {'agree of planned':>16}")
    for kind in [*sorted(set(scenarios.values())), "all"]:
        n_sites = roads * sum(kind in ("all", k) for k in scenarios.values())
        chosen = [r for r in planned if kind in ("all", r.kind)]
        osc = sum(bool(r.osc and r.osc.passed) for r in chosen)
        sumo = sum(bool(r.sumo and r.sumo.passed) for r in chosen)
        agree = sum(r.agree for r in chosen)
        n = len(chosen)
        print(
            f"{kind:<14}{n_sites:>6}{n:>8} | OSC {osc:>5}{_pct(osc, n_sites):>10}{_pct(osc, n):>12}"
            f" | SUMO {sumo:>5}{_pct(sumo, n_sites):>10}{_pct(sumo, n):>12} | {agree:>9}{_pct(agree, n):>7}"
        )


def _pct(n: int, of: int) -> str:
    return f"{100 * n / of:.1f}%" if of else "-"


def _disagreements(planned: list[Row]) -> None:
    both = Counter((r.sumo.passed, r.osc.passed) for r in planned if r.sumo and r.osc)
    print(
        f"\nboth pass {both[(True, True)]}, both fail {both[(False, False)]}, "
        f"only SUMO passes {both[(True, False)]}, only OSC passes {both[(False, True)]}"
    )
    print("\ndisagreements (scenario, site, SUMO | OSC failed checks, why):")
    classes: dict[str, list[Row]] = defaultdict(list)
    for r in planned:
        if r.agree:
            continue
        assert r.sumo is not None and r.osc is not None
        sumo, osc = _failed(r.sumo), _failed(r.osc)
        reasons = explain(r)
        for reason in reasons:
            classes[reason.kind].append(r)
        print(f"  {r.scenario} {r.site}: SUMO {sorted(sumo) or 'pass'} | OSC {sorted(osc) or 'pass'}")
        print(f"    why: {_why(reasons)}")
        if sumo:
            print(f"    SUMO: {_message(r.sumo, sumo)}")
        if osc:
            print(f"    OSC: {_message(r.osc, osc)}")
    print("\ndisagreements by class (a plan may fall in several):")
    for kind, chosen in sorted(classes.items(), key=lambda item: -len(item[1])):
        print(f"  {kind} ({len(chosen)}): " + ", ".join(f"{r.scenario}@{r.site}" for r in chosen))
        print(f"    {CLASSES.get(kind, 'the two oracles judge the same check differently: read both messages')}")


def _same_touch(sumo: dict[str, Any], osc: dict[str, Any]) -> tuple[bool, bool, bool]:
    """Whether the two oracles' first touches agree in time (0.03 s), angle (3°) and faces."""
    return (
        abs(sumo["time"] - osc["first_contact_time"]) <= 0.03,
        abs(sumo["angle"] - osc["relative_heading"]) <= 3.0,
        (sumo["striker_face"], sumo["victim_face"]) == (osc["striker_face"], osc["victim_face"]),
    )


def _first_touches(planned: list[Row]) -> None:
    """Whether both oracles saw the same first touch, and where not, what each saw."""
    pairs = [
        (r, r.sumo.facts["impact"], r.osc.facts)
        for r in planned
        if r.sumo and r.osc and "impact" in r.sumo.facts and "victim_face" in r.osc.facts
    ]
    same = [_same_touch(s, o) for _, s, o in pairs]
    counts = [sum(flags[k] for flags in same) for k in range(3)]
    print(
        f"\nfirst touch, SUMO beside OSC ({len(pairs)} plans where both see one): time within 0.03 s {counts[0]},"
        f" angle within 3° {counts[1]}, same faces {counts[2]}"
    )
    causes: Counter[str] = Counter()
    for (r, s, o), flags in zip(pairs, same, strict=True):
        if not all(flags):
            cause = _face_cause(s, o) if flags[:2] == (True, True) else "time or angle differ"
            causes[cause] += 1
            print(
                f"  {r.scenario} {r.site}: SUMO {s['striker_face']}/{s['victim_face']} {s['angle']}° t={s['time']}"
                f" | OSC {o['striker_face']}/{o['victim_face']} {o['relative_heading']}° t={o['first_contact_time']}"
                f" ({cause})"
            )
    for cause, n in causes.most_common():
        print(f"  {cause} ({n}): {FACE_CAUSES.get(cause, 'read both verdicts')}")


def report(rows: list[Row], roads: int) -> None:
    planned = [r for r in rows if r.osc is not None and r.sumo is not None]
    _rates(rows, roads)
    _disagreements(planned)
    _first_touches(planned)
    by_check: dict[str, list[Row]] = defaultdict(list)
    for r in planned:
        for c in sorted(_failed(r.osc)):
            by_check[c].append(r)
    print("\nOpenSCENARIO failures by check (a plan may fail several):")
    for c, chosen in sorted(by_check.items(), key=lambda item: -len(item[1])):
        print(f"  {c} ({len(chosen)}): " + ", ".join(f"{r.scenario}@{r.site}" for r in chosen))
    print("\nnot planned (lowering or synthesis; not judged by either oracle):")
    for r in rows:
        if r.error is not None:
            print(f"  {r.scenario} {r.site}: {r.error}")
    print("\ntime per scenario-site, median (max):")
    for stage in ("synthesize", "sumo check", "osc emit", "osc check"):
        values = [r.seconds[stage] for r in planned if stage in r.seconds]
        if values:
            print(f"  {stage:<12}{statistics.median(values) * 1e3:9.0f} ms ({max(values) * 1e3:.0f} ms)")


def dump(rows: list[Row], out: str) -> None:
    def side(v: Verdict | None) -> dict[str, Any] | None:
        return None if v is None else {"passed": v.passed, "failures": [[f.check, f.message] for f in v.failures]}

    data = [
        {"scenario": r.scenario, "kind": r.kind, "site": r.site, "error": r.error, "sumo": side(r.sumo),
         "openscenario": side(r.osc), "why": None if r.agree or r.osc is None else _why(explain(r)),
         "classes": [] if r.agree or r.osc is None else [c.kind for c in explain(r)]}
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
    parser.add_argument("-m", "--map", type=resolve, default=TOWN, help="a file or a map's name (default: the town)")
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
    report(rows, args.roads)
    print(f"  wall time   {time.perf_counter() - start:9.1f} s")
    if args.json:
        dump(rows, args.json)


if __name__ == "__main__":
    main()
