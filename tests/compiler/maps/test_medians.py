"""Divided roads as an OpenDRIVE map describes them: what lies between the two directions decides
whether they are one two-way road or two one-way ones (maps/medians.py).

Each map is one straight 300 m OpenDRIVE road, two car lanes each way, written here and converted
by netconvert: the ground between the directions is what each test varies.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.compiler.maps import RoadMap, find_sites, load_map
from sovarc.compiler.maps.medians import open_medians, road_of
from sovarc.compiler.maps.survey import describe
from sovarc.dsl.ir import RoadKind

pytestmark = pytest.mark.slow  # needs SUMO

LENGTH = 300.0


def _lane(lane_id: int, kind: str, width: float, extra: str = "") -> str:
    return (
        f'<lane id="{lane_id}" type="{kind}" level="false"><link/>'
        f'<width sOffset="0" a="{width}" b="0" c="0" d="0"/>{extra}</lane>'
    )


def xodr(median: list[tuple[str, float]], objects: str = "", extra: str = "", centre_mark: str = "solid") -> str:
    """The road: `median` lanes (kind, width) on each side of the centre line, then two driving
    lanes; `extra` goes into each median lane (a height, a road mark); `objects` on the road."""
    left = [_lane(k + 1, kind, width, extra) for k, (kind, width) in enumerate(median)]
    right = [_lane(-(k + 1), kind, width, extra) for k, (kind, width) in enumerate(median)]
    n = len(median)
    left += [_lane(n + 1, "driving", 3.5), _lane(n + 2, "driving", 3.5)]
    right += [_lane(-(n + 1), "driving", 3.5), _lane(-(n + 2), "driving", 3.5)]
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE><header revMajor="1" revMinor="4" name="median" version="1"/>
<road name="r" length="{LENGTH}" id="7" junction="-1"><link/>
<planView><geometry s="0" x="0" y="0" hdg="0" length="{LENGTH}"><line/></geometry></planView>
<elevationProfile/><lateralProfile/>
<lanes><laneSection s="0">
<left>{"".join(reversed(left))}</left>
<center><lane id="0" type="none" level="false"><roadMark sOffset="0" type="{centre_mark}" width="0.15"/></lane></center>
<right>{"".join(right)}</right>
</laneSection></lanes>
<objects>{objects}</objects>
</road></OpenDRIVE>
"""


def build(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, text: str) -> RoadMap:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    path = tmp_path / "road.xodr"
    path.write_text(text)
    return load_map(path)


def arms_per_site(road_map: RoadMap) -> list[int]:
    sites = find_sites(road_map)
    assert {s.kind for s in sites} == {RoadKind.STRAIGHT}
    return sorted(len(s.arms) for s in sites)


SHOULDERS = [("shoulder", 3.0)]  # 6 m of shoulders between the directions


def test_an_open_median_of_shoulders_is_one_two_way_road(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    road_map = build(tmp_path, monkeypatch, xodr(SHOULDERS))
    (site,) = find_sites(road_map)
    assert len(site.arms) == 2 and all(arm.two_way for arm in site.arms)
    assert [len(arm.incoming) for arm in site.arms] == [2, 2]
    assert site.median == pytest.approx(6.0, abs=0.3)  # netconvert's gap between the inner lanes
    assert "open median 6.0 m" in describe(site)


def test_a_painted_island_of_border_and_median_lanes_is_open(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    road_map = build(tmp_path, monkeypatch, xodr([("border", 0.5), ("median", 1.5)]))
    assert arms_per_site(road_map) == [2]


# What stops a car between the directions: each makes the halves two one-way roads (a site each).
def barrier(kind: str = "barrier", name: str = "guardrail", t: float = 0.0) -> str:
    """An object repeated along the whole road at `t` (metres left of the centre line)."""
    return (
        f'<object type="{kind}" name="{name}" id="1" s="0" t="{t}" zOffset="0" orientation="none" height="0.8">'
        f'<repeat s="0" length="{LENGTH}" distance="0" tStart="{t}" tEnd="{t}" heightStart="0.8" heightEnd="0.8"'
        ' zOffsetStart="0" zOffsetEnd="0"/></object>'
    )


BARRIER = barrier()


@pytest.mark.parametrize(
    ("median", "objects", "extra"),
    [
        (SHOULDERS, BARRIER, ""),  # a guardrail along the middle
        (SHOULDERS, barrier("pole", "jersey", t=1.0), ""),
        (SHOULDERS, "", '<height sOffset="0" inner="0.15" outer="0.15"/>'),  # a kerbed, raised island
        (SHOULDERS, "", '<roadMark sOffset="0" type="curb" width="0.2"/>'),  # kerbs at its edges
        ([("shoulder", 1.0), ("sidewalk", 2.0), ("shoulder", 1.0)], "", ""),  # a path on it
        ([("shoulder", 6.0)], "", ""),  # 12 m of ground: too wide to be one road's
    ],
    ids=["guardrail", "standing-object", "raised", "kerbed", "path", "too-wide"],
)
def test_what_stops_a_car_divides_the_road(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, median: list[tuple[str, float]], objects: str, extra: str
) -> None:
    road_map = build(tmp_path, monkeypatch, xodr(median, objects, extra))
    assert arms_per_site(road_map) == [1, 1]
    assert all(site.median == 0.0 for site in find_sites(road_map))


def test_a_painted_object_in_the_median_does_not_divide_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    arrow = '<object type="roadMark" name="Stencil_Arrow" id="2" s="50" t="0" zOffset="0" orientation="none"/>'
    road_map = build(tmp_path, monkeypatch, xodr(SHOULDERS, arrow))
    assert arms_per_site(road_map) == [2]


def test_a_barrier_elsewhere_on_the_road_does_not_divide_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    road_map = build(tmp_path, monkeypatch, xodr(SHOULDERS, barrier(t=-12.0)))
    assert arms_per_site(road_map) == [2]


def test_open_medians_names_the_edges_of_open_roads(tmp_path: Path) -> None:
    (tmp_path / "a.xodr").write_text(xodr(SHOULDERS))
    edges = ["7", "-7", "-7.150.00", "70", "-8", ":j_0"]
    assert open_medians(tmp_path / "a.xodr", edges) == {"7", "-7", "-7.150.00"}
    (tmp_path / "b.xodr").write_text(xodr(SHOULDERS, BARRIER))
    assert open_medians(tmp_path / "b.xodr", edges) == frozenset()
    assert road_of("-12.30.5") == "12" and road_of("12") == "12"


def test_a_sumo_network_has_no_open_medians(town: RoadMap) -> None:
    # a SUMO network does not say what lies between two carriageways: none is taken to be open
    assert all(site.median == 0.0 for site in find_sites(town))


def test_a_garbled_number_leaves_a_road_closed(tmp_path: Path) -> None:
    # a map's defect is no exception: nothing is known of that road's median, so it stays divided
    (tmp_path / "c.xodr").write_text(xodr(SHOULDERS).replace('a="3.0"', 'a="wide"'))
    assert open_medians(tmp_path / "c.xodr", ["7", "-7"]) == frozenset()
