"""Parked and reversing vehicles, lowered and synthesized on the example town: where a parked car
stands, how a car backs (its reversing speed and ramps, its body facing the way it came), that a
backing striker meets its victim with its rear, and that its body never leaves the road."""

from __future__ import annotations

import functools
import itertools
import math
from pathlib import Path

import pytest
from sovarc.compiler.crashes import backing_at, fits, planned_touch
from sovarc.compiler.geometry.bodies import Box, Contact
from sovarc.compiler.lower import sites_for, stagings_on
from sovarc.compiler.lower.backing import KERB_GAP
from sovarc.compiler.maps import load_map
from sovarc.compiler.plan import Plan
from sovarc.compiler.staging import stage_on_site
from sovarc.compiler.vehicles import CAR_MODEL
from sovarc.dsl import parse
from sovarc.dsl.errors import LoweringError
from sovarc.dsl.ir import CrashType
from sovarc.targets.sumo.network import read_network
from sovarc.targets.sumo.on_road import on_road

from tests.conftest import EXAMPLES as EXAMPLE_DIR
from tests.conftest import SHARED, requires_shared

EXAMPLES = EXAMPLE_DIR / "scenarios"
TOWN = EXAMPLE_DIR / "maps" / "town.net.xml"
TOWN01 = SHARED / "data" / "opendrive" / "carla" / "Town01.xodr"
BACK_INTO_STOPPED = "straight_reverse_into_stopped_rear_end"
BACK_OUT = "straight_back_out_of_parking_rear_end"
PARKED_STRUCK = "straight_parked_car_struck_rear_end"
MOVES = (BACK_INTO_STOPPED, BACK_OUT, PARKED_STRUCK)
SLACK = 1.1  # synthesis's own slack over a limit
# the moves' variants, shared with benchmarks/bench_backing.py
VARIANTS = EXAMPLE_DIR / "variants"
BACKING = (EXAMPLES / f"{BACK_INTO_STOPPED}.sov").read_text()


def _variant(name: str) -> str:
    return (VARIANTS / f"{name}.sov").read_text()


@functools.cache
def plans(name: str, map_path: Path = TOWN, roads: int = 2) -> tuple[Plan, ...]:
    road_map = load_map(map_path)
    staged, notes, matches = sites_for(parse((EXAMPLES / f"{name}.sov").read_text()), road_map, roads=roads)
    return tuple(stage_on_site(staged, notes, road_map, m) for m in matches)


def _moving_back(plan: Plan, who: str) -> list[tuple[float, float]]:
    """(speed, displacement along the heading) of each step the participant moves."""
    samples = plan.trajectory(who).samples
    out = []
    for a, b in itertools.pairwise(samples):
        rad = math.radians(a.heading)
        along = (b.x - a.x) * math.sin(rad) + (b.y - a.y) * math.cos(rad)
        if abs(b.speed) > 0.05:
            out.append((b.speed, along))
    return out


def test_a_car_backs_facing_the_way_it_came_within_its_reversing_limits() -> None:
    limits = CAR_MODEL.limits
    for plan in plans(BACK_INTO_STOPPED):
        steps = _moving_back(plan, "V1")
        assert steps, "it moves"
        assert all(speed < 0.0 and along < 0.0 for speed, along in steps)  # backwards, body facing ahead
        samples = plan.trajectory("V1").samples
        assert min(s.speed for s in samples) >= -limits.reverse_speed * SLACK
        accel = [abs(b.speed - a.speed) / (b.t - a.t) for a, b in itertools.pairwise(samples)]
        assert max(accel) <= limits.reverse_accel * SLACK
        assert samples[0].speed == 0.0  # it stands before it backs


def test_a_backing_striker_meets_its_victim_with_its_rear() -> None:
    for name in (BACK_INTO_STOPPED, BACK_OUT):
        for plan in plans(name):
            contact = planned_touch(plan)
            assert contact is not None
            assert backing_at(plan, "V1", contact.time)
            assert "rear" in contact.zones[0] and "front" in contact.zones[1], contact
            assert contact.angle <= 45.0  # same headings: the rear_end of a backing striker
            assert fits(CrashType.REAR_END, contact, backing=True)
            assert not fits(CrashType.REAR_END, contact)  # read as a forward striker, it would not fit
            # C_A is at the striker's leading face: its rear bumper
            at = plan.trajectory("V1").at(plan.impact.time)
            rad = math.radians(at.heading)
            rear = (at.x - 4.6 * math.sin(rad), at.y - 4.6 * math.cos(rad))
            assert math.dist(rear, plan.impact.point) < 0.01


def test_a_parked_car_stands_at_the_kerb_throughout() -> None:
    for plan in plans(PARKED_STRUCK):
        samples = plan.trajectory("V2").samples
        assert {(s.x, s.y, s.heading, s.speed) for s in samples} == {
            (samples[0].x, samples[0].y, samples[0].heading, 0.0)
        }
        network = read_network(Path(plan.network.sumo))
        spot = min(
            (
                network.spot(lane, samples[0].x, samples[0].y)
                for lane in network.near(samples[0].x, samples[0].y, 4.0)
                if not lane.pedestrian_only
            ),
            key=lambda found: found[1],
        )[0]
        edge_gap = spot.lane.width / 2.0 - (abs(spot.offset) + 1.8 / 2.0)
        assert spot.offset < -0.3  # right of its lane's centre, towards the kerb
        assert edge_gap == pytest.approx(KERB_GAP, abs=0.05)  # its body inside the road's edge
        contact = planned_touch(plan)
        assert contact is not None and "front" in contact.zones[0] and "rear" in contact.zones[1]


def test_parked_and_backing_bodies_never_leave_the_road() -> None:
    for name in MOVES:
        for plan in plans(name):
            network = read_network(Path(plan.network.sumo))
            t = plan.trajectory("V2" if name == PARKED_STRUCK else "V1")
            for s in t.samples:
                if s.t > plan.impact.time:
                    break
                for x, y in Box.of(t.body, s.x, s.y, s.heading).corners():
                    assert on_road(network, x, y), f"{name}: {t.participant} off the road at t={s.t}"


@requires_shared
def test_on_a_carla_town() -> None:
    for name in MOVES:
        found = plans(name, TOWN01, 1)
        assert found
        if name != PARKED_STRUCK:
            contact = planned_touch(found[0])
            assert contact is not None and fits(CrashType.REAR_END, contact, backing=True)


def _stage(text: str) -> None:
    road_map = load_map(TOWN)
    staged, notes, matches = sites_for(parse(text), road_map, roads=1)
    next(stagings_on(staged, matches[0], road_map, notes))


def test_backing_is_staged_as_a_first_move_on_a_straight_road_only() -> None:
    with pytest.raises(LoweringError, match="after `parked` or `reverse` only"):
        _stage(BACKING.replace("      reverse\n", "      reverse\n      follow_lane\n"))
    with pytest.raises(LoweringError, match="staged on a straight road only"):
        _stage(BACKING.replace("kind straight", "kind intersection"))


def test_crash_types_read_for_a_backing_striker() -> None:
    def contact(striker: tuple[str, ...], victim: tuple[str, ...], angle: float) -> Contact:
        return Contact(0.0, (0.0, 0.0), (striker[0], victim[0]), (striker, victim), angle)

    assert fits(CrashType.REAR_END, contact(("rear",), ("front",), 0.0), backing=True)
    assert not fits(CrashType.REAR_END, contact(("rear",), ("front",), 90.0), backing=True)
    assert not fits(CrashType.REAR_END, contact(("front",), ("rear",), 0.0), backing=True)
    assert fits(CrashType.FRONTAL, contact(("rear",), ("rear",), 180.0), backing=True)
    assert fits(CrashType.SIDE, contact(("rear", "left"), ("right",), 80.0), backing=True)
    assert not fits(CrashType.SIDE, contact(("front",), ("right",), 80.0), backing=True)


def _first_plan(text: str) -> Plan:
    road_map = load_map(TOWN)
    staged, notes, matches = sites_for(parse(text), road_map, roads=1)
    return stage_on_site(staged, notes, road_map, matches[0])


def test_a_car_backing_out_is_struck_in_its_rear() -> None:
    """The victim backs: its faces are named as ever (the passing car's front into its rear), its line
    runs against them."""
    plan = _first_plan(_variant("straight_backing_out_struck_rear_end"))
    contact = planned_touch(plan)
    assert contact is not None and backing_at(plan, "V1", contact.time) and not backing_at(plan, "V2", contact.time)
    assert "front" in contact.zones[0] and "rear" in contact.zones[1] and fits(CrashType.REAR_END, contact)


def test_a_parked_car_pulls_out_forwards() -> None:
    plan = _first_plan(_variant("straight_parked_pulls_out_struck_rear_end"))
    samples = plan.trajectory("V1").samples
    assert samples[0].speed == 0.0 and min(s.speed for s in samples) >= 0.0 and max(s.speed for s in samples) > 1.0
    contact = planned_touch(plan)
    assert contact is not None and fits(CrashType.REAR_END, contact)


def test_a_backing_car_strikes_a_crossing_pedestrian_with_its_rear() -> None:
    plan = _first_plan(_variant("straight_backing_into_pedestrian_side"))
    contact = planned_touch(plan)
    assert contact is not None and "rear" in contact.zones[0]
    assert fits(CrashType.SIDE, contact, backing=True)
