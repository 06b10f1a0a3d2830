"""The front end's command-line options, through the real entry point: --llm, --model, --llm-base-url."""

from __future__ import annotations

from pathlib import Path

from sovarc.compiler.frontend import check_llm, default_llm, model_extra_installed

from tests.compiler.cli.test_cli import sovarc
from tests.conftest import EXAMPLES

REPORT = EXAMPLES / "reports" / "double_yellow_pass_frontal.txt"


def test_llm_values() -> None:
    assert [check_llm(v) for v in ("embedded", "none", "openai:gpt-4o")] == ["embedded", "none", "openai:gpt-4o"]
    bad = sovarc("extract", str(REPORT), "--llm", "openai:")
    assert bad.returncode == 2 and "invalid --llm 'openai:'" in bad.stderr
    assert default_llm() == ("embedded" if model_extra_installed() else "none")


def test_options_that_do_not_go_together_are_usage_errors(tmp_path: Path) -> None:
    model = sovarc("extract", str(REPORT), "--llm", "none", "--model", str(tmp_path / "m.gguf"))
    assert model.returncode == 2 and "--model PATH.gguf goes with --llm embedded" in model.stderr
    url = sovarc("extract", str(REPORT), "--llm", "embedded", "--llm-base-url", "http://127.0.0.1:9/v1")
    assert url.returncode == 2 and "--llm-base-url goes with --llm openai:MODEL" in url.stderr


def test_a_model_file_that_is_no_gguf_is_one_clear_error(tmp_path: Path) -> None:
    fake = tmp_path / "model.gguf"
    fake.write_bytes(b"not a model at all")
    result = sovarc("extract", str(REPORT), "--model", str(fake))
    assert result.returncode == 1
    assert result.stderr.strip().endswith(f"{fake} is not a GGUF model file")
    assert "Traceback" not in result.stderr


def test_an_unreachable_endpoint_is_one_clear_error(tmp_path: Path) -> None:
    out = tmp_path / "out"
    result = sovarc(
        "extract", str(REPORT), "-o", str(out), "--llm", "openai:any", "--llm-base-url", "http://127.0.0.1:9/v1"
    )
    assert (
        result.returncode == 1 and "cannot reach the OpenAI-compatible endpoint http://127.0.0.1:9/v1" in result.stderr
    )
    assert "Traceback" not in result.stderr
    assert not out.exists() or not list(out.iterdir())  # no partial files
