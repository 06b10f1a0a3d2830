"""The reference ego FMU and the town map, once per session, for the ego-test evaluation."""

from __future__ import annotations

import pytest
from sovarc.compiler.maps import RoadMap, load_map

from tests.targets.fmu.conftest import reference  # noqa: F401 - the FMU tests' session fixture
from tests.targets.fmu.plans import TOWN


@pytest.fixture(scope="session")
def town() -> RoadMap:
    return load_map(TOWN)
