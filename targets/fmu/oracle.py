"""The oracle of one FMU test: did the ego under test fail?

The NPCs replay their trajectories and never react, so the oracle counts only what the ego did:
- collision: the ego touched another body while moving faster than MOVING, and its own motion brought
  the conflict on within CONTACT_WINDOW before (the test below). An ego hit while it stood still, run
  into from behind, or driven into where standing still would not have helped has not failed: that is
  the replaying NPC's doing (the paper counts the collisions an ADS causes);
- goal: it reached its goal within its time budget (not judged when a collision ended the run). An
  ego held up at the end by a body ahead on its route (standing, or no faster than it) had no way
  through, as the NPCs never move aside: not its failure;
- min_ttc: while it moved, its time to collision (the ego on along its route at its speed, the other
  straight on at its velocity) never fell below TTC_LIMIT through its own motion: a step counts when,
  had the ego stood still, the conflict would have come OWN_MARGIN later or never (an NPC closing
  from behind or driving into a slow ego is not the ego's near miss);
- harsh_braking: it never braked harder than HARSH_BRAKING, unless forced to by a body that was
  coming at it (the same test at the moment it braked) or by the state the test began in.
The verdict's facts give the measured values, `failure` (the first failed check) and `violation`,
what the ego did wrong in the spirit of the paper's violation types (violations.py).
"""

from __future__ import annotations

import math

import numpy as np
from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.geometry.bodies import Box, overlap
from sovarc.compiler.plan import Plan
from sovarc.targets.fmu.geometry import (
    TTC_HORIZON,
    Future,
    straight_on,
    ticks,
    time_to_collision,
)
from sovarc.targets.fmu.harness import Run, Track
from sovarc.targets.fmu.interface import STEP
from sovarc.targets.fmu.task import to_ego_frame
from sovarc.targets.fmu.violations import VIOLATIONS, violation
from sovarc.targets.verdict import Finding, Verdict

MOVING = 0.5  # m/s: slower than this, the ego stands still
TTC_LIMIT = 1.0  # s: a smaller time to collision is a near miss
OWN_MARGIN = 0.5  # s: the ego's own motion brought a conflict this much sooner
HARSH_BRAKING = 5.0  # m/s²: braking harder than this is harsh (about half of g)
BLOCKED_AHEAD = 25.0  # m of its route ahead of the ego where a body in the way holds it up
HELD_UP = 0.5  # m/s: a body ahead on the route no faster than the ego plus this holds it up
BRAKE_WINDOW = 1.0  # s around the hardest braking in which to look for what the ego braked for
CONTACT_WINDOW = 3.0  # s before a collision in which the ego's own motion must have brought it on
START_GRACE = 1.0  # s: harsh braking begun before this answers the state the test began in

# The checks that can fail a test, most serious first (the evaluation's table counts them in this order).
FAILURE_CLASSES: dict[str, str] = {
    "collision": "collision while the ego moved",
    "goal": "goal not reached, its route clear",
    "near_miss": f"near miss of its own making (TTC under {TTC_LIMIT:g} s)",
    "harsh_braking": f"harsh braking of its own making (over {HARSH_BRAKING:g} m/s²)",
}

# How the ego and another body met at a collision (facts["collision"]["kind"]).
CONTACT_KINDS = ("rear_end", "struck_from_behind", "head_on", "angle", "pedestrian")

__all__ = ["FAILURE_CLASSES", "VIOLATIONS", "judge"]


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
    failure: str | None = None
    partner: tuple[str | None, float] = (None, float(run.times[-1]))  # who and when, for the violation
    ttc = _Ttc(run)
    if run.contact is not None:
        finding, details = _collision(run, ttc)
        findings.append(finding)
        facts["collision"] = details
        if not finding.passed:
            failure, partner = "collision", (run.contact.other, run.contact.time)
    else:
        findings.append(Finding("collision", True, "the ego touched no one"))
        finding, blocker = _goal(run)
        findings.append(finding)
        facts["goal_time"] = _r(float(run.times[-1])) if run.ended == "goal" else None
        if blocker is not None:
            facts["blocked_by"] = blocker
        if not finding.passed:
            failure = "goal"

    best, own = _nearest(ttc, run.times, mask=ttc.moving), _nearest(ttc, run.times, mask=ttc.own)
    facts["min_ttc"] = None if best is None else _r(best[0])
    facts["min_own_ttc"] = None if own is None else _r(own[0])
    near = own is not None and own[0] < TTC_LIMIT
    findings.append(_ttc_finding(best, own, near))
    if near and failure is None:
        assert own is not None
        failure, partner = "near_miss", (own[2], own[1])

    finding, peak, braked_for, k = _braking(run, ttc)
    facts["peak_braking"] = _r(peak)
    findings.append(finding)
    if not finding.passed and failure is None:
        failure, partner = "harsh_braking", (braked_for, float(run.times[k]))

    facts["failure"] = failure
    stalled = float(ego.speed[-1]) <= MOVING
    facts["violation"] = violation(run, plan, failure, *partner, stalled=stalled) if failure else None
    facts["max_speed"] = _r(float(ego.speed.max()))
    return Verdict("fmu", plan.scenario.name, plan.site, tuple(findings), facts)


def _collision(run: Run, ttc: _Ttc) -> tuple[Finding, dict[str, object]]:
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
    name, at = run.contact.other, run.contact.time
    if speed <= MOVING:
        message = f"{name} struck the ego while it stood still ({speed:.1f} m/s): not the ego's failure"
        return Finding("collision", True, message, at), details
    if kind == "struck_from_behind":
        message = f"{name} ran into the back of the ego (at {speed:.1f} m/s): not the ego's failure"
        return Finding("collision", True, message, at), details
    recent = (run.times >= at - CONTACT_WINDOW) & np.isfinite(ttc.driven[name])
    if not (ttc.own[name] & recent).any():
        message = f"{name} drove into the ego (at {speed:.1f} m/s), which standing still would have been hit as soon"
        return Finding("collision", True, message + ": not the ego's failure", at), details
    message = f"the ego, at {speed:.1f} m/s, collided with {name} ({kind.replace('_', ' ')})"
    return Finding("collision", False, message, at), details


def _contact_kind(run: Run) -> str:
    assert run.contact is not None
    ego, other = run.ego_track, run.tracks[run.contact.other]
    if other.body.vclass == "pedestrian":
        return "pedestrian"
    turn = abs(angle_diff(float(other.heading[-1]), float(ego.heading[-1])))
    if turn >= 150.0:
        return "head_on"
    if turn > 30.0:
        return "angle"
    ox, oy = Box.of(other.body, float(other.x[-1]), float(other.y[-1]), float(other.heading[-1])).centre
    ex, ey = Box.of(ego.body, float(ego.x[-1]), float(ego.y[-1]), float(ego.heading[-1])).centre
    ahead, _ = to_ego_frame(ox, oy, ex, ey, float(ego.heading[-1]))
    return "rear_end" if ahead > 0.0 else "struck_from_behind"


def _goal(run: Run) -> tuple[Finding, str | None]:
    """The goal finding, and the body that blocked the ego's route if that is why it fell short."""
    end = float(run.times[-1])
    task = run.task
    if task.hold:
        moved = float(run.progress.max())
        message = f"the ego's task was to hold its position (its participant never moved): it moved {moved:.1f} m"
        return Finding("goal", moved <= task.goal, message, end), None
    if run.ended == "goal":
        message = f"the ego reached its goal at t = {end:.2f} s (budget {task.budget:.1f} s)"
        return Finding("goal", True, message, end), None
    short = task.goal - float(run.progress[-1])
    blocker = _blocked(run)
    if blocker is not None:
        message = f"the ego ended {short:.1f} m short of its goal, held up by {blocker} ahead on its route"
        return Finding("goal", True, message + ": not the ego's failure", end), blocker
    stalled = float(run.ego_track.speed[-1]) <= MOVING
    how = "it stood still, its route clear," if stalled else "it drove too slowly and was"
    message = f"the ego did not reach its goal within {task.budget:.1f} s: {how} {short:.1f} m short"
    return Finding("goal", False, message, end), None


def _blocked(run: Run) -> str | None:
    """The body that held the ego up where it ended: on its route within BLOCKED_AHEAD, and no faster
    than the ego (standing, or a slower NPC that it followed and the reference ego cannot pass)."""
    ego = run.ego_track
    speed = float(ego.speed[-1])
    s = float(run.progress[-1])
    route = run.task.route
    ahead = np.arange(s, min(s + BLOCKED_AHEAD, route.length), 1.0)
    poses = [(*route.point_at(float(a)), route.heading(float(a))) for a in ahead]
    for name in sorted(run.tracks):
        track = run.tracks[name]
        if name == run.ego or float(track.speed[-1]) > max(speed, MOVING) + HELD_UP:
            continue
        box = Box.of(track.body, float(track.x[-1]), float(track.y[-1]), float(track.heading[-1]))
        if any(overlap(Box.of(ego.body, x, y, h), box) for x, y, h in poses):
            return name
    return None


class _Ttc:
    """Per other body, per step the ego moved: the time to collision with the ego going on along its
    route at its speed, and had it stood still; the other goes straight on at its velocity."""

    def __init__(self, run: Run) -> None:
        ego = run.ego_track
        self.moving = ego.speed > MOVING
        steps = np.flatnonzero(self.moving)
        driving = _along_route(run, steps)
        self.driven: dict[str, np.ndarray] = {}
        self.standing: dict[str, np.ndarray] = {}
        for name in sorted(run.tracks):
            if name == run.ego:
                continue
            track: Track = run.tracks[name]
            self.driven[name] = np.full(len(ego.speed), np.inf)
            self.standing[name] = np.full(len(ego.speed), np.inf)
            # only steps where the two could meet within the horizon are worth predicting
            reach = (ego.speed[steps] + np.abs(track.speed[steps])) * TTC_HORIZON + ego.body.length + track.body.length
            near = np.hypot(track.x[steps] - ego.x[steps], track.y[steps] - ego.y[steps]) <= reach
            if not near.any():
                continue
            at = steps[near]
            theirs = straight_on(track.x[at], track.y[at], track.heading[at], track.speed[at])
            mine = tuple(a[near] for a in driving)
            self.driven[name][at] = time_to_collision(mine, ego.body, theirs, track.body)  # type: ignore[arg-type]
            meets = at[np.isfinite(self.driven[name][at])]  # standing still matters only where it meets
            if len(meets):
                still = straight_on(ego.x[meets], ego.y[meets], ego.heading[meets], np.zeros(len(meets)))
                them = straight_on(track.x[meets], track.y[meets], track.heading[meets], track.speed[meets])
                self.standing[name][meets] = time_to_collision(still, ego.body, them, track.body)
        # per body: the steps where the ego's own motion brought the conflict OWN_MARGIN sooner (or at all)
        self.own = {n: self.moving & (self.standing[n] >= self.driven[n] + OWN_MARGIN) for n in self.driven}


def _along_route(run: Run, steps: np.ndarray) -> Future:
    """Where the ego will be at each tick from each step if it drives on along its route at its speed."""
    ego, route = run.ego_track, run.task.route
    here = run.progress[steps]
    s = here[:, None] + ego.speed[steps, None] * ticks()[None, :]
    ahead = route.points_at(s.ravel()).reshape(*s.shape, 2) - route.points_at(here)[:, None, :]
    turn = route.headings(s) - route.headings(here)[:, None]
    return (
        ego.x[steps, None] + ahead[..., 0],
        ego.y[steps, None] + ahead[..., 1],
        (ego.heading[steps, None] + turn) % 360.0,
    )


def _nearest(
    ttc: _Ttc, times: np.ndarray, *, mask: np.ndarray | dict[str, np.ndarray]
) -> tuple[float, float, str] | None:
    """(smallest TTC, when, with whom) over the steps the mask keeps, or None if no body came within the horizon."""
    best: tuple[float, float, str] | None = None
    for name, values in ttc.driven.items():
        keep = mask[name] if isinstance(mask, dict) else mask
        if not keep.any():
            continue
        kept = np.where(keep, values, np.inf)
        k = int(np.argmin(kept))
        if math.isfinite(kept[k]) and (best is None or kept[k] < best[0]):
            best = (float(kept[k]), float(times[k]), name)
    return best


def _ttc_finding(best: tuple[float, float, str] | None, own: tuple[float, float, str] | None, near: bool) -> Finding:
    if best is None:
        return Finding("min_ttc", True, "no body came within the TTC horizon while the ego moved")
    ttc, at, other = best
    message = f"the smallest time to collision while moving was {ttc:.2f} s, with {other}"
    if near:
        assert own is not None
        return Finding("min_ttc", False, f"{message}; of its own making {own[0]:.2f} s, with {own[2]}", own[1])
    if ttc < TTC_LIMIT:
        message += ", coming at the ego: not of its own making"
    return Finding("min_ttc", True, message, at)


def _braked_for(ttc: _Ttc, times: np.ndarray, k: int) -> tuple[str | None, bool]:
    """The body the ego braked for when its hardest braking began at step k (the smallest TTC then, or
    else within BRAKE_WINDOW while it moved; None: no one), and whether that body was coming at it
    (the conflict not of the ego's own making at that step)."""
    per = max(round(BRAKE_WINDOW / STEP), 1)
    window = np.zeros(len(times), dtype=bool)
    window[max(k - per, 0) : k + per + 1] = True
    best: tuple[float, str, int] | None = None
    for steps in (np.arange(len(times)) == k, window & ttc.moving):
        for name, values in ttc.driven.items():
            kept = np.where(steps, values, np.inf)
            j = int(np.argmin(kept))
            if math.isfinite(kept[j]) and (best is None or kept[j] < best[0]):
                best = (float(kept[j]), name, j)
        if best is not None:
            break
    if best is None:
        return None, False
    _, name, j = best
    return name, not bool(ttc.own[name][j])


def _braking(run: Run, ttc: _Ttc) -> tuple[Finding, float, str | None, int]:
    """The harsh-braking finding, the hardest deceleration, what the ego braked for and the step it began.

    Braking that began within START_GRACE answers the state the test put the ego in (a plan may start
    a striker a car length behind its victim), so it is reported but not held against the ego."""
    speed = run.ego_track.speed
    decel = -np.diff(speed) / STEP if len(speed) > 1 else np.zeros(1)
    peak = max(float(decel.max()), 0.0)
    harsh = decel > HARSH_BRAKING + 1e-9
    counted = decel.copy()
    k = 0
    while k < len(harsh) and run.times[k] < START_GRACE:  # each harsh braking begun in the grace, to its end
        while k < len(harsh) and harsh[k]:
            counted[k] = 0.0
            k += 1
        k += 1
    k = int(np.argmax(counted))
    message = f"the hardest braking was {peak:.1f} m/s²"
    if counted[k] <= HARSH_BRAKING + 1e-9:
        if peak > HARSH_BRAKING + 1e-9:
            message += f" (limit {HARSH_BRAKING:g}), at the start, answering the state the test began in"
        at = int(np.argmax(decel))
        return Finding("harsh_braking", True, message, float(run.times[at + 1]) if peak > 0 else None), peak, None, at
    braked_for, forced = _braked_for(ttc, run.times, k)
    message = f"the hardest braking was {float(counted[k]):.1f} m/s² (limit {HARSH_BRAKING:g})"
    message += (
        f", forced by {braked_for} coming at it" if forced else f", for {braked_for or 'no one on a collision course'}"
    )
    return Finding("harsh_braking", forced, message, float(run.times[k + 1])), peak, braked_for, k


def _r(value: float) -> float:
    rounded = round(value, 3)
    return 0.0 if rounded == 0 else rounded
