"""The SUMO target: emit a plan as a scenario folder that `sumo -c` replays, and check it in SUMO."""

from sovarc.targets.sumo.emit import emit

__all__ = ["emit"]
