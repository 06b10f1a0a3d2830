"""Run an emitted scenario folder in SUMO (libsumo) and record what happened, step by step.

The run uses the folder's own `scenario.sumocfg` options (network, types, step, collision
detection) and its FCD trajectories. It does what SUMO's fcd-replay device does for a plain
`sumo -c` run, but from Python: that device keeps static state in the SUMO library and
replays nothing in a second simulation of the same process, which the oracle needs. Every
step each participant is moved onto its recorded position (moveToXY, the FCD lane as hint);
the trace keeps each one's pose and lane, and SUMO's collisions, one record per pair
(`simulation.getCollisions()` repeats a pair every step the bodies overlap).

libsumo runs one simulation per process. `replay` runs in this process when libsumo is
free (and always closes it), and in a fresh child process when a simulation is already
loaded here or when asked (`fresh_process=True`); the child prints the trace as JSON.
"""

from __future__ import annotations

import itertools
import json
import subprocess
import sys
import tempfile
from collections.abc import Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any
from xml.etree import ElementTree

from sovarc.dsl.errors import OracleError

TIMEOUT_S = 300


@dataclass(frozen=True)
class Pose:
    """A participant as SUMO has it after a step: the front (vehicle) or body (person) position."""

    x: float
    y: float
    angle: float  # compass degrees
    lane: str  # SUMO lane id ('' when off the network)


@dataclass(frozen=True)
class Collision:
    """SUMO's collision of one pair; first and last step it was reported."""

    collider: str
    victim: str
    kind: str  # SUMO's type: 'collision', 'junction', 'frontal', 'swap', 'sharedLane', ...
    lane: str
    first: float  # s
    last: float  # s


@dataclass(frozen=True)
class Trace:
    times: tuple[float, ...]
    poses: dict[str, tuple[Pose | None, ...]]  # per participant, per step; None while not in the simulation
    collisions: tuple[Collision, ...]  # in order of first report
    sumo: str  # SUMO's version

    def to_json(self) -> dict[str, Any]:
        return {
            "times": list(self.times),
            "poses": {k: [None if p is None else asdict(p) for p in v] for k, v in self.poses.items()},
            "collisions": [asdict(c) for c in self.collisions],
            "sumo": self.sumo,
        }

    @staticmethod
    def from_json(data: dict[str, Any]) -> Trace:
        return Trace(
            tuple(data["times"]),
            {k: tuple(None if p is None else Pose(**p) for p in v) for k, v in data["poses"].items()},
            tuple(Collision(**c) for c in data["collisions"]),
            data["sumo"],
        )


def replay(config: Path, people: Sequence[str], vehicles: Sequence[str], fresh_process: bool = False) -> Trace:
    """Run `config` to its end and return the trace of the named persons and vehicles."""
    import libsumo

    if fresh_process or libsumo.simulation.isLoaded():
        return _in_child(config, people, vehicles)
    return _run(config, people, vehicles)


def _run(config: Path, people: Sequence[str], vehicles: Sequence[str]) -> Trace:
    import libsumo

    tracks = read_fcd(config.parent / _option(config, "device.fcd-replay.files"))
    with tempfile.TemporaryDirectory(prefix="sovarc-sumo-") as tmp:
        args = [*_sumo_args(config, Path(tmp)), "--no-step-log", "true", "--no-warnings", "true"]
        try:
            libsumo.start([*args, "--log", str(Path(tmp) / "sumo.log")])
        except libsumo.TraCIException as exc:
            raise OracleError(f"SUMO cannot run {config}: {_log_tail(Path(tmp) / 'sumo.log') or exc}") from None
        try:
            return _drive(libsumo, tracks, people, vehicles)
        except (libsumo.TraCIException, libsumo.libsumo.FatalTraCIError) as exc:
            raise OracleError(f"SUMO failed while replaying {config}: {exc}") from None
        finally:
            libsumo.close()


def _option(config: Path, key: str) -> str:
    found = ElementTree.parse(config).getroot().find(f"./*/{key}")
    if found is None:
        raise OracleError(f"{config} has no {key} option: not a folder made by the SUMO target")
    return found.get("value", "")


def _sumo_args(config: Path, scratch: Path) -> list[str]:
    """The configuration's options as a command line, minus the replay device (this module drives),
    with file names made absolute and SUMO's outputs sent to `scratch`."""
    args = ["sumo"]
    for section in ElementTree.parse(config).getroot():
        for option in section:
            key, value = option.tag, option.get("value", "")
            if key.startswith("device.fcd-replay."):
                continue
            if key in {"net-file", "additional-files", "route-files"}:
                value = ",".join(str((config.parent / v).resolve()) for v in value.split(","))
            elif key.endswith("-output"):
                value = str(scratch / Path(value).name)
            args += [f"--{key}", value]
    return args


@dataclass(frozen=True)
class Entry:
    """One participant at one FCD timestep."""

    time: float
    x: float
    y: float
    angle: float
    speed: float
    where: str  # lane id (vehicle) or edge id (person)
    pos: float
    type: str


def read_fcd(path: Path) -> dict[str, list[Entry]]:
    tracks: dict[str, list[Entry]] = {}
    for step in ElementTree.parse(path).getroot():
        time = float(step.get("time", "0"))
        for row in step:
            where = row.get("lane") if row.tag == "vehicle" else row.get("edge")
            entry = Entry(
                time,
                float(row.get("x", "0")),
                float(row.get("y", "0")),
                float(row.get("angle", "0")),
                float(row.get("speed", "0")),
                where or "",
                float(row.get("pos", "0")),
                row.get("type", ""),
            )
            tracks.setdefault(row.get("id", ""), []).append(entry)
    return tracks


def _edge(lane: str) -> str:
    return lane.rsplit("_", 1)[0]


def _drivable(libsumo: Any, edge: str, vclass: str) -> bool:
    for i in range(libsumo.edge.getLaneNumber(edge)):
        allowed, banned = libsumo.lane.getAllowed(f"{edge}_{i}"), libsumo.lane.getDisallowed(f"{edge}_{i}")
        if (not allowed or vclass in allowed) and vclass not in banned:
            return True
    return False


def _connected(libsumo: Any, edges: Sequence[str]) -> bool:
    """Whether each edge leads into the next through some lane's connection."""
    for a, b in itertools.pairwise(edges):
        lanes = (f"{a}_{i}" for i in range(libsumo.edge.getLaneNumber(a)))
        if not any(_edge(link[0]) == b for lane in lanes for link in libsumo.lane.getLinks(lane)):
            return False
    return True


def _depart_lane(libsumo: Any, where: str, edges: Sequence[str]) -> str:
    """The lane index to insert on: the first sample's, when the route's first edge has it
    (a trajectory that starts inside a junction does not); moveToXY places it exactly anyway."""
    index = where.rsplit("_", 1)[1]
    first_edge = edges[0] if edges else _edge(where)
    if where.startswith(":") or _edge(where) != first_edge:
        return "0"
    return index if int(index) < libsumo.edge.getLaneNumber(first_edge) else "0"


def _drive(libsumo: Any, tracks: dict[str, list[Entry]], people: Sequence[str], vehicles: Sequence[str]) -> Trace:
    """Add every participant at t = 0 and move it onto its FCD position every step (moveToXY with
    the lane as a hint, keepRoute=2: exact position), as SUMO's fcd-replay device does."""
    end = libsumo.simulation.getEndTime()
    step = libsumo.simulation.getDeltaT()
    for v in vehicles:
        first = tracks[v][0]
        edges = list(dict.fromkeys(_edge(e.where) for e in tracks[v] if not e.where.startswith(":")))
        vclass = libsumo.vehicletype.getVehicleClass(first.type)
        while len(edges) > 1 and not _drivable(libsumo, edges[0], vclass):
            edges.pop(0)  # it starts off the road (a driveway over a footway): insert it where it can drive
        lane = _depart_lane(libsumo, first.where, edges)
        if not _connected(libsumo, edges):
            edges = edges[:1]  # e.g. a wrong-way stretch: SUMO would refuse the route at insertion
        try:
            libsumo.route.add(f"{v}.replay", edges or [_edge(first.where)])
            libsumo.vehicle.add(v, f"{v}.replay", typeID=first.type, depart="0", departLane=lane, departSpeed="0")
        except libsumo.TraCIException:  # edges SUMO cannot route along: moveToXY (keepRoute=2) re-routes anyway
            libsumo.route.add(f"{v}.start", edges[:1] or [_edge(first.where)])
            libsumo.vehicle.add(v, f"{v}.start", typeID=first.type, depart="0", departLane="first", departSpeed="0")
        libsumo.vehicle.setSpeedMode(v, 0)
    for p in people:
        first = tracks[p][0]
        edges = list(dict.fromkeys(e.where for e in tracks[p]))
        libsumo.person.add(p, first.where, first.pos, depart=0.0, typeID=first.type)
        try:
            libsumo.person.appendWalkingStage(p, edges, -1)
        except libsumo.TraCIException:  # not a walkable route: moveToXY places the person anyway
            libsumo.person.appendWalkingStage(p, [first.where], -1)
    version = libsumo.getVersion()[1]
    times: list[float] = []
    poses: dict[str, list[Pose | None]] = {p: [] for p in (*vehicles, *people)}
    seen: dict[frozenset[str], Collision] = {}
    k = 0
    while True:
        now = round(libsumo.simulation.getTime(), 6)
        if now > end - step / 2:
            break
        for v in vehicles:
            if k < len(tracks[v]) and tracks[v][k].time <= now + 1e-9:
                e = tracks[v][k]
                lane_edge, index = _edge(e.where), int(e.where.rsplit("_", 1)[1])
                libsumo.vehicle.moveToXY(v, lane_edge, index, e.x, e.y, e.angle, 2)
                libsumo.vehicle.setSpeed(v, e.speed)
        for p in people:
            if k < len(tracks[p]) and tracks[p][k].time <= now + 1e-9:
                e = tracks[p][k]
                libsumo.person.moveToXY(p, e.where, e.x, e.y, e.angle, 2)
        libsumo.simulationStep()
        k += 1
        times.append(now)
        present_vehicles = set(libsumo.vehicle.getIDList())
        present_people = set(libsumo.person.getIDList())
        for v in vehicles:
            poses[v].append(_pose(libsumo.vehicle, v) if v in present_vehicles else None)
        for p in people:
            poses[p].append(_pose(libsumo.person, p) if p in present_people else None)
        for c in libsumo.simulation.getCollisions():
            key = frozenset((c.collider, c.victim))
            old = seen.get(key)
            first_time = now if old is None else old.first
            seen[key] = Collision(c.collider, c.victim, c.type, c.lane, first_time, now)
    return Trace(tuple(times), {k: tuple(v) for k, v in poses.items()}, tuple(seen.values()), version)


def _pose(domain: Any, ident: str) -> Pose:
    x, y = domain.getPosition(ident)
    return Pose(round(x, 4), round(y, 4), round(domain.getAngle(ident) % 360.0, 4), domain.getLaneID(ident))


def _log_tail(log: Path) -> str:
    if not log.exists():
        return ""
    lines = [line for line in log.read_text(encoding="utf-8", errors="replace").splitlines() if line.strip()]
    errors = [line for line in lines if line.startswith("Error")]
    return (errors or lines or [""])[-1]


def _in_child(config: Path, people: Sequence[str], vehicles: Sequence[str]) -> Trace:
    args = [sys.executable, "-m", "sovarc.targets.sumo.replay", str(config), ",".join(people), ",".join(vehicles)]
    try:
        done = subprocess.run(args, capture_output=True, text=True, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        raise OracleError(f"the SUMO replay of {config} did not finish within {TIMEOUT_S} s") from None
    if done.returncode != 0:
        raise OracleError(done.stderr.strip().splitlines()[-1] if done.stderr.strip() else f"replay of {config} failed")
    return Trace.from_json(json.loads(done.stdout))


def _split(text: str) -> list[str]:
    return [part for part in text.split(",") if part]


def main(argv: Sequence[str]) -> int:
    """`python -m sovarc.targets.sumo.replay CONFIG PEOPLE VEHICLES`: the trace as JSON on stdout."""
    config, people, vehicles = argv
    try:
        trace = _run(Path(config), _split(people), _split(vehicles))
    except OracleError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    print(json.dumps(trace.to_json(), separators=(",", ":")))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
