"""A turn pocket: a lane that opens beside the approach lane a short way before a crossing.

The arm reaches back through the node where the pocket opens (maps/roads.RoadNet.reach): both
lanes are reached from the one lane behind it, so cars planned in them start in that lane one
behind the other, their bodies apart at t = 0 (lower/solve._apart_at_start). A report naming the
lane a car turned from is staged from that lane, across its neighbour, when the map's arrows send
the move from the other lane (lower/routes._from_own_lane), after every staging that keeps them.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from sovarc.compiler.lower import sites_for
from sovarc.compiler.maps import RoadMap, find_sites, load_map
from sovarc.compiler.maps.netconvert import netconvert_path
from sovarc.compiler.staging import stage_on_site
from sovarc.dsl import parse
from sovarc.dsl.ir import RoadKind
from sovarc.targets.sumo.check import check

pytestmark = pytest.mark.slow  # netconvert builds the network, SUMO replays the plans

NODES = {"w0": (-150, 0), "w1": (-25, 0), "c": (0, 0), "e": (150, 0), "n": (0, 150), "s": (0, -150)}
# (id, from, to, lanes); each with a reverse edge of one lane
EDGES = [("far", "w0", "w1", 1), ("pocket", "w1", "c", 2), ("east", "c", "e", 1)]
EDGES += [("north", "c", "n", 1), ("south", "c", "s", 1)]
# the pocket's right lane turns right only; its left lane goes straight on or turns left
LINKS = [("pocket", "south", 0), ("pocket", "east", 1), ("pocket", "north", 1)]


def pocket_map(tmp_path: Path) -> RoadMap:
    nodes = "".join(f'<node id="{n}" x="{x}" y="{y}" type="traffic_light"/>' for n, (x, y) in NODES.items())
    rows = []
    for eid, a, b, lanes in EDGES:
        rows.append(f'<edge id="{eid}" from="{a}" to="{b}" numLanes="{lanes}" speed="13.9"/>')
        rows.append(f'<edge id="-{eid}" from="{b}" to="{a}" numLanes="1" speed="13.9"/>')
    links = "".join(f'<connection from="{a}" to="{b}" fromLane="{k}" toLane="0"/>' for a, b, k in LINKS)
    (tmp_path / "n.nod.xml").write_text(f"<nodes>{nodes}</nodes>")
    (tmp_path / "n.edg.xml").write_text(f"<edges>{''.join(rows)}</edges>")
    (tmp_path / "n.con.xml").write_text(f"<connections>{links}</connections>")
    args = ["-n", "n.nod.xml", "-e", "n.edg.xml", "-x", "n.con.xml", "-o", "n.net.xml", "--no-turnarounds"]
    subprocess.run([netconvert_path(), *args, "--no-warnings"], cwd=tmp_path, check=True, capture_output=True)
    return load_map(tmp_path / "n.net.xml")


def side_crash(name: str, v1: tuple[int, str], v2: tuple[int, str], striker: str) -> str:
    """Two cars heading east in the lanes given, each with its move at the crossing ('' for none)."""

    def vehicle(pid: str, lane: int, move: str) -> str:
        actions = "follow_lane" + (f"\n      {move}" if move else "")
        return f"vehicle {pid} {{\n    heading east\n    lane {lane}\n    actions {{\n      {actions}\n    }}\n  }}"

    victim = "V2" if striker == "V1" else "V1"
    return (
        f"scenario {name} {{\n  road {{\n    kind intersection\n  }}\n  {vehicle('V1', *v1)}\n  {vehicle('V2', *v2)}\n"
        f"  crash {{\n    type side\n    striker {striker}\n    victim {victim}\n  }}\n}}\n"
    )


@pytest.fixture(scope="module")
def road_map(tmp_path_factory: pytest.TempPathFactory) -> RoadMap:
    return pocket_map(tmp_path_factory.mktemp("pocket"))


def test_a_pockets_lanes_are_reached_from_the_lane_it_opens_off(road_map: RoadMap) -> None:
    (site,) = find_sites(road_map, RoadKind.INTERSECTION)
    arm = next(a for a in site.arms if a.id == "pocket")
    assert [lane.edges for lane in arm.incoming] == [("far", "pocket"), ("far", "pocket")]
    assert arm.incoming[0].shape[0] == arm.incoming[1].shape[0]  # one lane up to the pocket
    assert arm.length > 120.0  # the 125 m of road behind the pocket too, not its 25 m alone
    back = next(a for a in site.arms if a.id == "-east")
    assert [lane.edges for lane in back.incoming] == [("-east",)]


@pytest.mark.parametrize(
    ("v1", "v2", "striker", "kept"),
    [
        ((2, "turn_right"), (1, ""), "V1", {"V1", "V2"}),  # a right turn from the left lane across the right one
        ((1, "turn_right"), (2, "turn_right"), "V1", {"V2"}),  # both turn right, V2 from the left lane across V1
        ((1, ""), (2, "turn_right"), "V2", {"V1", "V2"}),
    ],
)
def test_cars_in_a_pocket_start_apart_and_turn_from_the_lanes_reported(
    road_map: RoadMap, v1: tuple[int, str], v2: tuple[int, str], striker: str, kept: set[str]
) -> None:
    scenario = parse(side_crash("pocket", v1, v2, striker))
    staged, notes, matches = sites_for(scenario, road_map, roads=1)
    plan = stage_on_site(staged, notes, road_map, matches[0])
    said = {pid for pid in ("V1", "V2") if any(n.startswith(f"{pid} makes its") for n in plan.notes)}
    assert said == kept
    verdict = check(plan)
    assert verdict.passed, verdict.dumps()
