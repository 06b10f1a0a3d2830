"""SRR per map: sites found per kind, reconstruction rate per kind, failures by class (issue 17).

    .venv/bin/python benchmarks/bench_srr_maps.py TRUTH_DIR [--group GROUP] [--map NAME ...]
        [--only GLOB] [--roads 3] [--seed 0] [--save DIR] [--reuse]

TRUTH_DIR holds the shared ground-truth scenarios as .sov files
(`sovarc import-truth ../shared/data/nmvccs/truth/*/*.json -o truth`). Each scenario is staged on
--roads sites of each map and replayed in SUMO, as `sovarc eval srr` does. GROUP picks the maps:
- dev, held-out, all: the development maps (CARLA Town01, 02, 04; esmini's maps; the bundled town;
  SUMO's networks) and the held-out ones (CARLA Town06, 07), printed in separate groups: the
  held-out maps are for reporting, never for tuning;
- generated: maps made at run time by SUMO's netgenerate, each as generated and round-tripped
  through OpenDRIVE (netgen_maps.py), its development half (gen-dev) printed beside its held-out
  half (gen-held-out); either half can be run alone.
Also prints, per map, the CPU time of loading it and finding its sites. An SRR
in brackets is of a kind the map has fewer than 3 sites of (no target there). Each SRR is printed
over all scenario-sites / over those the map has a site of the needed shape for: a scenario-site
the map has no site of the shape for (its kind, the lanes each participant needs, an arm where each
move leads; fewer such sites than --roads) is its own failure class, not a planning failure
(`srr.NO_SHAPE`). Planning failures are split by what their reasons say: no site fits, the
record contradicts itself, a site that fits only clamped, or a fitting site cannot host the crash.

A full run is minutes per town: --only runs a subset of scenarios (a glob on file names), --map
picks maps by name, and --save/--reuse keep each map's rows in DIR so that a table can be printed
again without replaying.
"""

from __future__ import annotations

import argparse
import json
import os
import time
from collections import Counter
from pathlib import Path

import sumo
from netgen_maps import GROUPS
from netgen_maps import maps as generated_maps
from sovarc.compiler.evaluation.srr import FAILURE_CLASSES, NO_SHAPE, reconstruct
from sovarc.compiler.maps import find_sites, load_map
from sovarc.dsl import parse
from sovarc.dsl.ir import RoadKind

ROOT = Path(__file__).resolve().parent.parent
SHARED = Path(os.environ.get("SOVARC_SHARED", ROOT.parent / "shared"))
OPENDRIVE = SHARED / "data" / "opendrive"
GAME = Path(sumo.SUMO_HOME) / "tools" / "game"
KINDS = (RoadKind.INTERSECTION, RoadKind.T_JUNCTION, RoadKind.STRAIGHT)
SHORT = {RoadKind.INTERSECTION: "X", RoadKind.T_JUNCTION: "T", RoadKind.STRAIGHT: "S"}


def maps(group: str) -> dict[str, dict[str, Path]]:
    """The maps of `group`, by group; the generated ones are made only when asked for."""
    if group in GROUPS:
        return {group: generated_maps(group)}
    if group == "generated":
        return {name: generated_maps(name) for name in GROUPS}
    return _shipped()


def _shipped() -> dict[str, dict[str, Path]]:
    dev = {f"Town0{k}": OPENDRIVE / "carla" / f"Town0{k}.xodr" for k in (1, 2, 4)}
    dev |= {p.stem: p for p in sorted(OPENDRIVE.glob("*.xodr"))}
    dev["town"] = ROOT / "examples" / "maps" / "town.net.xml"
    dev |= {"DRT": GAME / "DRT" / "osm.net.xml", "A10KW": GAME / "A10KW" / "osm.net.xml"}
    dev["bs3d"] = GAME / "bs3d" / "bs.net.xml"
    held = {f"Town0{k}": OPENDRIVE / "carla" / f"Town0{k}.xodr" for k in (6, 7)}
    return {"dev": dev, "held-out": held}


def run_map(name: str, path: Path, scenarios: list[tuple[Path, object]], args: argparse.Namespace) -> dict:
    saved = args.save / f"{name}.json" if args.save else None
    if saved and args.reuse and saved.exists():
        return json.loads(saved.read_text())
    started = time.process_time()
    road_map = load_map(path)
    sites = find_sites(road_map)
    site_s = time.process_time() - started
    counts = Counter(s.kind.value for s in sites)
    rows = []
    for file, scenario in scenarios:
        rows += reconstruct(scenario, file, road_map, roads=args.roads, seed=args.seed)  # type: ignore[arg-type]
    result = {"map": name, "sites": {k.value: counts[k.value] for k in KINDS}, "site_s": site_s, "rows": rows}
    if saved:
        saved.parent.mkdir(parents=True, exist_ok=True)
        saved.write_text(json.dumps(result, indent=1))
    return result


# Why a scenario-site failed to plan, by what its reason says: the map lacks the kind or a site that
# fits (a truthful miss), the record contradicts itself, a site that fits only clamped (too few lanes,
# a move with no connection) cannot host it, or a site that fits cannot host the crash.
PLANNING = (
    ("map lacks the kind", ("has no ",)),
    ("no site fits", ("no site of ", "fewer fitting sites than asked", "none of its")),
    ("record contradicts itself", ("no road can stage it",)),
    ("site fits only clamped", ("the site fits only clamped",)),
    ("site cannot host it", ("",)),
)


def planning_class(row: dict, first: dict[str, str]) -> str:
    """The class of a planning failure; a scenario's follow-up rows ('no site') take its first row's."""
    reason = row["reason"] if row["reason"] != "no site" else first.get(row["scenario"], "")
    return next(name for name, marks in PLANNING if any(mark in reason for mark in marks))


def table(group: str, results: list[dict]) -> str:
    head = f"{'map':<22}{'sites X/T/S':>13}  {'SRR X':>13} {'SRR T':>13} {'SRR S':>13}  {'sites s':>7}  failures"
    lines = [f"== {group} maps ==", head]
    for r in results:
        sites = "/".join(str(r["sites"][k.value]) for k in KINDS)
        rates = []
        for kind in KINDS:
            chosen = [row for row in r["rows"] if row["kind"] == kind.value]
            ok = sum(row["passed"] for row in chosen)
            hosted = sum(row["failure"] != NO_SHAPE for row in chosen)
            # all rows / the rows the map has a site of the needed shape for (srr.NO_SHAPE)
            rate = f"{100.0 * ok / len(chosen):.1f}" if chosen else "-"
            if chosen:
                rate += f"/{100.0 * ok / hosted:.1f}" if hosted else "/-"
            # in brackets: a kind the map has fewer than 3 sites of, where the 97% target does not apply
            rates.append(f"{rate if r['sites'][kind.value] >= 3 or not chosen else f'({rate})':>13}")
        failures = Counter(row["failure"] for row in r["rows"] if not row["passed"])
        failed = ", ".join(f"{c} {failures[c]}" for c in FAILURE_CLASSES if failures[c]) or "none"
        lines.append(f"{r['map']:<22}{sites:>13}  {' '.join(rates)}  {r['site_s']:7.2f}  {failed}")
        first: dict[str, str] = {}
        for row in r["rows"]:
            first.setdefault(row["scenario"], row["reason"] or "")
        for kind in KINDS:
            planning = Counter(
                planning_class(row, first)
                for row in r["rows"]
                if row["kind"] == kind.value and row["failure"] == "planning failed"
            )
            if planning:
                why = ", ".join(f"{name} {planning[name]}" for name, _ in PLANNING if planning[name])
                lines.append(f"{'':<22}{'planning failed ' + SHORT[kind]:>28}: {why}")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("truth", type=Path)
    parser.add_argument("--group", choices=("dev", "held-out", "all", "generated", *GROUPS), default="dev")
    parser.add_argument("--map", action="append", help="only maps of this name (repeatable)")
    parser.add_argument("--only", default="*", help="a glob on the scenarios' file names")
    parser.add_argument("--roads", type=int, default=3)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--save", type=Path, help="a folder for each map's rows")
    parser.add_argument("--reuse", action="store_true", help="print saved rows instead of replaying")
    args = parser.parse_args()
    files = sorted(args.truth.glob(f"{args.only}.sov"))
    scenarios = [(f, parse(f.read_text(encoding="utf-8"))) for f in files]
    print(f"{len(scenarios)} scenarios x {args.roads} sites, seed {args.seed}; sites s: CPU s to load and find sites")
    for group, chosen in maps(args.group).items():
        if args.group not in ("all", "generated", group):  # 'generated' is both generated halves
            continue
        picked = {n: p for n, p in chosen.items() if not args.map or n in args.map}
        if picked:
            results = [run_map(name, path, scenarios, args) for name, path in picked.items() if path.exists()]
            print(table(group, results))


if __name__ == "__main__":
    main()
