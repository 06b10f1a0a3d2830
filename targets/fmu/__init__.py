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
"""

from sovarc.targets.fmu.interface import STEP, EgoFmu, FmuInterfaceError, validate_fmu
from sovarc.targets.fmu.output import run_target, write_results
from sovarc.targets.fmu.reference import reference_fmu
from sovarc.targets.fmu.runner import TestResult, egos, run_test_results, run_tests

__all__ = [
    "STEP",
    "EgoFmu",
    "FmuInterfaceError",
    "TestResult",
    "egos",
    "reference_fmu",
    "run_target",
    "run_test_results",
    "run_tests",
    "validate_fmu",
    "write_results",
]
