"""`--stop-after STAGE` and `--dump-ir-after STAGE` work for every stage of the pipeline alike, each
printing that stage's printable form."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.compiler.pipeline import PIPELINE, STAGE_NAMES, Options, run_pipeline
from sovarc.dsl.span import Source

from tests.compiler.cli.test_cli import sovarc
from tests.conftest import EXAMPLES

STOPPED_TRAFFIC = EXAMPLES / "scenarios" / "straight_rear_end_stopped_traffic.sov"
PER_SITE = {s.name for s in PIPELINE if s.per_site}
# the per-site stages lower and synthesize on the bundled town
STAGES = [pytest.param(n, marks=pytest.mark.slow) if n in PER_SITE else n for n in STAGE_NAMES]


@pytest.fixture(scope="module")
def printed(tmp_path_factory: pytest.TempPathFactory) -> dict[str, str]:
    """Each stage's printable form, from one run of the whole pipeline in this process."""
    source = Source(str(STOPPED_TRAFFIC), STOPPED_TRAFFIC.read_text(encoding="utf-8"))
    options = Options(out_dir=tmp_path_factory.mktemp("out"))
    _, log = run_pipeline(source, start="read", options=options)
    return {stage.name: stage.render(log.outputs[stage.name]) for stage in PIPELINE}


@pytest.mark.parametrize("stage", STAGES)
def test_stop_after_prints_the_stage_s_printable_form(stage: str, printed: dict[str, str], tmp_path: Path) -> None:
    result = sovarc(str(STOPPED_TRAFFIC), "--stop-after", stage, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout == printed[stage]
    assert printed[stage].strip()
    written = (tmp_path / "sovarc-out").exists()
    assert written == (stage in ("emit", "check"))  # only emit and check write the sites' folders


@pytest.mark.parametrize("stage", STAGES)
def test_dump_ir_after_prints_the_stage_s_printable_form(stage: str, printed: dict[str, str], tmp_path: Path) -> None:
    result = sovarc(str(STOPPED_TRAFFIC), f"--dump-ir-after={stage}", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith(f"// ----- IR after {stage} -----\n{printed[stage]}")
    assert result.stdout.count("// ----- IR after") == 1


def test_the_printable_forms_say_what_each_stage_made(printed: dict[str, str]) -> None:
    assert printed["read"] == printed["verify"] == STOPPED_TRAFFIC.read_text(encoding="utf-8")
    assert printed["assume"].endswith("}\n") and "scenario straight_rear_end_stopped_traffic" in printed["assume"]
    assert printed["sites"].startswith("# ") and " slot\n" in printed["sites"]
    assert printed["stage"].startswith("// ----- plan on ")
    assert printed["emit"].split("\n")[0].split() == ["site", "impact"]
    assert printed["check"] == printed["emit"]  # no target asked for: nothing to check
