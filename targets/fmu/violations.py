"""What the ego did wrong in a failed test, in the spirit of the paper's safety-violation types.

SoVAR (RQ3) sorts Apollo's collisions by the situation: the ego did not slow for a vehicle crossing
at speed (its type 1), turned without yielding to one going straight (type 2), did not slow for a
vehicle or pedestrian entering the road (types 3 and 4), or did not stop for a wrong-way driver (its
collision type 2). The same situations are read here from the run itself (headings, positions and
the ego's route where it failed), so that report-derived and random tests are sorted alike; only
"entering" needs the other's planned actions, which a random NPC never has.
"""

from __future__ import annotations

import numpy as np
from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.geometry.bodies import Box
from sovarc.compiler.plan import Plan
from sovarc.targets.fmu.harness import Run
from sovarc.targets.fmu.task import to_ego_frame

VIOLATIONS: dict[str, str] = {
    "crossing": "did not slow for a vehicle crossing its path",
    "turn_across": "turned across another vehicle's path without yielding",
    "entering": "did not slow for a vehicle entering or leaving the road",
    "pedestrian": "did not slow for a pedestrian",
    "oncoming": "did not avoid an oncoming vehicle on its side of the road",
    "rear_end": "ran up on a slower or stopped vehicle ahead",
    "cut_in": "moved across into a vehicle going its way",
    "stalled": "stood still with its route clear",
    "slow": "too slow to reach its goal in time",
    "phantom_braking": "braked hard with no one on a collision course",
}

ENTERING = {"drive_into", "drive_off"}  # the IR actions of a vehicle entering or leaving the road
SAME_WAY = 30.0  # deg: headings closer than this go the same way
ONCOMING = 150.0  # deg: headings further apart than this meet head on
TURNING = 30.0  # deg the ego's route turns through near where it failed: it was turning
TURN_BEHIND, TURN_AHEAD = 5.0, 30.0  # m of its route before and after that point to look at


def violation(run: Run, plan: Plan, failure: str, other: str | None, time: float, *, stalled: bool) -> str:
    """The key in VIOLATIONS for a test that failed `failure`, with `other` (if any) at `time`."""
    if failure == "goal":
        return "stalled" if stalled else "slow"
    if other is None:
        return "phantom_braking"
    ego, them = run.ego_track, run.tracks[other]
    k = min(int(np.searchsorted(run.times, time - 1e-9)), len(run.times) - 1)
    if them.body.vclass == "pedestrian":
        return "pedestrian"
    if other in {t.participant for t in plan.trajectories}:
        actions = {s.action.split(":")[-1] for s in plan.trajectory(other).segments}
        if actions & ENTERING:
            return "entering"
    apart = abs(angle_diff(float(them.heading[k]), float(ego.heading[k])))
    if apart <= SAME_WAY:  # ran up on it from behind, or moved across into it
        ex, ey = Box.of(ego.body, float(ego.x[k]), float(ego.y[k]), float(ego.heading[k])).centre
        ox, oy = Box.of(them.body, float(them.x[k]), float(them.y[k]), float(them.heading[k])).centre
        ahead, _ = to_ego_frame(ox, oy, ex, ey, float(ego.heading[k]))
        closing = float(ego.speed[k]) - float(them.speed[k]) * np.cos(np.radians(apart))
        return "rear_end" if ahead > 0.0 and closing > 0.0 else "cut_in"
    if _turning(run, k):
        return "turn_across"
    return "oncoming" if apart >= ONCOMING else "crossing"


def _turning(run: Run, k: int) -> bool:
    """The ego's route turns through more than TURNING degrees around where the ego was at step k."""
    route = run.task.route
    s = float(run.progress[k])
    at = np.arange(max(s - TURN_BEHIND, 0.0), min(s + TURN_AHEAD, route.length), 1.0)
    if len(at) < 2:
        return False
    headings = np.array([route.heading(float(a)) for a in at])
    turned = np.degrees(np.unwrap(np.radians(headings)))
    return float(turned.max() - turned.min()) > TURNING
