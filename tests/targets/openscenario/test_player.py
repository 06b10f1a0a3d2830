"""The esmini harness. esmini is not on PyPI or in Debian: most tests run `play` against a stand-in
script that speaks esmini's command line and log format; the target's check runs the real player
when one is found ($ESMINI, PATH, or the shared tools' headless build)."""

from __future__ import annotations

import os
import shutil
import stat
from pathlib import Path

import pytest
from sovarc.targets import registry
from sovarc.targets.openscenario.player import (
    Collision,
    PlayerError,
    esmini_command,
    esmini_path,
    judge_collisions,
    parse_collisions,
    play,
)

from tests.conftest import SHARED
from tests.targets.openscenario.conftest import Emitter
from tests.targets.openscenario.plans import CASES, on_opendrive

SHARED_ESMINI = SHARED / "tools" / "esmini" / "bin" / "esmini"


def real_esmini() -> str | None:
    for candidate in (os.environ.get("ESMINI"), shutil.which("esmini"), str(SHARED_ESMINI)):
        if candidate and Path(candidate).is_file() and os.access(candidate, os.X_OK):
            return candidate
    return None


LOG = """\
0.000: Init V1 TeleportAction initState -> startTransition -> runningState
[2.500] [info] Collision between V3 and V4
4.010: Collision between V1 and V2
4.600: Collision between V1 and V2 dissolved
"""


def test_collisions_are_read_from_both_log_formats() -> None:
    assert parse_collisions(LOG) == [Collision(2.5, "V3", "V4"), Collision(4.01, "V1", "V2")]


def test_the_right_pair_near_the_planned_time_passes() -> None:
    findings = judge_collisions([Collision(4.01, "V2", "V1")], "V1", "V2", 4.0)
    assert all(f.passed for f in findings)
    assert findings[0].message == "esmini saw V1 and V2 collide at t=4.01 s (planned 4 s)"


def test_a_late_crash_or_an_earlier_other_collision_fails() -> None:
    late, other = judge_collisions(parse_collisions(LOG), "V1", "V2", 3.0)
    assert not late.passed and late.message == "esmini saw V1 and V2 collide at t=4.01 s, planned at 3 s"
    assert not other.passed and other.message == "esmini saw V3 and V4 collide at t=2.5 s, before the crash"
    (missing, _) = judge_collisions([], "V1", "V2", 3.0)
    assert missing.message == "esmini saw no collision between V1 and V2"


def test_the_collision_is_judged_against_the_files_first_touch_not_the_impact_time() -> None:
    # a slow turn: the striker's leading corner touches 0.55 s before its bumper centre meets the
    # victim's face (the impact time), inside C_A; esmini sees that touch when the file has it
    seen = [Collision(11.45, "V1", "V2")]
    (early, _) = judge_collisions(seen, "V1", "V2", 12.0)
    assert not early.passed
    (at_touch, _) = judge_collisions(seen, "V1", "V2", 12.0, touch=11.44)
    assert at_touch.passed
    assert at_touch.message == "esmini saw V1 and V2 collide at t=11.45 s (the file's bodies first touch at 11.44 s)"
    (off, _) = judge_collisions(seen, "V1", "V2", 12.0, touch=10.8)
    assert not off.passed


def test_the_command_runs_headless_with_collision_detection(tmp_path: Path) -> None:
    command = esmini_command("/opt/esmini/bin/esmini", tmp_path / "scenario.xosc", tmp_path / "log.txt")
    assert command[:4] == ["/opt/esmini/bin/esmini", "--headless", "--osc", str(tmp_path / "scenario.xosc")]
    assert {"--collision", "--disable_stdout"} <= set(command)
    assert command[command.index("--fixed_timestep") + 1] == "0.01"


def test_a_missing_player_is_a_clear_error(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.delenv("ESMINI", raising=False)
    monkeypatch.setenv("PATH", str(tmp_path))
    with pytest.raises(PlayerError, match=r"esmini not found: set \$ESMINI to the esmini binary or put it on PATH"):
        esmini_path()


def _stand_in(tmp_path: Path, log: str) -> str:
    """A script that accepts esmini's arguments and writes `log` where --logfile_path says."""
    script = tmp_path / "esmini"
    script.write_text(
        "#!/bin/sh\n"
        'while [ "$#" -gt 0 ]; do\n'
        '  if [ "$1" = "--logfile_path" ]; then shift; out="$1"; fi\n'
        "  shift\n"
        "done\n"
        f"cat > \"$out\" <<'EOF'\n{log}EOF\n",
        encoding="utf-8",
    )
    script.chmod(script.stat().st_mode | stat.S_IEXEC)
    return str(script)


@pytest.mark.slow  # emits (needs SUMO for the road network)
def test_play_runs_the_player_and_judges_its_log(emitted: Emitter, tmp_path: Path) -> None:
    plan, files = emitted("t_bone")
    verdict = play(files.xosc, plan, esmini=_stand_in(tmp_path, "4.020: Collision between V1 and V2\n"))
    assert verdict.passed, verdict.dumps()
    assert verdict.target == "openscenario:esmini"
    assert verdict.facts == {"collisions": [[4.02, "V1", "V2"]]}
    missed = play(files.xosc, plan, esmini=_stand_in(tmp_path, "0.000: nothing happened\n"))
    assert [f.check for f in missed.failures] == ["player_collision"]


def _target_check(case: str, tmp_path: Path) -> list[str]:
    target = registry.get("openscenario")
    plan = on_opendrive(CASES[case]())
    artifacts = target.emit(plan, tmp_path, target.Options())
    (verdict,) = target.check(plan, artifacts, target.Options())
    assert verdict.passed, verdict.failures
    return [f.check for f in verdict.findings]


def test_without_esmini_the_targets_check_is_the_oracles(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.delenv("ESMINI", raising=False)
    monkeypatch.setenv("PATH", str(tmp_path / "bin"))
    checks = _target_check("rear_end", tmp_path)
    assert "xsd" in checks and not any(c.startswith("player") for c in checks)


@pytest.mark.slow  # runs the real player
@pytest.mark.skipif(real_esmini() is None, reason="no esmini: set $ESMINI or put it on PATH")
def test_the_targets_check_plays_the_scenario_in_esmini_when_found(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.setenv("ESMINI", str(real_esmini()))
    checks = _target_check("left_turn", tmp_path)
    assert {"xsd", "player_run", "player_collision", "player_other_collisions"} <= set(checks)
