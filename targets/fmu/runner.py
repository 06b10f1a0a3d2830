"""Test generation and running: every vehicle of a plan takes its turn as the ego.

`run_tests(plan)` makes one test per vehicle participant (a pedestrian is never the ego: the ego is a
driving system; nor is a vehicle whose plan reverses, in a three-point turn: the ego interface drives
forward only, INTERFACE.md) and judges each. `tests` gives, per ego, another plan for its test: the random
baseline's, whose NPCs are random but plausible on the same site (sovarc.compiler.evaluation.baseline), run
with `method="random"`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

from sovarc.compiler.plan import Plan
from sovarc.targets.fmu.driver import Driver
from sovarc.targets.fmu.harness import Run, run_test
from sovarc.targets.fmu.interface import STEP, EgoFmu, validate_fmu
from sovarc.targets.fmu.oracle import judge
from sovarc.targets.fmu.reference import reference_fmu
from sovarc.targets.fmu.world import World
from sovarc.targets.verdict import Verdict

Method = Literal["report", "random"]


@dataclass(frozen=True)
class TestResult:
    verdict: Verdict
    run: Run
    plan: Plan  # the plan the test ran (for the random baseline: the one with random NPCs)

    __test__ = False  # not a pytest class


def egos(plan: Plan) -> list[str]:
    """The participants that take a turn as the ego: the vehicles that never reverse, in plan order."""
    return [
        t.participant
        for t in plan.trajectories
        if t.body.vclass != "pedestrian" and all(s.speed >= 0.0 for s in t.samples)
    ]


def run_tests(
    plan: Plan, ego_fmu: str | Path | EgoFmu | None = None, seed: int = 0, *, method: Method = "report"
) -> list[Verdict]:
    """One verdict per vehicle of the plan as the ego, in plan order."""
    return [r.verdict for r in run_test_results(plan, ego_fmu, seed, method=method)]


def run_test_results(
    plan: Plan,
    ego_fmu: str | Path | EgoFmu | None = None,
    seed: int = 0,
    *,
    method: Method = "report",
    tests: Mapping[str, Plan] | None = None,
) -> list[TestResult]:
    """Like run_tests, with each test's run (for pictures and measurements); `tests` maps an ego to the
    plan its test runs (default: `plan` for every ego)."""
    ego = ego_fmu if isinstance(ego_fmu, EgoFmu) else validate_fmu(ego_fmu or reference_fmu())
    results = []
    net = Path(plan.network.sumo)  # the network the plan was planned on (an OpenDRIVE map's conversion)
    with Driver(ego) as driver:
        for name in egos(plan):
            test_plan = plan if tests is None else tests[name]
            with World(net, STEP, seed) as world:
                run = run_test(test_plan, name, driver, world)
            verdict = judge(run, test_plan, seed=seed, fmu=ego.model_name, method=method)
            results.append(TestResult(verdict, run, test_plan))
    return results
