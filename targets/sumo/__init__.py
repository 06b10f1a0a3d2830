"""The SUMO target: emit a plan as a scenario folder that `sumo -c` replays, and check it in SUMO.

cfg = emit(plan, "out/site1")        # -> out/site1/scenario.sumocfg
verdict = check(plan, "out/site1")   # replays it through libsumo; check(plan) emits to a temp folder
"""

from sovarc.targets.sumo.check import check
from sovarc.targets.sumo.emit import emit

__all__ = ["check", "emit"]
