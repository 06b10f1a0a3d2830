"""An oracle's verdict, the same shape for every target: pass or fail, with reasons and times."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any

# Degrees between the headings at first touch that each crash type allows, for every oracle.
# Frontal is front into front with the two approaching each other: head-on, or a car turning
# across an oncoming one (crash databases, and the ground truth, code that front-to-front). A
# front corner touching a crossing car at right angles is not frontal: that is a side crash.
CRASH_ANGLES: dict[str, tuple[float, float]] = {
    "rear_end": (0.0, 45.0),
    "frontal": (100.0, 180.0),
    "side": (0.0, 180.0),
}
# m a body may reach over a lane line before it counts as crossing it: the SUMO oracle's bound,
# which lowering (compiler/lower/swing.py) plans inside.
LINE_TOLERANCE = 0.25


@dataclass(frozen=True)
class Finding:
    """One thing an oracle checked."""

    check: str  # short name: 'collision', 'pair', 'impact_angle', 'lane_lines', 'xsd', ...
    passed: bool
    message: str  # one sentence a person can act on
    time: float | None = None  # s of simulated time the finding refers to, if any


@dataclass(frozen=True)
class Verdict:
    target: str  # 'sumo', 'openscenario', 'fmu'
    scenario: str
    site: str
    findings: tuple[Finding, ...]
    facts: dict[str, Any] = field(default_factory=dict)  # measured values: collision time, angle, ...

    @property
    def passed(self) -> bool:
        return all(f.passed for f in self.findings)

    @property
    def failures(self) -> tuple[Finding, ...]:
        return tuple(f for f in self.findings if not f.passed)

    def to_json(self) -> dict[str, Any]:
        return {
            "target": self.target,
            "scenario": self.scenario,
            "site": self.site,
            "passed": self.passed,
            "findings": [
                {"check": f.check, "passed": f.passed, "message": f.message, "time": f.time} for f in self.findings
            ],
            "facts": self.facts,
        }

    def dumps(self) -> str:
        return json.dumps(self.to_json(), indent=2, sort_keys=False, ensure_ascii=False) + "\n"
