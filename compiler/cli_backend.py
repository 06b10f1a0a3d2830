"""The back-end commands of the CLI: `sovarc lower`, `-t TARGET` on the main job, `sovarc eval srr`."""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from pathlib import Path
from typing import Any

from sovarc.compiler.backend import compile_sites, default_map, first_message, passed, plans_for, summary
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.maps import load_map
from sovarc.compiler.progress import progress
from sovarc.dsl.errors import EXIT_INPUT, EXIT_OK, SovarcError
from sovarc.dsl.ir import Scenario
from sovarc.targets import registry

# The OpenSCENARIO versions the target writes, as its --osc-version option declares them.
OSC_VERSIONS: tuple[str, ...] = next(f.choices or () for f in registry.all_flags() if f.flag == "--osc-version")
FAILURE_CLASSES = ("planning failed", "crash type mismatch", "line crossing", "replay error")


def add_site_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-m", "--map", help="road network, .net.xml or .xodr (default: the bundled example town)")
    parser.add_argument("--roads", type=int, default=1, metavar="N", help="stage on N distinct sites (default 1)")
    add_spare_option(parser)


def add_spare_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--spare-sites",
        type=_not_negative,
        metavar="K",
        help="when a chosen site cannot host the crash, try up to K more sites in its place, each one noted "
        "with its reason (default: three times --roads; 0 keeps the first choice, failures and all)",
    )


def _not_negative(value: str) -> int:
    number = int(value)
    if number < 0:
        raise argparse.ArgumentTypeError(f"must be 0 or more, not {number}")
    return number


def target_names(value: str) -> tuple[str, ...]:
    """`-t`: a registered target's name, or all of them."""
    names = registry.names()
    if value == "all":
        return names
    if value not in names:
        raise argparse.ArgumentTypeError(f"unknown target '{value}'; choose from {', '.join(names)} or all")
    return (value,)


def add_target_options(parser: argparse.ArgumentParser) -> None:
    """Each registered target's options as flags (a shared one, like --seed, the parser has already)."""
    for flag in registry.all_flags():
        if flag.shared:
            continue
        parser.add_argument(flag.flag, type=flag.type, choices=flag.choices, default=flag.default, help=flag.help)


def run_targets(scenario: Scenario, args: argparse.Namespace) -> int:
    """The main job's back end: plans on --roads sites, each target emitted and checked."""
    out = Path(args.output) if args.output else Path("sovarc-out") / scenario.name
    results = compile_sites(
        scenario,
        args.map,
        roads=args.roads,
        seed=args.seed,
        spare=args.spare_sites,
        targets=args.target,
        out_dir=out,
        ego=args.ego,
        osc_version=args.osc_version,
    )
    _print_summary(summary(results, args.target), out)
    print(f"written to {out}/", file=sys.stderr)
    # A failed ego test (fmu) is a finding about the driving system, not a failure of the run.
    ok = all(r.plan is not None and all(passed(v) for t, v in r.verdicts.items() if t != "fmu") for r in results)
    return EXIT_OK if ok else EXIT_INPUT


def print_plans(scenario: Scenario, args: argparse.Namespace) -> int:
    """`--dump-ir-after=lower`: the plan of each site in its text form."""
    from sovarc.compiler.plan_text import render_plan

    results = plans_for(scenario, load_map(args.map or default_map()), args.roads, args.seed, args.spare_sites)
    for r in results:
        print(f"// ----- plan on {r.site} -----")
        if r.plan is not None:
            print(render_plan(r.plan), end="")
        elif r.error is not None:
            print(r.error.render(), file=sys.stderr)
    return EXIT_OK if all(r.plan for r in results) else EXIT_INPUT


def add_lower_parser(sub: Any, summary: str, formatter: Any) -> None:
    low = sub.add_parser(
        "lower",
        help=summary,
        formatter_class=formatter,
        description=(
            "Stage a scenario on sites of a map: routes, the collision area, Z3 constraints (Groups 1-5),\n"
            "OMPL paths and Ruckig timing. Writes, per site, plan.txt (readable), plan.json and plan.png.\n\n"
            "examples:\n"
            "  sovarc lower examples/scenarios/intersection_left_turn_across_path_side.sov -o out\n"
            "  sovarc lower scenario.sov -m city.net.xml --roads 3 --seed 7 -o out"
        ),
    )
    low.add_argument("input", help="a scenario (.sov or .json)")
    add_site_options(low)
    low.add_argument("--seed", type=int, default=0, help="seed for the choice of sites (default 0)")
    low.add_argument("-o", "--output", required=True, help="folder for one sub-folder per site")


def add_srr_parser(which: Any, formatter: Any) -> None:
    srr = which.add_parser(
        "srr",
        formatter_class=formatter,
        help="scenario reconstruction rate in SUMO, per road kind",
        description="Stage every scenario on --roads sites of each map, replay it in SUMO and print the\n"
        "reconstruction rate per road kind (the paper's Table 4) and the failures by class\n"
        "(Table 5: planning failed, crash type mismatch, line crossing).\n\n"
        "example:\n"
        "  sovarc import-truth ../shared/data/nmvccs/truth -o truth\n"
        "  sovarc eval srr truth --roads 3 -m examples/maps/town.net.xml --json srr.json",
    )
    srr.add_argument("scenarios", nargs="+", help=".sov files, or folders of them")
    srr.add_argument("-m", "--map", action="append", help="a map (repeatable; default: the bundled town)")
    srr.add_argument("--roads", type=int, default=3, metavar="N", help="sites per scenario (default 3)")
    add_spare_option(srr)
    srr.add_argument("--seed", type=int, default=0, help="seed for the choice of sites (default 0)")
    srr.add_argument("--json", help="also write every scenario-site's result here")


def cmd_lower(args: argparse.Namespace) -> int:
    from sovarc.compiler.scenario_io import load_scenario
    from sovarc.dsl import verify_or_raise

    scenario, _ = load_scenario(args.input)
    verify_or_raise(scenario)
    results = compile_sites(
        scenario, args.map, roads=args.roads, seed=args.seed, spare=args.spare_sites, out_dir=args.output
    )
    for r in results:
        if r.error is not None:
            print(r.error.render(), file=sys.stderr)
    _print_summary(summary(results, ()), Path(args.output))
    return EXIT_OK if all(r.plan for r in results) else EXIT_INPUT


def _print_summary(table: str, out: Path) -> None:
    """Print the table and keep it as out/summary.txt: the sites given up, and why, are in no site's folder."""
    write_atomic(out / "summary.txt", table)
    print(table, end="")


def classify(verdict: object) -> str | None:
    """The paper's Table 5 classes for a SUMO verdict; None when it passed."""
    failed = {f.check for f in verdict.failures}  # type: ignore[attr-defined]
    if not failed:
        return None
    if failed & {"collision", "pair", "impact_angle"}:
        return "crash type mismatch"
    if "lane_lines" in failed:
        return "line crossing"
    return "replay error"


def cmd_eval_srr(args: argparse.Namespace) -> int:
    """The scenario reconstruction rate of the SUMO oracle, per road kind (the paper's Tables 4 and 5)."""
    from sovarc.compiler.scenario_io import load_scenario
    from sovarc.targets import sumo

    files = sorted(p for name in args.scenarios for p in _sov_files(Path(name)))
    maps = args.map or [str(default_map())]
    report: dict[str, dict[str, object]] = {}
    for map_path in maps:
        road_map = load_map(map_path)
        rows: list[dict[str, object]] = []
        for path in progress(files, len(files), label=f"srr {Path(map_path).name}"):
            scenario, _ = load_scenario(path)
            kind = scenario.road.kind.value if hasattr(scenario.road.kind, "value") else "unknown"
            try:
                results = plans_for(scenario, road_map, args.roads, args.seed, args.spare_sites)
            except Exception as exc:  # no fitting site: every requested site failed to plan
                results = []
                reason = getattr(exc, "diagnostics", None)
                rows += [_row(path, kind, "-", "planning failed", str(reason[0].message if reason else exc))]
                rows += [_row(path, kind, "-", "planning failed", "no site")] * (args.roads - 1)
                continue
            for r in results:
                if r.plan is None:
                    rows.append(_row(path, kind, r.site, "planning failed", first_message(r.error)))
                else:
                    try:
                        verdict = sumo.check(r.plan)
                        failure = classify(verdict)
                        rows.append(_row(path, kind, r.site, failure, "; ".join(f.message for f in verdict.failures)))
                    except SovarcError as error:  # SUMO refused the scenario: counted, and the batch goes on
                        rows.append(_row(path, kind, r.site, "replay error", str(error)))
                rows[-1]["skipped"] = [{"site": s.site, "reason": first_message(s.error)} for s in r.skipped]
            missing = args.roads - len(results)
            rows += [_row(path, kind, "-", "planning failed", "fewer fitting sites than asked")] * missing
        key = _map_key(map_path, maps)
        report[key] = {"rows": rows}
        print(_srr_table(key, rows))
    if args.json:
        write_atomic(args.json, json.dumps(report, indent=2) + "\n")
    return EXIT_OK


def _map_key(map_path: str, maps: list[str]) -> str:
    """A map's file name, or the path as given when another map has the same name (two cities'
    osm.net.xml), so that no map's rows overwrite another's in the JSON."""
    name = Path(map_path).name
    return name if [Path(m).name for m in maps].count(name) == 1 else map_path


def _row(path: Path, kind: str, site: str, failure: str | None, reason: str) -> dict[str, object]:
    return {"scenario": path.stem, "kind": kind, "site": site, "passed": failure is None, "failure": failure,
            "reason": reason}  # fmt: skip


def _srr_table(name: str, rows: list[dict[str, object]]) -> str:
    kinds = sorted({str(r["kind"]) for r in rows})
    lines = [f"SRR on {name} (scenario-sites reconstructed / attempted)", f"  {'road kind':<14}{'SRR':>8}  n"]
    for kind in [*kinds, "all"]:
        chosen = [r for r in rows if kind in ("all", r["kind"])]
        ok = sum(1 for r in chosen if r["passed"])
        lines.append(f"  {kind:<14}{100.0 * ok / max(1, len(chosen)):7.1f}%  {ok}/{len(chosen)}")
    counts = Counter(str(r["failure"]) for r in rows if not r["passed"])
    lines.append("  failures: " + ", ".join(f"{c} {counts[c]}" for c in FAILURE_CLASSES))
    replaced = sum(1 for r in rows if r.get("skipped") and r["failure"] != "planning failed")
    given_up = sum(len(r.get("skipped", ())) for r in rows)  # type: ignore[arg-type]
    if given_up:
        lines.append(f"  sites that could not host their crash: {given_up}; slots filled by another site: {replaced}")
    return "\n".join(lines) + "\n"


def _sov_files(path: Path) -> list[Path]:
    return sorted(path.glob("*.sov")) if path.is_dir() else [path]
