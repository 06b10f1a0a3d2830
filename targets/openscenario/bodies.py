"""Participant bodies as OpenSCENARIO describes them, and the plan's points moved onto them.

OpenSCENARIO places a vehicle by its reference point, the centre of the rear axle on the
ground, and its BoundingBox centre is given relative to that point. The plan gives the
front-bumper centre (a pedestrian: the body centre). So a vehicle's reference point lies
`front_offset` metres behind the plan's point, along the heading.

Angles: the plan's compass degrees (0 = north, clockwise) become OpenSCENARIO's heading `h`,
radians counter-clockwise from +x: h = radians(90 - compass), kept in [0, 2 pi).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from sovarc.compiler.plan import Sample
from sovarc.compiler.vehicles import Body, model

TAU = 2.0 * math.pi

# SUMO vehicle class -> OpenSCENARIO vehicleCategory, height (m), mass (kg).
VEHICLE_CLASSES: dict[str, tuple[str, float, float]] = {
    "passenger": ("car", 1.5, 1500.0),
    "taxi": ("car", 1.5, 1500.0),
    "private": ("car", 1.5, 1500.0),
    "delivery": ("van", 2.2, 2500.0),
    "truck": ("truck", 3.2, 12000.0),
    "trailer": ("semitrailer", 3.8, 30000.0),
    "bus": ("bus", 3.2, 12000.0),
    "motorcycle": ("motorbike", 1.3, 250.0),
    "moped": ("motorbike", 1.2, 120.0),
    "bicycle": ("bicycle", 1.7, 90.0),
}
PEDESTRIAN_HEIGHT = 1.8
PEDESTRIAN_MASS = 75.0


@dataclass(frozen=True)
class OscBody:
    """A body in OpenSCENARIO terms; all lengths in metres, relative to the reference point."""

    pedestrian: bool
    category: str  # vehicleCategory or pedestrianCategory
    length: float
    width: float
    height: float
    mass: float
    center_x: float  # bounding-box centre ahead of the reference point
    wheelbase: float  # 0 for a pedestrian
    wheel_diameter: float
    track_width: float

    @property
    def front_offset(self) -> float:
        """How far ahead of the reference point the plan's point lies."""
        return 0.0 if self.pedestrian else self.center_x + self.length / 2.0


def osc_body(body: Body) -> tuple[OscBody, str | None]:
    """The OpenSCENARIO body of a plan body, and a note when its class had to be approximated."""
    if body.vclass == "pedestrian":
        return OscBody(
            True, "pedestrian", body.length, body.width, PEDESTRIAN_HEIGHT, PEDESTRIAN_MASS, 0, 0, 0, 0
        ), None
    note = None
    if body.vclass not in VEHICLE_CLASSES:
        note = f"vehicle class {body.vclass!r} has no OpenSCENARIO category; written as 'car'"
    category, height, mass = VEHICLE_CLASSES.get(body.vclass, VEHICLE_CLASSES["passenger"])
    kind = model(body)  # its overhangs: a three-point turn is laid out about its rear axle
    rear = kind.rear_overhang * body.length
    wheelbase = body.length * (1.0 - kind.rear_overhang - kind.front_overhang)
    wheel = round(min(0.8, max(0.5, 0.14 * body.length)), 2)
    track = round(0.85 * body.width, 2)
    return OscBody(
        False, category, body.length, body.width, height, mass, body.length / 2 - rear, wheelbase, wheel, track
    ), note


def osc_heading(compass: float) -> float:
    """OpenSCENARIO heading (radians, counter-clockwise from +x, in [0, 2 pi)) of a compass heading."""
    return math.radians(90.0 - compass) % TAU


def compass_of(h: float) -> float:
    """The compass heading (degrees, [0, 360)) of an OpenSCENARIO heading."""
    return (90.0 - math.degrees(h)) % 360.0


def reference_point(sample: Sample, body: OscBody) -> tuple[float, float, float]:
    """(x, y, h) of the reference point for a plan sample."""
    h = osc_heading(sample.heading)
    back = body.front_offset
    return sample.x - back * math.cos(h), sample.y - back * math.sin(h), h
