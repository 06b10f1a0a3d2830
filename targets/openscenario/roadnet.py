"""The road network beside the scenario, as OpenDRIVE.

The plan carries its network's OpenDRIVE file (`plan.network.opendrive`): the user's `.xodr`, or
for a SUMO map the conversion the compiler made before this target ran (compiler/maps/networks.py,
which says how netconvert's output is made byte-stable, valid OpenDRIVE 1.4). It is copied byte
for byte, named after the map: `town.net.xml` travels as `town.xodr`.
"""

from __future__ import annotations

from pathlib import Path

from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.plan import Network
from sovarc.dsl.errors import Diagnostic, InputError, UnsupportedError
from sovarc.dsl.span import Span


def xodr_name(map_path: Path) -> str:
    name = map_path.name
    if name.lower().endswith(".net.xml"):
        return name[: -len(".net.xml")] + ".xodr"
    return name


def write_road_network(network: Network, out_dir: Path) -> Path:
    """Write the network's .xodr into out_dir, named after its map, and return its path."""
    source = Path(network.map)
    if not source.name.lower().endswith((".net.xml", ".xodr")):
        raise InputError(
            Diagnostic("not a road network: expected a .net.xml or .xodr file", Span.whole_file(str(source)))
        )
    if network.opendrive is None:
        raise UnsupportedError(
            f"the plan on {source.name} carries no OpenDRIVE file: the compiler provides it before this target "
            "runs (sovarc.compiler.maps.with_opendrive)"
        )
    target = out_dir / xodr_name(source)
    data = _read(Path(network.opendrive))
    if not (target.exists() and target.read_bytes() == data):
        write_atomic(target, data)
    return target


def _read(source: Path) -> bytes:
    try:
        return source.read_bytes()
    except OSError as e:
        raise InputError(Diagnostic(f"cannot read the map: {e.strerror}", Span.whole_file(str(source)))) from None
