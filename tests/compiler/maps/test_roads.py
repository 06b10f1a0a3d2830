"""Roads as netconvert builds them: small networks written here as plain XML, then converted.

Each network is built for one rule: a road split into several edges is one road; a lane drop
ends a straight stretch and a junction's arm; the two directions of a road are paired even
where they are split at different nodes; a divided road's halves are one-way sites.
"""

from __future__ import annotations

import subprocess
from collections import Counter
from pathlib import Path

import pytest
from sovarc.compiler.maps import RoadMap, find_sites, load_map
from sovarc.compiler.maps.netconvert import netconvert_path
from sovarc.compiler.maps.survey import describe, draw, missing, survey
from sovarc.dsl.ir import RoadKind

from tests.conftest import SHARED, requires_shared

pytestmark = pytest.mark.slow  # needs SUMO

X, T, S = RoadKind.INTERSECTION, RoadKind.T_JUNCTION, RoadKind.STRAIGHT
HERE = Path(__file__).parent
CARLA = SHARED / "data" / "opendrive" / "carla"


def build(
    tmp_path: Path, nodes: dict[str, tuple[float, float]], edges: list[str], forbid: tuple[str, ...] = ()
) -> RoadMap:
    """A network from nodes (id: x, y) and edges ('id from to lanes', plus ' oneway' for no
    edge back): a two-way edge gets a reverse edge '-id'. `forbid` names connections
    ('from_edge to_edge') netconvert must not make."""
    nod = "".join(f'<node id="{n}" x="{x}" y="{y}" type="priority"/>' for n, (x, y) in nodes.items())
    rows = []
    for spec in edges:
        eid, a, b, lanes, *flags = spec.split()
        rows.append(f'<edge id="{eid}" from="{a}" to="{b}" numLanes="{lanes}" speed="13.9"/>')
        if "oneway" not in flags:
            rows.append(f'<edge id="-{eid}" from="{b}" to="{a}" numLanes="{lanes}" speed="13.9"/>')
    (tmp_path / "n.nod.xml").write_text(f"<nodes>{nod}</nodes>")
    (tmp_path / "n.edg.xml").write_text(f"<edges>{''.join(rows)}</edges>")
    out = tmp_path / "n.net.xml"
    args = ["-n", "n.nod.xml", "-e", "n.edg.xml", "-o", out.name, "--no-turnarounds", "--no-warnings"]
    if forbid:
        cons = "".join(f'<delete from="{a}" to="{b}"/>' for a, b in (pair.split() for pair in forbid))
        (tmp_path / "n.con.xml").write_text(f"<connections>{cons}</connections>")
        args += ["-x", "n.con.xml"]
    subprocess.run([netconvert_path(), *args], cwd=tmp_path, check=True, capture_output=True)
    return load_map(out)


def kinds(road_map: RoadMap) -> dict[RoadKind, int]:
    return dict(Counter(s.kind for s in find_sites(road_map)))


def test_a_road_split_into_short_edges_is_one_straight_site(tmp_path: Path) -> None:
    # 200 m of road in three edges, none of them 80 m long: lane sections, as OpenDRIVE has them
    nodes = {"a": (0, 0), "b": (60, 0), "c": (120, 0), "d": (200, 0)}
    road_map = build(tmp_path, nodes, ["e1 a b 1", "e2 b c 1", "e3 c d 1"])
    (site,) = find_sites(road_map)
    assert site.kind is S and site.min_length == pytest.approx(200.0, abs=3.0)
    east = next(a for a in site.arms if round(a.heading) == 90)
    (lane,) = east.incoming
    assert lane.edges == ("e1", "e2", "e3")  # the route, in the order driven
    assert [x for x in lane.lanes if not x.startswith(":")] == ["e1_0", "e2_0", "e3_0"]
    assert lane.shape[0][0] == pytest.approx(0.0, abs=1.0) and lane.shape[-1][0] == pytest.approx(200.0, abs=1.0)
    (back,) = east.outgoing
    assert back.edges == ("-e3", "-e2", "-e1")


def test_a_lane_drop_ends_a_straight_stretch_and_a_junction_arm(tmp_path: Path) -> None:
    # two lanes each way for 100 m, then one lane for 100 m up to a T with a side road
    nodes = {"a": (0, 0), "b": (100, 0), "c": (200, 0), "d": (300, 0), "s": (200, -100)}
    road_map = build(tmp_path, nodes, ["wide a b 2", "narrow b c 1", "on c d 1", "side c s 1"])
    # the two-lane road; the one-lane road, on through the T where it has the right of way; the side road
    assert kinds(road_map) == {T: 1, S: 3}
    lanes = {s.id: s.lanes for s in find_sites(road_map, S)}
    assert sorted(lanes.values()) == [1, 1, 2]
    (through,) = [
        s for s in find_sites(road_map, S) if "narrow" in s.arms[0].incoming[0].edges + s.arms[1].incoming[0].edges
    ]
    east = next(a for a in through.arms if round(a.heading) == 90)
    assert east.incoming[0].edges == ("narrow", "on") and east.incoming[0].lanes[1].startswith(":c_")
    (tee,) = find_sites(road_map, T)
    west = next(a for a in tee.arms if a.id == "narrow")
    assert [lane.edges for lane in west.incoming] == [("narrow",)]  # not back into the two-lane road


def test_the_directions_of_a_road_split_at_different_nodes_are_paired(tmp_path: Path) -> None:
    # eastbound split at x=60, westbound at x=140 (as OSM ways often are): still one two-way road
    nodes = {"a": (0, 0), "b": (60, 0), "c": (200, 0), "d": (140, 0)}
    edges = ["e1 a b 1 oneway", "e2 b c 1 oneway", "w1 c d 1 oneway", "w2 d a 1 oneway"]
    road_map = build(tmp_path, nodes, edges)
    (site,) = find_sites(road_map)
    assert site.kind is S and len(site.arms) == 2 and all(a.two_way for a in site.arms)
    east = next(a for a in site.arms if round(a.heading) == 90)
    assert east.incoming[0].edges == ("e1", "e2") and east.outgoing[0].edges == ("w1", "w2")


def test_a_road_ending_in_a_turning_loop_is_still_two_way(tmp_path: Path) -> None:
    # 200 m of two-way road whose end is a one-way loop back into it (a turning circle, as CARLA's
    # Town06 avenue ends): the road does not run on round the loop into its own other direction
    nodes = {"a": (0, 0), "b": (200, 0), "p": (240, 8), "r1": (270, 20), "r2": (290, 0), "r3": (270, -20)}
    nodes["q"] = (240, -8)
    loop = ["l1 b p 1", "l2 p r1 1", "l3 r1 r2 1", "l4 r2 r3 1", "l5 r3 q 1", "l6 q b 1"]
    road_map = build(tmp_path, nodes, ["e a b 1", *(f"{leg} oneway" for leg in loop)])
    (site,) = find_sites(road_map, S)
    assert len(site.arms) == 2 and all(a.two_way for a in site.arms)
    assert site.min_length == pytest.approx(200.0, abs=5.0)


def test_a_divided_road_gives_one_way_sites(tmp_path: Path) -> None:
    # two one-way carriageways of two lanes, 20 m apart: no lane line between them
    nodes = {"a": (0, 0), "b": (200, 0), "c": (200, 20), "d": (0, 20)}
    road_map = build(tmp_path, nodes, ["east a b 2 oneway", "west c d 2 oneway"])
    sites = find_sites(road_map)
    assert [(len(s.arms), s.arms[0].two_way) for s in sites] == [(1, False), (1, False)]
    # a pass over the centre line finds no lane line to cross here, and the miss says whose need fails
    from sovarc.compiler.maps import match_sites
    from sovarc.dsl.errors import LoweringError

    from tests.compiler.maps.conftest import scenario

    with pytest.raises(LoweringError) as caught:
        match_sites(scenario("straight_double_yellow_pass_frontal"), road_map)
    message = caught.value.diagnostics[0].message
    assert "; none of its 2 straight roads is two-way throughout" in message  # the miss says why
    assert "; of its 2 straight roads, each participant alone fits: V1 0, V2 2" in message


def test_junctions_are_recognised_by_their_arms_headings(tmp_path: Path) -> None:
    # a cross, a T, and a fork whose three arms make no T
    nodes = {"x": (0, 0), "n": (0, 100), "s": (0, -100), "e": (100, 0), "w": (-100, 0)}
    nodes |= {"t": (400, 0), "t1": (300, 0), "t2": (500, 0), "t3": (400, -100)}
    nodes |= {"f": (800, 0), "f1": (700, 0), "f2": (900, 30), "f3": (900, -30)}
    edges = ["xn x n 1", "xs x s 1", "xe x e 1", "xw x w 1", "t1 t1 t 1", "t2 t t2 1", "t3 t t3 1"]
    edges += ["f1 f1 f 1", "f2 f f2 1", "f3 f f3 1"]
    road_map = build(tmp_path, nodes, edges)
    found = {s.junction: s.kind for s in find_sites(road_map) if s.junction}
    assert found == {"x": X, "t": T}


def test_the_survey_lists_draws_and_says_what_is_missing(tmp_path: Path) -> None:
    nodes = {"a": (0, 0), "b": (100, 0), "c": (200, 0), "d": (300, 0), "s": (200, -100)}
    road_map = build(tmp_path, nodes, ["wide a b 2", "narrow b c 1", "on c d 1", "side c s 1"])
    report = survey(road_map)
    text = report.text()
    assert text.splitlines()[0] == "n.net.xml: 0 intersections, 1 T-junctions, 3 straight roads"
    assert "T-junctions (1):" in text and "straight roads (3):" in text
    tee = find_sites(road_map, T)[0]
    assert describe(tee).startswith("junction:c at (200, 100) priority")  # netconvert moves the map
    assert "1 in (3.2 m) + 1 out (3.2 m)" in describe(tee)
    assert [s.kind for s in survey(road_map, "straight").sites] == [S, S, S]
    assert missing(road_map, X) == (
        "n.net.xml has no intersection (a 4-way junction): it has 0 intersections, 1 T-junctions, 3 straight roads"
    )
    assert missing(road_map, T) is None
    png = draw(road_map, report.sites, tmp_path / "map.png")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@requires_shared
@pytest.mark.parametrize("town", ["Town01", "Town02"])
def test_carla_town_site_lists(town: str, golden: object) -> None:
    road_map = load_map(CARLA / f"{town}.xodr")
    golden.check(HERE / "golden" / f"{town}.sites", survey(road_map).text())  # type: ignore[attr-defined]


@requires_shared
def test_carla_town04_straight_roads(golden: object) -> None:
    # its motorway's two directions are parted by 7 m of shoulders and nothing on them: ten two-way
    # sites with an open median (maps/medians.py); the one-way ramps stay one-way sites
    road_map = load_map(CARLA / "Town04.xodr")
    text = survey(road_map, S).text().split("\n", 1)[1]  # the straight roads only (not the junction counts)
    golden.check(HERE / "golden" / "Town04.straight.sites", text)  # type: ignore[attr-defined]
    assert text.count("open median 7.0 m") == 10


def test_a_scenario_is_staged_across_a_road_of_several_edges(tmp_path: Path) -> None:
    from sovarc.compiler.lower import lower
    from sovarc.compiler.synth import synthesize

    from tests.compiler.maps.conftest import scenario

    # 300 m of two-lane road (each way) in five 60 m edges: only the chained road is a site
    nodes = {f"n{k}": (60.0 * k, 0.0) for k in range(6)}
    road_map = build(tmp_path, nodes, [f"e{k} n{k} n{k + 1} 2" for k in range(5)])
    (lowered,) = lower(scenario("straight_rear_end_stopped_traffic"), road_map, seed=0)
    plan = synthesize(lowered, seed=0)
    forward = [f"e{k}" for k in range(5)]
    backward = [f"-e{k}" for k in reversed(range(5))]
    for t in plan.trajectories:
        assert t.edges in (tuple(forward), tuple(backward))  # a route along the chain, in order
        internal = {lane for lane in t.lanes if lane.startswith(":")}
        assert len(internal) >= 4  # the lanes between its edges are its own to drive on
