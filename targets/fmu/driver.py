"""The driving system under test: an ego FMU, loaded and stepped with fmpy.

A `Driver` unpacks the FMU once; each test gets a fresh instance (`Driver.session`), so that no state
leaks from one test into the next.
"""

from __future__ import annotations

import shutil
import tempfile
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from types import TracebackType
from typing import Any

from sovarc.dsl.errors import OracleError
from sovarc.targets.fmu.bicycle import Geometry
from sovarc.targets.fmu.interface import MAX_OBJECTS, OBJECT_FIELDS, PATH_POINTS, STEP, EgoFmu

INPUTS: tuple[str, ...] = (
    "ego_x",
    "ego_y",
    "ego_heading",
    "ego_speed",
    "target_speed",
    "goal_distance",
    *(f"path_{axis}_{k}" for k in range(1, PATH_POINTS + 1) for axis in "xy"),
    *(f"obj_{k}_{field}" for k in range(1, MAX_OBJECTS + 1) for field, _unit, _text in OBJECT_FIELDS),
)


class Session:
    """One instance of the FMU, stepped at STEP."""

    def __init__(self, slave: Any, refs: dict[str, int]) -> None:
        self._slave = slave
        self._inputs = [refs[name] for name in INPUTS]
        self._count = [refs["obj_count"]]
        self._outputs = [refs["accel"], refs["steer"]]

    def step(self, time: float, inputs: Sequence[float], count: int) -> tuple[float, float]:
        """Set the inputs (in INPUTS order) and the object count, step, and return (accel, steer)."""
        slave = self._slave
        slave.setReal(self._inputs, list(inputs))
        slave.setInteger(self._count, [count])
        status = slave.doStep(currentCommunicationPoint=time, communicationStepSize=STEP)
        if status not in (None, 0):
            raise OracleError(f"the ego FMU failed its step at t = {time:.2f} s (fmi2Status {status})")
        accel, steer = slave.getReal(self._outputs)
        return float(accel), float(steer)


class Driver:
    """`with Driver(ego) as driver:` then `with driver.session(geometry) as s:` per test."""

    def __init__(self, ego: EgoFmu) -> None:
        self.ego = ego
        self._folder: str | None = None
        self._count = 0

    def __enter__(self) -> Driver:
        from fmpy import extract

        self._folder = tempfile.mkdtemp(prefix="sovarc-ego-")
        extract(str(self.ego.path), self._folder)
        return self

    def __exit__(self, kind: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None) -> None:
        if self._folder is not None:
            shutil.rmtree(self._folder, ignore_errors=True)
            self._folder = None

    @contextmanager
    def session(self, geometry: Geometry) -> Iterator[Session]:
        from fmpy.fmi2 import FMU2Slave

        if self._folder is None:
            raise RuntimeError("the driver is not loaded")
        self._count += 1
        slave = FMU2Slave(
            guid=self.ego.guid,
            unzipDirectory=self._folder,
            modelIdentifier=self.ego.model_identifier,
            instanceName=f"ego{self._count}",
        )
        try:
            slave.instantiate()
        except Exception as exc:  # fmpy raises a bare Exception when instantiation fails
            raise OracleError(f"cannot instantiate the ego FMU {self.ego.path.name}: {exc}") from None
        try:
            slave.setupExperiment(startTime=0.0)
            slave.enterInitializationMode()
            parameters = {
                "ego_length": geometry.length,
                "ego_width": geometry.width,
                "ego_wheelbase": geometry.wheelbase,
                "ego_rear_axle": geometry.rear_axle,
            }
            present = [(self.ego.refs[n], v) for n, v in parameters.items() if n in self.ego.refs]
            if present:
                slave.setReal([r for r, _ in present], [v for _, v in present])
            slave.exitInitializationMode()
            yield Session(slave, self.ego.refs)
            slave.terminate()
        finally:
            slave.freeInstance()
