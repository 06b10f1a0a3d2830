"""What the ego did wrong, read from hand-made runs: the situations of the paper's violation types."""

from __future__ import annotations

import numpy as np
import pytest
from sovarc.compiler.vehicles import CAR, PEDESTRIAN, Body
from sovarc.targets.fmu.harness import Run, Track
from sovarc.targets.fmu.task import make_task
from sovarc.targets.fmu.violations import violation

from tests.targets.fmu.plans import along, car_following, plan_of

STEPS = 21


def _run(plan, other: tuple[float, float, float, float], body: Body = CAR) -> Run:
    """The ego V1 at the start of its task, at 10 m/s; V2 at (x, y, heading, speed) - all steps alike."""
    task = make_task(plan, "V1")
    start = task.start
    ego = Track("V1", CAR, *(np.full(STEPS, v) for v in (start.x, start.y, start.heading, 10.0)))
    them = Track("V2", body, *(np.full(STEPS, v) for v in other))
    times = np.arange(STEPS) * 0.05
    return Run(
        "V1", task, times, {"V1": ego, "V2": them}, np.zeros(STEPS), np.zeros((STEPS, 2)), "budget", None, (), 0.0
    )


def _turning_plan():
    """V1 drives 20 m east, then turns north: its route turns through 90 degrees near its start."""
    points = [(0.0, 0.0), (20.0, 0.0), (24.0, 1.0), (27.0, 4.0), (28.0, 8.0), (28.0, 60.0)]
    v1 = along("V1", points, 0.0, 10.0, 5.0, ("ave2_1",), ("ave2",))
    return plan_of(v1, car_following().trajectory("V2"))


@pytest.mark.parametrize(
    ("other", "body", "expected"),
    [
        ((60.0, 10.0, 180.0, 10.0), CAR, "crossing"),  # from the left, heading south across its path
        ((60.0, -8.25, 270.0, 10.0), CAR, "oncoming"),  # head on, in its lane
        ((40.0, -8.25, 90.0, 2.0), CAR, "rear_end"),  # ahead, slower, its way
        ((22.0, -5.0, 90.0, 14.0), CAR, "cut_in"),  # beside it and faster: it moved across into it
        ((40.0, -6.0, 0.0, 1.5), PEDESTRIAN, "pedestrian"),
    ],
)
def test_the_situation_is_read_from_headings_and_positions(
    other: tuple[float, float, float, float], body: Body, expected: str
) -> None:
    plan = car_following()  # V1 starts at (20, -8.25) heading east
    assert violation(_run(plan, other, body), plan, "near_miss", "V2", 0.5, stalled=False) == expected


def test_a_turning_ego_turns_across_and_the_other_failures_need_no_partner() -> None:
    plan = _turning_plan()
    run = _run(plan, (40.0, 0.0, 270.0, 10.0))  # coming west, straight on
    assert violation(run, plan, "collision", "V2", 0.5, stalled=False) == "turn_across"
    assert violation(run, plan, "harsh_braking", None, 0.5, stalled=False) == "phantom_braking"
    assert violation(run, plan, "goal", None, 1.0, stalled=True) == "stalled"
    assert violation(run, plan, "goal", None, 1.0, stalled=False) == "slow"
