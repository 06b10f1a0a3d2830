"""`sovarc eval tests`: ego failures found by report-derived tests against random ones (the paper's Table 6).

Every scenario is staged on --roads sites of a map (the pipeline's assume, sites and stage); for each
plan, every vehicle takes its turn as the FMU target's ego twice: among the participants replaying the
report's crash, and among random NPCs on the same site (baseline.py). The table is in the form of the
paper's Table 6: failed tests per road kind, report-derived versus random; then the failures by check
and by violation (targets/fmu/violations.py, the spirit of the paper's violation types). A
scenario-site that could not be planned is counted as such, with its reason.
"""

from __future__ import annotations

import statistics
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

from sovarc.compiler.batch.tasks import worker_map
from sovarc.compiler.evaluation.baseline import random_tests
from sovarc.compiler.maps import RoadMap
from sovarc.compiler.pipeline import Options, stage_sites
from sovarc.compiler.plan import Plan
from sovarc.compiler.scenario_io import load_scenario
from sovarc.compiler.slots import first_message
from sovarc.dsl.errors import InputError, SovarcError, SynthesisError, UnsatError
from sovarc.dsl.ir import RoadKind, Scenario
from sovarc.targets.fmu import EgoFmu, egos, reference_fmu, run_test_results, validate_fmu, write_results
from sovarc.targets.fmu.oracle import FAILURE_CLASSES, VIOLATIONS
from sovarc.targets.fmu.runner import Method
from sovarc.targets.verdict import Verdict

METHODS: tuple[Method, ...] = ("report", "random")
KINDS: tuple[str, ...] = tuple(k.value for k in RoadKind)
WHAT_THE_EGO_DID = "what the ego did wrong (the paper's violation types)"


@dataclass
class Tally:
    tests: int = 0
    failed: int = 0
    classes: Counter[str] = field(default_factory=Counter)  # FAILURE_CLASSES key -> tests
    violations: Counter[str] = field(default_factory=Counter)  # VIOLATIONS key -> tests

    def add(self, verdict: Verdict) -> None:
        self.tests += 1
        if not verdict.passed:
            self.failed += 1
            self.classes[str(verdict.facts.get("failure"))] += 1
            self.violations[str(verdict.facts.get("violation"))] += 1

    def merge(self, other: Tally) -> None:
        self.tests += other.tests
        self.failed += other.failed
        self.classes.update(other.classes)
        self.violations.update(other.violations)


@dataclass(frozen=True)
class Unplanned:
    """A scenario-site that could not be planned, so has no tests."""

    scenario: str
    kind: str
    site: str  # '-' when no site of the kind could be chosen
    why: str  # a short class: 'no fitting site', 'unsat', 'synthesis', ...
    reason: str  # the error's first message


@dataclass
class TestsTable:
    """Tallies per (road kind, method), every verdict, the scenario-sites that could not be planned,
    and the wall time of each test."""

    tallies: dict[tuple[str, Method], Tally] = field(default_factory=dict)
    verdicts: list[Verdict] = field(default_factory=list)
    planned: Counter[str] = field(default_factory=Counter)  # road kind -> planned scenario-sites
    unplanned: list[Unplanned] = field(default_factory=list)
    walls: list[float] = field(default_factory=list)  # s per test
    simulated: list[float] = field(default_factory=list)  # s of simulated time per test

    __test__ = False  # not a pytest class

    def merge(self, other: TestsTable) -> None:
        """Add another table's tests after this one's (the tables of tasks run apart, in task order)."""
        for key, tally in other.tallies.items():
            self.tallies.setdefault(key, Tally()).merge(tally)
        self.verdicts += other.verdicts
        self.planned.update(other.planned)
        self.unplanned += other.unplanned
        self.walls += other.walls
        self.simulated += other.simulated

    def add(self, kind: str, method: Method, verdict: Verdict) -> None:
        self.tallies.setdefault((str(kind), method), Tally()).add(verdict)
        self.verdicts.append(verdict)

    def add_plan(
        self,
        plan: Plan,
        road_map: RoadMap,
        ego: EgoFmu,
        seed: int = 0,
        *,
        baseline: bool = True,
        out_dir: Path | None = None,
    ) -> None:
        """Run the plan's report-derived tests and (with baseline) its random ones on the map's site; with
        out_dir, write each test's verdict there, and a picture of each failed one."""
        self.planned[plan.kind.value] += 1
        for method in METHODS if baseline else METHODS[:1]:
            tests = random_tests(plan, road_map, seed, egos(plan)) if method == "random" else None
            results = run_test_results(plan, ego, seed, method=method, tests=tests)
            for result in results:
                self.add(plan.kind.value, method, result.verdict)
                self.walls.append(result.run.wall)
                self.simulated.append(float(result.run.times[-1]))
            if out_dir is not None:
                write_results([r for r in results if r.verdict.passed], out_dir, pictures=False)
                write_results([r for r in results if not r.verdict.passed], out_dir)

    def add_unplanned(self, scenario: str, kind: str, site: str, why: str, reason: str) -> None:
        self.unplanned.append(Unplanned(scenario, str(kind), site, why, reason))

    def kinds(self) -> list[str]:
        """The road kinds of the table: the paper's three, then any other met (an unknown kind)."""
        seen = set(self.planned) | {u.kind for u in self.unplanned} | {k for k, _ in self.tallies}
        return [*KINDS, *sorted(seen - set(KINDS))]

    def tally(self, kind: str | None, method: Method) -> Tally:
        if kind is not None:
            return self.tallies.get((kind, method), Tally())
        total = Tally()
        for (_, m), t in self.tallies.items():
            if m == method:
                total.merge(t)
        return total

    def ratio(self) -> float | None:
        """Report-derived failures per random failure (None when random found none)."""
        report, random = self.tally(None, "report").failed, self.tally(None, "random").failed
        return report / random if random else None

    def render(self, title: str = "Ego failures found by the tests") -> str:
        """The Table 6 form, then failures by check and by violation, what could not be planned, and timing."""
        lines = [
            f"{title} (the paper's Table 6 form)",
            "",
            f"{'road kind':<14}{'sites':>7}{'planned':>9}{'tests':>7}{'report-derived':>16}{'random':>8}",
        ]
        unplanned = Counter(u.kind for u in self.unplanned)
        for kind in [*self.kinds(), None]:
            report, random = self.tally(kind, "report"), self.tally(kind, "random")
            planned = self.planned[kind] if kind else sum(self.planned.values())
            sites = planned + (unplanned[kind] if kind else len(self.unplanned))
            name = kind or "total"
            rand = str(random.failed) if random.tests or not report.tests else "-"
            lines.append(f"{name:<14}{sites:>7}{planned:>9}{report.tests:>7}{report.failed:>16}{rand:>8}")
        report, random = self.tally(None, "report"), self.tally(None, "random")
        ratio = self.ratio()
        if random.tests:
            shown = f"{ratio:.1f}x" if ratio is not None else ("n/a" if not report.failed else "no random failures")
            lines += ["", f"report-derived / random failures: {shown}"]
        lines += ["", f"{'failures by check':<62}{'report':>8}{'random':>8}"]
        lines += self._rows(FAILURE_CLASSES, report.classes, random.classes)
        lines += ["", f"{WHAT_THE_EGO_DID:<62}{'report':>8}{'random':>8}"]
        lines += self._rows(VIOLATIONS, report.violations, random.violations)
        if self.unplanned:
            reasons = Counter(u.why for u in self.unplanned)
            listed = ", ".join(f"{why} {n}" for why, n in reasons.most_common())
            lines += ["", f"not planned: {len(self.unplanned)} scenario-site(s), no tests ({listed})"]
        if self.walls:
            lines += ["", self.timing()]
        return "\n".join(lines) + "\n"

    def timing(self) -> str:
        walls = sorted(self.walls)
        p90 = walls[min(int(0.9 * len(walls)), len(walls) - 1)]
        per20 = statistics.median(w * 20.0 / max(s, 1.0) for w, s in zip(self.walls, self.simulated, strict=True))
        return (
            f"wall time per test: median {statistics.median(walls):.2f} s, p90 {p90:.2f} s, max {walls[-1]:.2f} s; "
            f"per 20 s simulated: median {per20:.2f} s ({len(walls)} tests)"
        )

    @staticmethod
    def _rows(names: dict[str, str], report: Counter[str], random: Counter[str]) -> list[str]:
        rows = [
            f"  {text:<60}{report[key]:>8}{random[key]:>8}" for key, text in names.items() if report[key] or random[key]
        ]
        return rows or ["  (none)"]

    def to_json(self) -> dict[str, Any]:
        """Figures for tools (no wall times: the same run gives the same JSON)."""
        rows = {}
        for kind in self.kinds():
            rows[kind] = {
                "planned": self.planned[kind],
                "unplanned": sum(1 for u in self.unplanned if u.kind == kind),
                **{m: {"tests": self.tally(kind, m).tests, "failed": self.tally(kind, m).failed} for m in METHODS},
            }
        total = {m: self.tally(None, m) for m in METHODS}
        return {
            "rows": rows,
            "total": {m: {"tests": t.tests, "failed": t.failed} for m, t in total.items()},
            "ratio": None if self.ratio() is None else round(self.ratio() or 0.0, 3),
            "classes": {m: dict(sorted(t.classes.items())) for m, t in total.items()},
            "violations": {m: dict(sorted(t.violations.items())) for m, t in total.items()},
            "unplanned": [u.__dict__ for u in self.unplanned],
            "verdicts": [v.to_json() for v in self.verdicts],
        }


def load_ego(path: str | Path | None) -> EgoFmu:
    """The driving system under test: the FMU at `path`, else the reference ego; refused when its interface is not
    the one the FMU target drives (FmuInterfaceError lists every mismatch)."""
    return validate_fmu(path or reference_fmu())


def evaluate_tests(
    plans: Iterable[Plan],
    road_map: RoadMap,
    ego_fmu: str | Path | EgoFmu | None = None,
    seed: int = 0,
    *,
    baseline: bool = True,
) -> TestsTable:
    """Run the report-derived tests of every plan (staged on `road_map`), and (with baseline) the random ones."""
    ego = ego_fmu if isinstance(ego_fmu, EgoFmu) else validate_fmu(ego_fmu or reference_fmu())
    table = TestsTable()
    for plan in plans:
        table.add_plan(plan, road_map, ego, seed, baseline=baseline)
    return table


@dataclass(frozen=True)
class TestsTask:
    """One scenario's tests on one map: plain data, so any executor can run it in another process."""

    scenario: str  # a .sov or .json file
    map: str
    ego: str | None  # the FMU under test; None: the reference ego
    roads: int
    seed: int = 0
    spare: int | None = None
    baseline: bool = True
    out_dir: str | None = None

    __test__ = False  # not a pytest class


def run_tests_task(task: TestsTask) -> TestsTable:
    """The task's scenario and its tests; the map and the ego are loaded once per worker process."""
    scenario, _ = load_scenario(task.scenario)
    out_dir = Path(task.out_dir) if task.out_dir else None
    return scenario_tests(scenario, worker_map(task.map), _ego(task.ego), roads=task.roads, seed=task.seed,
                          spare=task.spare, baseline=task.baseline, out_dir=out_dir)  # fmt: skip


def scenario_tests(
    scenario: Scenario,
    road_map: RoadMap,
    ego: EgoFmu,
    *,
    roads: int,
    seed: int = 0,
    spare: int | None = None,
    baseline: bool = True,
    out_dir: Path | None = None,
) -> TestsTable:
    """Plan a scenario on `roads` sites of the map and run its tests (writing them under out_dir, if
    given); a scenario-site that cannot be planned is counted, with its reason, and has no tests."""
    table = TestsTable()
    options = Options(map=road_map, roads=roads, seed=seed, spare=spare)
    kind = scenario.road.kind.value if isinstance(scenario.road.kind, RoadKind) else "unknown"
    try:
        results = stage_sites(scenario, options)
    except SovarcError as exc:  # facts no road can reconcile, or no site of its kind
        why = "unsat" if isinstance(exc, UnsatError) else "no fitting site"
        for _ in range(roads):
            table.add_unplanned(scenario.name, kind, "-", why, first_message(exc))
        return table
    for r in results:
        if r.plan is None:
            table.add_unplanned(scenario.name, kind, r.site, _why(r.error), first_message(r.error))
        else:
            table.add_plan(r.plan, road_map, ego, seed, baseline=baseline, out_dir=out_dir)
    for _ in range(roads - len(results)):
        table.add_unplanned(scenario.name, kind, "-", "no fitting site", "fewer fitting sites than asked")
    return table


def tests_table(scenarios: Iterable[Scenario], road_map: RoadMap, ego: EgoFmu, **options: Any) -> TestsTable:
    """Every scenario's tests on one map, one after another in this process (`scenario_tests`' options)."""
    return merged(scenario_tests(s, road_map, ego, **options) for s in scenarios)


@lru_cache(maxsize=2)
def _ego(path: str | None) -> EgoFmu:
    """Each worker process validates (and, for the reference ego, builds) the FMU once."""
    return load_ego(path)


def merged(tables: Iterable[TestsTable]) -> TestsTable:
    whole = TestsTable()
    for table in tables:
        whole.merge(table)
    return whole


def scenario_files(names: list[str]) -> list[Path]:
    files: list[Path] = []
    for name in names:
        path = Path(name)
        if path.is_dir():
            found = sorted(path.glob("*.sov"))
            if not found:
                raise InputError(f"{name}: no .sov scenarios in this folder")
            files += found
        else:
            files.append(path)  # a missing or unreadable file is load_scenario's clear error
    return files


def _why(error: SovarcError | None) -> str:
    if isinstance(error, UnsatError):
        return "unsat"
    if isinstance(error, SynthesisError):
        return "synthesis"
    return "lowering" if error is not None and error.stage == "lower" else "other"
