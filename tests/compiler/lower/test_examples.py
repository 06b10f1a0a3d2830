"""Every example scenario on the example town: it stages on three sites, and a golden summary of its first site.

The golden files (`golden/<scenario>.txt`) hold a compact, rounded summary of the plan on the
first site `lower(roads=3, seed=0)` picks: the site, the impact, and per participant where it
starts, where it is at impact and its cruise speeds. Regenerate with `pytest --update-goldens`
and review the diff like code. A scenario that fails to stage records its error instead.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.dsl.errors import SovarcError

from tests.compiler.lower.staging import NAMES, ROADS, Staged, staged
from tests.conftest import Golden

pytestmark = pytest.mark.slow  # shares the session's lowering of every example (about 20 s)

GOLDEN = Path(__file__).parent / "golden"


def _n(value: float, digits: int = 0) -> str:
    text = f"{value:.{digits}f}"
    return text[1:] if text.lstrip("-0.") == "" and text.startswith("-") else text  # no '-0'


def summary(first: Staged) -> str:
    lowered, solution = first.lowered, first.lowered.solution
    lines = [
        f"site {lowered.match.site.id} (rotation {lowered.match.rotation})",
        f"impact {_n(solution.impact_time, 1)} s: {lowered.striker} strikes {lowered.victim}, {lowered.crash.value}",
    ]
    for pid in sorted(lowered.routes):
        at_impact = solution.impact.get(pid)
        impact = "-" if at_impact is None else f"{_n(at_impact)} m"
        speeds = ", ".join(_n(leg.v, 1) for leg in solution.legs.get(pid, ()))
        moves = f"cruise {speeds} m/s" if speeds else "stands"
        lines.append(f"{pid} start {_n(solution.starts[pid])} m, impact {impact}, {moves}")
    if first.error is not None:
        lines.append(f"synthesis: {type(first.error).__name__}: {first.error.diagnostics[0].message}")
    return "\n".join(lines) + "\n"


# Examples that do not yet stage on every one of three town sites: the open gaps of issue 4,
# named in its closing note. The test fails when one starts to stage, so the list stays true.
KNOWN_GAPS = frozenset(
    {
        "intersection_dual_left_turn_side",
        "straight_median_u_turn_wrong_way_frontal",
    }
)


# Examples whose bus or truck cannot take the tightest junction corner among the three town sites
# `lower(roads=3)` picks: lowering refuses a line that bends under the body's 9 m, and a corner just
# over it leaves the speed synthesis plans above what the body's own path allows there (TOPP-RA).
# The CLI's spare sites stage them on three others (tests/targets/test_kinds.py); this test takes none.
TOO_TIGHT_FOR_HEAVY = frozenset({"intersection_bus_left_turn_cyclist_side", "intersection_truck_left_turn_side"})


@pytest.mark.parametrize("name", NAMES)
def test_example_stages_on_three_town_sites(name: str) -> None:
    result = staged(name)
    if isinstance(result, SovarcError):
        failed = [f"lowering failed:\n{result}"]
    else:
        failed = [f"{s.lowered.match.site.id}: {s.error}" for s in result if s.error is not None]
        if len({s.lowered.match.site.id for s in result}) != ROADS:
            failed.append(f"fewer than {ROADS} sites")
    if name in KNOWN_GAPS | TOO_TIGHT_FOR_HEAVY:
        assert failed, f"{name} now stages on {ROADS} sites: remove it from its list of gaps"
        if name in TOO_TIGHT_FOR_HEAVY:
            assert any("corner" in f or "TOPP-RA" in f for f in failed), failed
    else:
        assert not failed, "\n".join(failed)


@pytest.mark.parametrize("name", NAMES)
def test_golden_plan_summary(name: str, golden: Golden) -> None:
    result = staged(name)
    if isinstance(result, SovarcError):
        text = f"lowering: {type(result).__name__}: {result.diagnostics[0].message}\n"
    else:
        text = summary(result[0])
    golden.check(GOLDEN / f"{name}.txt", text)
