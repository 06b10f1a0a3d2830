"""A wrong-way swerve crosses a lane line into oncoming lanes that run beside it, never a median;
at a junction the wrong-way car leaves by the arm its move leads to, never its own."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sumo
from sovarc.compiler.lower import lower_on
from sovarc.compiler.lower.assume import assume
from sovarc.compiler.lower.corridor import Corridor, Drive
from sovarc.compiler.lower.routes import _junction_line
from sovarc.compiler.maps import (
    Arm,
    Connection,
    LaneInfo,
    RoadMap,
    Site,
    SiteMatch,
    find_sites,
    load_map,
    match_site,
    scenario_needs,
)
from sovarc.dsl import parse
from sovarc.dsl.errors import LoweringError
from sovarc.dsl.ir import ActionKind, RoadKind

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


def test_a_swerve_crosses_an_open_median_its_site_records() -> None:
    # open ground the map describes (maps/medians.py): the site's `median`, crossed as a lane line is
    drive = _eastbound_with_oncoming(start=0.0, median=3.0)
    drive.median = 3.0
    drive.retrograde(1, 40.0)
    assert drive.against and drive.line.resample(1.0)[-1, 1] == pytest.approx(WIDTH + 3.0)
    # twice a lane's width sideways: a lane change's length (30 m at 10 m/s) times the root of the
    # widths crossed, for the same sideways acceleration
    lo, hi = drive.stretches[1]
    assert hi - lo == pytest.approx(30.0 * ((WIDTH + 3.0) / WIDTH) ** 0.5, abs=0.5)
    wider = _eastbound_with_oncoming(start=0.0, median=5.0)
    wider.median = 3.0  # a gap wider than the site's open median is still refused
    with pytest.raises(LoweringError, match=r"a median 5\.0 m wide divides the road"):
        wider.retrograde(1, 40.0)


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


def _askew_t(*links: tuple[str, str, str]) -> SiteMatch:
    """A T with arms from the north (slot 2), the south (slot 0) and the east (slot 3), none from
    the west, lanes ending 8 m from the centre. `links`: (from arm, to arm, SUMO direction)."""

    def arm(name: str, slot: int, inward: tuple[float, float], right: tuple[float, float]) -> Arm:
        far, near = np.multiply(inward, -100.0), np.multiply(inward, -8.0)
        shift = np.multiply(right, WIDTH / 2.0)
        incoming = _lane(name, (tuple(far + shift), tuple(near + shift)))
        outgoing = _lane(f"-{name}", (tuple(near - shift), tuple(far - shift)))
        return Arm(name, 0.0, slot, (incoming,), (outgoing,), 92.0)

    arms = (arm("s", 0, (0.0, 1.0), (1.0, 0.0)), arm("n", 2, (0.0, -1.0), (-1.0, 0.0)))
    arms += (arm("e", 3, (-1.0, 0.0), (0.0, 1.0)),)
    connections = tuple(Connection(f"{a}_0", f"-{b}_0", d, None) for a, b, d in links)
    site = Site("junction:askew", RoadKind.T_JUNCTION, (0.0, 0.0), 0.0, arms, connections)
    return SiteMatch(site, 0, (), ())


def _wrong_way_on_north_arm(match: SiteMatch) -> tuple[Drive, Arm]:
    """Southbound in the north arm's northbound lane, up to the junction."""
    arm = match.site.arms[1]
    corridor = Corridor.entering(arm)
    return Drive(corridor, corridor.other_line(1), 1, against=True, site=match.site.id), arm


def test_a_wrong_way_move_leaves_by_the_arm_its_connection_leads_to() -> None:
    """SUMO calls the move from the north arm to the south one a right turn where the road bends
    there; the compass cross has no arm in the right turn's slot (the west). Before, the line
    was laid into the car's own arm, from the point it stood on to itself, and failed."""
    match = _askew_t(("n", "s", "r"), ("n", "e", "l"))
    drive, arm = _wrong_way_on_north_arm(match)
    road_map: RoadMap = None  # type: ignore[assignment]  # a wrong-way move reads no internal lanes
    line, corridor, number = _junction_line(drive, arm, ActionKind.TURN_RIGHT, None, match, road_map, -1)
    assert corridor.own[0].id == "-s_0" and number == 1
    assert line.point(0.0) == pytest.approx((WIDTH / 2.0, 8.0))
    assert line.point(line.length) == pytest.approx((-WIDTH / 2.0, -8.0))  # into the southbound lane


def test_a_wrong_way_move_with_no_arm_to_leave_by_is_refused_with_the_reason() -> None:
    match = _askew_t(("n", "s", "s"), ("n", "e", "l"))
    drive, arm = _wrong_way_on_north_arm(match)
    road_map: RoadMap = None  # type: ignore[assignment]
    with pytest.raises(LoweringError, match="no arm to turn_right into from arm n for a car driving the wrong way"):
        _junction_line(drive, arm, ActionKind.TURN_RIGHT, None, match, road_map, -1)
