"""Issue 20's first target, measured: each new road user and move compiles to all three targets on the
bundled town and on CARLA towns, and passes every oracle, esmini included.

    ESMINI=.../esmini python benchmarks/bench_kinds.py [-m MAP]... [--roads 3] [-j 1] [--out DIR]

Each issue-20 example (examples/scenarios: every kind, every move, twilight) and the backing
variants (examples/variants) go through `sovarc batch -t all` on every map; the table is read back
from the batch's manifest and each site's verdict files. One row per scenario and map, one column
per target: sites passed / sites asked for, then the first reason of each failure. The OpenSCENARIO
column counts a site as passed only when esmini also played it (set ESMINI, or put esmini on PATH);
"fmu ran" counts sites where every vehicle that can be the ego took its turn, and "fmu ego passed"
those where the reference ego passed each of its tests: a verdict on that driver, not on the
scenario. Beneath each map: how often the reference ego, meeting a cyclist or a reversing car,
braked for it (it saw it) and struck it while moving. Without -m: the town and Town01 (the maps
the moves were built on), then Town02 (held out). Asserts nothing; prints the CPU time per map.
"""

from __future__ import annotations

import argparse
import json
import tempfile
from collections import Counter
from pathlib import Path
from typing import Any

from maps import ROOT, TOWN, add_map_argument, carla, grouped
from sovarc.compiler.cli import main as sovarc
from sovarc.dsl import parse

TUNED = [TOWN, *carla(1)]
HELD_OUT = carla(2)
TARGETS = ("sumo", "openscenario", "fmu")
# what each scenario stands for in issue 20 -> its file (examples/scenarios, else examples/variants)
SCENARIOS = {
    "van": "straight_van_lane_change_rear_end",
    "pickup, twilight": "t_junction_pickup_left_turn_out_side",
    "bus, cyclist partner": "intersection_bus_left_turn_cyclist_side",
    "truck": "intersection_truck_left_turn_side",
    "motorcycle": "straight_motorcycle_rear_ended",
    "bicycle, twilight": "intersection_cyclist_go_across_side",
    "reverse": "straight_reverse_into_stopped_rear_end",
    "parked": "straight_parked_car_struck_rear_end",
    "parked, reverse": "straight_back_out_of_parking_rear_end",
    # T-junction variants (examples/variants): the CARLA towns have no four-way crossing
    "truck, right turn out": "t_junction_truck_right_turn_out_side",
    "bus right turn out, cyclist": "t_junction_bus_right_turn_out_cyclist_side",
    "cyclist, car turns out": "t_junction_cyclist_left_turn_out_side",
}


def source(name: str) -> Path:
    for folder in ("scenarios", "variants"):
        path = ROOT / "examples" / folder / f"{name}.sov"
        if path.is_file():
            return path
    raise FileNotFoundError(name)


def _failures(site: Path, target: str) -> list[str]:
    """The messages of the failed findings in a site's verdict for `target`, first ones first."""
    path = site / f"verdict-{target}.json"
    if not path.is_file():
        return [f"no verdict-{target}.json"]
    data = json.loads(path.read_text(encoding="utf-8"))
    verdicts = data if isinstance(data, list) else [data]
    found = []
    for verdict in verdicts:
        prefix = f"ego {verdict.get('facts', {}).get('ego')}: " if target == "fmu" else ""
        found += [prefix + f["message"] for f in verdict.get("findings", []) if not f["passed"]]
    if target == "openscenario" and not any(
        f.get("check") == "player_run" for v in verdicts for f in v.get("findings", [])
    ):
        found.append("esmini did not play it (set ESMINI)")
    return found


def _ego_tests(site: Path) -> list[dict[str, Any]]:
    path = site / "verdict-fmu.json"
    return json.loads(path.read_text(encoding="utf-8")) if path.is_file() else []


def ran(rows: list[dict[str, Any]], out: Path, roads: int) -> str:
    """`sites/roads` where the FMU harness ran an ego test for every vehicle that can be one."""
    done = sum(1 for r in rows if r["planned"] and all(v.get("findings") for v in _ego_tests(out / r["folder"])))
    return f"{done}/{roads}"


def meetings(rows: list[dict[str, Any]], out: Path, source_text: str) -> Counter[str]:
    """The reference ego, driving, meeting a cyclist or a reversing car: tests, tests where it braked
    (it saw the other: two-party scenarios have no one else to brake for), and collisions while it moved."""
    scenario = parse(source_text)
    others = {p.id: "cyclist" for p in scenario.participants if str(getattr(p.kind, "value", "")) == "bicycle"}
    others |= {
        p.id: "reversing car" for p in scenario.participants if any(a.kind.value == "reverse" for a in p.known_actions)
    }
    found: Counter[str] = Counter()
    for row in (r for r in rows if r["planned"]):
        for test in _ego_tests(out / row["folder"]):
            facts = test.get("facts", {})
            for pid, what in others.items():
                if facts.get("ego") == pid or (facts.get("max_speed") or 0.0) < 0.5:
                    continue  # it is the other, or a standing ego's test (a car stopped in the way)
                found[f"{what}: tests"] += 1
                found[f"{what}: braked for it"] += int((facts.get("peak_braking") or 0.0) > 1.0)
                hit = facts.get("collision") or {}
                found[f"{what}: struck it moving"] += int(hit.get("other") == pid and hit.get("ego_speed", 0.0) > 0.5)
    return found


def cell(rows: list[dict[str, Any]], out: Path, target: str, roads: int) -> tuple[str, list[str]]:
    """`passed/roads` for one target, and the reasons of the misses."""
    reasons: list[str] = []
    passed = 0
    for row in rows:
        if not row["site"]:  # the task found no site, or failed as a whole
            reasons.append(f"no site: {row['error']}")
            continue
        if not row["planned"]:
            reasons.append(f"not planned: {row['error']}")
            continue
        failures = _failures(out / row["folder"], target)
        if not failures:
            passed += 1
        reasons += failures[:1]
    missing = roads - len([r for r in rows if r["site"]])
    if rows and rows[0]["site"] and missing > 0:
        reasons += [f"{missing} site(s) short"]
    return f"{passed}/{roads}", reasons


def _reasons(cells: list[tuple[str, list[str]]]) -> Counter[str]:
    """Each miss once: a site not planned (or no site) fails every target for one reason."""
    found: Counter[str] = Counter()
    for target, (_, reasons) in zip(TARGETS, cells, strict=True):
        for reason in reasons:
            shared = reason.startswith(("not planned", "no site"))
            if not shared or target == TARGETS[0]:
                found[f"{'all' if shared else target}: {reason[:150]}"] += 1
    return found


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_map_argument(parser, "built-on, then held-out")
    parser.add_argument("--roads", type=int, default=3)
    parser.add_argument("-j", "--jobs", type=int, default=1)
    parser.add_argument("--out", type=Path, default=None)
    parser.add_argument("--only", action="append", help="only these scenarios (their file names)")
    args = parser.parse_args()
    maps = grouped(args.map, TUNED, HELD_OUT)
    out = args.out or Path(tempfile.mkdtemp(prefix="bench_kinds_"))
    chosen = {k: v for k, v in SCENARIOS.items() if not args.only or v in args.only}
    inputs = [str(source(name)) for name in chosen.values()]
    argv = ["batch", *inputs, "-t", "all", "--roads", str(args.roads), "-j", str(args.jobs), "-o", str(out)]
    sovarc(argv + [arg for m, _ in maps for arg in ("-m", str(m))])
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    totals: Counter[tuple[str, str]] = Counter()
    for map_path, why in maps:
        rows_here = [r for r in manifest if Path(r["map"]) == map_path]
        cpu = sum({r["task"]: r["cpu_seconds"] or 0.0 for r in rows_here}.values())
        print(f"\n{map_path.name}{', ' + why if why else ''} (CPU {cpu:.0f} s)")
        print(f"  {'kind / move':<28} " + " ".join(f"{t:<13}" for t in (*TARGETS[:2], "fmu ran", "fmu ego passed")))
        met: Counter[str] = Counter()
        for label, name in chosen.items():
            rows = [r for r in rows_here if Path(r["input"]).stem == name]
            cells = [cell(rows, out, t, args.roads) for t in TARGETS]
            for target, (text, _) in zip(TARGETS, cells, strict=True):
                totals[(why or map_path.name, target)] += int(text.split("/")[0])
            texts = [cells[0][0], cells[1][0], ran(rows, out, args.roads), cells[2][0]]
            print(f"  {label:<28} " + " ".join(f"{text:<13}" for text in texts))
            met += meetings(rows, out, source(name).read_text(encoding="utf-8"))
            for reason, count in sorted(_reasons(cells).items()):
                print(f"      {count} x {reason}")
        for what in ("cyclist", "reversing car"):
            if met[f"{what}: tests"]:
                tests, braked, struck = (met[f"{what}: {k}"] for k in ("tests", "braked for it", "struck it moving"))
                print(f"  the reference ego, driving, meets a {what} in {tests} tests: brakes for it in {braked}, "
                      f"strikes it while moving in {struck}")  # fmt: skip
    print(f"\npassed of {len(chosen) * args.roads} per map, summed per map group:", dict(totals))
    print(f"batch folder: {out}")


if __name__ == "__main__":
    main()
