"""Running an emitted scenario in esmini, the reference OpenSCENARIO player, headless.

    play(xosc_path, plan=None, esmini=None) -> Verdict     target 'openscenario:esmini'

esmini is not a Python package; it is found as $ESMINI (the binary) or `esmini` on PATH. It runs
with `--headless --fixed_timestep --collision`, logs to a file, and prints one line per new
bounding-box overlap ("Collision between A and B"), which this module reads back. The verdict
says whether the first collision is between the right pair, near the planned time.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

from sovarc.compiler.plan import Plan
from sovarc.dsl.errors import SovarcError
from sovarc.targets.openscenario import provenance as p
from sovarc.targets.openscenario.crash import first_touch_time
from sovarc.targets.openscenario.motion import single_trajectories
from sovarc.targets.openscenario.readback import read_scenario
from sovarc.targets.verdict import Finding, Verdict

TARGET = "openscenario:esmini"
ESMINI_ENV = "ESMINI"
TIMESTEP = 0.01  # s
# s between the planned impact and the player's first collision. esmini tests boxes at its own frame
# step and interpolates poses between trajectory vertices; on 393 plans on CARLA towns its first contact
# came a median 0.05 s early, 5 % of them 0.43 s or more early.
TIME_TOL = 0.5
TIMEOUT_S = 300

# esmini log lines: "4.050: Collision between V1 and V2" (older) or "[4.050] [info] Collision between V1 and V2".
_COLLISION = re.compile(
    r"^\s*\[?(?P<t>-?\d+(?:\.\d+)?)\]?:?\s*(?:\[\w+\]\s*)?Collision between (?P<a>\S+) and (?P<b>\S+)\s*$"
)


class PlayerError(SovarcError):
    """The player is missing or failed to run (not the scenario's fault)."""

    stage = "check"


@dataclass(frozen=True)
class Collision:
    time: float
    a: str
    b: str

    @property
    def pair(self) -> frozenset[str]:
        return frozenset((self.a, self.b))


def esmini_path(explicit: str | None = None) -> str:
    """The esmini binary: the one given, $ESMINI, or `esmini` on PATH."""
    for candidate in (explicit, os.environ.get(ESMINI_ENV), shutil.which("esmini")):
        if candidate and Path(candidate).is_file() and os.access(candidate, os.X_OK):
            return candidate
    raise PlayerError(
        f"esmini not found: set ${ESMINI_ENV} to the esmini binary or put it on PATH "
        "(it is not on PyPI or in Debian; build it from its source release)"
    )


def esmini_command(esmini: str, xosc: Path, log: Path, timestep: float = TIMESTEP) -> list[str]:
    return [
        esmini,
        "--headless",
        "--osc",
        str(xosc),
        "--fixed_timestep",
        f"{timestep:g}",
        "--collision",
        "--logfile_path",
        str(log),
        "--disable_stdout",
    ]


def parse_collisions(log: str) -> list[Collision]:
    """Every new collision the log reports, in order ('... dissolved' lines are not collisions)."""
    return [
        Collision(float(m["t"]), m["a"], m["b"])
        for line in log.splitlines()
        if (m := _COLLISION.match(line)) is not None
    ]


def judge_collisions(
    collisions: list[Collision], striker: str, victim: str, impact_time: float, touch: float | None = None
) -> list[Finding]:
    """The player's collisions judged against the file: the pair first collides when the file's bodies
    first touch (`touch`; the planned impact time when not given), within TIME_TOL, and no other first.
    The impact time is where the striker's bumper centre meets the victim's face; a leading corner
    touches before it, inside C_A (the OSC oracle's `first_contact`), and at a slow turn that is over
    half a second earlier: esmini's first contact 0.50-0.57 s before the impact time on T-junction turns
    was that touch, which it saw at the time the file has it."""
    pair = frozenset((striker, victim))
    first = next((c for c in collisions if c.pair == pair), None)
    earlier = [c for c in collisions if c.pair != pair and (first is None or c.time < first.time)]
    expected = impact_time if touch is None else touch
    when = f"planned at {impact_time:g} s" if touch is None else f"the file's bodies first touch at {touch:g} s"
    findings = []
    if first is None:
        findings.append(Finding("player_collision", False, f"esmini saw no collision between {striker} and {victim}"))
    elif abs(first.time - expected) > TIME_TOL:
        message = f"esmini saw {striker} and {victim} collide at t={first.time:g} s, {when}"
        findings.append(Finding("player_collision", False, message, first.time))
    else:
        said = f"planned {impact_time:g} s" if touch is None else when
        message = f"esmini saw {striker} and {victim} collide at t={first.time:g} s ({said})"
        findings.append(Finding("player_collision", True, message, first.time))
    if earlier:
        c = earlier[0]
        message = f"esmini saw {c.a} and {c.b} collide at t={c.time:g} s, before the crash"
        findings.append(Finding("player_other_collisions", False, message, c.time))
    else:
        findings.append(Finding("player_other_collisions", True, "esmini saw no other collision before the crash"))
    return findings


def play(xosc_path: str | Path, plan: Plan | None = None, esmini: str | None = None) -> Verdict:
    """Run the scenario in esmini headless and judge the collisions it reports."""
    path = Path(xosc_path)
    file = read_scenario(path)
    params = file.parameters
    striker, victim = params[p.STRIKER], params[p.VICTIM]
    impact_time = float(params[p.IMPACT_TIME])
    _, paths = single_trajectories(file)
    touch = first_touch_time(file, paths, striker, victim) if {striker, victim} <= set(paths) else None
    binary = esmini_path(esmini)
    with tempfile.TemporaryDirectory(prefix="sovarc-esmini-") as tmp:
        log = Path(tmp) / "log.txt"
        done = subprocess.run(
            esmini_command(binary, path.resolve(), log), capture_output=True, text=True, timeout=TIMEOUT_S
        )
        text = log.read_text(encoding="utf-8", errors="replace") if log.exists() else done.stdout
    scenario = plan.scenario.name if plan else params.get(p.SCENARIO, path.stem)
    site = plan.site if plan else params.get(p.SITE, "unknown")
    if done.returncode != 0:
        reason = (done.stderr.strip().splitlines() or [f"exit code {done.returncode}"])[-1]
        return Verdict(TARGET, scenario, site, (Finding("player_run", False, f"esmini failed: {reason}"),))
    collisions = parse_collisions(text)
    findings = [Finding("player_run", True, "esmini ran the scenario headless to its stop trigger")]
    findings += judge_collisions(collisions, striker, victim, impact_time, touch)
    facts = {"collisions": [[c.time, c.a, c.b] for c in collisions]}
    return Verdict(TARGET, scenario, site, tuple(findings), facts)
