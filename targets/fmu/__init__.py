"""The FMU target: test a driving system, given as an FMI 2.0 co-simulation FMU, on reconstructed crashes.

Every vehicle of a plan takes its turn as the ego under test; the other participants replay their
trajectories in SUMO (libsumo); the FMU drives the ego (fmpy) through a kinematic bicycle model; an
oracle judges each run. The ego interface (names, units, frames, step) is in INTERFACE.md.

    verdicts = run_tests(plan)                            # the reference ego, one Verdict per vehicle
    verdicts = run_tests(plan, "my_ads.fmu", seed=0)      # a user's FMU, validated first
    run_test_results(plan, tests=plans, method="random")  # each ego's test on the plan given for it
    run_target(plan, "out/")                              # the same, writing verdict JSON and a PNG per test
    validate_fmu("my_ads.fmu")                            # FmuInterfaceError lists every mismatch
    reference_fmu()                                       # path of the reference ego FMU (built once, cached)
    TARGET                                                # the target contract's object: one verdict per ego

The plan's network (`plan.network.sumo`) is the SUMO network the other participants replay on.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

from sovarc.compiler.plan import Plan
from sovarc.targets.contract import Artifacts, option
from sovarc.targets.fmu.interface import STEP, EgoFmu, FmuInterfaceError, validate_fmu
from sovarc.targets.fmu.output import run_target, write_results
from sovarc.targets.fmu.reference import reference_fmu
from sovarc.targets.fmu.runner import TestResult, egos, run_test_results, run_tests
from sovarc.targets.verdict import Verdict


@dataclass(frozen=True)
class FmuOptions:
    ego: str | None = option(None, "--ego", "with -t fmu: the driving system under test, an FMI 2.0 FMU")
    seed: int = option(0, "--seed", "seed for every random choice", shared=True)


class FmuTarget:
    """Every vehicle of the plan takes its turn as the ego: one test, and one verdict, per ego.

    The tests run the plan itself, so emit only makes the target's folder; check runs the tests and
    writes, per test, its verdict and a picture of the run there (`fmu-<scenario>-<site>-ego-<id>`)."""

    name = "fmu"
    Options: ClassVar[type[FmuOptions]] = FmuOptions
    needs_opendrive = False
    one_verdict = False

    def emit(self, plan: Plan, folder: Path, options: FmuOptions) -> Artifacts:
        Path(folder).mkdir(parents=True, exist_ok=True)
        return Artifacts(Path(folder))

    def check(self, plan: Plan, artifacts: Artifacts, options: FmuOptions) -> list[Verdict]:
        return run_target(plan, artifacts.folder, ego_fmu=options.ego, seed=options.seed)


TARGET = FmuTarget()

__all__ = [
    "STEP",
    "TARGET",
    "EgoFmu",
    "FmuInterfaceError",
    "FmuOptions",
    "FmuTarget",
    "TestResult",
    "egos",
    "reference_fmu",
    "run_target",
    "run_test_results",
    "run_tests",
    "validate_fmu",
    "write_results",
]
