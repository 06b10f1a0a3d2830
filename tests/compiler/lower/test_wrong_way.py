"""A wrong-way swerve crosses a lane line into oncoming lanes that run beside it, never a median."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sumo
from sovarc.compiler.lower import lower_on
from sovarc.compiler.lower.assume import assume
from sovarc.compiler.lower.corridor import Corridor, Drive
from sovarc.compiler.maps import LaneInfo, find_sites, load_map, match_site, scenario_needs
from sovarc.dsl import parse
from sovarc.dsl.errors import LoweringError

CITY = Path(sumo.SUMO_HOME) / "tools" / "game" / "DRT" / "osm.net.xml"
WIDTH = 3.2
HEAD_ON = """scenario swerve_left_head_on {
  road {
    kind t_junction
    lanes 2
    speed_limit 56 km/h
  }
  vehicle V1 {
    heading east
    lane 1
    speed unknown
    actions {
      follow_lane
      retrograde
    }
  }
  vehicle V2 {
    heading west
    lane 1
    speed unknown
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
"""


def _lane(edge: str, shape: tuple[tuple[float, float], ...]) -> LaneInfo:
    length = float(np.hypot(*np.subtract(shape[-1], shape[0])))
    return LaneInfo(f"{edge}_0", edge, 0, 1, WIDTH, length, 13.9, shape)


def _eastbound_with_oncoming(start: float, median: float) -> Drive:
    """A 200 m eastbound lane; the oncoming lane beside it runs from x = 200 back to x = `start`,
    `median` metres of no lane between the two."""
    own = _lane("east", ((0.0, 0.0), (200.0, 0.0)))
    y = WIDTH + median
    oncoming = _lane("west", ((200.0, y), (start, y)))
    corridor = Corridor((own,), (oncoming,))
    return Drive(corridor, corridor.own_line(1), 1, speed=10.0, site="road:test")


def test_a_swerve_starts_where_the_oncoming_edge_begins_beside_it() -> None:
    drive = _eastbound_with_oncoming(start=150.0, median=0.0)
    end = drive.retrograde(1, 40.0)
    lo, hi = drive.stretches[1]
    assert lo == pytest.approx(150.0, abs=0.5) and hi == end <= 195.0
    points = drive.line.resample(1.0)
    before = points[points[:, 0] < 149.5]
    assert np.abs(before[:, 1]).max() < 1e-6  # in its own lane until the oncoming lane is beside it
    assert points[-1, 1] == pytest.approx(WIDTH)  # ends in the oncoming lane
    assert drive.lanes == {"east_0", "west_0"} and drive.against
    assert any("where lane west_0 begins" in note for note in drive.notes)


def test_a_swerve_over_a_lane_line_starts_where_asked() -> None:
    drive = _eastbound_with_oncoming(start=0.0, median=0.0)
    drive.retrograde(1, 40.0)
    assert drive.stretches[1][0] == 40.0 and not drive.notes


def test_a_swerve_across_a_median_is_refused_with_the_reason() -> None:
    drive = _eastbound_with_oncoming(start=0.0, median=3.0)
    with pytest.raises(LoweringError, match=r"on road:test, a median 3\.0 m wide divides the road"):
        drive.retrograde(1, 40.0)


def test_a_head_on_swerve_is_not_staged_across_a_city_median() -> None:
    """A city T-junction whose eastbound arm is a divided road (the westbound carriageway ~3 m
    off, split by a node 35 m before the junction): before, the swerve cut across the median and
    the oncoming edge before the split, lanes its route did not hold."""
    road_map = load_map(CITY)
    staged, notes = assume(parse(HEAD_ON, "head_on.sov"))
    site = next(s for s in find_sites(road_map) if s.id == "junction:cluster_1560223815_1560223847_301292612_56231397")
    match = match_site(site, scenario_needs(staged), clamp=True)
    assert match is not None
    with pytest.raises(LoweringError, match=r"a median [0-9.]+ m wide divides the road"):
        lower_on(staged, match, road_map, notes)


def test_a_swerve_asked_for_at_the_end_of_the_road_has_no_room() -> None:
    drive = _eastbound_with_oncoming(start=0.0, median=0.0)
    with pytest.raises(LoweringError, match="leave no room to move across"):
        drive.retrograde(1, 200.0)
