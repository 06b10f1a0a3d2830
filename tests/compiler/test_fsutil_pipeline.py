"""Atomic writes and the stage runner."""

from __future__ import annotations

import itertools
import os
from pathlib import Path

import pytest
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.pipeline import PIPELINE, PipelineError, SiteJob, Sites, entry_stage, run_pipeline
from sovarc.dsl import Scenario, VerifyError
from sovarc.dsl.span import Source

from tests.conftest import EXAMPLES

LEFT_TURN = EXAMPLES / "scenarios" / "intersection_left_turn_across_path_side.sov"


def test_write_atomic_replaces_whole_files(tmp_path: Path) -> None:
    target = tmp_path / "deep" / "out.txt"
    write_atomic(target, "one")
    write_atomic(target, b"two")
    assert target.read_text() == "two"
    assert os.listdir(target.parent) == ["out.txt"]


def test_write_atomic_leaves_nothing_behind_on_failure(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    target = tmp_path / "out.txt"
    target.write_text("old")

    def broken_replace(src: str, dst: str) -> None:
        raise OSError("disk full")

    monkeypatch.setattr(os, "replace", broken_replace)
    with pytest.raises(OSError, match="disk full"):
        write_atomic(target, "new")
    assert target.read_text() == "old"
    assert os.listdir(tmp_path) == ["out.txt"]


def test_stages_are_an_ordered_tuple_with_typed_ends() -> None:
    assert [s.name for s in PIPELINE] == ["read", "verify", "assume", "sites", "stage", "emit", "check"]
    assert [s.name for s in PIPELINE if s.per_site] == ["stage", "emit", "check"]
    for before, after in itertools.pairwise(PIPELINE):
        if after.per_site and not before.per_site:  # the site-filling wrapper: one SiteJob per candidate site
            assert (before.produces, after.consumes) == (Sites, SiteJob)
        else:
            assert before.produces is after.consumes


def test_run_pipeline_reports_each_stage() -> None:
    seen: list[str] = []
    source = Source(str(LEFT_TURN), LEFT_TURN.read_text())
    result, log = run_pipeline(
        source, start="read", stop="verify", after_stage=lambda stage, value: seen.append(stage.name)
    )
    assert isinstance(result, Scenario) and seen == ["read", "verify"]
    assert set(log.outputs) == {"read", "verify"} and log.warnings == []


def test_stop_after_and_verification() -> None:
    source = Source("bad.sov", LEFT_TURN.read_text().replace("lane 2", "lane 7", 1))
    parsed, _ = run_pipeline(source, start="read", stop="read")
    assert parsed.participants[0].lane == 7
    with pytest.raises(VerifyError, match="V1 starts in lane 7"):
        run_pipeline(source, start="read", stop="verify")


def test_bad_stage_names_and_inputs() -> None:
    with pytest.raises(PipelineError, match="no stage named 'lower'"):
        run_pipeline(None, start="lower")
    with pytest.raises(PipelineError, match="comes before"):
        run_pipeline(None, start="verify", stop="read")
    with pytest.raises(PipelineError, match=r"unknown input kind '\.pdf'"):
        entry_stage("report.pdf")
    assert entry_stage("a.sov") == "read"
