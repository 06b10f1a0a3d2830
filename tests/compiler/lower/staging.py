"""The example scenarios lowered and synthesized on the example town, computed once per test session.

Lowering a scenario on three sites takes up to a second, so every test module that needs
plans takes them from here (cached), never lowering the same scenario twice.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from pathlib import Path

from sovarc.compiler.lower import Lowered, lower
from sovarc.compiler.maps import RoadMap, load_map
from sovarc.compiler.plan import Plan
from sovarc.compiler.synth import synthesize
from sovarc.dsl import parse
from sovarc.dsl.errors import SovarcError
from sovarc.dsl.ir import RoadKind, Scenario

from tests.conftest import EXAMPLES

TOWN = EXAMPLES / "maps" / "town.net.xml"
SCENARIO_DIR = EXAMPLES / "scenarios"
NAMES = tuple(sorted(p.stem for p in SCENARIO_DIR.glob("*.sov")))
ROADS = 3
SEEDS = (0, 1)  # straight scenarios only: on the town the junction sites are the same for every seed


@dataclass(frozen=True)
class Staged:
    """One scenario on one site: what lowering made and what synthesis made of it (or its error)."""

    name: str
    seed: int
    lowered: Lowered
    plan: Plan | None
    error: SovarcError | None


@cache
def town() -> RoadMap:
    return load_map(TOWN)


@cache
def scenario(name: str) -> Scenario:
    path = SCENARIO_DIR / f"{name}.sov"
    return parse(path.read_text(encoding="utf-8"), str(path))


def seeds_for(name: str) -> tuple[int, ...]:
    return SEEDS if scenario(name).road.kind is RoadKind.STRAIGHT else SEEDS[:1]


@cache
def staged(name: str, seed: int = 0) -> tuple[Staged, ...] | SovarcError:
    """Every site `lower(roads=3, seed)` picks, each synthesized; or the lowering error."""
    try:
        lowered = lower(scenario(name), town(), roads=ROADS, seed=seed)
    except SovarcError as error:
        return error
    out = []
    for item in lowered:
        try:
            out.append(Staged(name, seed, item, synthesize(item, seed=seed), None))
        except SovarcError as error:
            out.append(Staged(name, seed, item, None, error))
    return tuple(out)


def plans(name: str) -> list[Plan]:
    """Every plan synthesized for the scenario, over its seeds (failures are left to the feasibility test)."""
    found: list[Plan] = []
    for seed in seeds_for(name):
        result = staged(name, seed)
        if not isinstance(result, SovarcError):
            found += [s.plan for s in result if s.plan is not None]
    return found


def source_path(name: str) -> Path:
    return SCENARIO_DIR / f"{name}.sov"
