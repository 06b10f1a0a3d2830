"""The site-filling wrapper: a chosen site that cannot host the crash is replaced by the next one, and the
output says so."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import pytest
from sovarc.compiler.maps import load_map
from sovarc.compiler.pipeline import Options, stage_sites
from sovarc.compiler.slots import SiteResult, fill_slots, summary
from sovarc.dsl import parse
from sovarc.dsl.errors import Diagnostic, UnsatError

from tests.compiler.cli.test_cli import sovarc
from tests.conftest import EXAMPLES

# A follower strikes the side of a car turning left off a straight road from lane 2: on a road where
# the turn clears the follower's lane before it has turned far enough to be met on its side (its
# corner widened so as not to swing its rear into lane 1), the follower can only meet its rear, and
# that site cannot host the crash. (Crossings at right angles host frontal
# crashes between two cars going straight over since the corner frontal, so that no longer serves.)
DRIVEWAY_SIDE = """\
scenario driveway_side {
  road { kind straight lanes 4 speed_limit 48 km/h }
  vehicle V1 { heading north lane 2 actions { follow_lane } }
  vehicle V2 { heading north lane 2 actions { follow_lane turn_left } }
  crash { type side striker V1 victim V2 }
}
"""


@dataclass(frozen=True)
class _Site:
    id: str


@dataclass(frozen=True)
class _Match:
    site: _Site


def _attempts(good: set[str]) -> tuple[list[str], object]:
    tried: list[str] = []

    def attempt(match: _Match) -> SiteResult:
        tried.append(match.site.id)
        result = SiteResult(match.site.id)
        if match.site.id in good:
            result.plan = object()  # type: ignore[assignment]
        else:
            result.error = UnsatError(Diagnostic(f"{match.site.id} cannot"))
        return result

    return tried, attempt


def _matches(*names: str) -> list[_Match]:
    return [_Match(_Site(n)) for n in names]


def test_failed_slots_are_filled_in_order_and_keep_what_they_replaced() -> None:
    tried, attempt = _attempts({"a", "e", "f"})
    slots = fill_slots(_matches("a", "b", "c", "d", "e", "f", "g"), 3, attempt)  # type: ignore[arg-type]
    assert [s.site for s in slots] == ["a", "e", "f"]
    assert [s.site for s in slots[1].skipped] == ["b", "d"]  # d was tried for b's slot, the first failed one
    assert [s.site for s in slots[2].skipped] == ["c"]
    assert tried == ["a", "b", "c", "d", "e", "f"]  # g is never tried: every slot holds a plan


def test_a_slot_no_candidate_fills_keeps_its_first_failure() -> None:
    tried, attempt = _attempts({"a"})
    slots = fill_slots(_matches("a", "b", "c", "d"), 2, attempt)  # type: ignore[arg-type]
    assert [s.site for s in slots] == ["a", "b"] and slots[1].plan is None
    assert [s.site for s in slots[1].skipped] == ["c", "d"]
    assert tried == ["a", "b", "c", "d"]


def test_no_spare_keeps_the_first_choice() -> None:
    tried, attempt = _attempts(set())
    slots = fill_slots(_matches("a", "b"), 2, attempt)  # type: ignore[arg-type]
    assert [s.site for s in slots] == ["a", "b"] and not slots[0].skipped and tried == ["a", "b"]


def test_a_crash_moves_to_the_sites_that_can_host_it() -> None:
    town = load_map(EXAMPLES / "maps" / "town.net.xml")
    scenario = parse(DRIVEWAY_SIDE, "driveway.sov")
    first = stage_sites(scenario, Options(map=town, roads=3, spare=0))
    spared = stage_sites(scenario, Options(map=town, roads=3))
    assert sum(r.plan is not None for r in spared) > sum(r.plan is not None for r in first)
    assert [r.site for r in spared] == [r.site for r in stage_sites(scenario, Options(map=town, roads=3))]
    given_up = [s for r in spared for s in r.skipped]
    assert given_up and all("paths cross at" in s.error.diagnostics[0].message for s in given_up)
    planned = {r.site for r in spared if r.plan is not None}
    assert not planned & {s.site for s in given_up}
    notes = summary(spared, ())
    # each site given up is named: one whose slot another site filled, or one tried in place of it that failed too
    assert all(
        f"note: {s.site} could not host the crash" in notes or f"note: {s.site}, tried in place of" in notes
        for s in given_up
    )


def test_eval_srr_counts_the_sites_given_up(tmp_path: Path) -> None:
    (tmp_path / "driveway.sov").write_text(DRIVEWAY_SIDE, encoding="utf-8")
    out = tmp_path / "srr.json"
    spared = sovarc("eval", "srr", str(tmp_path / "driveway.sov"), "--json", str(out))
    assert spared.returncode == 0, spared.stderr
    assert "sites that could not host their crash:" in spared.stdout
    rows = json.loads(out.read_text(encoding="utf-8"))["town.net.xml"]["rows"]
    assert any(row["skipped"] for row in rows) and all("reason" in s for row in rows for s in row["skipped"])
    strict = sovarc("eval", "srr", str(tmp_path / "driveway.sov"), "--spare-sites", "0")
    assert "could not host" not in strict.stdout
    assert sovarc("eval", "srr", str(tmp_path / "driveway.sov"), "--spare-sites", "-1").returncode == 2


def test_the_output_folder_says_which_sites_were_given_up(tmp_path: Path) -> None:
    (tmp_path / "driveway.sov").write_text(DRIVEWAY_SIDE, encoding="utf-8")
    result = sovarc("lower", str(tmp_path / "driveway.sov"), "--roads", "3", "-o", str(tmp_path / "out"))
    written = (tmp_path / "out" / "summary.txt").read_text(encoding="utf-8")
    assert written == result.stdout and "could not host the crash" in written
    given_up = [line.split()[1] for line in written.splitlines() if line.startswith("note:")]
    assert given_up and not any((tmp_path / "out" / name.replace(":", "_")).exists() for name in given_up)


def test_a_defect_on_one_site_is_that_site_s_error_and_the_next_site_is_tried(monkeypatch: pytest.MonkeyPatch) -> None:
    import sovarc.compiler.synth as synth

    real = synth.synthesize
    calls: list[str] = []

    def breaks_first(lowered: object, seed: int = 0) -> object:
        calls.append(lowered.match.site.id)  # type: ignore[attr-defined]
        if len(calls) == 1:
            raise ValueError("a polyline needs two distinct points")
        return real(lowered, seed=seed)  # type: ignore[arg-type]

    monkeypatch.setattr(synth, "synthesize", breaks_first)
    scenario = parse((EXAMPLES / "scenarios" / "straight_rear_end_stopped_traffic.sov").read_text(), "s.sov")
    [slot] = stage_sites(scenario, Options(map=load_map(EXAMPLES / "maps" / "town.net.xml")))
    assert slot.plan is not None and slot.site == calls[1]
    [given_up] = slot.skipped
    message = given_up.error.diagnostics[0].message  # type: ignore[union-attr]
    assert message == (
        f"on {calls[0]}, sovarc failed on this site's geometry "
        "(ValueError: a polyline needs two distinct points); please report it"
    )


def test_eval_srr_keeps_two_maps_of_one_file_name_apart(tmp_path: Path) -> None:
    (tmp_path / "driveway.sov").write_text(DRIVEWAY_SIDE, encoding="utf-8")
    maps = []
    for city in ("a", "b"):
        (tmp_path / city).mkdir()
        maps += ["-m", str(tmp_path / city / "town.net.xml")]
        (tmp_path / city / "town.net.xml").write_bytes((EXAMPLES / "maps" / "town.net.xml").read_bytes())
    out = tmp_path / "srr.json"
    done = sovarc("eval", "srr", str(tmp_path / "driveway.sov"), *maps, "--roads", "1", "--json", str(out))
    assert done.returncode == 0, done.stderr
    assert list(json.loads(out.read_text(encoding="utf-8"))) == [maps[1], maps[3]]
    assert f"SRR on {maps[1]}" in done.stdout and f"SRR on {maps[3]}" in done.stdout
