"""`sovarc sites`: the sites a map offers, listed per kind, drawn, and a missing kind said truthfully."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.compiler.cli.test_cli import sovarc
from tests.conftest import EXAMPLES, SHARED, requires_shared

pytestmark = pytest.mark.slow  # loads maps with SUMO's tools

TOWN = EXAMPLES / "maps" / "town.net.xml"


def test_the_town_lists_every_kind_with_arms_lanes_and_widths() -> None:
    done = sovarc("sites", str(TOWN))
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == "town.net.xml: 5 intersections, 4 T-junctions, 21 straight roads"
    assert "intersections (5):" in lines and "T-junctions (4):" in lines
    x_main = next(line for line in lines if "junction:x_main" in line)
    assert "90° 4 in (3.5/3.5/3.5/3.5 m) + 4 out (3.5/3.5/3.5/3.5 m)" in x_main


def test_one_kind_and_a_picture(tmp_path: Path) -> None:
    png = tmp_path / "town.png"
    done = sovarc("sites", str(TOWN), "--kind", "t_junction", "--png", str(png))
    assert done.returncode == 0, done.stderr
    assert "T-junctions (4):" in done.stdout and "intersections (" not in done.stdout
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@requires_shared
def test_a_kind_the_map_lacks_is_said_with_what_it_has() -> None:
    done = sovarc("sites", str(SHARED / "data" / "opendrive" / "carla" / "Town01.xodr"), "--kind", "intersection")
    assert done.returncode == 1
    assert "Town01.xodr has no intersection (a 4-way junction): it has 0 intersections, 12 T-junctions" in done.stderr


def test_a_missing_map_is_an_input_error(tmp_path: Path) -> None:
    done = sovarc("sites", str(tmp_path / "nowhere.net.xml"))
    assert done.returncode == 1 and "nowhere.net.xml" in done.stderr
