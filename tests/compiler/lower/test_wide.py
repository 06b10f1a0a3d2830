"""A bus or truck takes a corner drawn for a car wide (compiler/lower/wide.py): its plan swings out,
turns no tighter than its front at full lock, and its body, facing the way its rear axle trails,
stays on the road, as SUMO's road check sees it."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from sovarc.compiler.crashes import LINE_TOLERANCE
from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.geometry.bodies import Box
from sovarc.compiler.lower import sites_for
from sovarc.compiler.lower.wide import _arc
from sovarc.compiler.maps import load_map
from sovarc.compiler.staging import stage_on_site
from sovarc.dsl import parse
from sovarc.dsl.errors import SovarcError
from sovarc.targets.sumo.network import read_network
from sovarc.targets.sumo.on_road import on_road

from tests.conftest import EXAMPLES, SHARED, requires_shared

BUS_RIGHT = EXAMPLES / "variants" / "t_junction_bus_right_turn_out_cyclist_side.sov"
TOWN02 = SHARED / "data" / "opendrive" / "carla" / "Town02.xodr"


@pytest.mark.parametrize("turn", [90.0, -90.0, 60.0])
def test_an_arc_turns_its_whole_angle_at_its_radius(turn: float) -> None:
    arc = _arc((10.0, 5.0), 30.0, turn, 11.5)
    assert arc.length == pytest.approx(11.5 * math.radians(abs(turn)), rel=1e-3)
    assert angle_diff(arc.heading(arc.length), 30.0) == pytest.approx(turn, abs=2.0)
    inside = (arc.s > 4.5) & (arc.s < arc.length - 4.5)  # as the corner check measures it, over 8 m
    assert arc.curvature_radius(window=8.0)[inside] == pytest.approx(np.full(inside.sum(), 11.5), rel=0.08)


@requires_shared
def test_a_bus_turning_right_at_a_carla_corner_swings_wide_and_stays_on_the_road() -> None:
    road_map = load_map(TOWN02)
    staged, notes, matches = sites_for(parse(BUS_RIGHT.read_text()), road_map, roads=3)
    plans = []
    for match in matches:
        try:
            plans.append(stage_on_site(staged, notes, road_map, match))
        except SovarcError:
            continue  # a corner with no room to swing wide: refused, as it should be
    wide = [p for p in plans if any("swings wide" in n for n in p.notes)]
    assert wide, "no CARLA corner of Town02 let the bus swing wide"
    for plan in wide:
        network = read_network(Path(plan.network.sumo))
        bus = plan.trajectory("V1")
        tangent_gap = 0.0
        for a, b in zip(bus.samples, bus.samples[1:], strict=False):
            if b.t > plan.impact.time:
                break
            if math.dist((a.x, a.y), (b.x, b.y)) > 0.2:
                tangent = math.degrees(math.atan2(b.x - a.x, b.y - a.y))
                tangent_gap = max(tangent_gap, abs(angle_diff(tangent, b.heading)))
            for x, y in Box.of(bus.body, b.x, b.y, b.heading).corners(shrink=LINE_TOLERANCE):
                assert on_road(network, x, y), f"the bus leaves the road at t={b.t} on {plan.site}"
        assert tangent_gap > 20.0  # in the turn it faces well short of its front's path: its rear trails
