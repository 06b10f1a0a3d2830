"""A left turner and an oncoming car on a narrow crossing: one lane each way of 2.7-3.0 m.

On such a road the turner's front corner is in the oncoming lane only some 30 degrees into its
turn, so its front closes on the oncoming car's side at a shallow angle and slowly (a turning
speed), while the oncoming car drives on at the limit. A contact with the corner a quarter of a
width into the side was first touched 0.2 s early, by the oncoming car's front corner; the last
pass meets the side where the corner just reaches it (lower/contact._grazing), first touched there.
"""

from __future__ import annotations

import subprocess
from collections.abc import Iterable, Iterator
from pathlib import Path

import pytest
from sovarc.compiler import synth
from sovarc.compiler.lower import Lowered, sites_for, stagings_on
from sovarc.compiler.lower.contact import contacts
from sovarc.compiler.maps import RoadMap, load_map
from sovarc.compiler.maps.netconvert import netconvert_path
from sovarc.compiler.plan import Plan
from sovarc.dsl import parse
from sovarc.dsl.errors import SynthesisError
from sovarc.dsl.ir import CrashType
from sovarc.targets.sumo.check import check

pytestmark = pytest.mark.slow  # netconvert builds the network, SUMO replays the plans

ARMS = {"n": (0, 200), "s": (0, -200), "e": (200, 0), "w": (-200, 0)}


def narrow_map(folder: Path, width: float, arms: str, junction: str) -> RoadMap:
    """A junction of the `arms` given, each a road of one lane each way `width` m wide."""
    nodes = [f'<node id="c" x="0" y="0" type="{junction}"/>']
    nodes += [f'<node id="{a}" x="{ARMS[a][0]}" y="{ARMS[a][1]}" type="priority"/>' for a in arms]
    edges = []
    for a in arms:
        edges.append(f'<edge id="in_{a}" from="{a}" to="c" numLanes="1" speed="22.2" width="{width}"/>')
        edges.append(f'<edge id="out_{a}" from="c" to="{a}" numLanes="1" speed="22.2" width="{width}"/>')
    (folder / "n.nod.xml").write_text(f"<nodes>{''.join(nodes)}</nodes>")
    (folder / "n.edg.xml").write_text(f"<edges>{''.join(edges)}</edges>")
    args = ["-n", "n.nod.xml", "-e", "n.edg.xml", "-o", "n.net.xml", "--no-turnarounds", "--no-warnings"]
    subprocess.run([netconvert_path(), *args], cwd=folder, check=True, capture_output=True)
    return load_map(folder / "n.net.xml")


def turn_across(kind: str, striker: str) -> str:
    """V1 drives south through the junction at a town road's limit, V2 comes north and turns left
    across its path; `striker` strikes the other's side."""
    victim = "V2" if striker == "V1" else "V1"
    return f"""scenario narrow {{
  road {{
    kind {kind}
    speed_limit 50 mph
  }}
  vehicle V1 {{
    heading south
    actions {{
      follow_lane
    }}
  }}
  vehicle V2 {{
    heading north
    actions {{
      turn_left
    }}
  }}
  crash {{
    type side
    striker {striker}
    victim {victim}
  }}
}}
"""


@pytest.mark.parametrize("width", [2.7, 3.0])
@pytest.mark.parametrize(
    ("kind", "arms", "junction"), [("intersection", "nsew", "traffic_light"), ("t_junction", "nse", "priority")]
)
def test_a_left_turner_strikes_the_side_of_an_oncoming_car_on_a_narrow_road(
    tmp_path: Path, width: float, kind: str, arms: str, junction: str
) -> None:
    road_map = narrow_map(tmp_path, width, arms, junction)
    scenario = parse(turn_across(kind, "V2"))
    staged, notes, matches = sites_for(scenario, road_map, roads=1)
    refused = 0
    for lowered in stagings_on(staged, matches[0], road_map, notes):
        try:
            plan = synth.synthesize(lowered)
        except SynthesisError as error:
            # the usual contacts: the oncoming car's front corner touches first, and the reason says so
            assert "would first touch V1's front" in error.diagnostics[0].message
            refused += 1
            continue
        break
    else:
        pytest.fail("no staging synthesizes")
    assert refused > 0  # the usual contacts are refused on a road this narrow ...
    striker, victim = lowered.routes["V2"], lowered.routes["V1"]
    assert lowered.contact in contacts(striker, victim, CrashType.SIDE, grazing=True)  # ... the last pass's is not
    verdict = check(plan)
    assert verdict.passed, verdict.dumps()


@pytest.mark.parametrize("width", [2.7, 3.0])
def test_an_oncoming_car_strikes_a_left_turners_side_on_a_narrow_crossing(tmp_path: Path, width: float) -> None:
    road_map = narrow_map(tmp_path, width, "nsew", "traffic_light")
    scenario = parse(turn_across("intersection", "V1"))
    staged, notes, matches = sites_for(scenario, road_map, roads=1)
    plan = next(_synthesized(stagings_on(staged, matches[0], road_map, notes)))
    verdict = check(plan)
    assert verdict.passed, verdict.dumps()


def _synthesized(stagings: Iterable[Lowered]) -> Iterator[Plan]:
    """The plans of the stagings that synthesize, in order."""
    for lowered in stagings:
        try:
            yield synth.synthesize(lowered)
        except SynthesisError:
            continue
