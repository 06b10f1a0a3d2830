"""ONE touching rule: bodies overlap only when they share area, and every oracle judges alike.

The SUMO oracle, the FMU harness and the OpenSCENARIO oracle each place a plan's body in their
own way (front bumper, rear axle, box centre; compass degrees or radians) and then ask the kernel.
Given the same poses they must agree, touching included (it is not a collision for any of them).
"""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st
from sovarc.compiler.crashes import first_overlap
from sovarc.compiler.geometry.bodies import Box, overlap
from sovarc.compiler.plan import Sample, Trajectory
from sovarc.compiler.vehicles import CAR, PEDESTRIAN, Body
from sovarc.dsl.ir import Role
from sovarc.targets.fmu.harness import _first_contact
from sovarc.targets.openscenario import kinematics
from sovarc.targets.openscenario.bodies import osc_body, reference_point
from sovarc.targets.openscenario.readback import Entity, Pose
from sovarc.targets.sumo.oracle import body_of
from sovarc.targets.sumo.replay import Pose as SumoPose

coordinate = st.floats(-20.0, 20.0, allow_nan=False)
heading = st.floats(0.0, 360.0, allow_nan=False, exclude_max=True)
size = st.floats(0.3, 12.0, allow_nan=False)
boxes = st.builds(Box, coordinate, coordinate, heading, size, size, st.booleans())
bodies = st.sampled_from([CAR, PEDESTRIAN])


@given(boxes, boxes)
def test_overlap_is_symmetric(a: Box, b: Box) -> None:
    assert overlap(a, b) == overlap(b, a)


@given(boxes, st.floats(-1.0, 1.0), st.sampled_from([1.0, -1.0]), size, size)
def test_boxes_sharing_only_an_edge_do_not_overlap(
    a: Box, along: float, side: float, length: float, width: float
) -> None:
    """A box beside `a`, same heading, its side on `a`'s side (slid along it by up to half `a`'s
    length), and one in line, its rear on `a`'s front: touching, so not overlapping."""
    (fx, fy), (lx, ly) = a.axes
    cx, cy = a.centre
    slide = along * a.length / 2.0
    reach = side * (a.width + width) / 2.0
    beside = Box(cx + slide * fx + reach * lx, cy + slide * fy + reach * ly, a.heading, length, width, False)
    ahead = (a.length + length) / 2.0
    in_line = Box(cx + ahead * fx, cy + ahead * fy, a.heading, length, a.width, False)
    assert not overlap(a, beside) and not overlap(beside, a)
    assert not overlap(a, in_line) and not overlap(in_line, a)
    inside = Box(cx + 0.99 * ahead * fx, cy + 0.99 * ahead * fy, a.heading, length, a.width, False)
    assert overlap(a, inside)  # a centimetre-scale push in shares area


def _sumo(body: Body, x: float, y: float, h: float) -> Box:
    trajectory = Trajectory("P", Role.VEHICLE if body is CAR else Role.PEDESTRIAN, body, (), (), (), (), None)
    return body_of(trajectory, SumoPose(x, y, h, ""))


def _osc(body: Body, x: float, y: float, h: float) -> Box:
    osc, _ = osc_body(body)
    entity = Entity("P", osc.pedestrian, osc.length, osc.width, osc.center_x, 0.0, None, None, None, {})
    rx, ry, rh = reference_point(Sample(0.0, x, y, h, 0.0), osc)
    return kinematics.box(entity, Pose(0.0, rx, ry, rh))


def _judgements(a: tuple[Body, float, float, float], b: tuple[Body, float, float, float]) -> dict[str, bool]:
    sumo = first_overlap([_sumo(*a)], [_sumo(*b)]) == 0
    fmu = _first_contact("A", {"A": (*a[1:], 0.0), "B": (*b[1:], 0.0)}, {"A": a[0], "B": b[0]}) is not None
    osc = overlap(_osc(*a), _osc(*b))
    return {"sumo": sumo, "fmu": fmu, "openscenario": osc}


@given(bodies, coordinate, coordinate, heading, bodies, coordinate, coordinate, heading)
def test_every_oracle_judges_the_same_poses_the_same_way(
    body_a: Body, xa: float, ya: float, ha: float, body_b: Body, xb: float, yb: float, hb: float
) -> None:
    judged = _judgements((body_a, xa, ya, ha), (body_b, xb, yb, hb))
    assert len(set(judged.values())) == 1, judged


@given(heading, st.floats(-0.8, 0.8))
def test_every_oracle_calls_touching_bumpers_and_sides_no_collision(h: float, slide: float) -> None:
    """Where the FMU harness once counted touching as a collision, and the others did not."""
    f = (math.sin(math.radians(h)), math.cos(math.radians(h)))
    left = (-f[1], f[0])
    behind = (CAR, -CAR.length * f[0], -CAR.length * f[1], h)  # its front bumper on the other's rear
    beside = (CAR, CAR.width * left[0] + slide * f[0], CAR.width * left[1] + slide * f[1], h)
    for other in (behind, beside):
        judged = _judgements((CAR, 0.0, 0.0, h), other)
        assert not any(judged.values()), judged
