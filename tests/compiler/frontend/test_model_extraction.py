"""The real embedded model on two of our own example reports (slow: it loads a 1.1 GB model on the CPU).

The two reports are not among the prompt's worked examples, so the model has
not seen them. The asserts hold the facts every run must get right; the
golden files of `test_hybrid` hold one full recorded reading.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.cache import CachedProvider
from sovarc.dsl import parse, read_source, to_text, verify

from tests.conftest import EXAMPLES

REPORTS = ("double_yellow_pass_frontal", "left_turn_oncoming_pickup")


@pytest.mark.slow
def test_the_embedded_model_reads_two_of_our_reports(tmp_path: Path) -> None:
    front_end = FrontEnd("embedded", cache_dir=tmp_path / "answers")
    first: dict[str, str] = {}
    try:
        for name in REPORTS:
            report = EXAMPLES / "reports" / f"{name}.txt"
            hand = parse((EXAMPLES / "reports" / f"{name}.sov").read_text())
            got = front_end.extract(read_source(str(report), "crash report")).scenario
            assert [d for d in verify(got) if d.severity == "error"] == []
            assert got.provenance is not None and got.provenance.frontend == "embedded"
            assert str(got.provenance.model).startswith("qwen2.5-coder-1.5b-instruct-q4_k_m.gguf@sha256:")
            assert (got.environment, got.road) == (hand.environment, hand.road)
            assert [(p.id, p.role) for p in got.participants] == [(p.id, p.role) for p in hand.participants]
            assert got.crash.type == hand.crash.type
            first[name] = to_text(got)
    finally:
        front_end.close()
    provider = front_end.provider()  # a fresh provider: the rerun comes from the answer cache alone
    assert isinstance(provider, CachedProvider)
    for name in REPORTS:
        again = front_end.extract(read_source(str(EXAMPLES / "reports" / f"{name}.txt"), "crash report")).scenario
        assert to_text(again) == first[name]
    assert (provider.hits, provider.misses) == (len(REPORTS), 0)
    front_end.close()
