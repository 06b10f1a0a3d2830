"""The OpenSCENARIO target: a plan as an ASAM OpenSCENARIO XML scenario with its OpenDRIVE road network.

emit(plan, out_dir, version="1.3") -> Path     writes scenario.xosc and the .xodr beside it; returns the .xosc
emit_files(plan, out_dir, ...) -> Emitted      the same, with the notes on what the format cannot say
check(xosc_path, plan=None) -> Verdict         the oracle: XSD validation and a kinematic re-check of the file
play(xosc_path, plan=None) -> Verdict          runs it in esmini headless ($ESMINI or PATH), judges the collision
"""

from sovarc.targets.openscenario.emit import SCENARIO_FILE, Emitted, choose_ego, emit, emit_files
from sovarc.targets.openscenario.oracle import check
from sovarc.targets.openscenario.player import play
from sovarc.targets.openscenario.versions import DEFAULT_VERSION, VERSIONS

__all__ = [
    "DEFAULT_VERSION",
    "SCENARIO_FILE",
    "VERSIONS",
    "Emitted",
    "check",
    "choose_ego",
    "emit",
    "emit_files",
    "play",
]
