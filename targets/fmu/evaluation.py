"""`sovarc eval tests --baseline random`: ego failures found by report-derived tests against random ones.

For each plan (one scenario on one site), every vehicle takes its turn as the ego twice: among the
participants replaying the report's crash, and among random NPCs on the same site. The table is in
the form of the paper's Table 6: failed tests per road kind, report-derived versus random; the
closing note classifies the failures in the spirit of the paper's violation types.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from sovarc.compiler.plan import Plan
from sovarc.dsl.ir import RoadKind
from sovarc.targets.fmu.interface import EgoFmu, validate_fmu
from sovarc.targets.fmu.oracle import FAILURE_CLASSES
from sovarc.targets.fmu.reference import reference_fmu
from sovarc.targets.fmu.runner import Method, run_tests
from sovarc.targets.verdict import Verdict

METHODS: tuple[Method, ...] = ("report", "random")
KINDS = (RoadKind.INTERSECTION, RoadKind.T_JUNCTION, RoadKind.STRAIGHT)


@dataclass
class Tally:
    tests: int = 0
    failed: int = 0
    classes: Counter[str] = field(default_factory=Counter)

    def add(self, verdict: Verdict) -> None:
        self.tests += 1
        if not verdict.passed:
            self.failed += 1
            self.classes[str(verdict.facts.get("failure"))] += 1


@dataclass
class TestsTable:
    """Tallies per (road kind, method), and every verdict."""

    tallies: dict[tuple[RoadKind, Method], Tally] = field(default_factory=dict)
    verdicts: list[Verdict] = field(default_factory=list)
    scenarios: Counter[RoadKind] = field(default_factory=Counter)

    __test__ = False  # not a pytest class

    def add(self, kind: RoadKind, method: Method, verdict: Verdict) -> None:
        self.tallies.setdefault((kind, method), Tally()).add(verdict)
        self.verdicts.append(verdict)

    def tally(self, kind: RoadKind | None, method: Method) -> Tally:
        if kind is not None:
            return self.tallies.get((kind, method), Tally())
        total = Tally()
        for (_, m), t in self.tallies.items():
            if m == method:
                total.tests += t.tests
                total.failed += t.failed
                total.classes.update(t.classes)
        return total

    def render(self) -> str:
        """The table, then the failure classes."""
        lines = [
            "Ego failures found by the tests (the paper's Table 6 form)",
            "",
            f"{'road kind':<14}{'plans':>7}{'tests':>7}{'report-derived':>16}{'random':>8}",
        ]
        for kind in [*KINDS, None]:
            report, random = self.tally(kind, "report"), self.tally(kind, "random")
            plans = self.scenarios[kind] if kind else sum(self.scenarios.values())
            name = kind.value if kind else "total"
            lines.append(f"{name:<14}{plans:>7}{report.tests:>7}{report.failed:>16}{random.failed:>8}")
        report, random = self.tally(None, "report"), self.tally(None, "random")
        ratio = f"{report.failed / random.failed:.1f}x" if random.failed else ("n/a" if not report.failed else "inf")
        lines += ["", f"report-derived / random failures: {ratio}", "", "failures by class (report-derived, random):"]
        for key, text in FAILURE_CLASSES.items():
            a, b = report.classes[key], random.classes[key]
            if a or b:
                lines.append(f"  {text:<60}{a:>5}{b:>8}")
        return "\n".join(lines) + "\n"

    def to_json(self) -> dict[str, Any]:
        rows = {}
        for kind in KINDS:
            rows[kind.value] = {
                "plans": self.scenarios[kind],
                **{m: {"tests": self.tally(kind, m).tests, "failed": self.tally(kind, m).failed} for m in METHODS},
            }
        classes = {m: dict(sorted(self.tally(None, m).classes.items())) for m in METHODS}
        return {"rows": rows, "classes": classes, "verdicts": [v.to_json() for v in self.verdicts]}


def evaluate_tests(
    plans: Iterable[Plan], ego_fmu: str | Path | EgoFmu | None = None, seed: int = 0, *, baseline: bool = True
) -> TestsTable:
    """Run the report-derived tests of every plan, and (with baseline) the random ones."""
    ego = ego_fmu if isinstance(ego_fmu, EgoFmu) else validate_fmu(ego_fmu or reference_fmu())
    table = TestsTable()
    for plan in plans:
        table.scenarios[plan.kind] += 1
        for method in METHODS if baseline else METHODS[:1]:
            for verdict in run_tests(plan, ego, seed, method=method):
                table.add(plan.kind, method, verdict)
    return table
