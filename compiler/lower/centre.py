"""Which lane of a wider road a report's lane names, when a car crosses the centre line.

A report counts lanes from the right of its own road. On a road of k lanes each way its lane k
is the right-most but k - 1 and equally the lane by the centre line; staged on a site of more
lanes each way the two readings part. Lowering keeps the count from the right (the kerb lane for
lane 1), but for a driver who crosses the centre line into the oncoming lanes (`retrograde`):
drifting over, it starts from the lane next to the line, and the oncoming car it meets is most
likely in the lane next to the line too. Both readings agree with the report; the one by the
centre keeps the sideways travel of the swerve least (one lane and the median, not the whole road).
"""

from __future__ import annotations

from sovarc.compiler.lower.assume import COMPASS
from sovarc.compiler.maps import SiteMatch
from sovarc.dsl.ir import ActionKind, Heading, Participant, Role, Scenario


def lanes_each_way(scenario: Scenario) -> int | None:
    """The report's lanes in each direction of a two-way road: half its lanes when they split
    evenly; None when the count is unknown or odd (which direction has the extra lane is not said)."""
    lanes = scenario.road.lanes
    if not isinstance(lanes, int) or lanes < 2 or lanes % 2:
        return None
    return lanes // 2


def centre_lanes(scenario: Scenario, match: SiteMatch, striker: str, victim: str) -> dict[str, tuple[int, str]]:
    """Site lane numbers (from the right, as placements count) for the vehicles read from the
    centre line, each with the note saying why: a wrong-way driver whose report lane is its road's
    lane by the centre, and its crash partner coming the other way in such a lane."""
    per = lanes_each_way(scenario)
    if per is None:
        return {}
    pair = {striker: victim, victim: striker}
    chosen: dict[str, tuple[int, str]] = {}
    for p in scenario.participants:
        if not _wrong_way(p) or p.id not in pair or not _by_centre(p, per):
            continue
        partner = scenario.participant(pair[p.id])
        _choose(p, match, per, f"{p.id} crosses the centre line", chosen)
        if partner is None or _wrong_way(partner) or not _by_centre(partner, per):
            continue
        if isinstance(p.heading, Heading) and partner.heading == COMPASS[(COMPASS.index(p.heading) + 2) % 4]:
            _choose(partner, match, per, f"{p.id} comes at it across the centre line", chosen)
    return chosen


def _wrong_way(p: Participant) -> bool:
    return p.role is Role.VEHICLE and any(a.kind is ActionKind.RETROGRADE for a in p.known_actions)


def _by_centre(p: Participant, per: int) -> bool:
    return p.role is Role.VEHICLE and p.lane == per


def _choose(p: Participant, match: SiteMatch, per: int, why: str, chosen: dict[str, tuple[int, str]]) -> None:
    placement = match.placement(p.id)
    if placement is None or placement.arm is None:
        return
    arm = match.site.arm(placement.arm)
    count = len(arm.incoming)
    if count <= per or placement.lane == count:
        return  # the site's lane by the centre is the lane the report counts to from the right
    each = "one lane" if per == 1 else f"{per} lanes"
    note = (
        f"lane {p.lane} of the report's road ({each} each way) is its lane by the centre line as much as "
        f"from the right: planned in lane {count} of {count}, by the centre line ({why})"
    )
    chosen[p.id] = (count, note)
