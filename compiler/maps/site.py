"""What a site is: its arms, their lanes and a junction's connections (found by sites.py and straights.py).

Headings are compass degrees, 0 = north (+y), 90 = east (+x). An arm's heading is the direction of
travel of traffic ENTERING the junction along it; for an exit-only arm, the direction traffic would
enter by. A straight site has one arm per direction of travel: its `incoming` lanes travel in
`heading`, its `outgoing` lanes the other way.
"""

from __future__ import annotations

import statistics
from dataclasses import dataclass

from sovarc.compiler.geometry.polyline import Point
from sovarc.compiler.maps.roads import LaneInfo
from sovarc.dsl.ir import RoadKind


@dataclass(frozen=True)
class Connection:
    """A link through a junction, from the end of one lane to the start of another."""

    from_lane: str
    to_lane: str
    direction: str  # s straight, l/L left/partly left, r/R right/partly right, t turnaround (sites.py)
    via: str | None  # the first internal lane that carries it, if the network has one
    # every SUMO lane between from_lane and to_lane, in order: the internal lanes, and across a
    # junction of several nodes (clusters.py) the lanes of the short edges between them
    path: tuple[str, ...] = ()
    edges: tuple[str, ...] = ()  # the short edges between a junction's nodes it drives, in order


@dataclass(frozen=True)
class Arm:
    """One road at a site. Lanes are ordered right-most first."""

    id: str  # the incoming edge's id, or the outgoing edge's for an exit-only arm
    heading: float  # compass degrees of the traffic on `incoming` (see the module docstring)
    slot: int  # place in the site's compass cross, 0..3
    incoming: tuple[LaneInfo, ...]  # towards the junction (straight site: travelling in `heading`)
    outgoing: tuple[LaneInfo, ...]  # away from the junction (straight site: the other direction)
    length: float  # m, of the incoming lanes (of the outgoing ones for an exit-only arm)

    @property
    def two_way(self) -> bool:
        return bool(self.incoming and self.outgoing)


@dataclass(frozen=True)
class Site:
    """A place of one road kind where a scenario can happen."""

    # 'junction:<SUMO junction id>' ('<id>+<id>...' for a junction of several nodes, clusters.py), or
    # 'road:<direction>[|<other direction>]', a direction named by its
    # first edge ('<first>..<last>' over several), with '@<m>' when it begins or ends inside an edge
    id: str
    kind: RoadKind
    centre: Point  # the junction's point, or the middle of the road
    orientation: float  # degrees in [-45, 45): the compass cross's offset from true north
    arms: tuple[Arm, ...]  # sorted by slot
    connections: tuple[Connection, ...] = ()  # sorted by (from_lane, to_lane); none on a straight road
    junction: str | None = None  # SUMO junction id ('<id>+<id>...' over several nodes)
    control: str | None = None  # SUMO junction type: priority, traffic_light, ... ('/'-joined over several kinds)
    # m: on a straight site, the widest median between its directions that a car may drive across
    # (flat and open, as the map describes it: medians.py); 0 where their lanes lie side by side
    median: float = 0.0

    def arm_in_slot(self, slot: int) -> Arm | None:
        return next((arm for arm in self.arms if arm.slot == slot % 4), None)

    def arm(self, arm_id: str) -> Arm:
        """The arm of that id (a placement's `arm`)."""
        return next(a for a in self.arms if a.id == arm_id)

    def arm_of_lane(self, lane_id: str) -> Arm | None:
        return next((a for a in self.arms if any(lane.id == lane_id for lane in a.incoming + a.outgoing)), None)

    def connections_from(self, arm: Arm) -> tuple[Connection, ...]:
        ids = {lane.id for lane in arm.incoming}
        return tuple(c for c in self.connections if c.from_lane in ids)

    @property
    def lanes(self) -> int:
        """The most lanes any arm has in one direction."""
        return max(max(len(a.incoming), len(a.outgoing)) for a in self.arms)

    @property
    def mean_width(self) -> float:
        return statistics.fmean(lane.width for a in self.arms for lane in a.incoming + a.outgoing)

    @property
    def min_length(self) -> float:
        return min(a.length for a in self.arms)
