"""Unseen maps made at run time with SUMO's netgenerate, for `bench_srr_maps.py --group generated`.

Each network is generated with a fixed --seed, so the same SUMO gives the same roads, and is also
round-tripped through OpenDRIVE (netconvert --opendrive-output, then loaded as any .xodr map is:
converted back by the map layer), so both the structure netgenerate writes and the structure
netconvert gives OpenDRIVE maps (lane-section splits, clustered junctions, re-fitted geometry) are
exercised. The files go to a cache folder ($XDG_CACHE_HOME/sovarc/generated, else ~/.cache), named
by a hash of the options and the SUMO version; nothing is written into the repository.

The split was fixed before any of them was run: each half has one right-angled grid and one network
whose junctions are not right-angled.
- development (`gen-dev`): `grid2`, a 4x4 grid of 150 m blocks, 2 lanes each way (3.5 m),
  priority junctions; `spider`, 5 arms by 3 rings 90 m apart with no centre node (a ring of
  non-right-angled junctions round the middle), 1 or 2 lanes per road at random (3.2 m),
  right-before-left junctions.
- held out (`gen-held-out`, run and reported, never debugged on): `grid1long`, a 3x4 grid
  of 300 m by 220 m blocks, 1 lane each way (3.0 m), traffic lights; `random`, a random network
  (edges 120-300 m, junction angles at least 40 degrees), 1 to 3 lanes per road at random (3.3 m).
"""

from __future__ import annotations

import hashlib
import os
import subprocess
from pathlib import Path

import sumo

BIN = Path(sumo.SUMO_HOME) / "bin"
SEED = 17

NETWORKS: dict[str, tuple[str, ...]] = {
    "grid2": ("--grid", "--grid.number", "4", "--grid.length", "150", "-L", "2",
              "--default.lanewidth", "3.5", "-j", "priority"),
    "spider": ("--spider", "--spider.arm-number", "5", "--spider.circle-number", "3",
               "--spider.space-radius", "90", "--spider.omit-center", "-L", "2", "--random-lanenumber",
               "--default.lanewidth", "3.2", "-j", "right_before_left"),
    "grid1long": ("--grid", "--grid.x-number", "3", "--grid.y-number", "4", "--grid.x-length", "300",
                  "--grid.y-length", "220", "-L", "1", "--default.lanewidth", "3.0", "-j", "traffic_light"),
    "random": ("--rand", "--rand.iterations", "60", "--rand.min-distance", "120", "--rand.max-distance",
               "300", "--rand.min-angle", "40", "-L", "3", "--random-lanenumber",
               "--default.lanewidth", "3.3", "-j", "priority"),
}  # fmt: skip
GROUPS = {"gen-dev": ("grid2", "spider"), "gen-held-out": ("grid1long", "random")}


def cache_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "sovarc" / "generated"


def _run(tool: str, args: list[str], cwd: Path) -> None:
    command = [str(BIN / tool), *args, "--no-warnings", "true", "--xml-validation", "never"]
    subprocess.run(command, cwd=cwd, check=True, capture_output=True, timeout=300)


def generate(name: str) -> dict[str, Path]:
    """The network `name` as netgenerate writes it (`name`) and round-tripped through OpenDRIVE
    (`name.xodr`), made now unless cached."""
    options = [*NETWORKS[name], "--seed", str(SEED)]
    version = subprocess.run([str(BIN / "netgenerate"), "--version"], capture_output=True, text=True).stdout
    key = hashlib.sha256("\0".join([version.splitlines()[0], *options]).encode()).hexdigest()[:12]
    folder = cache_dir() / f"{name}-{key}"
    net, xodr = folder / f"{name}.net.xml", folder / f"{name}.xodr"
    if not xodr.is_file():
        folder.mkdir(parents=True, exist_ok=True)
        _run("netgenerate", [*options, "-o", net.name], folder)
        _run("netconvert", ["--sumo-net-file", net.name, "--opendrive-output", "tmp.xodr"], folder)
        (folder / "tmp.xodr").replace(xodr)  # last, so a cut-off run leaves no half-made pair
    return {name: net, f"{name}.xodr": xodr}


def maps(group: str) -> dict[str, Path]:
    return {label: path for name in GROUPS[group] for label, path in generate(name).items()}
