"""Straight sites: stretches of bounded curvature along a road, wherever its edges split.

A road (`RoadNet.chain`) is walked along one direction's inner car lane, sampled every STEP
metres. At each sample it is known how many car lanes each direction has and whether the
other direction runs beside it with no median between (a two-way road). A straight stretch
keeps both of these and turns little: its direction of travel spreads over no more than its
length allows at STRAIGHT_RADIUS, and never more than STRAIGHT_TURN. A long stretch is cut
into several sites of at most SITE_MAX metres.

The walk cuts a road into stretches by the rule for `min_length` (the turn a stretch may take grows
with it); those that come out shorter than `min_length` but at least `floor` long are kept apart, as
short sites (a city block of 50-70 m between junctions): the site search tries them last (search.py),
so the long sites and every choice among them are as they were without them.

A median the map describes as flat, open ground (medians.py) does not divide a road: where the
edges on both sides are of roads with one, the directions up to OPEN_MEDIAN_MAX apart are one
two-way road, and the site records how wide its median is (`Site.median`) for lowering to cross.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np
from sovarc.compiler.geometry.polyline import Point, heading_between, point_at, shape_length
from sovarc.compiler.maps.geometry import fit_frame
from sovarc.compiler.maps.roads import LaneInfo, RoadNet, cumulative, cut, is_road, project, project_many
from sovarc.compiler.maps.site import Arm, Site
from sovarc.dsl.ir import RoadKind

STEP = 2.0  # m between samples along a road
STRAIGHT_RADIUS = 400.0  # m: a straight stretch turns no more than a curve of this radius would
STRAIGHT_TURN = 15.0  # degrees: and never more than this in all
SITE_MAX = 250.0  # m: a stretch twice as long or more gives several sites, each at least this long
LOCAL = 20.0  # m: the chords on which a bend is judged
LOCAL_SLACK = 1.5  # a bend up to this many times STRAIGHT_RADIUS's turn over LOCAL is noise, not a bend
SNAP = STEP + 0.5  # m: a stretch this close to its edges' ends runs to them
# Inner lane edges of the two directions further apart than this: a divided road. Its halves
# are staged as one-way roads, because a median (often with paths or rails on it) is no lane
# line a wrong-way or overtaking car can cross.
MEDIAN_MAX = 1.0  # m
# The widest flat, unobstructed median taken as one road's: within about 10 m a car that leaves its
# lanes reaches the oncoming ones, which is why design guides (AASHTO's Roadside Design Guide: 30 ft)
# ask for a median barrier below that width on fast roads, and cross-median crashes happen there.
OPEN_MEDIAN_MAX = 10.0  # m


def straight_sites(
    roads: RoadNet, min_length: float, open_edges: frozenset[str] = frozenset(), *, floor: float | None = None
) -> tuple[list[Site], list[Site]]:
    """The straight sites at least `min_length` long, and the short ones: the stretches the same walk
    found shorter than that but at least `floor` long (none when `floor` is None).
    `open_edges`: the edges whose road has a median a car can drive across (medians.py)."""
    shortest = min_length if floor is None else min(floor, min_length)
    sites: list[Site] = []
    short: list[Site] = []
    done: set[str] = set()
    for edge in sorted((e for e in roads.net.getEdges() if is_road(e)), key=lambda e: e.getID()):
        if edge.getID() in done or not roads.lanes(edge):
            continue
        chain = roads.chain(edge, through=True)
        done.update(e.getID() for e in chain)
        road = _Road(roads, chain, open_edges)
        for lo, hi, two_way, median in road.stretches(min_length, shortest):
            if two_way and road.partner is not None and road.partner.first < road.first:
                continue  # the partner's walk stages the two-way stretch (it sees the same one)
            count = max(1, int((hi - lo) // max(SITE_MAX, min_length)))
            step = (hi - lo) / count
            for k in range(count):
                directions = road.cut(lo + k * step, lo + (k + 1) * step, two_way)
                if directions is None:
                    continue
                if not two_way and len(directions[0][1]) < 2:
                    continue  # a one-way single lane is not a road to stage a crash on
                site = _site(directions, median)
                if hi - lo >= min_length:
                    sites.append(site)
                elif site.min_length >= shortest:  # both directions hold a short site's length, not one alone
                    short.append(site)
    return sites, short


def _site(directions: list[tuple[str, tuple[LaneInfo, ...]]], median: float) -> Site:
    axes = [lanes[len(lanes) // 2].shape for _, lanes in directions]
    headings = [heading_between(a[0], a[-1]) for a in axes]
    frame = fit_frame(headings)
    arms = []
    for k, (_name, own) in enumerate(directions):
        other = directions[1 - k][1] if len(directions) == 2 else ()
        arms.append(Arm(own[0].edge, round(headings[k], 6), frame.slots[k], own, other, own[0].length))
    middles = [point_at(a, shape_length(a) / 2.0) for a in axes]
    centre = (sum(p[0] for p in middles) / len(middles), sum(p[1] for p in middles) / len(middles))
    return Site(
        id="road:" + "|".join(name for name, _ in directions),
        kind=RoadKind.STRAIGHT,
        centre=(round(centre[0], 3), round(centre[1], 3)),
        orientation=frame.orientation,
        arms=tuple(sorted(arms, key=lambda arm: arm.slot)),
        median=median,
    )


class _Direction:
    """One direction of a road: its edges and its inner car lane, chained."""

    def __init__(self, roads: RoadNet, edges: list[Any], open_edges: frozenset[str]) -> None:
        self.roads = roads
        self.edges = edges
        self.open = np.asarray([e.getID() in open_edges for e in edges])  # per edge: its median is crossable
        self.first = edges[0].getID()
        shape: list[Point] = []
        ends = []
        for e in edges:
            inner = roads.lanes(e)[-1].shape
            shape += inner if not shape or inner[0] != shape[-1] else inner[1:]
            ends.append(len(shape) - 1)
        self.points = np.asarray(shape, dtype=float)
        self.s = cumulative(self.points)
        self.bounds = np.asarray([0.0, *(self.s[k] for k in ends)])  # arc length where each edge ends
        self.bounds[-1] = self.s[-1]
        self.counts = [len(roads.lanes(e)) for e in edges]
        self.widths = [roads.lanes(e)[-1].width for e in edges]

    @property
    def length(self) -> float:
        return float(self.s[-1])

    def edge_at(self, s: np.ndarray) -> np.ndarray:
        return np.clip(np.searchsorted(self.bounds, s, side="right") - 1, 0, len(self.edges) - 1)

    def sample(self, s: np.ndarray) -> np.ndarray:
        return np.column_stack([np.interp(s, self.s, self.points[:, i]) for i in (0, 1)])

    def lanes_between(
        self,
        lo: float,
        hi: float,
    ) -> tuple[str, tuple[LaneInfo, ...]] | None:
        """Its car lanes from arc length `lo` to `hi`, chained over the edges there and cut to the stretch."""
        # a stretch ends at the first sample past it: up to a sample into the next edge, which is left out
        middle = (lo + hi) / 2.0
        first = int(self.edge_at(np.array([min(lo + SNAP, middle)]))[0])
        last = int(self.edge_at(np.array([max(hi - SNAP, middle)]))[0])
        lo, hi = max(lo, float(self.bounds[first])), min(hi, float(self.bounds[last + 1]))
        # within a sample of its edges' ends, a stretch runs to them
        lo = float(self.bounds[first]) if lo - self.bounds[first] <= SNAP else lo
        hi = float(self.bounds[last + 1]) if self.bounds[last + 1] - hi <= SNAP else hi
        edges = self.edges[first : last + 1]
        # tiny edges between lane sections may have other lanes: the longest edge names the lanes
        spans = [min(hi, self.bounds[k + 1]) - max(lo, self.bounds[k]) for k in range(first, last + 1)]
        chained = self.roads.chained(edges, spans.index(max(spans)))
        ends = self.sample(np.array([lo, hi]))
        lanes = []
        for lane in chained:
            points = np.asarray(lane.shape, dtype=float)
            t0, t1 = project(points, ends[0])[0], project(points, ends[1])[0]
            if t1 - t0 < 1.0:
                return None
            shape = cut(lane.shape, t0, t1)
            lanes.append(replace(lane, shape=shape, length=round(shape_length(shape), 3)))
        name = edges[0].getID() + (f"..{edges[-1].getID()}" if len(edges) > 1 else "")
        whole = lo == self.bounds[first] and hi == self.bounds[last + 1]
        if not whole:
            name += f"@{max(0.0, lo - self.bounds[first]):.0f}"
        return name, tuple(lanes)


class _Road:
    """A road walked along one direction (`own`), with the other direction (`partner`) if any."""

    def __init__(self, roads: RoadNet, chain: list[Any], open_edges: frozenset[str]) -> None:
        self.own = _Direction(roads, chain, open_edges)
        self.first = self.own.first
        backs = [
            b for e in chain if (b := roads.reverse(e)) is not None and b.getID() not in {x.getID() for x in chain}
        ]
        self.partner = _Direction(roads, roads.chain(backs[0], through=True), open_edges) if backs else None

    def stretches(self, min_length: float, floor: float) -> list[tuple[float, float, bool, float]]:
        """Straight stretches, cut by the rule for `min_length` and at least `floor` long: (from, to,
        two-way, the widest open median between the directions, 0 for none), in arc length along `own`."""
        own = self.own
        if own.length < floor:
            return []
        s = np.linspace(0.0, own.length, max(2, int(own.length / STEP) + 1))
        points = own.sample(s)
        keys = np.asarray(own.counts)[own.edge_at(s)] * 100
        medians = np.zeros(len(s))
        if self.partner is not None:
            back = self.partner
            reversed_points = back.points[::-1]
            total = back.length
            widest = OPEN_MEDIAN_MAX if own.open.any() and back.open.any() else MEDIAN_MAX
            along, gap = project_many(reversed_points, points, near=widest + 2.0 * max(own.widths + back.widths))
            t = total - along  # arc length along the partner's own direction
            at = back.edge_at(t)
            widths = (np.asarray(back.widths)[at] + np.asarray(own.widths)[own.edge_at(s)]) / 2.0
            median = gap - widths
            crossable = own.open[own.edge_at(s)] & back.open[at] & (median <= OPEN_MEDIAN_MAX)
            beside = (median <= MEDIAN_MAX) | crossable
            medians = np.where(crossable & (median > MEDIAN_MAX), median, 0.0)
            keys = keys + np.where(beside, np.asarray(back.counts)[at], 0)
        headings = np.degrees(np.arctan2(*np.diff(points, axis=0).T)) % 360.0  # compass: atan2(dx, dy)
        keys = np.where(_curved(points), -1, keys)
        found_stretches = []
        start = 0
        n = len(s)
        while start < n - 1:
            end = start + 1  # samples start..end: segments start..end-1
            base = headings[start]
            lo_turn = hi_turn = 0.0
            while end < n - 1 and keys[end] == keys[start]:
                turn = _diff(headings[end], base)
                lo2, hi2 = min(lo_turn, turn), max(hi_turn, turn)
                length = max(s[end + 1] - s[start], min_length)
                if hi2 - lo2 > min(STRAIGHT_TURN, math.degrees(length / STRAIGHT_RADIUS)):
                    break
                lo_turn, hi_turn = lo2, hi2
                end += 1
            if s[end] - s[start] >= floor and keys[start] >= 0:
                median = round(float(medians[start : end + 1].max()), 1)
                found_stretches.append((float(s[start]), float(s[end]), bool(keys[start] % 100 > 0), median))
            start = end
        return found_stretches

    def cut(self, lo: float, hi: float, two_way: bool) -> list[tuple[str, tuple[LaneInfo, ...]]] | None:
        own = self.own.lanes_between(lo, hi)
        if own is None:
            return None
        if not two_way or self.partner is None:
            return [own]
        back = self.partner
        ends = self.own.sample(np.array([lo, hi]))
        reversed_points = back.points[::-1]
        t_hi, t_lo = (back.length - project(reversed_points, p)[0] for p in ends)
        other = back.lanes_between(t_lo, t_hi)
        if other is None:
            return None
        return [own, other]


def _curved(points: np.ndarray) -> np.ndarray:
    """Per sample: whether the road bends there more tightly than STRAIGHT_RADIUS (with some slack
    for the noise of polylines), judged on the chords LOCAL metres before and after it."""
    w = max(1, round(LOCAL / STEP))
    n = len(points)
    k = np.arange(n)
    before, after = np.clip(k - w, 0, n - 1), np.clip(k + w, 0, n - 1)
    back = points[k] - points[before]
    ahead = points[after] - points[k]
    h1 = np.degrees(np.arctan2(back[:, 0], back[:, 1]))
    h2 = np.degrees(np.arctan2(ahead[:, 0], ahead[:, 1]))
    turn = np.abs((h2 - h1 + 180.0) % 360.0 - 180.0)
    valid = (k - w >= 0) & (k + w <= n - 1)
    return valid & (turn > LOCAL_SLACK * math.degrees(LOCAL / STRAIGHT_RADIUS))


def _diff(a: float, b: float) -> float:
    d = (a - b) % 360.0
    return d - 360.0 if d > 180.0 else d
