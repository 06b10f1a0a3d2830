"""A plan is judged by its bodies' first touch, as the SUMO oracle judges its replay.

Lowering measured a crossing's angle between the lanes' lines where the bumper centres meet. At a
crossing with a turning car the front corners touch a little earlier, while it is still turning,
at a smaller angle: ground truth t/2 on SUMO's Braunschweig (junction cluster_26153648_34043448)
was lowered at 100.5 degrees and first touched at 98.8 in SUMO, failing its frontal crash type.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import sumo
from sovarc.compiler.crashes import CRASH_ANGLES, planned_touch
from sovarc.compiler.plan import Impact, Network, Plan, Sample, Trajectory
from sovarc.compiler.synth.impact import check_impact
from sovarc.compiler.vehicles import CAR
from sovarc.dsl import parse
from sovarc.dsl.errors import SynthesisError
from sovarc.dsl.ir import CrashType, RoadKind, Role

from tests.conftest import SHARED, requires_shared

FRONTAL = CRASH_ANGLES["frontal"][0]
MEET_T = 3.0  # s: the bumper centres meet at the origin
STEP = 0.1
SCENARIO = parse(
    """\
scenario turn_across {
  road { kind t_junction lanes 1 }
  vehicle V1 { heading east lane 1 actions { turn_left } }
  vehicle V2 { heading south lane 1 actions { follow_lane } }
  crash { type frontal striker V2 victim V1 }
}
""",
    "turn_across.sov",
)


def _times() -> list[float]:
    return [round(k * STEP, 6) for k in range(41)]


def _straight(heading: float, speed: float) -> tuple[Sample, ...]:
    """Driving straight at `heading` through the origin at MEET_T."""
    fx, fy = math.sin(math.radians(heading)), math.cos(math.radians(heading))
    return tuple(Sample(t, fx * speed * (t - MEET_T), fy * speed * (t - MEET_T), heading, speed) for t in _times())


def _turning_left(heading: float, speed: float, radius: float) -> tuple[Sample, ...]:
    """Turning left on a circle, at `heading` as it passes the origin at MEET_T."""
    h = math.radians(heading)
    cx, cy = -radius * math.cos(h), radius * math.sin(h)  # the centre, on its left
    out = []
    for t in _times():
        a = h + speed / radius * (MEET_T - t)  # turning left: the compass heading falls with time
        out.append(Sample(t, cx + radius * math.cos(a), cy - radius * math.sin(a), math.degrees(a) % 360.0, speed))
    return tuple(out)


def _plan(victim: tuple[Sample, ...]) -> Plan:
    def trajectory(pid: str, samples: tuple[Sample, ...]) -> Trajectory:
        return Trajectory(pid, Role.VEHICLE, CAR, samples, (), (), (), None)

    return Plan(
        scenario=SCENARIO,
        network=Network("none", "0", "none"),
        site="junction:j",
        kind=RoadKind.T_JUNCTION,
        rotation=0,
        seed=0,
        step=STEP,
        impact=Impact(MEET_T, (0.0, 0.0), 2.0, "V2", "V1", CrashType.FRONTAL),
        trajectories=(trajectory("V1", victim), trajectory("V2", _straight(180.0, 6.0))),
        notes=(),
    )


def test_a_turn_across_met_at_100_degrees_that_first_touches_under_it_is_refused() -> None:
    """Fronts meet at 100.5 degrees, but the front corners touch 0.13 s earlier, at 98.5."""
    plan = _plan(_turning_left(79.5, 4.0, 15.0))
    touch = planned_touch(plan)
    assert touch is not None and touch.time < MEET_T - 0.1
    assert touch.zones == (("front", "right"), ("front", "left"))
    assert touch.angle < FRONTAL
    with pytest.raises(SynthesisError, match=r"at 98\.5 degrees .*at least 100 degrees apart"):
        check_impact(plan)


def test_a_crossing_of_straight_paths_at_100_degrees_is_frontal() -> None:
    check_impact(_plan(_straight(79.5, 4.0)))


@requires_shared
@pytest.mark.slow  # loads SUMO's Braunschweig network and replays in SUMO
def test_t2_on_braunschweig_is_planned_as_its_replay_then_measures_it() -> None:
    from sovarc.compiler.frontend.truth import import_truth_file
    from sovarc.compiler.lower import sites_for
    from sovarc.compiler.maps import load_map
    from sovarc.compiler.staging import stage_on_site
    from sovarc.targets.sumo import check

    city = load_map(Path(sumo.SUMO_HOME) / "tools" / "game" / "bs3d" / "bs.net.xml")
    scenario = import_truth_file(SHARED / "data" / "nmvccs" / "truth" / "t" / "2.json").scenario
    staged, notes, matches = sites_for(scenario, city, roads=12)
    match = next(m for m in matches if m.site.id == "junction:cluster_26153648_34043448")
    plan = stage_on_site(staged, notes, city, match)
    planned = planned_touch(plan)
    assert planned is not None and planned.angle >= FRONTAL
    verdict = check(plan)
    assert verdict.passed, verdict.failures
    assert verdict.facts["impact"]["angle"] == pytest.approx(planned.angle, abs=0.2)
