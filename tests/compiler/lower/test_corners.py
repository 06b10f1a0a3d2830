"""A car whose route runs through a tight corner before the site starts past it.

An arm runs back through a 2-arm node (`RoadNet.chain`); where that node is a corner (a grid's
90-degree bend) the kerb lane turns at a radius of a metre or two, and a body laid back along its
heading from the front bumper swings its rear over the lane's line there, into the lane beside
(the SUMO oracle's line crossing). The solver then holds the car's start past the last pose the
oracle would judge crossing (lower/corners.py); a plan whose start was past it already is
unchanged. Found on generated grids (issue 17).
"""

from __future__ import annotations

import subprocess
from dataclasses import replace
from pathlib import Path

import pytest
from sovarc.compiler import synth
from sovarc.compiler.lower import Lowered, _limit, _schedules, lower_on, sites_for
from sovarc.compiler.lower.solve import Solution
from sovarc.compiler.maps import RoadMap, load_map
from sovarc.compiler.maps.netconvert import netconvert_path
from sovarc.dsl import Scenario, parse
from sovarc.targets.sumo.check import check
from sovarc.targets.verdict import Finding

pytestmark = pytest.mark.slow  # netconvert builds the networks, SUMO replays the plans


def t_junction(folder: Path, corner: float) -> RoadMap:
    """A T junction at j: the through road comes 250 m from the south, bends east at the corner k
    (a 2-arm node) and runs `corner` metres on to j; the stem leaves j to the north. Three lanes
    each way, 3.2 m wide."""
    spots = {"s": (0, -250), "k": (0, 0), "j": (corner, 0), "e": (corner + 200, 0), "n": (corner, 200)}
    nodes = "".join(f'<node id="{n}" x="{x}" y="{y}" type="traffic_light"/>' for n, (x, y) in spots.items())
    rows = []
    for eid, a, b in [("sk", "s", "k"), ("kj", "k", "j"), ("je", "j", "e"), ("jn", "j", "n")]:
        rows.append(f'<edge id="{eid}" from="{a}" to="{b}" numLanes="3" speed="13.9" width="3.2"/>')
        rows.append(f'<edge id="-{eid}" from="{b}" to="{a}" numLanes="3" speed="13.9" width="3.2"/>')
    (folder / "n.nod.xml").write_text(f"<nodes>{nodes}</nodes>")
    (folder / "n.edg.xml").write_text(f"<edges>{''.join(rows)}</edges>")
    args = ["-n", "n.nod.xml", "-e", "n.edg.xml", "-o", "n.net.xml", "--no-turnarounds", "--no-warnings"]
    subprocess.run([netconvert_path(), *args], cwd=folder, check=True, capture_output=True)
    return load_map(folder / "n.net.xml")


# V2 comes up from the south through the corner and goes on across j, into V1 turning out of the stem
CRASH = parse("""scenario corner {
  road {
    kind t_junction
  }
  vehicle V1 {
    heading south
    actions {
      follow_lane
      stop
      turn_left(to: 1)
    }
  }
  vehicle V2 {
    heading east
    lane 1
    actions {
      follow_lane
      go_across
    }
  }
  crash {
    type side
    striker V2
    victim V1
  }
}
""")


def _lowered(road_map: RoadMap) -> tuple[Scenario, list[str], Lowered]:
    staged, notes, matches = sites_for(CRASH, road_map, roads=1)
    match = matches[0]
    assert match.site.arm(match.placement("V2").arm).incoming[0].edges[:2] == ("sk", "kj")  # through the corner
    return staged, notes, lower_on(staged, match, road_map, notes)


def _unheld(staged: Scenario, notes: list[str], lowered: Lowered) -> Solution:
    """The solution the solver finds with no start bound on any route (as before corners.py)."""
    routes = {pid: replace(r, start_lo=0.0) for pid, r in lowered.routes.items()}
    limit, fact = _limit(staged, list(notes))
    found = next(iter(_schedules(staged, routes, [lowered.contact], limit, fact)))
    assert not isinstance(found, Exception)
    return found[1]


def _lane_lines(lowered: Lowered) -> Finding:
    return next(f for f in check(synth.synthesize(lowered)).findings if f.check == "lane_lines")


def test_a_car_routed_through_a_tight_corner_starts_past_it(tmp_path: Path) -> None:
    staged, notes, lowered = _lowered(t_junction(tmp_path, 60.0))
    route, solution = lowered.routes["V2"], lowered.solution
    assert solution.held == ("V2",) and solution.starts["V2"] >= route.start_lo > 0.0
    assert any(n.startswith("V2 starts at least") for n in lowered.notes)
    lanes = _lane_lines(lowered)
    assert lanes.passed, lanes.message
    # before: started in the corner's bend, its rear swung over the line into the lane beside
    before = _unheld(staged, notes, lowered)
    assert before.starts["V2"] < route.start_lo
    lanes = next(
        f for f in check(synth.synthesize(replace(lowered, solution=before))).findings if f.check == "lane_lines"
    )
    assert not lanes.passed and lanes.message.startswith("V2 enters lane sk_"), lanes.message


def test_a_plan_that_starts_past_the_corner_is_unchanged(tmp_path: Path) -> None:
    staged, notes, lowered = _lowered(t_junction(tmp_path, 100.0))
    route, solution = lowered.routes["V2"], lowered.solution
    assert route.start_lo > 0.0 and solution.held == ()  # the corner lies behind where it starts
    assert solution == _unheld(staged, notes, lowered)
