"""The oracle of one FMU test: did the ego under test fail?

Four checks, each a Finding:
- collision: the ego touched another body while moving faster than MOVING (an ego hit while it stood
  still has not failed: that is the NPC's doing);
- goal: it reached its goal within its time budget (not judged when a collision ended the run);
- min_ttc: while it moved, its time to collision with any body never fell below TTC_LIMIT;
- harsh_braking: it never braked harder than HARSH_BRAKING.
The verdict's facts give the measured values and `failure`, the first failed check's class, which
the evaluation groups in the spirit of the paper's violation types.
"""

from __future__ import annotations

import math

import numpy as np
from sovarc.compiler.plan import Plan
from sovarc.targets.fmu.geometry import centre, time_to_collision
from sovarc.targets.fmu.harness import Run
from sovarc.targets.fmu.interface import STEP
from sovarc.targets.fmu.task import to_ego_frame
from sovarc.targets.verdict import Finding, Verdict

MOVING = 0.5  # m/s: slower than this, the ego stands still
TTC_LIMIT = 1.0  # s: a smaller time to collision is a near miss
HARSH_BRAKING = 5.0  # m/s²: braking harder than this is harsh (about half of g)
BLOCKED_AHEAD = 20.0  # m: a standing body this close ahead of a stopped ego blocks it

# Failure classes, most serious first (the evaluation's table counts them in this order).
FAILURE_CLASSES: dict[str, str] = {
    "rear_end": "collision: the ego ran into the back of another",
    "struck_from_behind": "collision: hit from behind while moving",
    "head_on": "collision: head-on",
    "angle": "collision: angle or side",
    "pedestrian": "collision: hit a pedestrian",
    "stuck": "did not reach its goal: stopped behind a standing vehicle",
    "goal": "did not reach its goal in time",
    "near_miss": f"near miss: time to collision under {TTC_LIMIT:g} s",
    "harsh_braking": f"harsh braking: over {HARSH_BRAKING:g} m/s²",
}


def judge(run: Run, plan: Plan, *, seed: int = 0, fmu: str = "", method: str = "report") -> Verdict:
    ego = run.ego_track
    findings: list[Finding] = []
    facts: dict[str, object] = {
        "ego": run.ego,
        "fmu": fmu,
        "method": method,
        "seed": seed,
        "ended": run.ended,
        "duration": _r(float(run.times[-1])),
        "budget": _r(run.task.budget),
    }
    failure = None
    if run.contact is not None:
        finding, kind, details = _collision(run)
        findings.append(finding)
        facts["collision"] = details
        failure = None if finding.passed else kind
    else:
        findings.append(Finding("collision", True, "the ego touched no one"))
        reached = run.ended == "goal"
        end = float(run.times[-1])
        if run.task.hold:
            moved = float(run.progress.max())
            reached = moved <= run.task.goal
            message = f"the ego's task was to hold its position (its participant never moved): it moved {moved:.1f} m"
        elif reached:
            message = f"the ego reached its goal at t = {end:.2f} s (budget {run.task.budget:.1f} s)"
        else:
            short = run.task.goal - float(run.progress[-1])
            message = f"the ego did not reach its goal within {run.task.budget:.1f} s: it stopped {short:.1f} m short"
        findings.append(Finding("goal", reached, message, end))
        facts["goal_time"] = _r(end) if reached else None
        failure = failure or (None if reached else ("stuck" if _blocked(run) else "goal"))

    ttc, at, other = _min_ttc(run)
    facts["min_ttc"] = None if math.isinf(ttc) else _r(ttc)
    if other is None:
        findings.append(Finding("min_ttc", True, "no body came within the TTC horizon while the ego moved"))
    else:
        near = ttc < TTC_LIMIT
        findings.append(
            Finding(
                "min_ttc", not near, f"the smallest time to collision while moving was {ttc:.2f} s, with {other}", at
            )
        )
        failure = failure or ("near_miss" if near else None)

    decel, when = _peak_braking(run)
    facts["peak_braking"] = _r(decel)
    harsh = decel > HARSH_BRAKING + 1e-9
    message = f"the hardest braking was {decel:.1f} m/s²" + (f" (limit {HARSH_BRAKING:g})" if harsh else "")
    findings.append(Finding("harsh_braking", not harsh, message, when if decel > 0 else None))
    failure = failure or ("harsh_braking" if harsh else None)

    facts["failure"] = failure
    facts["max_speed"] = _r(float(ego.speed.max()))
    return Verdict("fmu", plan.scenario.name, plan.site, tuple(findings), facts)


def _collision(run: Run) -> tuple[Finding, str, dict[str, object]]:
    assert run.contact is not None
    ego, other = run.ego_track, run.tracks[run.contact.other]
    speed = float(ego.speed[-1])
    kind = _contact_kind(run)
    details: dict[str, object] = {
        "time": _r(run.contact.time),
        "other": run.contact.other,
        "ego_speed": _r(speed),
        "other_speed": _r(float(other.speed[-1])),
        "kind": kind,
    }
    if speed > MOVING:
        message = f"the ego, at {speed:.1f} m/s, collided with {run.contact.other}: {FAILURE_CLASSES[kind]}"
        return Finding("collision", False, message, run.contact.time), kind, details
    message = f"{run.contact.other} struck the ego while it stood still ({speed:.1f} m/s): not the ego's failure"
    return Finding("collision", True, message, run.contact.time), kind, details


def _contact_kind(run: Run) -> str:
    assert run.contact is not None
    ego, other = run.ego_track, run.tracks[run.contact.other]
    if other.body.vclass == "pedestrian":
        return "pedestrian"
    turn = abs(((float(other.heading[-1]) - float(ego.heading[-1]) + 180.0) % 360.0) - 180.0)
    if turn >= 150.0:
        return "head_on"
    if turn > 30.0:
        return "angle"
    ox, oy = centre(float(other.x[-1]), float(other.y[-1]), float(other.heading[-1]), other.body)
    ex, ey = centre(float(ego.x[-1]), float(ego.y[-1]), float(ego.heading[-1]), ego.body)
    ahead, _ = to_ego_frame(ox, oy, ex, ey, float(ego.heading[-1]))
    return "rear_end" if ahead > 0.0 else "struck_from_behind"


def _blocked(run: Run) -> str | None:
    """The standing body the ego ended up stopped behind (within BLOCKED_AHEAD, in its lane), if any."""
    ego = run.ego_track
    if float(ego.speed[-1]) > MOVING:
        return None
    x, y, heading = float(ego.x[-1]), float(ego.y[-1]), float(ego.heading[-1])
    for name in sorted(run.tracks):
        track = run.tracks[name]
        if name == run.ego or float(track.speed[-1]) > MOVING:
            continue
        cx, cy = centre(float(track.x[-1]), float(track.y[-1]), float(track.heading[-1]), track.body)
        ahead, left = to_ego_frame(cx, cy, x, y, heading)
        if 0.0 < ahead < BLOCKED_AHEAD and abs(left) < (ego.body.width + track.body.width) / 2.0 + 0.5:
            return name
    return None


def _min_ttc(run: Run) -> tuple[float, float | None, str | None]:
    ego = run.ego_track
    moving = ego.speed > MOVING
    best, at, who = math.inf, None, None
    if not moving.any():
        return best, at, who
    mine = (ego.x[moving], ego.y[moving], ego.heading[moving], ego.speed[moving])
    times = run.times[moving]
    for name in sorted(run.tracks):
        if name == run.ego:
            continue
        track = run.tracks[name]
        theirs = (track.x[moving], track.y[moving], track.heading[moving], track.speed[moving])
        ttc = time_to_collision(mine, ego.body, theirs, track.body)
        k = int(np.argmin(ttc))
        if ttc[k] < best:
            best, at, who = float(ttc[k]), float(times[k]), name
    return best, at, who


def _peak_braking(run: Run) -> tuple[float, float]:
    speed = run.ego_track.speed
    if len(speed) < 2:
        return 0.0, 0.0
    decel = -np.diff(speed) / STEP
    k = int(np.argmax(decel))
    return max(float(decel[k]), 0.0), float(run.times[k + 1])


def _r(value: float) -> float:
    rounded = round(value, 3)
    return 0.0 if rounded == 0 else rounded
