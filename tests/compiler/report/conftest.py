"""One small run for the report's tests: the bundled left-turn scenario on two sites of the town, SUMO."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.compiler.cli.test_cli import sovarc
from tests.conftest import EXAMPLES

SCENARIO = EXAMPLES / "scenarios" / "intersection_left_turn_across_path_side.sov"


@pytest.fixture(scope="session")
def run_out(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("report") / "out"
    result = sovarc(str(SCENARIO), "-t", "sumo", "--roads", "2", "-o", str(out))
    assert result.returncode == 0, result.stderr
    return out
