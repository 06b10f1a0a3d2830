"""Fixtures: the hand-made plans, emitted once per session and version."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.compiler.plan import Plan
from sovarc.targets.openscenario import Emitted

from tests.targets.openscenario.plans import CASES, emit_files

FIXTURES = Path(__file__).resolve().parent / "fixtures"


class Emitter:
    """Emits each (case, version) once per test session into its own folder."""

    def __init__(self, root: Path) -> None:
        self.root = root
        self.done: dict[tuple[str, str], tuple[Plan, Emitted]] = {}

    def __call__(self, case: str, version: str = "1.3") -> tuple[Plan, Emitted]:
        key = (case, version)
        if key not in self.done:
            plan = CASES[case]()
            self.done[key] = (plan, emit_files(plan, self.root / case / version, version))
        return self.done[key]


@pytest.fixture(scope="session")
def emitted(tmp_path_factory: pytest.TempPathFactory) -> Emitter:
    return Emitter(tmp_path_factory.mktemp("osc"))
