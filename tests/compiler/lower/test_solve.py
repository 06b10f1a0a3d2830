"""Z3's answer does not hang on its time limits: a problem one engine is lost on goes to the other;
and a pass that can only fail again is not tried."""

from __future__ import annotations

import sys
from collections.abc import Callable
from pathlib import Path

import pytest
import sovarc.compiler.lower as lowering
import sumo
import z3
from sovarc.compiler.frontend.truth import import_truth_file
from sovarc.compiler.lower import lower_on, sites_for
from sovarc.compiler.lower.solve import MAX_PATIENCE, NICE_T_MAX, T_MAX, ConflictError, Fact, Problem, Solution
from sovarc.compiler.maps import load_map

from tests.conftest import EXAMPLES, SHARED, requires_shared

solve_module = sys.modules["sovarc.compiler.lower.solve"]  # the package's `solve` is the function

TRUTH = SHARED / "data" / "nmvccs" / "truth"
CITY = Path(sumo.SUMO_HOME) / "tools" / "game" / "DRT" / "osm.net.xml"
# A cluster junction of the DRT city where crossing_14's natural pass (impact within 12 s) under
# tracking literals ran past any sensible time limit, so the plan depended on when it gave up.
CLUSTER = "junction:cluster_1560223404_2335739502_3273797701"


@requires_shared
def test_a_hard_nonlinear_problem_is_solved_in_the_natural_pass_not_given_up_on_a_clock() -> None:
    scenario = import_truth_file(TRUTH / "crossing" / "14.json").scenario
    road_map = load_map(CITY)
    staged, notes, matches = sites_for(scenario, road_map, roads=12)
    match = next(m for m in matches if m.site.id == CLUSTER)
    lowered = lower_on(staged, match, road_map, notes)
    assert not lowered.solution.relaxed
    assert lowered.solution.impact_time <= NICE_T_MAX[0]


def _every_pass(problem: Problem) -> Solution:
    """`solve` as first written: every natural pass, then the relaxed one."""
    for t_max in NICE_T_MAX:
        try:
            return solve_module._solve(problem, nice=True, t_max=t_max)
        except ConflictError:
            pass
    return solve_module._solve(problem, nice=False, t_max=T_MAX)


def _outcome(run: Callable[[Problem], Solution], problem: Problem) -> Solution | list[Fact]:
    try:
        return run(problem)
    except ConflictError as conflict:
        return conflict.facts


@requires_shared
def test_a_natural_pass_whose_conflict_leaves_out_the_deadline_is_not_tried_again_later(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The natural passes differ in their deadline alone: a conflict without it is a conflict under
    the later deadline too, so that pass is skipped, and every answer is the one all passes give."""
    problems: list[Problem] = []
    real = lowering.solve

    def keep(problem: Problem) -> Solution:
        problems.append(problem)
        return real(problem)

    monkeypatch.setattr(lowering, "solve", keep)
    # a car striking the side of one on a straight road (the double-yellow pass example served until
    # its swerve was read from the centre line: its passes no longer conflict without the deadline)
    scenario = import_truth_file(TRUTH / "straight" / "3.json").scenario
    lowering.lower(scenario, load_map(EXAMPLES / "maps" / "town.net.xml"), roads=3)
    monkeypatch.setattr(lowering, "solve", real)
    passes: list[float] = []
    solve_pass = solve_module._solve

    def counted(problem: Problem, nice: bool, t_max: float, patience: int = 1) -> Solution:
        passes.append(t_max)
        return solve_pass(problem, nice, t_max, patience)

    skipped = 0
    for problem in problems:
        monkeypatch.setattr(solve_module, "_solve", counted)
        passes.clear()
        outcome = _outcome(solve_module.solve, problem)
        skipped += NICE_T_MAX[0] in passes and NICE_T_MAX[1] not in passes and T_MAX in passes
        monkeypatch.setattr(solve_module, "_solve", solve_pass)
        assert outcome == _outcome(_every_pass, problem)
    assert skipped >= 1


def _lost(clock_ms: int) -> z3.Solver:
    """A nonlinear problem Z3 is lost on for far longer than `clock_ms`, under that clock."""
    x, y, w = z3.Reals("x y w")
    solver = z3.Solver()
    solver.set("timeout", clock_ms)
    solver.add(
        x * x * x + y * y * y == w * w * w, x > 1, y > 1, w > 1, x * y * w == 1000003, x * x + y == w * w * w * y
    )
    return solver


def test_a_search_is_judged_by_its_cpu_time_not_by_the_clock() -> None:
    """Z3's clock is wall time: a search it stops before the search has had its CPU budget was
    starved by a busy machine and is run again with a longer clock (so a loaded batch plans as an
    idle one does), until patience runs out; an answer found only past the budget counts as none."""
    with pytest.raises(solve_module._StarvedError):
        solve_module._check(_lost(50), 60_000, 1)  # stopped after 50 ms: far short of a minute's CPU
    assert solve_module._check(_lost(50), 60_000, MAX_PATIENCE) == z3.unknown
    assert solve_module._check(_lost(200), 20, 1) == z3.unknown  # it had its 20 ms and more
    x = z3.Real("x")
    easy = z3.Solver()
    easy.add(x * x == 2.0, x > 0)
    assert solve_module._check(easy, 1000, 1) == z3.sat
    assert solve_module._check(easy, 0, 1) == z3.unknown  # any work at all is past a budget of none
