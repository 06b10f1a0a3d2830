"""The replay: plain `sumo -c` sees what the oracle sees; repeated and child-process runs agree."""

from __future__ import annotations

import subprocess
from pathlib import Path
from xml.etree import ElementTree

import pytest
import sumo
from sovarc.targets.sumo import check, emit
from sovarc.targets.sumo.replay import replay

from tests.targets.sumo.plans import SCENES

pytestmark = pytest.mark.slow

SUMO = Path(sumo.SUMO_HOME) / "bin" / "sumo"


@pytest.mark.parametrize("scene", ["t_bone", "rear_end", "head_on", "sideswipe"])
def test_plain_sumo_run_shows_the_crash_the_oracle_sees(scene: str, tmp_path: Path) -> None:
    plan = SCENES[scene]()
    config = emit(plan, tmp_path)
    done = subprocess.run([str(SUMO), "-c", config.name], cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    (collision,) = ElementTree.parse(tmp_path / "collisions.xml").getroot().findall("collision")
    seen = check(plan, tmp_path).facts["collisions"][0]
    assert sorted([collision.get("collider"), collision.get("victim")]) == seen["pair"]
    assert float(collision.get("time")) == pytest.approx(seen["time"])


def test_replays_in_one_process_do_not_leak_into_each_other() -> None:
    first = [check(SCENES[s]()).to_json() for s in sorted(SCENES)]
    again = [check(SCENES[s]()).to_json() for s in sorted(SCENES)]
    assert first == again


def test_child_process_replay_gives_the_same_trace(tmp_path: Path) -> None:
    config = emit(SCENES["t_bone"](), tmp_path)
    here = replay(config, [], ["V1", "V2"])
    child = replay(config, [], ["V1", "V2"], fresh_process=True)
    assert child == here
    assert here.collisions[0].kind == "junction"
