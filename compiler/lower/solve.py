"""The constraint problem of one scenario on one site, solved with Z3.

Every participant drives its route in legs: a leg starts moving or from rest, cruises at
one speed, and ends at a stop or runs on. The stops of a three-point turn (before it and at
each change of gear) are stops like any other, at fixed places; the crash is on the last leg,
so after a turn's last change of gear (contact.py keeps to that stretch). Unknowns: where each participant starts, where
it stops (when the site leaves that open), each leg's speed and duration, each stop's
dwell, where on the contact the crash happens, and the impact time t_hit. The constraints are
the paper's groups:

- Group 1: starts and stops on the route, in range; a lead before the first action.
- Group 2: the route's geometry (built by routes.py); its curves cap speeds, below.
- Group 3: speeds positive, within the limit (or the reported speed), within the curve caps.
- Group 4: legs chain: a leg ends where the next begins, with the dwell between.
- Group 5: striker and victim reach the contact at the same t_hit, at the faces the crash
  type names; a rear-end striker is faster than its victim.

A leg from rest accelerates at A_UP and one ending at rest brakes at B_DOWN (a trapezoid
speed profile), which makes the problem polynomial; Z3 solves it exactly. Each constraint
is tracked under a `Fact` that points at the IR text it comes from, so an unsatisfiable
problem is reported as the set of conflicting facts, with their spans.

Passes: first with preferences that make a natural-looking crash (speeds near the reported
or usual ones, a few seconds of approach, the crash within 12 s, then within 25 s); if
those fail, with only the hard facts. Only the last pass's failure is an error.
"""

from __future__ import annotations

import itertools
import math
import time
from dataclasses import dataclass, field, replace
from fractions import Fraction
from typing import Any

import numpy as np
import z3
from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.lower.contact import Contact, meeting
from sovarc.compiler.lower.route import LEAD, Route
from sovarc.compiler.vehicles import PLANNED, model
from sovarc.dsl.ir import ActionKind, CrashType, Role

A_UP = PLANNED.start_accel  # m/s^2, a car starting from rest (each body's own: ramps())
B_DOWN = PLANNED.stop_decel  # m/s^2, a car braking to rest
DWELL = 0.5  # s, the least a stop lasts
NICE_DWELL = 1.5  # s
V_MIN = {Role.VEHICLE: 1.5, Role.PEDESTRIAN: 0.5}  # m/s while moving
V_PED_MAX = 3.0
T_MAX = 60.0  # s
NICE_T_MAX = (12.0, 25.0)  # s: a short approach first (Z3 takes any model, often the bound)
REAR_END_GAIN = 1.5  # m/s a rear-end striker is faster than its moving victim
MIN_LEAD = 6.0  # m a vehicle drives before the crash at the least (LEAD is the natural length)
AFTER_CRASH = 3.0  # m past the contact whose curves still cap the approach speed
START_TOUCH = 0.5  # m: lines that begin this close begin in one lane
PART_STEP = 0.5  # m between the points where lines that begin together are compared
PART_MARGIN = 0.3  # m between bodies side by side that have parted
START_TURN = 60.0  # degrees: lines that begin together and part by less go one way from there
START_GAP = 1.0  # m between two vehicles that start one behind the other in one lane
RLIMIT = 5_000_000  # Z3 resource units per check: the problems here take under 100 000
# Time limits, for the searches the work budget does not stop (nonlinear steps count little).
# Tracked solves take under 0.15 s but for a few that take 0.4 s or run to minutes; those go to
# the plain engine, which takes about 10 ms. A limit between the two keeps the answer the same
# under load up to a factor of about 2.5.
TRACKED_MS = 1000
PLAIN_MS = 3000
# The limits are of the search's own CPU time, so that a busy machine gives the answer an idle one
# does (a plan is the same however loaded its batch ran): Z3's clock is wall time, so a search it
# stops before it has had its CPU time is run again, from a fresh context, with a clock this many
# times longer, doubling; and an answer found only after its CPU time is taken as none.
MAX_PATIENCE = 32
BACKING_FOR = 2.0  # s a backing car is preferred to back at its speed before the crash
SHALLOW_SIDE = 60.0  # degrees: a side crash at a smaller angle is a sideswipe or a cut-in


@dataclass(frozen=True)
class Fact:
    """A source of constraints: what it says and where the IR says it."""

    label: str
    message: str
    span: Any = None  # dsl.span.Span or None for facts of the site


@dataclass
class Leg:
    start: Any  # z3 expression (m)
    end: Any | None  # None: runs on to the end of the plan
    from_rest: bool
    to_rest: bool
    v: Any
    t: Any  # duration; for an open leg, up to the impact (or the leg's own start time)
    begin: Any  # z3 expression: time the leg starts (s)
    up: float = A_UP  # m/s^2 of its ramp from rest
    down: float = B_DOWN  # m/s^2 of its ramp to rest
    backing: bool = False  # driven backing along the road (its ramps are the reversing ones)


@dataclass
class Motion:
    """The unknowns of one participant."""

    route: Route
    start: Any
    initial_dwell: Any | None
    legs: list[Leg] = field(default_factory=list)
    dwells: list[Any] = field(default_factory=list)  # after legs[i] when it ends at rest
    impact_s: Any | None = None
    stopped_at_impact: bool = False


@dataclass(frozen=True)
class LegValues:
    start: float
    end: float | None
    from_rest: bool
    to_rest: bool
    v: float
    begin: float
    duration: float | None
    dwell: float  # after it, when it ends at rest
    up: float = A_UP  # m/s^2 of its ramps (a backing leg's are the vehicle's reversing ones)
    down: float = B_DOWN
    backing: bool = False


@dataclass(frozen=True)
class Solution:
    impact_time: float
    impact: dict[str, float]  # participant -> arc length at impact (striker and victim)
    legs: dict[str, tuple[LegValues, ...]]
    initial_dwell: dict[str, float]
    starts: dict[str, float]
    relaxed: bool  # the natural-looking pass failed; only hard facts hold
    held: tuple[str, ...] = ()  # participants whose start was held past a corner (Route.start_lo)


class ConflictError(Exception):
    def __init__(self, facts: list[Fact], *, deadline: bool = True) -> None:
        super().__init__(", ".join(f.label for f in facts))
        self.facts = facts
        self.deadline = deadline  # False: Z3's unsat core leaves the deadline (t_max) out


@dataclass
class Problem:
    routes: dict[str, Route]
    striker: str
    victim: str
    crash: CrashType
    contact: Contact
    vmax: dict[str, tuple[float, Fact]]  # participant -> (hard speed bound, the fact behind it)
    preferred: dict[str, float]  # participant -> preferred cruise speed
    facts: dict[str, Fact]  # by label
    stationary: set[str] = field(default_factory=set)  # participants stopped throughout
    held: tuple[str, ...] = ()  # participants whose start is held to their route's start_lo


def solve(problem: Problem) -> Solution:
    """The problem's solution; solved again with the starts held past their corners (Route.start_lo)
    only when a start lies before one, so that a plan whose start was past it is unchanged. Where
    no start past the corner fits, the first solution stands (its plan crosses the line)."""
    solution = _passes(problem)
    early = tuple(
        pid
        for pid, route in problem.routes.items()
        if pid not in problem.stationary and not route.starts_at_rest and solution.starts[pid] < route.start_lo - 1e-6
    )
    if not early:
        return solution
    try:
        return replace(_passes(replace(problem, held=early)), held=early)
    except ConflictError:
        return solution


def _passes(problem: Problem) -> Solution:
    for t_max in NICE_T_MAX:
        try:
            return _patiently(problem, nice=True, t_max=t_max)
        except ConflictError as conflict:
            if not conflict.deadline:
                # The natural passes differ in their deadline alone: constraints that conflict
                # without it conflict under a later one too, so that pass would only fail again.
                break
    return _patiently(problem, nice=False, t_max=T_MAX)


class _StarvedError(Exception):
    """A search Z3's clock stopped before it had used its CPU time: the machine was busy."""


def _patiently(problem: Problem, nice: bool, t_max: float) -> Solution:
    """`_solve`, again with a longer clock while the machine's load starves its searches."""
    patience = 1
    while True:
        try:
            return _solve(problem, nice, t_max, patience)
        except _StarvedError:
            patience *= 2


def _check(solver: Any, budget_ms: int, patience: int) -> Any:
    """The solver's answer within `budget_ms` of CPU time (its clock is `patience` times that):
    unknown when it needed more; _StarvedError when the clock stopped it first, unless patience is out."""
    used = time.thread_time()
    result = solver.check()
    used = (time.thread_time() - used) * 1000.0
    if used > budget_ms:
        return z3.unknown  # an idle machine's clock would have stopped it
    if result == z3.unknown and solver.reason_unknown() == "timeout" and patience < MAX_PATIENCE:
        raise _StarvedError
    return result


@dataclass(frozen=True)
class _Terms:
    """Makes Z3 terms in one context."""

    ctx: Any

    def real(self, name: str) -> Any:
        return z3.Real(name, self.ctx)

    def val(self, value: float) -> Any:
        return z3.RealVal(value, self.ctx)


def _solve(problem: Problem, nice: bool, t_max: float, patience: int = 1) -> Solution:
    # A fresh context per problem: Z3's choice among models depends on every term its context
    # has seen, so sharing the global one would make a plan depend on what was solved before.
    z = _Terms(z3.Context())
    tracked: list[tuple[str, Any]] = []  # (label, constraint) in the order they were made

    def need(label: str, constraint: Any) -> None:
        tracked.append((label, constraint))

    t_hit = z.real("t_hit")
    need("impact", z3.And(t_hit >= 2.0, t_max >= t_hit))
    deadline = f"impact#{len(tracked) - 1}"  # the one constraint that names t_max
    motions = {pid: _motion(pid, r, problem, need, nice, z) for pid, r in problem.routes.items()}
    _apart_at_start(problem, motions, need)
    _contact(problem, motions, t_hit, need, nice, z)
    # Tracked assertions first, which name the facts of an unsat core. Under tracking literals
    # Z3 leaves its nonlinear engine, which is quick on most problems and lost on a few (a
    # crossing on a city cluster junction: 38 s); the plain assertions, solved by that engine in
    # milliseconds, take over there. The plain engine is itself lost proving some problems unsat
    # (turns in legs), which the tracked solve settles at once: neither can go alone.
    solver = _solver(z, TRACKED_MS * patience)
    names: dict[str, str] = {}
    for i, (label, constraint) in enumerate(tracked):
        names[f"{label}#{i}"] = label
        solver.assert_and_track(constraint, z3.Bool(f"{label}#{i}", z.ctx))
    result = _check(solver, TRACKED_MS, patience)
    if result == z3.unsat:
        core = {str(b) for b in solver.unsat_core()}
        facts = [problem.facts[label] for label in sorted({names[b] for b in core})]
        raise ConflictError(facts, deadline=deadline in core)
    if result == z3.unknown:
        solver = _solver(z, PLAIN_MS * patience)
        solver.add(*(constraint for _, constraint in tracked))
        result = _check(solver, PLAIN_MS, patience)
    if result == z3.sat:
        return _values(solver.model(), motions, t_hit, problem, relaxed=not nice)
    if result == z3.unsat:  # proved by the plain engine alone: every fact is named
        raise ConflictError([problem.facts[label] for label in sorted({label for label, _ in tracked})])
    raise ConflictError([problem.facts["impact"]])


def _solver(z: _Terms, timeout_ms: int) -> Any:
    solver = z3.Solver(ctx=z.ctx)
    solver.set("random_seed", 0)
    # A budget of work, which does not depend on the machine's load, and a clock for the
    # nonlinear searches it does not stop.
    solver.set("rlimit", RLIMIT)
    solver.set("timeout", timeout_ms)
    return solver


def _motion(pid: str, route: Route, problem: Problem, need: Any, nice: bool, z: _Terms) -> Motion:
    role = route.participant.role
    stops = route.stops()
    actions = route.participant.known_actions
    final_stop = (
        pid == problem.victim
        and bool(stops)
        and bool(actions)
        and actions[-1].kind is ActionKind.STOP
        and stops[-1].index == len(actions) - 1
    )
    if pid == problem.striker and stops and actions and actions[-1].kind is ActionKind.STOP:
        stops = stops[:-1]  # a striker's last stop comes after the crash
    positions = []
    for k, stop in enumerate(stops):
        q = z.real(f"{pid}.stop{k}")
        label = f"{pid}.action{stop.index}" if stop.index >= 0 else f"{pid}.route"  # a turn no action names
        if final_stop and k == len(stops) - 1:
            need(label, z3.And(q >= 0.0, q <= route.line.length))
        else:
            need(label, z3.And(q >= stop.lo, q <= stop.hi))
        if positions:
            need(label, q >= positions[-1] + 1.0)
        positions.append(q)
    motion = Motion(route, None, None)
    if pid in problem.stationary:
        q = positions[-1] if positions else z.real(f"{pid}.start")
        need(f"{pid}.route", z3.And(q >= 0.0, q <= route.line.length - 1.0))
        motion.start = q
        motion.stopped_at_impact = True
        motion.impact_s = q
        return motion
    begin: Any = z.val(0)
    if route.starts_at_rest:
        initial = bool(stops) and stops[0].index == 0 and not stops[0].gear_stop  # its first action stops it
        start = positions.pop(0) if initial else z.val(0.0)
        if initial:
            stops = stops[1:]
        dwell = z.real(f"{pid}.dwell0")
        need(f"{pid}.route", dwell >= (NICE_DWELL if nice else DWELL))
        motion.initial_dwell = dwell
        begin = dwell
        from_rest = True
    else:
        start = z.real(f"{pid}.start")
        need(f"{pid}.route", z3.And(start >= 0.0, start <= route.start_hi))
        if pid in problem.held:  # past a corner its body would cross a line in (corners.py)
            need(f"{pid}.route", start >= route.start_lo)
        from_rest = False
    motion.start = start
    bounds = [start, *positions]
    vmax, vfact = problem.vmax[pid]
    for j, leg_start in enumerate(bounds):
        if final_stop and j == len(bounds) - 1:
            break  # stopped at the crash: no leg after the last stop
        end = bounds[j + 1] if j + 1 < len(bounds) else None
        v, t = z.real(f"{pid}.v{j}"), z.real(f"{pid}.t{j}")
        cap = _leg_cap(route, j, stops, _reach(problem, pid) if end is None else None)
        low = V_MIN[role]
        high = min(vmax, cap)
        need(vfact.label, z3.And(v >= low, v <= vmax))
        need(f"{pid}.curve{j}", v <= max(cap, low))
        if nice:
            pref = min(problem.preferred[pid], high)
            need(vfact.label, z3.And(v >= max(low, 0.75 * pref), v <= max(low, pref)))
        lo = 0.0 if j == 0 else stops[j - 1].lo
        up, down = _ramps(route, lo)
        leg = Leg(leg_start, end, from_rest, end is not None, v, t, begin, up, down, route.backing(lo))
        if end is not None:
            ramps = (v * v / (2 * up) if from_rest else 0) + v * v / (2 * down)
            need(f"{pid}.chain", end - leg_start == v * t - ramps)
            need(f"{pid}.chain", t >= (v / up if from_rest else 0) + v / down)
            dwell = z.real(f"{pid}.dwell{j + 1}")
            need(f"{pid}.chain", dwell >= (NICE_DWELL if nice else DWELL))
            motion.dwells.append(dwell)
            begin = begin + t + dwell
        motion.legs.append(leg)
        from_rest = True
    if final_stop:
        motion.stopped_at_impact = True
        motion.impact_s = positions[-1]
    return motion


def ramps(route: Route) -> tuple[float, float]:
    """The trapezoid's ramps of a route's body: its start from rest and its braking to rest (m/s^2)."""
    limits = model(route.body).limits
    return limits.start_accel, limits.stop_decel


def _ramps(route: Route, lo: float) -> tuple[float, float]:
    """The ramps of the leg from arc length `lo`: the body's own (`ramps`); a car backing along the road eases
    in and out at its reversing rate. The legs of a turn in legs keep the usual ramps: some are a metre long,
    too short to reach the least moving speed at that rate."""
    if route.backing(lo):
        backing = model(route.body).limits.reverse_accel
        return backing, backing
    return ramps(route)


def _leg_cap(route: Route, j: int, stops: list[Any], reach: float | None) -> float:
    """The lowest curve cap over leg j; an open leg of the crash pair only up to the crash
    (`reach`): what it would have driven after it does not slow it down before."""
    lo = 0.0 if j == 0 else stops[j - 1].lo
    hi = stops[j].hi if j < len(stops) else route.line.length
    if reach is not None:
        hi = min(hi, max(reach, lo + 1.0))
    return route.cap_between(lo, hi)


def _reach(problem: Problem, pid: str) -> float | None:
    """How far along its route a participant of the crash can be at the impact, or None."""
    c = problem.contact
    if pid == problem.striker:
        return c.hi + AFTER_CRASH
    if pid == problem.victim:
        return max(c.victim_s(c.lo), c.victim_s(c.hi)) + AFTER_CRASH
    return None


def _apart_at_start(problem: Problem, motions: dict[str, Motion], need: Any) -> None:
    """Vehicles whose lines begin together (one lane, one way) start a body length and START_GAP
    apart, the victim ahead of its striker: bodies that overlap at the start are a crash before
    the crash (or a striker that begins already past the victim's rear)."""
    vehicles = [pid for pid, r in problem.routes.items() if r.participant.role is Role.VEHICLE]
    for a, b in itertools.combinations(vehicles, 2):
        ra, rb = problem.routes[a], problem.routes[b]
        if not _start_together(ra, rb):
            continue
        if {a, b} != {problem.striker, problem.victim}:
            need(
                f"{b}.route",
                z3.Or(
                    motions[b].start - motions[a].start >= _spacing(problem, b),
                    motions[a].start - motions[b].start >= _spacing(problem, a),
                ),
            )
            continue
        victim, striker = problem.victim, problem.striker
        parted = _parting(problem.routes[victim], problem.routes[striker], problem.contact.lo)
        if parted is None:
            need(f"{victim}.route", motions[victim].start - motions[striker].start >= _spacing(problem, victim))
        else:
            # they part before the crash (a pocket opens beside the lane): either may lead, and the
            # one behind stays behind until they have parted
            need(
                f"{victim}.route",
                z3.Or(
                    _in_turn(problem, motions, victim, striker, parted),
                    _in_turn(problem, motions, striker, victim, parted),
                ),
            )


def _in_turn(problem: Problem, motions: dict[str, Motion], ahead: str, behind: str, parted: float) -> Any:
    """`ahead` starts a body length and START_GAP ahead of `behind`, and stays ahead until `behind`
    reaches `parted`. The second is said for cruising legs that run on to the crash (their gap
    changes linearly, so its two ends bound it); other legs are held to the start alone."""
    lead, follow = motions[ahead], motions[behind]
    order = lead.start - follow.start >= _spacing(problem, ahead)
    legs = lead.legs[:1] + follow.legs[:1]
    if len(legs) < 2 or any(leg.from_rest or leg.end is not None for leg in legs):
        return order
    first, second = legs
    # the leader's front, less the spacing, at the time the follower's reaches `parted`, times its speed
    gap = (first.start - parted - _spacing(problem, ahead)) * second.v + first.v * (parted - second.start)
    return z3.And(order, gap >= 0)


def _parting(a: Route, b: Route, before: float) -> float | None:
    """Where two lines that begin together lie a body's width apart (their bodies side by side clear),
    if that is before arc length `before`."""
    apart = max(a.body.width, b.body.width) + PART_MARGIN
    for s in np.arange(0.0, min(before, a.line.length, b.line.length), PART_STEP):
        if math.dist(a.line.point(float(s)), b.line.point(float(s))) > apart:
            return float(s)
    return None


def _start_together(a: Route, b: Route) -> bool:
    """The two lines begin at one place, going one way: bodies started near one arc length would
    overlap. One way is within START_TURN: lines of one lane that part soon after they begin (a turn
    pocket opening off it, smoothed into a bend) leave it at a wide angle."""
    gap = math.dist(a.line.point(0.0), b.line.point(0.0))
    turn = abs(angle_diff(a.line.heading(0.0), b.line.heading(0.0)))
    return gap < START_TOUCH and turn < START_TURN


def _spacing(problem: Problem, ahead: str) -> float:
    """How far the front of the vehicle ahead is at the least from the front of the one behind."""
    return problem.routes[ahead].body.length + START_GAP


def _contact(problem: Problem, motions: dict[str, Motion], t_hit: Any, need: Any, nice: bool, z: _Terms) -> None:
    c = problem.contact
    crash = f"crash.{problem.crash.value}"
    striker, victim = motions[problem.striker], motions[problem.victim]
    s = z.real("contact")
    need(crash, z3.And(s >= c.lo, s <= c.hi))
    s_v = c.offset + c.sign * s if c.sign else z.val(c.offset)
    striker.impact_s = s
    _arrive(problem.striker, striker, s, t_hit, need, nice)
    if victim.stopped_at_impact:
        need(crash, victim.impact_s == s_v)
        if victim.legs:
            last = victim.legs[-1] if victim.legs[-1].end is not None else victim.legs[-2]
            need(crash, last.begin + last.t <= t_hit - 0.3)
    else:
        victim.impact_s = s_v
        _arrive(problem.victim, victim, s_v, t_hit, need, nice)
        if _catches_up(problem):
            need(crash, striker.legs[-1].v >= victim.legs[-1].v + REAR_END_GAIN)
        elif nice and problem.crash is CrashType.SIDE and c.angle < SHALLOW_SIDE:
            # Nearly side by side, the striker's front surely reaches the victim's side first if
            # it keeps up with it; a slower striker may fall back into the victim's path instead.
            # Preferred, not required: a short road may leave no room for it.
            along = math.cos(math.radians(c.angle))
            need(crash, striker.legs[-1].v * along >= victim.legs[-1].v)


def _catches_up(problem: Problem) -> bool:
    """Whether the striker comes up behind a victim going its way, its leading face into the victim's
    trailing one (the lines of a rear-end; a backing body runs against its faces, contact.meeting)."""
    _, lines = meeting(problem.crash, problem.routes[problem.striker], problem.routes[problem.victim])
    return lines is CrashType.REAR_END


def _arrive(pid: str, motion: Motion, s: Any, t_hit: Any, need: Any, nice: bool) -> None:
    """The participant is at arc length s at time t_hit, cruising on its last leg."""
    leg = motion.legs[-1]
    ramp = leg.v * leg.v / (2 * leg.up) if leg.from_rest else 0
    # Seen moving before the crash: LEAD metres when the site allows (a short arm of a city
    # junction may not; then a few metres do).
    lead = (LEAD if nice else MIN_LEAD) if motion.route.participant.role is Role.VEHICLE else 2.0
    need(f"{pid}.route", s - leg.start >= ramp + (0.0 if leg.from_rest else lead))
    if nice and leg.backing:  # a backing car is seen backing for a while (not met at the end of its ramp)
        need(f"{pid}.route", s - leg.start >= ramp + BACKING_FOR * leg.v)
    if nice and not leg.from_rest:
        need(f"{pid}.route", s - leg.start >= 3.0 * leg.v)
    need("impact", s - leg.start == leg.v * (t_hit - leg.begin) - ramp)
    need("impact", t_hit - leg.begin >= (leg.v / leg.up if leg.from_rest else 0))
    need(f"{pid}.route", s <= motion.route.line.length - 1.0)


def _num(value: Any) -> float:
    if z3.is_rational_value(value):
        return float(Fraction(value.numerator_as_long(), value.denominator_as_long()))
    if z3.is_algebraic_value(value):
        return _num(value.approx(15))
    raise ValueError(f"not a number: {value}")


def _values(model: Any, motions: dict[str, Motion], t_hit: Any, problem: Problem, relaxed: bool) -> Solution:
    def val(expr: Any) -> float:
        return _num(model.eval(expr, model_completion=True))

    legs: dict[str, tuple[LegValues, ...]] = {}
    impact: dict[str, float] = {}
    dwell0: dict[str, float] = {}
    starts: dict[str, float] = {}
    for pid, m in motions.items():
        starts[pid] = val(m.start)
        if m.initial_dwell is not None:
            dwell0[pid] = val(m.initial_dwell)
        values = []
        for j, leg in enumerate(m.legs):
            values.append(
                LegValues(
                    start=val(leg.start),
                    end=None if leg.end is None else val(leg.end),
                    from_rest=leg.from_rest,
                    to_rest=leg.to_rest,
                    v=val(leg.v),
                    begin=val(leg.begin),
                    duration=None if leg.end is None else val(leg.t),
                    dwell=val(m.dwells[j]) if j < len(m.dwells) else 0.0,
                    up=leg.up,
                    down=leg.down,
                    backing=leg.backing,
                )
            )
        legs[pid] = tuple(values)
        if m.impact_s is not None:
            impact[pid] = val(m.impact_s)
    return Solution(val(t_hit), impact, legs, dwell0, starts, relaxed)
