"""THE vehicle model: per participant kind, its body and what it can do.

One row per kind of road user: the IR's vehicle kinds (car, van, pickup, bus, truck, motorcycle,
bicycle) and the pedestrian. A body's `vclass` is SUMO's vehicle class; several kinds may share one
(a pickup is a passenger car to SUMO), so a model is found by its body, which is each kind's own.

Lowering, synthesis and every oracle read these numbers from here. Two different quantities that
happen to be close (the turning radius of the rear axle, of the front bumper, and of a planned
path) are separate fields, each saying what it is.

Not here: the reference ego FMU's own driving settings (targets/fmu/reference/sovarc_ego.py: its
IDM acceleration, its comfortable braking, ...). They belong to the system under test, which is
built into a standalone FMU; the simulated vehicle it drives is the one modelled here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

# SUMO's drawing of each vehicle class that has one of its own.
GUI_SHAPES = {
    "delivery": "delivery",
    "bus": "bus",
    "truck": "truck",
    "motorcycle": "motorcycle",
    "bicycle": "bicycle",
    "pedestrian": "pedestrian",
}


@dataclass(frozen=True)
class Body:
    """A participant's dimensions as a plan carries them."""

    length: float  # m
    width: float  # m
    vclass: str  # SUMO vehicle class: passenger, delivery, bus, truck, motorcycle, bicycle, pedestrian

    @property
    def gui_shape(self) -> str:
        """How SUMO draws it (its guiShape): a class's own shape, a passenger car's for the car and the pickup."""
        return GUI_SHAPES.get(self.vclass, "passenger")

    @property
    def front_ref(self) -> bool:
        """Whether a sample's point is the front-bumper centre (a vehicle) rather than the body centre
        (a pedestrian): the plan's convention, and SUMO's."""
        return self.vclass != "pedestrian"


@dataclass(frozen=True)
class Limits:
    """How a participant may be planned to move. Every kind has its own: lowering and synthesis read
    `model(body).limits` of the body each route carries (PLANNED is the car's)."""

    path_radius: float  # m: the tightest bend a planned or reshaped path may take (a tight junction corner)
    plan_accel: float  # m/s^2: the most a planned trajectory asks, per axis (TOPP-RA) and along it (Ruckig)
    start_accel: float  # m/s^2: the trapezoid profile's ramp up from rest
    stop_decel: float  # m/s^2: the trapezoid profile's ramp down to rest
    lateral_accel: float  # m/s^2: the most a curve may ask (comfortable; it caps speeds in curves)
    reverse_speed: float = 2.5  # m/s: the fastest it is planned to back (a walking pace or two: 9 km/h)
    reverse_accel: float = 1.0  # m/s^2: its ramps up and down when backing
    usual_speed: float = math.inf  # m/s: the most it is planned to cruise at unless a report says faster
    top_speed: float = math.inf  # m/s: the most it is planned to go unless a report says faster


PLANNED = Limits(path_radius=3.0, plan_accel=4.5, start_accel=2.0, stop_decel=3.0, lateral_accel=2.5)
# Heavy vehicles: gentle ramps (a loaded bus or truck accelerates at about 1 m/s^2, brakes at 3-5) and a wide
# tightest bend (a 12 m bus sweeps a 24 m kerb-to-kerb circle).
HEAVY = Limits(path_radius=9.0, plan_accel=3.0, start_accel=1.0, stop_decel=2.0, lateral_accel=1.5, reverse_speed=1.5)
# Two wheels: a motorcycle leans through bends a car takes slower, but is planned no harder than a car.
TWO_WHEELS = Limits(path_radius=2.5, plan_accel=4.5, start_accel=2.5, stop_decel=3.5, lateral_accel=3.0)
# A cyclist: ramps of a rider's legs and rim brakes.
# An everyday rider cruises at 15-20 km/h and rarely passes 30.
CYCLIST = Limits(
    path_radius=2.0,
    plan_accel=3.0,
    start_accel=1.0,
    stop_decel=2.5,
    lateral_accel=2.0,
    reverse_speed=0,
    usual_speed=5.0,
    top_speed=8.5,
)


@dataclass(frozen=True)
class Model:
    """One participant kind."""

    body: Body
    rear_overhang: float  # of the length: how far ahead of the rear the rear axle lies (the axle it turns about)
    front_overhang: float  # of the length: how far behind the front bumper the front axle lies
    axle_radius: float  # m: the rear axle's centre at full lock (a turn in legs is laid out with it)
    front_radius: float  # m: the front bumper's path at full lock (a U-turn's half circle, at the tightest)
    drive_accel: float  # m/s^2: the most the simulated vehicle accelerates, whatever it is asked
    drive_brake: float  # m/s^2: the most it brakes (about the grip of dry asphalt)
    # The FMU harness's bicycle model of the ego (targets/fmu/bicycle.py) has its own proportions:
    # wheelbase 60 % of the length, overhangs equal (20 %). They are not yet the overhangs above
    # (a 58 % wheelbase): making them one would change every FMU run.
    drive_wheelbase: float  # of the length
    drive_overhang: float  # of the length, at either end
    limits: Limits = PLANNED
    # Its plan faces the way its body does, the rear axle trailing the front's path (geometry/trailing.py):
    # a long wheelbase cuts inside a bend by metres. A shorter body's plan faces along its path, as it always has.
    trails: bool = False

    @property
    def axle_reach(self) -> float:
        """m from the front bumper back to the rear axle."""
        return (1.0 - self.rear_overhang) * self.body.length


CAR_MODEL = Model(
    Body(4.6, 1.8, "passenger"),
    rear_overhang=0.22,
    front_overhang=0.2,  # a 4.6 m car gets a 2.67 m wheelbase, 1.01 m behind the rear axle
    axle_radius=3.75,  # a 10.5 m kerb-to-kerb circle for the car
    front_radius=4.0,  # a 10-11 m kerb-to-kerb turning circle
    drive_accel=4.0,
    drive_brake=8.0,
    drive_wheelbase=0.6,
    drive_overhang=0.2,
)
# A walker turns on the spot and has no axles: its overhangs and radii are 0 (no module asks them).
# Only a vehicle is driven by an FMU; its drive_* fields are the car's, as they always were.
PEDESTRIAN_MODEL = Model(
    Body(0.5, 0.6, "pedestrian"),
    rear_overhang=0.0,
    front_overhang=0.0,
    axle_radius=0.0,
    front_radius=0.0,
    drive_accel=4.0,
    drive_brake=8.0,
    drive_wheelbase=0.6,
    drive_overhang=0.2,
)

# The other kinds: typical dimensions of each class (a minivan, a full-size pickup, a 12 m city bus, a
# rigid heavy truck, a touring motorcycle, an adult's bicycle with its rider), their turning circles and
# what they can do. Axle positions are fractions of the length, as the car's are.
VAN_MODEL = Model(
    Body(5.1, 2.0, "delivery"),
    rear_overhang=0.2,
    front_overhang=0.17,
    axle_radius=4.6,
    front_radius=5.0,  # a 12 m turning circle
    drive_accel=3.0,
    drive_brake=7.5,
    drive_wheelbase=0.6,
    drive_overhang=0.2,
)
PICKUP_MODEL = Model(
    Body(5.6, 2.0, "passenger"),
    rear_overhang=0.22,
    front_overhang=0.17,
    axle_radius=5.6,
    front_radius=6.2,  # a 13-14 m turning circle
    drive_accel=3.5,
    drive_brake=7.5,
    drive_wheelbase=0.6,
    drive_overhang=0.2,
)
BUS_MODEL = Model(
    Body(12.0, 2.55, "bus"),
    rear_overhang=0.26,
    front_overhang=0.22,
    axle_radius=9.0,
    front_radius=11.5,  # about 24 m kerb to kerb
    drive_accel=1.2,
    drive_brake=5.0,
    drive_wheelbase=0.6,
    drive_overhang=0.2,
    limits=HEAVY,
    trails=True,
)
TRUCK_MODEL = Model(
    Body(10.0, 2.5, "truck"),
    rear_overhang=0.22,
    front_overhang=0.14,
    axle_radius=8.5,
    front_radius=10.5,  # about 22 m kerb to kerb
    drive_accel=1.0,
    drive_brake=5.0,
    drive_wheelbase=0.6,
    drive_overhang=0.2,
    limits=HEAVY,
    trails=True,
)
MOTORCYCLE_MODEL = Model(
    Body(2.2, 0.8, "motorcycle"),
    rear_overhang=0.15,
    front_overhang=0.15,
    axle_radius=2.6,
    front_radius=2.8,
    drive_accel=5.0,
    drive_brake=7.0,
    drive_wheelbase=0.6,
    drive_overhang=0.2,
    limits=TWO_WHEELS,
)
BICYCLE_MODEL = Model(
    Body(1.8, 0.65, "bicycle"),
    rear_overhang=0.2,
    front_overhang=0.2,
    axle_radius=2.0,
    front_radius=2.2,
    drive_accel=1.5,
    drive_brake=3.5,
    drive_wheelbase=0.6,
    drive_overhang=0.2,
    limits=CYCLIST,
)

# Keyed by the IR's vehicle kinds (VehicleKind's values) and "pedestrian".
MODELS: dict[str, Model] = {
    "car": CAR_MODEL,
    "van": VAN_MODEL,
    "pickup": PICKUP_MODEL,
    "bus": BUS_MODEL,
    "truck": TRUCK_MODEL,
    "motorcycle": MOTORCYCLE_MODEL,
    "bicycle": BICYCLE_MODEL,
    "pedestrian": PEDESTRIAN_MODEL,
}
_BY_BODY = {m.body: m for m in MODELS.values()}

CAR = CAR_MODEL.body
PEDESTRIAN = PEDESTRIAN_MODEL.body
REAR_OVERHANG = CAR_MODEL.rear_overhang


def model(body: Body) -> Model:
    """The model whose body this is; a body of no kind's own (one a test made) is modelled as a car."""
    return _BY_BODY.get(body, CAR_MODEL)


def model_of(kind: str) -> Model:
    """The model of a kind named as the IR names it (`bus`, `pedestrian`); unknown kinds are staged as a car."""
    return MODELS.get(kind, CAR_MODEL)


def participant_model(participant: Any) -> Model:
    """The model of an IR participant: a pedestrian's, or its vehicle kind's (an unstated kind is a car)."""
    if participant.role == "pedestrian":
        return PEDESTRIAN_MODEL
    return model_of(str(getattr(participant.kind, "value", "car")))
