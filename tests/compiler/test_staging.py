"""The stage stage on one site: stagings tried in lowering's order, the first plan synthesis passes kept."""

from __future__ import annotations

import pytest
from sovarc.compiler import staging, synth
from sovarc.dsl.errors import Diagnostic, SynthesisError, UnsatError


def _stagings(*names: str):
    def stagings_on(*_: object) -> object:
        yield from names

    return stagings_on


def test_a_refused_staging_gives_way_to_the_next(monkeypatch: pytest.MonkeyPatch) -> None:
    tried: list[str] = []

    def refuse_first(lowered: str, **_: object) -> str:
        tried.append(lowered)
        if lowered == "first":
            raise SynthesisError(Diagnostic("first refused"))
        return f"plan of {lowered}"

    monkeypatch.setattr(synth, "synthesize", refuse_first)
    monkeypatch.setattr(staging, "stagings_on", _stagings("first", "second", "third"))
    assert staging.stage_on_site(None, [], None, None) == "plan of second"  # type: ignore[arg-type]
    assert tried == ["first", "second"]  # made only when asked for: the third never is
    monkeypatch.setattr(staging, "stagings_on", _stagings("first"))
    with pytest.raises(SynthesisError, match="first refused"):
        staging.stage_on_site(None, [], None, None)  # type: ignore[arg-type]


def test_no_staging_at_all_is_lowering_s_error(monkeypatch: pytest.MonkeyPatch) -> None:
    def unsat(*_: object) -> object:
        raise UnsatError(Diagnostic("these facts conflict"))
        yield  # a generator, as lowering's is

    monkeypatch.setattr(staging, "stagings_on", unsat)
    with pytest.raises(UnsatError, match="these facts conflict"):
        staging.stage_on_site(None, [], None, None)  # type: ignore[arg-type]
