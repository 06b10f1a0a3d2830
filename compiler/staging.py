"""The stage stage on one site: the lowering-and-synthesis search.

Lowering offers the scenario's stagings on the site best first (its chosen rotation's stagings,
each with its contacts in turn, then the other rotations'; `lower.stagings_on`); each is
synthesized into a Plan, which synthesis verifies (TOPP-RA's speed envelope, and that the bodies
first touch as the crash type needs); the first plan that passes is kept. A refused plan gives way
to the next staging; all refused, the site's result carries the first refusal.
"""

from __future__ import annotations

from dataclasses import replace

from sovarc.compiler import synth
from sovarc.compiler.lower import stagings_on
from sovarc.compiler.maps import RoadMap, SiteMatch
from sovarc.compiler.plan import Plan
from sovarc.dsl.errors import SovarcError, SynthesisError
from sovarc.dsl.ir import Scenario


def stage_on_site(staged: Scenario, notes: list[str], road_map: RoadMap, match: SiteMatch, *, seed: int = 0) -> Plan:
    """The plan of the first staging on the site that synthesizes and passes; else the first refusal
    (an UnsatError when lowering finds no staging at all), saying what the site lacked when it fits
    only clamped (too few lanes, a move its map draws no connection for): two cars side by side
    clamped into one lane fail for the lane the site lacks, which the reason then names."""
    try:
        return _first_plan(staged, notes, road_map, match, seed)
    except SovarcError as error:
        if not getattr(match, "clamped", ()) or not error.diagnostics:
            raise
        head, *rest = error.diagnostics
        lacked = "; ".join(match.clamped)
        said = replace(head, message=f"{head.message} (the site fits only clamped: {lacked})")
        raise type(error)([said, *rest]) from error


def _first_plan(staged: Scenario, notes: list[str], road_map: RoadMap, match: SiteMatch, seed: int) -> Plan:

    first: SynthesisError | None = None
    for lowered in stagings_on(staged, match, road_map, notes):
        try:
            return synth.synthesize(lowered, seed=seed)
        except SynthesisError as error:
            first = first or error
    assert first is not None, "lowering yields a staging or raises"
    raise first
