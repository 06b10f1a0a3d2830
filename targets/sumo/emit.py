"""Write a plan as a self-contained SUMO scenario folder that plain `sumo -c` replays.

    out_dir/
      <map>.net.xml      the road network the plan was planned on (for an OpenDRIVE map, the
                         conversion its plan carries); a big map is cropped to the roads around
                         the trajectories (crop.py)
      scenario.add.xml   a vType per participant, of its real size; each vehicle's route;
                         a POI on the collision area with weather, lighting and crash facts
      scenario.fcd.xml   the trajectories, one <timestep> per plan step
      scenario.sumocfg   step length = plan.step, collision detection on (junctions too)

What needs a driver and what does not:
- Nothing, to see the crash. The trajectories are replayed by SUMO's own `fcd-replay`
  device (as in the SUMO the project installs, 1.28): the configuration names the FCD file,
  SUMO builds each participant from it and moves it onto its recorded position every step
  (moveToXY with the recorded lane). `sumo -c scenario.sumocfg` (or `sumo-gui -c ...`)
  shows the crash and writes it to `collisions.xml`, with no TraCI script at all.
- The oracle (`check`) replays from Python instead (replay.py): same options, same FCD
  trajectories, moveToXY each step through libsumo. The device keeps static state in the
  SUMO library, so a second simulation in one process would replay nothing; the tests
  check that both replays see the same collision.

The same plan and map give the same bytes.
"""

from __future__ import annotations

import hashlib
import os
import re
from pathlib import Path

from sovarc.compiler.plan import Plan
from sovarc.dsl.errors import Diagnostic, InputError, UnsupportedError
from sovarc.dsl.span import Span
from sovarc.targets.sumo import documents
from sovarc.targets.sumo.crop import Box, crop, needs_crop
from sovarc.targets.sumo.network import Network, Spot, read_network

_NETCONVERT_HEADER = re.compile(rb"<!--\s*generated on.*?-->\s*", re.DOTALL)


def emit(plan: Plan, out_dir: str | os.PathLike[str]) -> Path:
    """Write the scenario folder for `plan` into `out_dir` (created if needed); returns the .sumocfg."""
    return emit_files(plan, out_dir)[0]


def emit_files(plan: Plan, out_dir: str | os.PathLike[str]) -> tuple[Path, ...]:
    """Write the scenario folder; returns the files written, the .sumocfg first."""
    _check_sampling(plan)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    net_file = copy_network(plan, out)
    network = read_network(net_file)
    spots = {t.participant: track(plan, t.participant, network) for t in plan.trajectories}
    files = {
        documents.ADDITIONAL: documents.additional(plan, net_file.name),
        documents.FCD: documents.fcd(plan, spots, network),
        documents.CONFIG: documents.config(plan, net_file.name),
    }
    for name, text in files.items():
        (out / name).write_text(text, encoding="utf-8", newline="\n")
    return (out / documents.CONFIG, out / documents.ADDITIONAL, out / documents.FCD, net_file)


def _check_sampling(plan: Plan) -> None:
    """Every trajectory sampled at the same times, from 0 at the plan's step (the plan's contract)."""
    if not plan.trajectories:
        raise UnsupportedError(f"plan of {plan.scenario.name} on {plan.site} has no trajectories")
    times = [s.t for s in plan.trajectories[0].samples]
    for t in plan.trajectories:
        mine = [s.t for s in t.samples]
        if len(mine) != len(times) or any(abs(a - b) > 1e-6 for a, b in zip(mine, times, strict=True)):
            first = plan.trajectories[0].participant
            raise UnsupportedError(f"{t.participant} is not sampled at the same times as {first}")
    if any(abs(t - k * plan.step) > 1e-6 for k, t in enumerate(times)):
        raise UnsupportedError(f"samples are not {plan.step} s apart from t = 0")


def copy_network(plan: Plan, out: Path) -> Path:
    """The plan's SUMO network in `out`, named after its map; the map must be the one the plan was made on."""
    source = Path(plan.map)
    if not source.is_file():
        raise InputError(Diagnostic("map file not found", Span.whole_file(plan.map)))
    if hashlib.sha256(source.read_bytes()).hexdigest() != plan.map_sha256:
        message = "map file changed since the plan was made (its sha256 differs); plan again on this map"
        raise InputError(Diagnostic(message, Span.whole_file(plan.map)))
    name = source.name
    if name.lower().endswith(".net.xml"):
        target = out / name
    elif name.lower().endswith(".xodr"):
        target = out / (name[: -len(".xodr")] + ".net.xml")
    else:
        raise InputError(Diagnostic("the SUMO target needs a .net.xml or .xodr map", Span.whole_file(plan.map)))
    network = Path(plan.network.sumo)
    if not network.is_file():
        message = f"the SUMO network the plan was made on is gone ({network}); plan again on this map"
        raise InputError(Diagnostic(message, Span.whole_file(plan.map)))
    data = network.read_bytes()
    if network != source:
        # a conversion: netconvert's header names the date and its paths; dropped for byte-stable output
        data = _NETCONVERT_HEADER.sub(b"", data, count=1)
    if needs_crop(data):
        box = Box.around([(s.x, s.y) for t in plan.trajectories for s in t.samples])
        data = crop(data, box, frozenset(e for t in plan.trajectories for e in t.edges))
    if not target.exists() or target.read_bytes() != data:
        target.write_bytes(data)
    return target


def track(plan: Plan, participant: str, network: Network) -> list[Spot]:
    """The lane (and place on it) of each of a participant's samples, for SUMO's replay.

    A vehicle never starts on a junction lane (SUMO cannot route from one): it starts at the
    end of the lane leading into it, and is moved onto its recorded position at the next step.
    """
    t = plan.trajectory(participant)
    prefer = frozenset(t.lanes)
    pedestrian = documents.is_person(t)
    spots: list[Spot] = []
    for s in t.samples:
        try:
            spots.append(network.locate(s.x, s.y, s.heading, prefer, pedestrian))
        except ValueError as exc:
            raise UnsupportedError(f"{participant} at t={s.t:.2f} s is off the road network: {exc}") from None
    first = spots[0]
    if first.lane.internal and not pedestrian:
        before = network.previous_normal_lane(first.lane)
        if before is not None:
            spots[0] = Spot(before, before.length, 0.0, first.heading)
    return spots
