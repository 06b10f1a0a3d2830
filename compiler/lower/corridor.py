"""Moves within one road: the actions a vehicle performs between two junctions.

A `Corridor` is one road seen in a direction of travel: its own lanes (right-most first)
and the other direction's lanes, all as lines running the way the vehicle drives. A
`Drive` walks along it applying actions to the line it follows: lane changes, crossing
into the other direction's lanes (retrograde), U-turns, and leaving the road to either side
or entering it from a driveway. Each action takes a stretch of the line, recorded as an event.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from sovarc.compiler.crashes import LINE_TOLERANCE
from sovarc.compiler.geometry.angles import heading_vector
from sovarc.compiler.geometry.bodies import corner_array
from sovarc.compiler.geometry.frame import Band
from sovarc.compiler.geometry.polyline import Point, Polyline, bezier, blend, concat
from sovarc.compiler.lower import kturn
from sovarc.compiler.lower.route import Manoeuvre, change_length, swept_change_length
from sovarc.compiler.lower.uturn import choose, too_narrow, u_turn_line
from sovarc.compiler.maps import Arm, LaneInfo
from sovarc.compiler.maps.sites import MEDIAN_MAX
from sovarc.compiler.vehicles import CAR, Body
from sovarc.dsl.errors import Diagnostic, LoweringError
from sovarc.dsl.ir import ActionKind, Side

OFF_ROAD = 6.0  # m beyond the road's edge that a driveway reaches
DRIVEWAY = 8.0  # m of driveway before (or after) the curve
# m sideways a driveway turn's corner reaches: a quarter turn of about 10 m mean radius (some
# 18 km/h at the planned 2.5 m/s^2 sideways), as across a road of one lane each way. Across a wider
# road the car turns such a corner and drives on straight over the rest: a curve as wide as the road
# crossed the car's own lane at a shallow angle, still facing along it, as no driver turns. A plan's
# body trails its front bumper along the heading (swing.py), so a tight corner swings the rear out
# behind the turn: where a lane lies on that side, the corner widens (CORNER_STEP at a time, up to
# the whole road) until the rear stays within the line, as a driver eases into a turn beside traffic.
CORNER_REACH = 11.25
CORNER_STEP = 1.0
SWING_MARGIN = 0.15  # m kept in hand when a long body's rear swings out in a lane change
OPEN_SLACK = 0.5  # m: an open median measured here may exceed the site's (sampled every 2 m) by this


@dataclass(frozen=True)
class Corridor:
    own: tuple[LaneInfo, ...]  # right-most first, shapes in the direction of travel
    other: tuple[LaneInfo, ...]  # the other direction's lanes, right-most (of theirs) first

    @classmethod
    def entering(cls, arm: Arm) -> Corridor:
        """The road of `arm` driven towards the junction (or along a straight site's heading)."""
        return cls(arm.incoming, arm.outgoing)

    @classmethod
    def leaving(cls, arm: Arm) -> Corridor:
        return cls(arm.outgoing, arm.incoming)

    def turned(self) -> Corridor:
        return Corridor(self.other, self.own)

    def own_line(self, number: int) -> Polyline:
        return Polyline(self.own[_clamp(number, len(self.own)) - 1].shape)

    def other_line(self, number: int) -> Polyline:
        """The other direction's lane `number`, as a line running our way."""
        return Polyline(self.other[_clamp(number, len(self.other)) - 1].shape).reversed()

    def half_width(self, median: float = 0.0) -> tuple[float, float]:
        """Distance from the centre of our lane 1 to the road's right edge, and to its far left edge
        (across `median` metres of open ground between the directions)."""
        right = self.own[0].width / 2.0
        left = sum(lane.width for lane in self.own) - right + median + sum(lane.width for lane in self.other)
        return right, left


def _clamp(number: int, count: int) -> int:
    return min(max(number, 1), count)


@dataclass
class Drive:
    """Builds a line along a corridor, one action at a time, from arc length `cursor` on."""

    corridor: Corridor
    line: Polyline
    lane: int  # current lane number; in `other` lanes when `against` is set
    against: bool = False
    speed: float = 13.9  # m/s, the nominal speed: sets how long a lane change is
    stretches: dict[int, tuple[float, float]] = field(default_factory=dict)
    lanes: set[str] = field(default_factory=set)
    edges: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    start_off_road: bool = False
    left_road: bool = False
    wrong_way_lane: int | None = None  # the lane of the other direction to drive in when retrograde
    site: str = ""  # the site's id, for errors
    median: float = 0.0  # m: the open median the site's directions lie apart by, crossable (Site.median)
    manoeuvres: list[Manoeuvre] = field(default_factory=list)  # three-point turns, on `line`
    body: Body = CAR  # what drives it: the room a turn needs is its body's
    junction: tuple[float, float] | None = None  # where its junction move begins and ends on `line`
    wide: bool = False  # it takes the junction's corner wide (wide.py), moving out of its lane before it

    def __post_init__(self) -> None:
        self._use(self.corridor.own[self.lane - 1])

    def _use(self, lane: LaneInfo) -> None:
        # a lane chained through pass-through nodes runs on several SUMO lanes and edges, in order
        self.lanes.update(lane.lanes)
        self.edges.extend(edge for edge in lane.edges if edge not in self.edges)

    def _target(self, number: int, against: bool) -> Polyline:
        lanes = self.corridor.other if against else self.corridor.own
        number = _clamp(number, len(lanes))
        self._use(lanes[number - 1])
        self.lane, self.against = number, against
        return self.corridor.other_line(number) if against else self.corridor.own_line(number)

    def change_lane(self, index: int, at: float, to: int | Side | None) -> float:
        number = self.lane + (1 if to is Side.LEFT else -1) if isinstance(to, Side) else to or self.lane + 1
        count = len(self.corridor.other if self.against else self.corridor.own)
        if not 1 <= number <= count or number == self.lane:
            self.notes.append(f"action {index + 1}: lane {number} does not exist here; changed to a neighbour lane")
            number = self.lane - 1 if self.lane > 1 else self.lane + 1
            if number > count:
                return at  # a one-lane road: nothing to change to
        for n in range(self.lane + (1 if number > self.lane else -1), number + (1 if number > self.lane else -1)):
            self._use((self.corridor.other if self.against else self.corridor.own)[n - 1])
        return self._blend(index, at, self._target(number, self.against))

    def _lane_width(self) -> float:
        lanes = self.corridor.other if self.against else self.corridor.own
        return lanes[_clamp(self.lane, len(lanes)) - 1].width

    def _change_length(self, lanes: float) -> float:
        """How long a move across `lanes` lane widths takes: long enough for the speed, and for the
        body's rear not to swing over the far line of the lane it leaves (the oracle's tolerance
        less a margin for the synthesized path). A body no longer than the car changes lanes as a car
        always has: its swing is within the shortest change but where the road is wide or the move
        long (a swerve into an oncoming lane past a gap), and a car's plans are not to change."""
        width = self._lane_width()
        room = width / 2.0 + LINE_TOLERANCE - self.body.width / 2.0 - SWING_MARGIN
        if self.median > 0.0 and lanes > 1.0:
            # across a road with an open median, far wider than its lanes side by side: long enough
            # to keep one lane change's sideways acceleration (the width over the length squared)
            return max(change_length(self.speed) * lanes**0.5, swept_change_length(self.body, lanes * width, room))
        if self.body.length <= CAR.length:
            return change_length(self.speed)
        return max(change_length(self.speed), swept_change_length(self.body, lanes * width, room))

    def shift_to(self, number: int) -> None:
        """Change to lane `number` just before the end of the road (to reach a junction connection)."""
        end = self.line.length - 3.0
        start = max(0.0, end - self._change_length(abs(number - self.lane)))
        if end - start < 8.0:
            raise LoweringError(
                Diagnostic(
                    f"lane {self.corridor.own[0].edge} is {self.line.length:.0f} m long: too short to change lanes"
                )
            )
        target = self._target(number, False)
        self.line = blend(self.line, target, start, end)

    def drift_to(self, number: int, at: float) -> float:
        """Move over to own lane `number` from arc length `at` on (a turn that ends in the lane
        the report names when no junction connection enters it); returns where it is there."""
        end = min(at + self._change_length(abs(number - self.lane)), self.line.length - 5.0)
        if end - at < 8.0:
            return at
        self.line = blend(self.line, self._target(number, False), at, end)
        return end

    def start_in(self, number: int) -> None:
        """Begin in own lane `number` instead (nothing has been placed on the line yet)."""
        self.line = self._target(number, False)

    def retrograde(self, index: int, at: float) -> float:
        """Cross into the other direction's lane: `wrong_way_lane` if set, else the one by the centre line.

        The swerve runs beside that lane: an arm's oncoming edge may begin further on than its own
        lane (a node splits it), and before it the car would cross lanes its route does not hold.
        It crosses a lane line or an open median, never a divided road's (see `over_median`).
        """
        lanes = self.corridor.own if self.against else self.corridor.other
        number = min(self.wrong_way_lane or len(lanes), len(lanes))
        target = self.corridor.own_line(number) if self.against else self.corridor.other_line(number)
        here = min(at, self.line.length - 1.0)
        ahead = self.line.sub(here, self.line.length)  # not the road behind a U-turn
        begins, ends = (here + ahead.project(target.point(s))[0] for s in (0.0, target.length))
        if begins > at + 0.5:
            self.notes.append(
                f"action {index + 1}: swerves {begins - at:.0f} m later, where lane {lanes[number - 1].id} begins"
            )
            at = begins
        self.over_median(index, at, min(at + change_length(self.speed), ends))
        return self._blend(index, at, self._target(number, not self.against), until=ends)

    def over_median(self, index: int, lo: float, hi: float) -> None:
        """Refuse a crossing between the directions, from arc length `lo` to `hi`, where their inner
        lanes lie further apart than MEDIAN_MAX: a median (a kerb, grass, rails) is no lane line,
        just as a divided road's halves make no two-way straight site (maps/sites.py). A median the
        map describes as flat, open ground is crossed (the site's `median`, maps/medians.py)."""
        inner = Polyline(self.corridor.own[-1].shape)
        facing = Polyline(self.corridor.other[-1].shape)
        widths = (self.corridor.own[-1].width + self.corridor.other[-1].width) / 2.0
        gaps = [0.0]
        for s in np.linspace(lo, max(lo, min(hi, self.line.length)), 9):
            beside = inner.point(inner.project(self.line.point(float(s)))[0])
            t, distance = facing.project(beside)
            if 0.5 < t < facing.length - 0.5:  # the other direction runs beside here
                gaps.append(distance - widths)
        if max(gaps) > max(MEDIAN_MAX, self.median + OPEN_SLACK):
            raise LoweringError(
                Diagnostic(
                    f"action {index + 1}: on {self.site}, a median {max(gaps):.1f} m wide divides the road "
                    f"({self.corridor.own[-1].edge} from {self.corridor.other[-1].edge}): "
                    "no lane line to cross into the oncoming lanes"
                )
            )

    def _blend(self, index: int, at: float, target: Polyline, until: float | None = None) -> float:
        """Move across to `target` from arc length `at`, ending by `until` if given."""
        shift = target.project(self.line.point(at))[1]
        end = at + self._change_length(shift / self._lane_width())
        end = min(end, self.line.length - 5.0, self.line.length if until is None else until)
        if end - at < 2.0:
            raise LoweringError(
                Diagnostic(f"action {index + 1}: {self.line.length:.0f} m of road leave no room to move across")
            )
        if end - at < 8.0:
            self.notes.append(f"action {index + 1}: squeezed into {end - at:.0f} m of road")
        self.line = blend(self.line, target, at, end)
        self.stretches[index] = (at, end)
        return end

    def u_turn(self, index: int, at: float, to: int | Side | None) -> float:
        """Turn back on a half circle that keeps the body on the road (see uturn.py), into lane
        `to` of the other direction; without one, into the lane the turn reaches most easily
        (the one by the centre line, unless the road is too narrow to turn into it). A road too
        narrow for a half circle takes a three-point turn (kturn.py)."""
        band = Band.across(self.corridor.own, self.corridor.other, self.median)
        self.lanes.update(lane.id for lane in self.corridor.own + self.corridor.other)  # the whole road
        p0 = self.line.point(at)
        self.corridor = self.corridor.turned()
        count = len(self.corridor.other if self.against else self.corridor.own)
        numbers = [_clamp(to, count)] if isinstance(to, int) else [count, *range(1, count)]
        lines = [self.corridor.other_line(n) if self.against else self.corridor.own_line(n) for n in numbers]
        number, d_to, plan = choose(band, p0, list(zip(numbers, lines, strict=True)), self.body)
        if not plan.fits:
            return self._k_turn(index, at, band, list(zip(numbers, lines, strict=True)))
        if number != numbers[0]:
            self.notes.append(
                f"action {index + 1}: the road is too narrow to U-turn into lane {numbers[0]}; turns into lane {number}"
            )
        target = self._target(number, self.against)
        turn, arc_end, joins = u_turn_line(band, p0, target, d_to, plan)
        head = self.line.sub(0.0, at)
        rest = [target.sub(joins, target.length)] if target.length - joins > 0.5 else []
        self.line = concat([head, turn, *rest])
        end = head.length + arc_end
        self.stretches[index] = (at, end)
        return end

    def _k_turn(self, index: int, at: float, band: Band, lanes: list[tuple[int, Polyline]]) -> float:
        """The U-turn of action `index` at arc length `at` in legs, into the first of `lanes` (number
        and line, the preferred first) they reach; the legs are recorded as a manoeuvre. It begins
        halfway along the road at the earliest: stopping and reversing takes some ten seconds more
        than one sweep, and traffic behind the car then has the road's length to come up."""
        at = max(at, kturn.ALONG * self.line.length)
        found = kturn.choose(band, self.line.point(at), lanes, self.body)
        if found is None:
            raise too_narrow(band, f"on {self.site}, the U-turn of action {index + 1}", kturn.MAX_LEGS)
        number, d_to, plan = found
        if number != lanes[0][0]:
            self.notes.append(f"action {index + 1}: a turn in legs cannot end in lane {lanes[0][0]}; ends in {number}")
        target = self._target(number, self.against)
        turn = kturn.k_turn_line(band, self.line.point(at), target, d_to, plan)
        head = self.line.sub(0.0, at)
        rest = [target.sub(turn.joins, target.length)] if target.length - turn.joins > 0.5 else []
        self.line = concat([head, turn.line, *rest])
        self.record_turn(index, turn, head.length, band, plan.count)
        end = head.length + float(turn.s[-1])
        self.stretches[index] = (at, end)
        return end

    def record_turn(self, index: int, turn: kturn.KTurnLine, shift: float, band: Band, legs: int) -> None:
        """Keep a turn in legs as a manoeuvre of the line (it begins `shift` metres along it), with a note."""
        stops = tuple(s + shift for s in turn.stops)
        self.manoeuvres.append(Manoeuvre(index, turn.s + shift, turn.heading, stops, turn.gears))
        name = {3: "a three-point turn", 5: "a five-point turn"}.get(legs, f"{legs} legs")
        who = f"action {index + 1}" if index >= 0 else "U-turn"  # one no action names, at a junction
        self.notes.append(
            f"{who}: the road is {band.left - band.right:.1f} m wide, too narrow for a U-turn in one "
            f"sweep: turns in {legs} legs ({name}), forward and reverse"
        )

    def _driveway(self, side: Side, against: bool) -> tuple[float, float]:
        """How far sideways a driveway on `side` lies from the line, and the turn (degrees) towards it.

        A driveway on the left is reached across the other direction's lanes, which become
        lanes the vehicle may use; driving against traffic, the road's sides swap.
        """
        right, left = self.corridor.half_width(self.median)
        if side is Side.LEFT:
            for lane in self.corridor.other:
                self._use(lane)
        near, far = (left, right) if against else (right, left)
        lateral = (near if side is Side.RIGHT else far) + OFF_ROAD
        return lateral, 90.0 if side is Side.RIGHT else -90.0

    def leave(self, index: int, at: float, side: Side) -> float:
        """Turn off the road into a driveway or side road on `side`."""
        heading = self.line.heading(at)
        lateral, turn = self._driveway(side, self.against)
        n = heading_vector(heading + turn)
        p0 = self.line.point(at)
        reach, corner, curve = self._corner(p0, heading, turn, lateral)
        p1 = (corner[0] + (lateral - reach) * n[0], corner[1] + (lateral - reach) * n[1])
        across = [Polyline([corner, p1])] if lateral > reach else []  # straight over the rest of the road
        tail_end = (p1[0] + DRIVEWAY * n[0], p1[1] + DRIVEWAY * n[1])
        head = self.line.sub(0.0, at)
        self.line = concat([head, curve, *across, Polyline([p1, tail_end])])
        self.left_road = True
        end = head.length + curve.length + lateral - reach
        self.stretches[index] = (at, end)
        return end

    def _corner(self, p0: Point, heading: float, turn: float, lateral: float) -> tuple[float, Point, Polyline]:
        """A driveway turn's corner from `p0`: its sideways reach, its end and its curve (CORNER_REACH)."""
        d, n = np.asarray(heading_vector(heading)), np.asarray(heading_vector(heading + turn))
        reaches = [*np.arange(CORNER_REACH, lateral, CORNER_STEP), lateral] if lateral > CORNER_REACH else [lateral]
        room = self._lane_width() / 2.0 + LINE_TOLERANCE  # the lane-line tolerance every oracle allows
        for k, reach in enumerate(reaches):
            corner = tuple(np.asarray(p0) + 0.8 * reach * d + reach * n)
            curve = bezier(p0, heading, corner, heading + turn)  # type: ignore[arg-type]
            if k == len(reaches) - 1 or not self._lane_behind(turn):
                return float(reach), corner, curve  # type: ignore[return-value]
            fine = bezier(p0, heading, corner, heading + turn, samples=64)  # type: ignore[arg-type]
            if _swing(fine, n, self.body) <= room:  # measured on the curve itself, not its 16 chords
                return float(reach), corner, curve  # type: ignore[return-value]
        raise AssertionError("unreachable: the last reach is taken")

    def _lane_behind(self, turn: float) -> bool:
        """Whether a lane lies beside the car on the side away from its turn (where its rear swings)."""
        if self.against:  # in the other direction's lanes: its lane 1 is on the car's left, its own lanes on the right
            return True if turn < 0.0 else self.lane > 1
        if turn < 0.0:  # a left turn swings the rear to the right: lanes numbered below its own
            return self.lane > 1
        return self.lane < len(self.corridor.own) or bool(self.corridor.other)

    def enter(self, index: int, at: float, side: Side) -> float:
        """Start in a driveway on `side` and drive onto the road, reaching the current lane at `at`."""
        heading = self.line.heading(at)
        lateral, turn = self._driveway(side, against=False)  # it joins the road on its own side
        reach = min(lateral, CORNER_REACH)  # straight over the road beyond its corner (see CORNER_REACH)
        back = reach * 0.8
        d, n = heading_vector(heading), heading_vector(heading + turn)
        p1 = self.line.point(at)
        corner = (p1[0] - back * d[0] + reach * n[0], p1[1] - back * d[1] + reach * n[1])
        p0 = (corner[0] + (lateral - reach) * n[0], corner[1] + (lateral - reach) * n[1])
        facing = (heading + turn + 180.0) % 360.0
        start = (p0[0] - DRIVEWAY * heading_vector(facing)[0], p0[1] - DRIVEWAY * heading_vector(facing)[1])
        curve = bezier(corner, facing, p1, heading)
        across = [Polyline([p0, corner])] if lateral > reach else []
        tail = self.line.sub(at, self.line.length)
        self.line = concat([Polyline([start, p0]), *across, curve, tail])
        self.start_off_road = True
        end = DRIVEWAY + lateral - reach + curve.length
        self.stretches[index] = (0.0, end)
        return end


def side_of(kind: ActionKind, neighbours: tuple[ActionKind, ...], default: Side) -> Side:
    """Which side a driveway move goes to: left when a left turn goes with it."""
    if kind is ActionKind.TURN_LEFT or ActionKind.TURN_LEFT in neighbours:
        return Side.LEFT
    if kind is ActionKind.TURN_RIGHT or ActionKind.TURN_RIGHT in neighbours:
        return Side.RIGHT
    return default


def _swing(curve: Polyline, towards: np.ndarray, body: Body) -> float:
    """How far the body's corners reach from the curve's start, away from the turn (`towards`), as its
    front follows `curve` (its heading along the curve, as a plan's body does): the farthest is the
    rear corner on the side away from the turn, swung out as the front comes round."""
    at = np.linspace(0.0, curve.length, 120)
    poses = np.column_stack([curve.points_at(at), curve.headings(at)])
    corners = corner_array(poses, body.length, body.width)
    return float(((corners - poses[0, :2]) @ -towards).max())
