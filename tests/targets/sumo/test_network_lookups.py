"""The lane look-ups the SUMO target makes for every sample give the numbers of the plain walk.

`Network.spot` walks a lane's segments with precomputed directions (numpy on long lanes), and
`locate` and `reaches` skip lanes whose box is too far; the reference below is the walk as first
written, segment by segment. Every number must be the same to the last bit: the FCD positions
and the oracle's verdicts are made of them.
"""

from __future__ import annotations

import itertools
import math
import random
from pathlib import Path

import pytest
import sumo
from sovarc.compiler.geometry.angles import angle_diff, compass
from sovarc.compiler.geometry.lanes import CELL, HEADING_MATCH, LONG_LANE, Lane
from sovarc.targets.sumo.network import Network, read_network

from tests.targets.sumo.plans import TOWN

CITY = Path(sumo.SUMO_HOME) / "tools" / "game" / "DRT" / "osm.net.xml"


def _reference_spot(lane: Lane, x: float, y: float) -> tuple[float, float, float, float]:
    """(pos, offset, heading, distance), as the walk was first written."""
    best = (math.inf, 0.0, 0.0, 0.0, 0.0)
    s = 0.0
    for p, q in itertools.pairwise(lane.shape):
        seg = math.dist(p, q)
        if seg == 0.0:
            continue
        ux, uy = (q[0] - p[0]) / seg, (q[1] - p[1]) / seg
        along = (x - p[0]) * ux + (y - p[1]) * uy
        u = min(max(along, 0.0), seg)
        cx, cy = p[0] + u * ux, p[1] + u * uy
        distance = math.hypot(x - cx, y - cy)
        if distance < best[0] - 1e-9:
            side = ux * (y - p[1]) - uy * (x - p[0])
            best = (distance, s + u, math.copysign(distance, side) if distance else 0.0, ux, uy)
        s += seg
    distance, pos, offset, ux, uy = best
    return min(pos, lane.length), offset, compass(ux, uy), distance


def _reference_locate(network: Network, x: float, y: float, heading: float, prefer: frozenset[str]) -> str:
    for radius in (0.0, CELL, 5 * CELL):
        ranked = []
        for lane in network.near(x, y, radius):
            if lane.pedestrian_only:
                continue
            _pos, _offset, lane_heading, distance = _reference_spot(lane, x, y)
            inside = distance <= lane.width / 2.0 + 1e-6
            along = abs(angle_diff(lane_heading, heading)) <= HEADING_MATCH
            ranked.append((0 if inside else 1, 0 if lane.id in prefer else 1, 0 if along else 1, distance, lane.id))
        if ranked and (radius > 0.0 or min(ranked)[0] == 0):
            return min(ranked)[-1]
    raise ValueError("off the network")


def _bits(values: tuple[float, ...]) -> tuple[str, ...]:
    return tuple(v.hex() for v in values)  # -0.0 and 0.0 differ here


def _points(network: Network, count: int, seed: int) -> list[tuple[Lane, float, float]]:
    """Points near lanes, long ones first, some on their vertices exactly (where a zero's sign shows)."""
    rng = random.Random(seed)
    lanes = sorted(network.lanes.values(), key=lambda lane: (-len(lane.shape), lane.id))
    chosen = lanes[:10] * 4 + rng.sample(lanes, 40)  # the long lanes, walked by numpy, half the time
    out = []
    for _ in range(count):
        lane = rng.choice(chosen)
        px, py = rng.choice(lane.shape)
        if rng.random() < 0.2:
            out.append((lane, px, py))
        else:
            out.append((lane, px + rng.uniform(-6.0, 6.0), py + rng.uniform(-6.0, 6.0)))
    return out


@pytest.mark.parametrize("path", [TOWN, CITY], ids=["town", "city"])
def test_spot_reaches_and_locate_match_the_plain_walk(path: Path) -> None:
    network = read_network(path)
    assert any(len(lane.shape) - 1 > LONG_LANE for lane in network.lanes.values()) or path == TOWN
    for lane, x, y in _points(network, 4000, seed=7):
        spot, distance = network.spot(lane, x, y)
        assert _bits((spot.pos, spot.offset, spot.heading, distance)) == _bits(_reference_spot(lane, x, y))
        for other in network.near(x, y, 5.0):
            reach = other.width / 2.0
            assert network.reaches(other, x, y, reach) == (_reference_spot(other, x, y)[3] <= reach)
        heading = random.Random(x).uniform(0.0, 360.0)
        prefer = frozenset({lane.id})
        assert network.locate(x, y, heading, prefer).lane.id == _reference_locate(network, x, y, heading, prefer)


def test_a_network_is_read_once_per_content(tmp_path: Path) -> None:
    copy = tmp_path / "town.net.xml"
    copy.write_bytes(TOWN.read_bytes())
    assert read_network(copy) is read_network(TOWN)
    copy.write_bytes(TOWN.read_bytes().replace(b"</net>", b"<!-- changed --></net>"))
    assert read_network(copy) is not read_network(TOWN)
