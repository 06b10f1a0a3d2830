"""Parked and reversing moves on many maps: how many sites plan and pass SUMO's and OpenSCENARIO's
oracles (esmini's too when it is found), the maps the moves were built on beside held-out ones.

    python benchmarks/bench_backing.py [-m MAP]... [--roads 3] [--out DIR]

The moves are the three examples (backing into the car stopped behind, backing out of a kerbside
space into a passing car, a parked car struck) and three variants in examples/variants (a car
struck while backing out, a parked car pulling out forwards, a backing car's rear into a crossing
pedestrian), which tests/compiler/lower/test_backing.py reads too.
Without -m: the example town and CARLA's Town01 (built on), then Town02, Town04, Town07 (held out),
from $SOVARC_SHARED. Prints one row per move and map, and the CPU time per map; asserts nothing.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

from maps import ROOT, TOWN, add_map_argument, carla, grouped
from sovarc.compiler.pipeline import Options, run_pipeline
from sovarc.dsl import parse

TUNED = [TOWN, *carla(1)]
HELD_OUT = carla(2, 4, 7)
EXAMPLES = [
    "straight_reverse_into_stopped_rear_end",
    "straight_back_out_of_parking_rear_end",
    "straight_parked_car_struck_rear_end",
]
# written for this benchmark, shared with tests/compiler/lower/test_backing.py
VARIANTS = [
    "straight_backing_out_struck_rear_end",
    "straight_parked_pulls_out_struck_rear_end",
    "straight_backing_into_pedestrian_side",
]


def scenarios() -> list[tuple[str, str]]:
    found = [(n, (ROOT / "examples" / "scenarios" / f"{n}.sov").read_text()) for n in EXAMPLES]
    return found + [(n, (ROOT / "examples" / "variants" / f"{n}.sov").read_text()) for n in VARIANTS]


def row(name: str, text: str, map_path: Path, roads: int, out: Path) -> str:
    options = Options(map=map_path, roads=roads, targets=("sumo", "openscenario"), out_dir=out / map_path.stem / name)
    try:
        slots, _ = run_pipeline(parse(text), start="assume", options=options)
    except Exception as error:  # a failure of the whole run is a figure too
        return f"error: {type(error).__name__}: {str(error).splitlines()[0][:90]}"
    planned = [r for r in slots.results if r.plan is not None]
    passed = [r for r in planned if all(v.passed for v in r.verdicts.values())]
    return f"{len(passed)}/{len(slots.results)} pass ({len(planned)} planned)"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_map_argument(parser, "built-on, then held-out")
    parser.add_argument("--roads", type=int, default=3)
    parser.add_argument("--out", type=Path, default=None)
    args = parser.parse_args()
    maps = grouped(args.map, TUNED, HELD_OUT)
    out = args.out or Path(tempfile.mkdtemp(prefix="bench_backing_"))
    for map_path, why in maps:
        start = time.process_time()
        lines = [f"  {name:<42} {row(name, text, map_path, args.roads, out)}" for name, text in scenarios()]
        label = f"{map_path.name}, {why}" if why else map_path.name
        print(f"{label} (CPU {time.process_time() - start:.0f} s)", *lines, sep="\n")


if __name__ == "__main__":
    main()
