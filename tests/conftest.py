"""Shared test helpers: project paths, the shared corpus and golden files.

Regenerate every golden file with `pytest --update-goldens`, then review the
diff like code.

Tests that read the shared corpus (NMVCCS reports and truth, OpenDRIVE maps) find it
through one variable, SOVARC_SHARED (default: `../shared` beside the checkout), and are
marked `requires_shared`: without the corpus they skip with a one-line reason.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
SHARED = Path(os.environ.get("SOVARC_SHARED") or ROOT.parent / "shared")
requires_shared = pytest.mark.skipif(
    not (SHARED / "data").is_dir(), reason=f"needs the shared corpus: set SOVARC_SHARED (no data under {SHARED})"
)


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--update-goldens", action="store_true", help="rewrite golden files from current output")


class Golden:
    def __init__(self, update: bool) -> None:
        self.update = update

    def check(self, path: Path, actual: str) -> None:
        """Compare `actual` with the golden file at `path` (or rewrite it under --update-goldens)."""
        if self.update:
            path.write_text(actual, encoding="utf-8")
            return
        assert path.exists(), f"missing golden file {path}; run pytest --update-goldens"
        expected = path.read_text(encoding="utf-8")
        assert actual == expected, f"output differs from golden {path.name}"


@pytest.fixture
def golden(request: pytest.FixtureRequest) -> Golden:
    return Golden(request.config.getoption("--update-goldens"))
