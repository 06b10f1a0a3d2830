"""Z3's answer does not hang on its time limits: a problem one engine is lost on goes to the other."""

from __future__ import annotations

from pathlib import Path

import sumo
from sovarc.compiler.frontend.truth import import_truth_file
from sovarc.compiler.lower import lower_on, sites_for
from sovarc.compiler.lower.solve import NICE_T_MAX
from sovarc.compiler.maps import load_map

from tests.conftest import SHARED, requires_shared

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
