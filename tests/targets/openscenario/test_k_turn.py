"""A three-point turn as OpenSCENARIO: each reference point placed from the heading the body faces,
valid against the schema and ASAM's checker, and the re-check finds the planned crash."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.targets.openscenario import check

from tests.compiler.synth.street import k_turn_plan
from tests.targets.openscenario.plans import emit_files

pytestmark = pytest.mark.slow


def test_the_turn_passes_the_oracle(tmp_path: Path) -> None:
    plan = k_turn_plan()
    files = emit_files(plan, tmp_path)
    verdict = check(files.xosc, plan)
    assert verdict.passed, verdict.dumps()
    checks = {f.check for f in verdict.findings}
    assert {"xsd", "asam_qc", "xodr", "speed", "acceleration", "first_contact", "impact_faces"} <= checks
    assert verdict.facts["striker"] == "V2" and "left" in verdict.facts["victim_face"]
