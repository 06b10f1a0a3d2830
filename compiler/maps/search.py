"""The paper's Algorithm 1 site search: the sites of a map where a scenario can be staged.

A site fits when it has the scenario's road kind and, under one rotation of the compass,
every participant finds its arm, enough lanes, and the connection its manoeuvre needs.

The rotation: report heading H is staged in the site direction H + rotation + the site's
orientation, with rotation a multiple of 90 degrees, so opposite headings stay opposite,
crossing ones stay crossing, and left stays left. Report 'north' is the arm whose entering
traffic travels (roughly, after rotation) north. Of the rotations that fit, the one that
turns the compass least is kept.

Lanes are asked per participant (its start lane, lane changes, the lane a turn enters); the
report's `road.lanes` (both directions together) is not a filter of its own.

Clamping (only with `clamp=True`): a site that has every arm and connection but too few
lanes also fits; the lane numbers are clamped to the site's lanes and each clamp is written
as a note in `SiteMatch.clamped`. Exact fits are always chosen before clamped ones.

Short straight sites (`sites.short_sites`: a block of 26-80 m between junctions) are of last resort:
tried only after every exact fit on a site of 80 m or more (an exact fit on one before a clamped fit
on a long site, a clamped fit on one after), so that a map with enough long sites that fit is staged
exactly as without them.
"""

from __future__ import annotations

import math
import random
from collections import Counter
from dataclasses import dataclass

from sovarc.compiler.crashes import CRASH_ANGLES
from sovarc.compiler.geometry.angles import angle_diff
from sovarc.compiler.maps.load import RoadMap
from sovarc.compiler.maps.needs import HEADING_DEGREES, JUNCTION_MOVES, Need, scenario_needs
from sovarc.compiler.maps.sites import DEFAULT_MIN_LENGTH, Arm, Site, find_sites, short_sites
from sovarc.compiler.maps.survey import ramps
from sovarc.dsl.errors import Diagnostic, LoweringError
from sovarc.dsl.ir import ActionKind, CrashType, Heading, RoadKind, Scenario

ROTATIONS = (0, 90, 180, 270)
BY_GEOMETRY = "laid across it by the arms' geometry"  # ends the note of a move with no connection in the map
FRONTAL_ARMS = CRASH_ANGLES["frontal"][0]  # degrees two straight-over paths must cross at for a frontal crash


@dataclass(frozen=True)
class Placement:
    """Where one participant starts on the site."""

    participant: str
    heading: Heading | None  # the report's heading
    site_heading: float | None  # compass degrees it is staged in; None when its heading is unknown
    arm: str | None  # id of the arm it starts on; None when it is not tied to an arm
    lane: int | None  # start lane on that arm (after clamping), from the right-most as 1


@dataclass(frozen=True)
class SiteMatch:
    """A site a scenario fits on, and how the report's compass was laid onto it."""

    site: Site
    rotation: int  # 0, 90, 180 or 270: added to a report heading, before the site's orientation
    arms: tuple[tuple[Heading, str | None], ...]  # report heading -> id of the arm entered that way, or None
    placements: tuple[Placement, ...]  # in the scenario's participant order
    clamped: tuple[str, ...] = ()  # one note per lane number clamped to the site's lanes; empty when exact

    @property
    def exact(self) -> bool:
        return not self.clamped

    def site_heading(self, heading: Heading) -> float:
        return (HEADING_DEGREES[heading] + self.rotation + self.site.orientation) % 360.0

    def arm_for(self, heading: Heading) -> Arm | None:
        arm_id = dict(self.arms)[heading]
        return next((a for a in self.site.arms if a.id == arm_id), None)

    def placement(self, participant: str) -> Placement | None:
        return next((p for p in self.placements if p.participant == participant), None)


def match_sites(
    scenario: Scenario,
    road_map: RoadMap,
    n: int = 1,
    seed: int = 0,
    *,
    clamp: bool = False,
    min_length: float = DEFAULT_MIN_LENGTH,
) -> list[SiteMatch]:
    """Up to `n` distinct fitting sites, chosen to differ in lane width, length and lane count.

    The same scenario, map and seed give the same sites in the same order. Fewer than `n`
    come back when fewer fit; none fitting is a LoweringError saying what was needed. The short
    straight sites follow every exact fit on a long one, chosen among themselves the same way.
    """
    if n < 1:
        raise ValueError(f"n must be at least 1, not {n}")
    kind = scenario.road.kind if isinstance(scenario.road.kind, RoadKind) else None
    needs = scenario_needs(scenario)
    sites = find_sites(road_map, kind, min_length=min_length)
    matches = [m for site in sites if (m := match_site(site, needs, clamp=clamp)) is not None]
    chosen = _ranked(matches, n, seed, needs, scenario.crash.type is CrashType.FRONTAL)
    if len(chosen) < n or not all(m.exact for m in chosen):
        chosen = _with_short(chosen, n, seed, needs, short_sites(road_map, kind, min_length=min_length), clamp)
    if not chosen:
        could_clamp = not clamp and any(match_site(site, needs, clamp=True) for site in sites)
        every_site = find_sites(road_map, min_length=min_length)
        raise LoweringError(_no_fit(scenario, needs, road_map, every_site, could_clamp))
    return chosen


def _with_short(
    chosen: list[SiteMatch], n: int, seed: int, needs: tuple[Need, ...], short: list[Site], clamp: bool
) -> list[SiteMatch]:
    """The long sites' picks with the short straight sites (a city block) after every exact fit on a
    long one: a map with enough long sites is staged as without them, and one of short blocks still
    hosts what fits in them. An exact fit on a short site goes before a clamped one on a long site: it
    keeps the lanes the record states, which clamping changes."""
    found = [m for site in short if (m := match_site(site, needs, clamp=clamp)) is not None]
    if not found:
        return chosen  # as picked, in the order the picking gave (oblique frontal sites first)
    exact = [m for m in chosen if m.exact]
    last = pick_diverse(found, n - len(exact), seed)  # exact fits first, as among the long sites
    clamped = [m for m in chosen if not m.exact]
    return (exact + [m for m in last if m.exact] + clamped + [m for m in last if not m.exact])[:n]


def _ranked(matches: list[SiteMatch], n: int, seed: int, needs: tuple[Need, ...], frontal: bool) -> list[SiteMatch]:
    """Up to `n` of the matches, in the order they are tried (`pick_diverse`)."""
    if frontal:
        # a frontal crash between two cars crossing straight over needs their arms oblique: sites
        # where they are come first, so a right-angled grid's crossings do not use up the spares
        oblique = [m for m in matches if _oblique(m, needs)]
        if oblique and len(oblique) < len(matches):
            chosen = pick_diverse(oblique, n, seed)
            rest = [m for m in matches if not any(m is o for o in oblique)]
            return chosen + pick_diverse(rest, n - len(chosen), seed) if len(chosen) < n else chosen
    return pick_diverse(matches, n, seed)


def _oblique(match: SiteMatch, needs: tuple[Need, ...]) -> bool:
    """Whether two participants going straight over a junction from two arms approach at an angle
    a frontal crash accepts (opposite arms do: head on); True when the needs are of another kind
    (a turn, an unplaced participant, a T's stem that must turn), where the arms' angle does not decide it."""
    across = [n for n in needs if n.placed and n.move in (None, ActionKind.GO_ACROSS)]
    if match.site.kind is not RoadKind.INTERSECTION or len(across) != 2 or len(needs) != 2:
        return True
    arms = [match.arm_for(n.heading) for n in across if n.heading is not None]
    if len(arms) != 2 or arms[0] is None or arms[1] is None or arms[0].id == arms[1].id:
        return True
    return abs(angle_diff(arms[0].heading, arms[1].heading)) >= FRONTAL_ARMS


def match_site(site: Site, needs: tuple[Need, ...], *, clamp: bool = False) -> SiteMatch | None:
    """The best way to stage `needs` on `site`: an exact fit under the least rotation, else the
    rotation with the fewest clamps (when allowed); None when no rotation fits."""
    found = site_rotations(site, needs, clamp=clamp)
    return found[0] if found else None


def site_rotations(site: Site, needs: tuple[Need, ...], *, clamp: bool = False) -> list[SiteMatch]:
    """Every rotation under which `needs` fit `site`, best first: fewest clamps; then the most
    participants without a stated manoeuvre that can go straight on (what lowering plans for
    them), so that a T's stem is left to turners; then the rotation nearest to none."""
    order = sorted(ROTATIONS, key=lambda r: (abs(angle_diff(r + site.orientation, 0.0)), r))
    found = [m for rotation in order if (m := _fit(site, needs, rotation, clamp)) is not None]
    return sorted(found, key=lambda m: (len(m.clamped), -_straight_on(site, needs, m)))


def _straight_on(site: Site, needs: tuple[Need, ...], match: SiteMatch) -> int:
    count = 0
    for need in needs:
        placement = match.placement(need.participant)
        if need.move is not None or placement is None or placement.arm is None or site.kind is RoadKind.STRAIGHT:
            continue
        arm = site.arm(placement.arm)
        count += any(c.direction == "s" for c in site.connections_from(arm))
    return count


def _fit(site: Site, needs: tuple[Need, ...], rotation: int, clamp: bool) -> SiteMatch | None:
    slots = {h: (HEADING_DEGREES[h] + rotation) // 90 for h in Heading}
    notes: list[str] = []
    placements = []
    for need in needs:
        site_heading = None
        if need.heading is not None:
            site_heading = round((HEADING_DEGREES[need.heading] + rotation + site.orientation) % 360.0, 6)
        if not need.placed:
            widest = max(len(a.incoming) for a in site.arms)
            if not _lanes_ok(need.lanes, widest, f"{need.participant}: the widest arm", clamp, notes):
                return None
            lane = min(need.lane, widest) if need.lane else None
            placements.append(Placement(need.participant, need.heading, site_heading, None, lane))
            continue
        assert need.heading is not None
        arm = site.arm_in_slot(slots[need.heading])
        if arm is None or not arm.incoming or not _move_ok(site, arm, need, clamp, notes):
            return None
        have = len(arm.incoming)
        if not _lanes_ok(need.lanes, have, f"{need.participant}: arm {arm.id}", clamp, notes):
            return None
        lane = min(need.lane, have) if need.lane else None
        placements.append(Placement(need.participant, need.heading, site_heading, arm.id, lane))
    arms = tuple((h, arm.id if (arm := site.arm_in_slot(slots[h])) else None) for h in Heading)
    return SiteMatch(site, rotation, arms, tuple(placements), tuple(notes))


def has_shape(site: Site, needs: tuple[Need, ...]) -> bool:
    """Whether the site has the shape the needs ask for: its lanes, and its arms where the moves lead
    (a move its map draws no connection for, laid across by the arms' geometry, counts: the road is
    there). A fit only with lanes clamped is a site of another shape."""
    return any(all(note.endswith(BY_GEOMETRY) for note in m.clamped) for m in site_rotations(site, needs, clamp=True))


def _lanes_ok(needed: int, have: int, what: str, clamp: bool, notes: list[str]) -> bool:
    if needed <= have:
        return True
    if clamp:
        notes.append(f"{what} has {have} of the {needed} lanes needed; lane numbers above {have} clamped to {have}")
    return clamp


def _move_ok(site: Site, arm: Arm, need: Need, clamp: bool, notes: list[str]) -> bool:
    """Whether the arm has what the participant's manoeuvre and wrong-way driving need."""
    if need.against_start and not arm.outgoing:
        return False
    if need.move is None:
        return True
    if need.move is ActionKind.U_TURN:
        targets: list[Arm] = [arm] if arm.outgoing else []
    elif site.kind is RoadKind.STRAIGHT:
        return True  # a turn off a straight road goes into a driveway or a side road off the map
    else:
        directions = JUNCTION_MOVES[need.move]
        ids = {c.to_lane for c in site.connections_from(arm) if c.direction in directions}
        targets = [a for a in site.arms if any(lane.id in ids for lane in a.outgoing)]
        if not targets and clamp and (across := geometric_exit(site, arm, need.move)) is not None:
            # the map draws no such way across: laid by the arms' geometry (lower/routes.py), after exact fits
            targets = [across]
            notes.append(
                f"{need.participant}: the junction has no {need.move.value} connection from arm {arm.id}; "
                + BY_GEOMETRY
            )
    if need.against_after:
        targets = [a for a in targets if a.incoming]
    if not targets:
        return False
    widest = max(len(a.outgoing) for a in targets)
    what = f"{need.participant}: the road its {need.move.value} enters"
    return _lanes_ok(need.to_lanes, widest, what, clamp, notes)


# Where each junction move leaves a junction, in places of its compass cross clockwise from the arm it enters by.
MOVE_SLOTS = {ActionKind.TURN_LEFT: 1, ActionKind.GO_ACROSS: 2, ActionKind.TURN_RIGHT: 3}


def geometric_exit(site: Site, arm: Arm, move: ActionKind) -> Arm | None:
    """The arm a move leaves a junction by when the map has no connection for it: the arm in the
    move's place in the compass cross, if traffic leaves along it and it is another arm. An OpenDRIVE
    junction holds only the connecting roads its author drew (netconvert makes SUMO's connections
    from them alone), and a crossing of two-way roads without its left turns is still one a car can
    turn left across: the road model, its arms' headings and lanes, says where that turn leads."""
    if move not in MOVE_SLOTS or site.kind is RoadKind.STRAIGHT:
        return None
    target = site.arm_in_slot((arm.slot + MOVE_SLOTS[move]) % 4)
    return target if target is not None and target.outgoing and target.id != arm.id else None


def features(match: SiteMatch) -> tuple[float, float, float]:
    """What makes sites differ for a test: mean lane width, shortest arm, most lanes."""
    return (match.site.mean_width, match.site.min_length, float(match.site.lanes))


def pick_diverse(matches: list[SiteMatch], n: int, seed: int) -> list[SiteMatch]:
    """Greedy farthest-point choice on normalized features; exact fits before clamped ones.

    The pool is shuffled by `random.Random(seed)` after sorting by site id, so the first pick
    and every tie depend on the seed alone.
    """
    pool = sorted(matches, key=lambda m: m.site.id)
    random.Random(seed).shuffle(pool)
    raw = [features(m) for m in pool]
    lows = [min(column) for column in zip(*raw, strict=True)]
    spans = [max(column) - low or 1.0 for column, low in zip(zip(*raw, strict=True), lows, strict=True)]
    vectors = {
        id(m): tuple((v - lo) / s for v, lo, s in zip(f, lows, spans, strict=True))
        for m, f in zip(pool, raw, strict=True)
    }
    chosen: list[SiteMatch] = []
    for group in ([m for m in pool if m.exact], [m for m in pool if not m.exact]):
        while group and len(chosen) < n:
            pick = group[0] if not chosen else max(group, key=lambda m: _gap(vectors, m, chosen))
            chosen.append(pick)
            group.remove(pick)
    return chosen


def _gap(vectors: dict[int, tuple[float, ...]], match: SiteMatch, chosen: list[SiteMatch]) -> float:
    return min(math.dist(vectors[id(match)], vectors[id(c)]) for c in chosen)


KIND_NAMES: dict[RoadKind, tuple[str, str]] = {
    RoadKind.INTERSECTION: ("an intersection", "intersections"),
    RoadKind.T_JUNCTION: ("a T-junction", "T-junctions"),
    RoadKind.STRAIGHT: ("a straight road", "straight roads"),
}


def _no_fit(
    scenario: Scenario, needs: tuple[Need, ...], road_map: RoadMap, sites: list[Site], could_clamp: bool
) -> Diagnostic:
    kind = KIND_NAMES[scenario.road.kind][0] if isinstance(scenario.road.kind, RoadKind) else "a site of any kind"
    asked = "; ".join(n.describe() for n in needs) or "no participants"
    counts = Counter(s.kind for s in sites)
    have = ", ".join(f"{counts[k]} {KIND_NAMES[k][1]}" + _most_lanes(sites, k) for k in RoadKind)
    message = f"no site of {road_map.name} fits scenario '{scenario.name}': it needs {kind} with {asked}"
    if isinstance(scenario.road.kind, RoadKind) and not counts[scenario.road.kind]:
        message = f"{road_map.name} has no {kind.split(' ', 1)[1]} for scenario '{scenario.name}' ({asked})"
    message += f"; the map has {have}"
    if isinstance(scenario.road.kind, RoadKind) and not counts[scenario.road.kind]:
        message += ramps(road_map, scenario.road.kind)
    of_kind = [site for site in sites if site.kind is scenario.road.kind]
    if of_kind and not any(all(arm.two_way for arm in site.arms) for site in of_kind):
        # say so plainly: a divided road's carriageways are staged one way at a time (straights.MEDIAN_MAX),
        # unless the map describes the ground between them as open (medians.py)
        message += (
            f"; none of its {len(of_kind)} {KIND_NAMES[scenario.road.kind][1]} is two-way throughout"
            " (divided by a barrier, a kerb or ground the map does not describe as open)"
        )
    if of_kind and len(needs) > 1:
        # which participant the map's sites of this kind fail, each need on its own (any rotation)
        alone = [sum(match_site(site, (need,), clamp=True) is not None for site in of_kind) for need in needs]
        fits = ", ".join(f"{need.participant} {count}" for need, count in zip(needs, alone, strict=True))
        message += f"; of its {len(of_kind)} {KIND_NAMES[scenario.road.kind][1]}, each participant alone fits: {fits}"
    hint = "some sites fit with fewer lanes; match with clamp=True to use them" if could_clamp else None
    return Diagnostic(message, scenario.road.meta.where("kind") or scenario.meta.span, hint=hint)


def _most_lanes(sites: list[Site], kind: RoadKind) -> str:
    most = max((s.lanes for s in sites if s.kind is kind), default=0)
    return f" (at most {most} lane{'s' if most > 1 else ''} per direction)" if most else ""
