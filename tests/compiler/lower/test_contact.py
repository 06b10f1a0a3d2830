"""Where a striker can meet a victim (the collision area C_A), on hand-made straight-line routes."""

from __future__ import annotations

import math

import numpy as np
import pytest
from sovarc.compiler.geometry.angles import heading_vector
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.geometry.trailing import trailing_headings
from sovarc.compiler.lower import contact
from sovarc.compiler.lower.contact import (
    ALONG,
    CORNER_DEPTH,
    FACE,
    SIDE_OVERLAP,
    SIDE_TURNED,
    TURNING_SIDE,
    contacts,
    describe,
)
from sovarc.compiler.lower.route import Route
from sovarc.compiler.vehicles import CAR, model_of
from sovarc.dsl.ir import CrashType, Participant, Role


def route(pid: str, *points: tuple[float, float]) -> Route:
    return Route(Participant(pid, Role.VEHICLE), CAR, Polyline(list(points)), [], (), (), 0.0)


NORTH = route("A", (0.0, -50.0), (0.0, 50.0))
EAST = route("B", (-50.0, 0.0), (50.0, 0.0))
ONCOMING_ACROSS = route("C", (-43.301, 25.0), (43.301, -25.0))  # heading 120: across NORTH's path and towards it


def test_a_crossing_is_one_point_for_side_and_frontal_but_not_rear_end() -> None:
    side, *further = contacts(NORTH, EAST, CrashType.SIDE)
    assert (side.kind, side.sign, side.angle) == ("crossing", 0, pytest.approx(90.0))
    # then the same point further back along the victim's side (TURNING_SIDE)
    assert [c.victim_s(c.lo) - side.victim_s(side.lo) for c in further] == [
        pytest.approx((face - TURNING_SIDE[0]) * CAR.length) for face in TURNING_SIDE[1:]
    ]
    # the striker's front face is into the victim's side by SIDE_OVERLAP and, head-on to it, a
    # quarter of the victim's width: short of the crossing point by the rest of its half width
    assert side.lo == side.hi == pytest.approx(50.0 - (CAR.width / 4 - SIDE_OVERLAP), abs=0.05)
    # the victim's front is half a body past the crossing, so that its side's middle is there
    assert side.victim_s(side.lo) == pytest.approx(50.0 + FACE[CrashType.SIDE] * CAR.length)
    assert contacts(NORTH, EAST, CrashType.REAR_END) == []
    # at right angles fronts meet only at a corner: the striker's front corner CORNER_DEPTH into the
    # victim's way as the victim's front reaches the striker's near side (crashes.corner_frontal)
    (corner,) = contacts(NORTH, EAST, CrashType.FRONTAL)
    assert (corner.kind, corner.angle) == ("corner", pytest.approx(90.0))
    assert corner.lo == pytest.approx(50.0 - (CAR.width / 2 - CORNER_DEPTH), abs=0.05)
    assert corner.victim_s(corner.lo) == pytest.approx(50.0 - CAR.width / 2, abs=0.05)
    assert all(c.kind != "corner" for c in contacts(NORTH, EAST, CrashType.SIDE))
    (frontal,) = contacts(NORTH, ONCOMING_ACROSS, CrashType.FRONTAL)
    assert frontal.angle == pytest.approx(120.0, abs=0.5)
    assert frontal.victim_s(frontal.lo) == pytest.approx(50.0)  # fronts meet
    assert describe(side) == "paths cross at 90 degrees"


def test_a_lane_shared_in_the_same_direction_is_a_rear_end_range() -> None:
    striker = route("A", (0.0, 0.0), (0.0, 100.0))
    victim = route("B", (0.0, 20.0), (0.0, 120.0))  # 20 m ahead on the same line
    (rear,) = contacts(striker, victim, CrashType.REAR_END)
    assert (rear.kind, rear.sign, rear.angle) == ("shared", 1, 0.0)
    assert (rear.lo, rear.hi) == (pytest.approx(20.0), pytest.approx(100.0))
    # at any striker position s the victim's front is one body length ahead: its rear touches the striker
    for s in (30.0, 60.0, 90.0):
        assert victim.line.point(rear.victim_s(s))[1] - striker.line.point(s)[1] == pytest.approx(CAR.length)
    assert contacts(striker, victim, CrashType.FRONTAL) == []
    assert contacts(striker, victim, CrashType.SIDE) == []  # 80 m side by side in one lane is no side impact
    assert describe(rear) == "paths share 80 m of lane, same direction"


def test_a_lane_shared_in_opposite_directions_is_a_head_on_range() -> None:
    striker = route("A", (0.0, 0.0), (0.0, 100.0))
    victim = route("B", (0.0, 100.0), (0.0, 0.0))
    (frontal,) = contacts(striker, victim, CrashType.FRONTAL)
    assert (frontal.kind, frontal.sign, frontal.angle) == ("shared", -1, 180.0)
    for s in (10.0, 50.0, 90.0):  # fronts at the same point
        assert victim.line.point(frontal.victim_s(s)) == pytest.approx(striker.line.point(s))
    assert contacts(striker, victim, CrashType.REAR_END) == []
    assert contacts(striker, victim, CrashType.SIDE) == []


def test_a_merge_gives_a_rear_end_range_after_it_and_a_side_contact_before_the_lines_join() -> None:
    striker = route("A", (-15.0, 24.0), (0.0, 50.0), (0.0, 100.0))  # joins the victim's line at 30 degrees
    victim = route("B", (0.0, 0.0), (0.0, 100.0))
    join = striker.line.s[1]  # about 30 m
    rear = contacts(striker, victim, CrashType.REAR_END)
    assert rear[0].kind == "shared" and rear[0].sign == 1 and rear[0].lo == pytest.approx(join, abs=0.5)
    assert any(c.kind == "crossing" and c.angle < 45.0 for c in rear[1:])
    side = contacts(striker, victim, CrashType.SIDE)
    assert side and all(c.kind == "crossing" for c in side)
    first = side[0]
    assert first.angle == pytest.approx(30.0, abs=1.0)
    # bodies touch before the lines join: where the lines are still (half a width each - overlap) apart
    gap = CAR.width - SIDE_OVERLAP
    assert first.lo == pytest.approx(join - gap / math.sin(math.radians(30.0)), abs=1.0)
    front = striker.line.point(first.lo)
    assert abs(front[0]) == pytest.approx(gap, abs=0.3)
    # ... and the striker's front meets the middle of the victim's side there
    middle = first.victim_s(first.lo) - FACE[CrashType.SIDE] * CAR.length
    assert victim.line.point(middle)[1] == pytest.approx(front[1], abs=0.6)
    assert contacts(striker, victim, CrashType.FRONTAL) == []


def test_lines_crossing_shallowly_meet_side_on_before_they_cross() -> None:
    # the striker drifts across the victim's line at 10 degrees and goes on past it
    slope = math.tan(math.radians(10.0))
    striker = route("A", (-50.0 * slope, 0.0), (50.0 * slope, 100.0))
    victim = route("B", (0.0, 0.0), (0.0, 100.0))
    side = contacts(striker, victim, CrashType.SIDE)[0]
    assert side.kind == "crossing" and side.angle == pytest.approx(10.0, abs=0.5)
    front = striker.line.point(side.lo)
    assert front[1] < 45.0  # before the crossing at y = 50
    assert abs(front[0]) == pytest.approx(CAR.width - SIDE_OVERLAP, abs=0.3)
    steep = contacts(NORTH, EAST, CrashType.SIDE)[0]
    # at right angles the front face is into the side before the lines cross (see above)
    assert steep.lo == pytest.approx(50.0 - (CAR.width / 4 - SIDE_OVERLAP), abs=0.05)


def test_a_victim_angling_out_of_the_lane_is_met_on_no_side_by_its_follower() -> None:
    # it leaves the shared line at 30 degrees: its rear corner, still in the striker's way, is what
    # the striker meets, from behind (a rear-end for every oracle), never its side
    striker = route("A", (0.0, 0.0), (0.0, 100.0))
    victim = route("B", (0.0, 10.0), (0.0, 50.0), (-15.0, 76.0))
    assert contacts(striker, victim, CrashType.SIDE) == []
    assert any(
        c.kind == "crossing" and c.angle == pytest.approx(30.0, abs=1.0)
        for c in contacts(striker, victim, CrashType.REAR_END)
    )


def test_a_victim_turning_sharply_off_the_lane_is_met_on_its_side_once_turned_past_a_rear_end() -> None:
    # a tight left turn (5 m radius) off the striker's line: the striker meets the victim's left side
    # once it has turned SIDE_TURNED, while its rear-left corner is still in the striker's way
    arc = [(-5.0 + 5.0 * math.cos(math.radians(a)), 50.0 + 5.0 * math.sin(math.radians(a))) for a in range(0, 91, 5)]
    striker = route("A", (0.0, 0.0), (0.0, 100.0))
    victim = route("B", (0.0, 10.0), *arc, (-30.0, 55.0))
    (side,) = [c for c in contacts(striker, victim, CrashType.SIDE) if c.kind == "crossing"]
    assert SIDE_TURNED <= side.angle <= SIDE_TURNED + 10.0
    front = victim.line.point(side.victim_s(side.lo))
    heading = victim.line.heading(side.victim_s(side.lo))
    (fx, fy), (lx, ly) = heading_vector(heading), heading_vector(heading - 90.0)
    rear_left = (front[0] - CAR.length * fx + CAR.width / 2 * lx, front[1] - CAR.length * fy + CAR.width / 2 * ly)
    # its rear-left corner is in the striker's way (the turn is to -x), or beyond its far (+x) edge
    assert rear_left[0] >= -(CAR.width / 2.0 - 0.3)
    # the striker's front is placed where it first reaches that side: the corner, or where the side
    # crosses its far edge
    along = max(0.0, (rear_left[0] - CAR.width / 2.0) / -fx)
    reached = (rear_left[0] + along * fx, rear_left[1] + along * fy)
    assert reached[0] <= CAR.width / 2.0 + 1e-6
    assert striker.line.point(side.lo)[1] == pytest.approx(reached[1], abs=0.3)


def test_a_wrong_way_swerve_meets_the_oncoming_side_before_the_lines_join() -> None:
    striker = route("A", (3.5, 0.0), (3.5, 20.0), (0.0, 40.0), (0.0, 100.0))  # swerves into the oncoming lane
    victim = route("B", (0.0, 100.0), (0.0, 0.0))
    swerve = [c for c in contacts(striker, victim, CrashType.SIDE) if c.kind == "crossing"]
    assert swerve
    front = striker.line.point(swerve[0].lo)
    assert front[1] < 40.0 and abs(front[0]) == pytest.approx(CAR.width - SIDE_OVERLAP, abs=0.3)


def test_a_rear_end_in_a_shared_lane_ends_while_the_victim_still_runs_along_it() -> None:
    striker = route("A", (0.0, 0.0), (0.0, 100.0))
    victim = route("B", (0.0, 20.0), (0.0, 60.0), (30.0, 60.0))  # turns off right at y = 60
    shared = [c for c in contacts(striker, victim, CrashType.REAR_END) if c.kind == "shared"]
    assert shared
    for rear in shared:
        # at the end of the range the victim's front, a body ahead, has not yet turned away
        turned = victim.line.heading(rear.victim_s(rear.hi)) - striker.line.heading(rear.hi)
        assert abs(turned) < ALONG
        assert rear.victim_s(rear.hi) <= 40.0 + 0.5  # its front is at most at the corner


def _left_turn(pid: str, body: object) -> Route:
    """North for 40 m, a quarter circle of 12 m to the left, then west: a heavy vehicle's left turn."""
    arc = [(12.0 * math.cos(a) - 12.0, 40.0 + 12.0 * math.sin(a)) for a in np.linspace(0.0, math.pi / 2, 40)]
    points = [(0.0, 0.0), *arc, (-60.0, 52.0)]
    return Route(Participant(pid, Role.VEHICLE), body, Polyline(points), [], (), (), 0.0)  # type: ignore[arg-type]


def test_a_trailing_body_faces_its_rear_axles_tractrix_and_a_car_its_line() -> None:
    truck = model_of("truck")
    turner = _left_turn("V", truck.body)
    at = np.arange(0.0, turner.line.length, 0.5)
    expected = trailing_headings(turner.line.points_at(at), 0.0, truck.axle_reach)
    assert np.abs((turner.facing(at) - expected + 180.0) % 360.0 - 180.0).max() < 0.5
    # mid-turn it faces well short of the way its front moves (it turns left: less far round)
    middle = float(turner.line.s[20])
    assert (turner.facing(np.array([middle]))[0] - turner.line.heading(middle)) % 360.0 > 15.0
    car = _left_turn("C", CAR)
    assert np.array_equal(car.facing(at), car.line.headings(at))


@pytest.mark.parametrize("kind", ["truck", "bus"])
def test_a_trailing_victim_struck_mid_turn_is_met_on_its_side_as_its_body_faces(kind: str) -> None:
    """An oncoming car crosses a heavy vehicle's left turn: its front is placed on the side of the
    body as it faces (the rear axle trailing), not of a body laid back along the front's curved path."""
    victim = _left_turn("V", model_of(kind).body)
    body = victim.body
    striker = route("S", (-10.0, 100.0), (-10.0, -20.0))  # south, across the turn's middle
    found = contacts(striker, victim, CrashType.SIDE)
    assert found
    for c in found:
        front = np.array(striker.line.point(c.lo))
        u = c.victim_s(c.lo)
        head = float(victim.facing(np.array([u]))[0])
        f = np.array(heading_vector(head))
        rel = np.array(victim.line.point(u)) - front
        back = float(rel @ f)  # m behind the victim's front, along the way it faces
        lateral = abs(float(rel[0] * f[1] - rel[1] * f[0]))
        assert -0.1 <= back <= body.length + 0.1
        assert lateral <= (body.width + CAR.width) / 2.0


def test_a_pairs_distances_are_made_once_for_every_crash_type_and_face(monkeypatch: pytest.MonkeyPatch) -> None:
    """`Lines` shares each pair of views' distance matrix among the crash types and faces asked of two
    routes (a side crash tries three faces on one view of the victim), and answers as a fresh search."""
    alone = {crash: contacts(NORTH, EAST, crash) for crash in CrashType}
    made: list[int] = []
    of = contact._Near.of
    monkeypatch.setattr(contact._Near, "of", lambda a, b: made.append(1) or of(a, b))
    lines = contact.Lines(NORTH, EAST)
    shared = {crash: contacts(NORTH, EAST, crash, lines=lines) for crash in CrashType}
    assert shared == alone
    assert len(made) == 1  # one view of each: the striker's front, the victim's line
    assert contacts(NORTH, EAST, CrashType.SIDE, whole=True, lines=lines) and len(made) == 1
    with pytest.raises(AssertionError):
        contacts(EAST, NORTH, CrashType.SIDE, lines=lines)  # another pair's question
