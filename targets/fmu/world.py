"""The world of a test: one SUMO simulation, run in-process through libsumo.

Every actor (the ego and the NPCs) is a SUMO vehicle placed each step with moveToXY, so SUMO holds
the ground truth that perception reads back. libsumo runs one simulation per process: a World starts
SUMO on entry and always closes it on exit, and refuses to start while another simulation is loaded.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from types import TracebackType
from typing import Any

from sovarc.compiler.geometry.polyline import Point
from sovarc.compiler.vehicles import Body
from sovarc.dsl.errors import OracleError

KEEP_ROUTE = 2  # moveToXY: place exactly at (x, y), off the lanes if need be


class World:
    """`with World(net, step) as world:` add actors, move them, step, read them back."""

    def __init__(self, net: Path, step: float, seed: int = 0) -> None:
        self.net = net
        self.step_length = step
        self.seed = seed
        self._sumo: Any = None
        self._route: str | None = None
        self._edge_ids: set[str] | None = None
        self.time = 0.0

    def __enter__(self) -> World:
        import libsumo

        if libsumo.simulation.isLoaded():
            raise OracleError("a SUMO simulation is already running in this process; close it before running FMU tests")
        args = ["sumo", "-n", str(self.net), "--step-length", repr(self.step_length), "--begin", "0"]
        args += ["--seed", str(self.seed), "--no-step-log", "true", "--no-warnings", "true"]
        args += ["--collision.action", "none", "--collision.check-junctions", "false", "--time-to-teleport", "-1"]
        libsumo.start(args)
        self._sumo = libsumo
        return self

    def __exit__(self, kind: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None) -> None:
        if self._sumo is not None and self._sumo.simulation.isLoaded():
            self._sumo.close()
        self._sumo = None

    @property
    def sumo(self) -> Any:
        if self._sumo is None:
            raise RuntimeError("the world is not running")
        return self._sumo

    def add(self, actor: str, body: Body, x: float, y: float, heading: float) -> None:
        """An actor of this size at (x, y): the front-bumper centre of a vehicle, a pedestrian's centre."""
        sumo = self.sumo
        if self._route is None:
            edge = next(e for e in sumo.edge.getIDList() if not e.startswith(":"))
            sumo.route.add("sovarc_route", [edge])
            self._route = "sovarc_route"
        vtype = f"sovarc_{actor}"
        sumo.vehicletype.copy("DEFAULT_VEHTYPE", vtype)
        sumo.vehicletype.setVehicleClass(vtype, "ignoring")  # may stand on any lane, or none
        sumo.vehicletype.setLength(vtype, body.length)
        sumo.vehicletype.setWidth(vtype, body.width)
        sumo.vehicletype.setMinGap(vtype, 0.0)
        sumo.vehicletype.setShapeClass(vtype, body.gui_shape)  # drawn as its kind (a bus, a cyclist)
        sumo.vehicle.add(actor, self._route, typeID=vtype, depart="now", departSpeed="0")
        sumo.vehicle.setSpeedMode(actor, 0)
        self.move(actor, x, y, heading)

    def move(self, actor: str, x: float, y: float, heading: float) -> None:
        self.sumo.vehicle.moveToXY(actor, "", -1, x, y, angle=heading, keepRoute=KEEP_ROUTE)

    def advance(self) -> None:
        self.sumo.simulationStep()
        self.time = float(self.sumo.simulation.getTime())

    def read(self, actor: str) -> tuple[float, float, float, float]:
        """(x, y, heading, speed) of an actor as SUMO has it."""
        v = self.sumo.vehicle
        x, y = v.getPosition(actor)
        return (x, y, v.getAngle(actor) % 360.0, v.getSpeed(actor))

    def lane_shapes(self, edge: str) -> Sequence[tuple[str, Sequence[Point]]]:
        """The lanes of an edge and their centre lines (none for an edge the map lacks)."""
        sumo = self.sumo
        if self._edge_ids is None:
            self._edge_ids = set(sumo.edge.getIDList())
        if edge not in self._edge_ids:
            return []
        lanes = [f"{edge}_{k}" for k in range(sumo.edge.getLaneNumber(edge))]
        return [(lane, sumo.lane.getShape(lane)) for lane in lanes]

    def all_lane_shapes(self) -> list[Sequence[Point]]:
        """The centre line of every lane of the map, junction lanes included, sorted by lane id."""
        sumo = self.sumo
        return [sumo.lane.getShape(lane) for lane in sorted(sumo.lane.getIDList())]
