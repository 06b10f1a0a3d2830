"""The reference ego FMU: built with pythonfmu into a cache, once, and valid against the interface."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.targets.fmu import reference_fmu, validate_fmu
from sovarc.targets.fmu.interface import VARIABLES

pytestmark = pytest.mark.slow  # runs pythonfmu's build


def test_built_once_into_the_cache_and_reused(tmp_path: Path) -> None:
    built = reference_fmu(cache_dir=tmp_path)
    assert built.parent == tmp_path and built.name.startswith("SovarcEgo-") and built.suffix == ".fmu"
    stamp = built.stat().st_mtime_ns
    assert reference_fmu(cache_dir=tmp_path) == built
    assert built.stat().st_mtime_ns == stamp  # not rebuilt
    assert [p.name for p in tmp_path.iterdir()] == [built.name]  # no partial files left behind
    ego = validate_fmu(built)
    assert set(ego.refs) == {v.name for v in VARIABLES}  # the optional parameters too
