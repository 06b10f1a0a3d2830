"""A bend past the latest start, driven whatever the start, eased so the body keeps off the lane beside.

Mapped roads often jog just past a junction: the through road leaves it on a short diagonal and
turns back a few metres on. The smoothed line turns the jog's second bend within a body length,
and a body laid back along its heading from the front bumper swings its rear over the centre line
into the oncoming lane (the SUMO oracle's line crossing). No start avoids it (corners.py), and it
is not the stop line's bend (swing.py): lower/bends.py eases it. Found on SUMO's A10KW network
(issue 17).
"""

from __future__ import annotations

import subprocess
from pathlib import Path

import numpy as np
import pytest
from sovarc.compiler import synth
from sovarc.compiler.lower import Lowered, lower_on, routes, sites_for
from sovarc.compiler.maps import RoadMap, load_map
from sovarc.compiler.maps.netconvert import netconvert_path
from sovarc.dsl import parse
from sovarc.targets.sumo.check import check
from sovarc.targets.verdict import Finding

pytestmark = pytest.mark.slow  # netconvert builds the networks, SUMO replays the plans


def t_junction(folder: Path, jog: float) -> RoadMap:
    """A T junction at j: one lane each way, 3.2 m wide; the through road comes 250 m from the south
    and leaves j to the north on a diagonal `jog` metres west over `jog` metres north (45 degrees),
    then runs north; the stem leaves j to the east. `jog` 0: the road runs straight on."""
    spots = {"s": (0, -250), "j": (0, 0), "n": (-jog, 250), "e": (200, 0)}
    nodes = "".join(f'<node id="{n}" x="{x}" y="{y}" type="priority"/>' for n, (x, y) in spots.items())
    shape = f"0,0 {-jog},{jog} {-jog},250" if jog else ""
    rows = []
    for eid, a, b in [("sj", "s", "j"), ("jn", "j", "n"), ("je", "j", "e")]:
        there = f' shape="{shape}"' if eid == "jn" and shape else ""
        back = f' shape="{" ".join(reversed(shape.split()))}"' if eid == "jn" and shape else ""
        rows.append(f'<edge id="{eid}" from="{a}" to="{b}" numLanes="1" speed="13.9" width="3.2"{there}/>')
        rows.append(f'<edge id="-{eid}" from="{b}" to="{a}" numLanes="1" speed="13.9" width="3.2"{back}/>')
    (folder / "n.nod.xml").write_text(f"<nodes>{nodes}</nodes>")
    (folder / "n.edg.xml").write_text(f"<edges>{''.join(rows)}</edges>")
    args = ["-n", "n.nod.xml", "-e", "n.edg.xml", "-o", "n.net.xml", "--no-turnarounds", "--no-warnings"]
    subprocess.run([netconvert_path(), *args], cwd=folder, check=True, capture_output=True)
    return load_map(folder / "n.net.xml")


# V2 drives up from the south across j and on past the jog, into V1 coming down on its side of the road
CRASH = parse("""scenario jog {
  road {
    kind t_junction
    lanes 2
  }
  vehicle V1 {
    heading east
    lane 1
    actions {
      follow_lane
      retrograde
    }
  }
  vehicle V2 {
    heading west
    lane 1
    actions {
      follow_lane
    }
  }
  crash {
    type frontal
    striker V1
    victim V2
  }
}
""")


def _lowered(road_map: RoadMap) -> Lowered:
    staged, notes, matches = sites_for(CRASH, road_map, roads=1)
    lowered = lower_on(staged, matches[0], road_map, notes)
    assert lowered.routes["V2"].edges[:2] == ("sj", "jn")  # across j and through the jog
    return lowered


def _lane_lines(lowered: Lowered) -> Finding:
    return next(f for f in check(synth.synthesize(lowered)).findings if f.check == "lane_lines")


def test_a_jog_past_the_junction_is_eased(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    road_map = t_junction(tmp_path, 8.0)
    lanes = _lane_lines(_lowered(road_map))
    assert lanes.passed, lanes.message
    # before: the line as smoothed, its rear swung over the centre line past the jog's second bend
    monkeypatch.setattr(routes, "keep_off_lines", lambda line, from_s, *args, **kwargs: (line, from_s))
    lanes = _lane_lines(_lowered(road_map))
    assert not lanes.passed and lanes.message.startswith("V2 enters lane -jn_0"), lanes.message


def test_a_straight_road_is_left_as_it_is(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    road_map = t_junction(tmp_path, 0.0)
    eased = _lowered(road_map).routes["V2"].line
    monkeypatch.setattr(routes, "keep_off_lines", lambda line, from_s, *args, **kwargs: (line, from_s))
    assert np.array_equal(_lowered(road_map).routes["V2"].line.points, eased.points)
