"""THE vehicle model: per participant kind, its body and what it can do.

One row per kind (today a car and a pedestrian). A new kind (bus, truck, motorcycle, bicycle) is a
new row of MODELS; its body's `vclass` is SUMO's vehicle class, which names the kind everywhere.

Lowering, synthesis and every oracle read these numbers from here. Two different quantities that
happen to be close (the turning radius of the rear axle, of the front bumper, and of a planned
path) are separate fields, each saying what it is.

Not here: the reference ego FMU's own driving settings (targets/fmu/reference/sovarc_ego.py: its
IDM acceleration, its comfortable braking, ...). They belong to the system under test, which is
built into a standalone FMU; the simulated vehicle it drives is the one modelled here.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Body:
    """A participant's dimensions as a plan carries them."""

    length: float  # m
    width: float  # m
    vclass: str  # SUMO vehicle class: passenger, pedestrian

    @property
    def front_ref(self) -> bool:
        """Whether a sample's point is the front-bumper centre (a vehicle) rather than the body centre
        (a pedestrian): the plan's convention, and SUMO's."""
        return self.vclass != "pedestrian"


@dataclass(frozen=True)
class Limits:
    """How a participant may be planned to move. Today every kind is planned with the same limits
    (walkers included: the modules that apply them do not ask which kind they plan)."""

    path_radius: float  # m: the tightest bend a planned or reshaped path may take (a tight junction corner)
    plan_accel: float  # m/s^2: the most a planned trajectory asks, per axis (TOPP-RA) and along it (Ruckig)
    start_accel: float  # m/s^2: the trapezoid profile's ramp up from rest
    stop_decel: float  # m/s^2: the trapezoid profile's ramp down to rest
    lateral_accel: float  # m/s^2: the most a curve may ask (comfortable; it caps speeds in curves)


PLANNED = Limits(path_radius=3.0, plan_accel=4.5, start_accel=2.0, stop_decel=3.0, lateral_accel=2.5)


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

MODELS: dict[str, Model] = {m.body.vclass: m for m in (CAR_MODEL, PEDESTRIAN_MODEL)}

CAR = CAR_MODEL.body
PEDESTRIAN = PEDESTRIAN_MODEL.body
REAR_OVERHANG = CAR_MODEL.rear_overhang


def model(body: Body) -> Model:
    """The model of a body's kind; a vehicle class with no row of its own is modelled as a car."""
    return MODELS.get(body.vclass, CAR_MODEL)
