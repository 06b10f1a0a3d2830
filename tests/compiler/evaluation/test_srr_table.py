"""How `sovarc eval srr` sorts planning failures (srr.PLANNING) and prints the SRR without the scenarios
whose record contradicts itself; the benchmark reads the same classes."""

from __future__ import annotations

from pathlib import Path

from sovarc.compiler.evaluation.srr import (
    CONTRADICTS,
    NO_SHAPE,
    PLANNING,
    _row,
    contradicting,
    first_reasons,
    planning_class,
    planning_split,
    reconstruct,
    srr_table,
)

from tests.compiler.lower.staging import town
from tests.compiler.lower.test_consistency import _pair

# What lower/consistency.py says of a record that contradicts itself (its whole message is tested there).
MIXED = "rear_end needs V1's front into V2's rear, ...: never its rear: no road can stage it"


def _rows(scenario: str, kind: str, *outcomes: tuple[str | None, str]) -> list[dict]:
    return [
        _row(Path(f"{scenario}.sov"), kind, f"s{k}", failure, reason) for k, (failure, reason) in enumerate(outcomes)
    ]


def test_each_planning_reason_has_its_class_and_follow_up_rows_take_the_first_rows() -> None:
    said = {
        "the map has no straight roads": "map lacks the kind",
        "fewer fitting sites than asked": "no site fits",
        MIXED: CONTRADICTS,
        "the site fits only clamped: V2 needs 2 lanes": "site fits only clamped",
        "on road:a, V1 cannot strike V2 as a side crash needs: their paths never meet": "site cannot host it",
    }
    for reason, name in said.items():
        assert planning_class(_row(Path("x.sov"), "straight", "-", "planning failed", reason), {}) == name
    assert set(said.values()) == {name for name, _ in PLANNING}
    rows = _rows("a", "straight", ("planning failed", MIXED), ("planning failed", "no site"))
    assert [planning_class(r, first_reasons(rows)) for r in rows] == [CONTRADICTS, CONTRADICTS]
    assert planning_split(rows) == {CONTRADICTS: 2}


def test_a_record_that_contradicts_itself_is_found_whatever_class_its_rows_were_given() -> None:
    rows = _rows("mixed", "straight", ("planning failed", MIXED), ("planning failed", "no site"))
    # a map short of sites of its shape: the row keeps the reason in brackets
    rows += _rows("short", "straight", (NO_SHAPE, f"the map has no site of the shape this scenario needs: ({MIXED})"))
    rows += _rows("host", "straight", ("planning failed", "cannot strike"), (None, ""))
    assert contradicting(rows) == {"mixed", "short"}
    assert contradicting(_rows("fine", "straight", (None, MIXED))) == set()  # a passed row says nothing


def test_the_table_splits_planning_failures_and_gives_the_srr_without_contradicting_records() -> None:
    rows = _rows("straight_13", "straight", *[("planning failed", MIXED)] + [("planning failed", "no site")] * 2)
    rows += _rows("straight_1", "straight", (None, ""), (None, ""), ("planning failed", "cannot strike V2"))
    rows += _rows("crossing_1", "intersection", (None, ""), (None, ""), (NO_SHAPE, "the map has no site of"))
    table = srr_table("m", rows).splitlines()
    assert table[2:] == [
        "  road kind          SRR  n             SRR  n             SRR  n",
        "  intersection     66.7%  2/3        100.0%  2/2        100.0%  2/2",
        "  straight         33.3%  2/6         33.3%  2/6         66.7%  2/3",
        "  all              44.4%  4/9         50.0%  4/8         80.0%  4/5",
        "  failures: planning failed 4, crash type mismatch 0, line crossing 0, replay error 0, no site of its shape 1",
        "  planning failed: map lacks the kind 0, no site fits 0, record contradicts itself 3, "
        "site fits only clamped 0, site cannot host it 1",
        "  records that contradict themselves: straight_13",
    ]
    assert "less the scenarios whose record contradicts itself" in table[1]
    clean = srr_table("m", rows[3:6])
    assert "planning failed: " in clean and "contradict themselves:" not in clean
    assert "planning failed:" not in srr_table("m", rows[6:8])  # no planning failure, no split


def test_the_consistency_refusal_is_a_contradicting_record_in_the_srr_rows() -> None:
    _, scenario = _pair("rear_end", "south", "north", a1="follow_lane\n      retrograde")
    rows = reconstruct(scenario, Path("pair.sov"), town(), roads=3)
    assert [r["failure"] for r in rows] == ["planning failed"] * 3
    assert planning_split(rows) == {CONTRADICTS: 3}
    assert contradicting(rows) == {"pair"}
