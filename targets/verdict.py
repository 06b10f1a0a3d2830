"""An oracle's verdict, the same shape for every target: pass or fail, with reasons and times."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any

# The crash definitions every oracle judges by (angles, faces, lane-line tolerance) are
# compiler/crashes.py's.


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
