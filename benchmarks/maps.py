"""The maps the benchmarks run on, named in one place, and how a benchmark's map arguments become them.

The example town, the shared OpenDRIVE maps (CARLA's towns and esmini's, from $SOVARC_SHARED or the
folder beside the project) and SUMO's bundled city networks, each by a short name (`named`). A map
argument is a file or one of those names (`resolve`: `-m Town04` or `-m ../shared/.../Town04.xodr`).
Without one, a benchmark runs the maps its work was built on, then the held-out ones (`grouped`).
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path

import sumo

ROOT = Path(__file__).resolve().parent.parent
SHARED = Path(os.environ.get("SOVARC_SHARED") or ROOT.parent / "shared")
OPENDRIVE = SHARED / "data" / "opendrive"
CARLA = OPENDRIVE / "carla"
GAME = Path(sumo.SUMO_HOME) / "tools" / "game"
TOWN = ROOT / "examples" / "maps" / "town.net.xml"
DRT = GAME / "DRT" / "osm.net.xml"
TRUTH = SHARED / "data" / "nmvccs" / "truth"

Group = list[tuple[Path, str]]  # maps in the order run, each with its group ("built on", "held out" or "")


def carla(*numbers: int) -> list[Path]:
    """CARLA's towns by number: carla(1, 2) is Town01 and Town02."""
    return [CARLA / f"Town{n:02d}.xodr" for n in numbers]


def named() -> dict[str, Path]:
    """Every map the benchmarks know by name: CARLA's towns, esmini's maps (by file name), the example
    town, SUMO's DRT, A10KW and bs3d networks."""
    maps = {path.stem: path for path in sorted(CARLA.glob("Town*.xodr"))}
    maps |= {path.stem: path for path in sorted(OPENDRIVE.glob("*.xodr"))}
    maps["town"] = TOWN
    maps |= {"DRT": DRT, "A10KW": GAME / "A10KW" / "osm.net.xml", "bs3d": GAME / "bs3d" / "bs.net.xml"}
    return maps


def resolve(arg: str) -> Path:
    """A map argument: the file it names, else the map `named` calls so (a name that is neither is kept
    as a path, for the map loader to say what is wrong with it)."""
    path = Path(arg)
    if path.exists():
        return path
    return named().get(arg, path)


def add_map_argument(parser: argparse.ArgumentParser, default: str) -> None:
    """-m/--map, repeatable, a file or a map's name (`resolve`); `default` says what runs without one."""
    names = "a file or a map's name (Town04, town, DRT, ...)"
    parser.add_argument("-m", "--map", action="append", type=resolve, help=f"{names}; repeatable; default: {default}")


def grouped(given: list[Path] | None, built_on: list[Path], held_out: list[Path]) -> Group:
    """The maps given, in no group; without any, the maps the work was built on, then the held-out ones."""
    if given:
        return [(path, "") for path in given]
    return [(path, "built on") for path in built_on] + [(path, "held out") for path in held_out]
