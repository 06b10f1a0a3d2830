"""The one vehicle model: a row for every kind the IR can name, each consistent in itself."""

from __future__ import annotations

import pytest
from sovarc.compiler.vehicles import CAR_MODEL, MODELS, model, model_of
from sovarc.dsl.ir import VehicleKind


@pytest.mark.parametrize("kind", [*VehicleKind, "pedestrian"], ids=str)
def test_every_kind_has_its_own_body_found_back_from_it(kind: str) -> None:
    row = model_of(str(kind))
    assert MODELS[str(kind)] is row
    assert model(row.body) is row  # the plan carries the body; every module finds the kind's row from it


@pytest.mark.parametrize("kind", list(VehicleKind), ids=str)
def test_a_vehicle_turns_wider_at_its_bumper_than_at_its_axle_and_brakes_harder_than_it_accelerates(
    kind: VehicleKind,
) -> None:
    row = model_of(kind)
    assert 0 < row.axle_radius < row.front_radius
    assert 0 < row.drive_accel < row.drive_brake
    assert 0 < row.front_overhang < 0.5 and 0 < row.rear_overhang < 0.5
    assert row.limits.start_accel <= row.limits.plan_accel and row.limits.stop_decel <= row.limits.plan_accel


def test_sizes_order_as_on_the_road() -> None:
    length = {k: model_of(k).body.length for k in VehicleKind}
    assert length["bicycle"] < length["motorcycle"] < length["car"] < length["van"] < length["pickup"]
    assert length["pickup"] < length["truck"] <= length["bus"]
    assert model_of("unknown") is CAR_MODEL and model_of(VehicleKind.CAR) is CAR_MODEL


def test_only_heavy_bodies_are_planned_facing_the_way_their_rear_axle_trails() -> None:
    """A car's plan faces along its path, as it always has; a bus's or truck's the way its body does."""
    assert {k for k, row in MODELS.items() if row.trails} == {"bus", "truck"}
    for row in MODELS.values():
        assert 0.5 * row.body.length <= row.axle_reach <= row.body.length
