"""The ego's motion: a kinematic bicycle model driven by the FMU's acceleration and steering.

The state is the front-bumper centre (the map's reference point for a vehicle), the compass heading
and the speed. The model turns about the rear axle, `rear_axle` metres behind the front bumper.
The ego never reverses: its speed stays in [0, MAX_SPEED].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from sovarc.compiler.vehicles import CAR_MODEL, Body, model

MAX_ACCEL = CAR_MODEL.drive_accel  # m/s² (the vehicle model's)
MAX_BRAKE = CAR_MODEL.drive_brake  # m/s², about the grip of dry asphalt
MAX_STEER = 0.6  # rad
MAX_SPEED = 50.0  # m/s
SUBSTEPS = 2  # integration steps per communication step


@dataclass(frozen=True)
class Geometry:
    length: float
    width: float
    wheelbase: float
    rear_axle: float  # m from the front bumper back to the rear axle

    @classmethod
    def of(cls, body: Body) -> Geometry:
        """The vehicle model's bicycle proportions (a car: wheelbase 60 % of the length, overhangs equal)."""
        kind = model(body)
        wheelbase = kind.drive_wheelbase * body.length
        return cls(body.length, body.width, wheelbase, wheelbase + kind.drive_overhang * body.length)


@dataclass(frozen=True)
class State:
    x: float  # m, front-bumper centre
    y: float
    heading: float  # compass degrees
    speed: float  # m/s
    accel: float = 0.0  # m/s² achieved over the last step


def advance(state: State, accel: float, steer: float, dt: float, geometry: Geometry) -> State:
    """The state after dt seconds of the (clamped) commands."""
    accel = min(max(accel, -MAX_BRAKE), MAX_ACCEL) if math.isfinite(accel) else -MAX_BRAKE
    steer = min(max(steer, -MAX_STEER), MAX_STEER) if math.isfinite(steer) else 0.0
    psi = math.radians(90.0 - state.heading)  # mathematical angle of the heading
    reach = geometry.rear_axle
    rx, ry = state.x - reach * math.cos(psi), state.y - reach * math.sin(psi)  # rear axle
    v = state.speed
    h = dt / SUBSTEPS
    for _ in range(SUBSTEPS):
        v_next = min(max(v + accel * h, 0.0), MAX_SPEED)
        v_mid = 0.5 * (v + v_next)
        yaw = v_mid * math.tan(steer) / geometry.wheelbase
        psi_mid = psi + 0.5 * yaw * h
        rx += v_mid * math.cos(psi_mid) * h
        ry += v_mid * math.sin(psi_mid) * h
        psi += yaw * h
        v = v_next
    heading = (90.0 - math.degrees(psi)) % 360.0
    x, y = rx + reach * math.cos(psi), ry + reach * math.sin(psi)
    return State(x, y, heading, v, (v - state.speed) / dt)
