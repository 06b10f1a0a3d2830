"""The reference ego FMU, built (or taken from the user cache) once per test session."""

from __future__ import annotations

import pytest
from sovarc.targets.fmu import EgoFmu, reference_fmu, validate_fmu


@pytest.fixture(scope="session")
def reference() -> EgoFmu:
    return validate_fmu(reference_fmu())
