"""sovarc's reference ego: a cautious but imperfect driver, as an FMI 2.0 co-simulation FMU.

This file is the FMU's whole source: pythonfmu packs it into SovarcEgo.fmu (see __init__.py), so it
imports nothing but pythonfmu and the standard library. The variables are those of the ego interface
(targets/fmu/INTERFACE.md); a test checks that the built FMU passes `validate_fmu`.

How it drives, every step:
- steering: pure pursuit on the route points, looking ahead further the faster it goes;
- speed: an IDM car-follower towards the speed the route asks for (slower in bends), following the
  nearest object whose body overlaps its path;
- emergency braking: full brakes when an object it sees comes within TTC_BRAKE seconds of touching it,
  both moving on at constant velocity, the ego along its path.
Where it is imperfect, on purpose: it sees only ahead of its front bumper and within SIGHT metres,
predicts others in straight lines, knows no right of way, and brakes no harder than MAX_DECEL.
"""

from __future__ import annotations

import itertools
import math

from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Integer, Real

MAX_OBJECTS = 8
PATH_POINTS = 12
OBJECT_FIELDS = ("x", "y", "heading", "speed", "length", "width")

ACCEL = 2.0  # m/s², IDM maximum acceleration
COMFORT = 2.5  # m/s², IDM comfortable deceleration
HEADWAY = 1.4  # s, IDM time headway
STANDSTILL = 2.5  # m, IDM gap at rest
MAX_DECEL = 7.0  # m/s², the hardest it brakes
LATERAL = 2.5  # m/s², the lateral acceleration it accepts in bends
SIGHT = 60.0  # m, how far it looks
TTC_BRAKE = 1.5  # s, time to collision that triggers full braking
HORIZON = 3.0  # s, how far ahead it predicts
TICK = 0.1  # s, its prediction step
MARGIN = 0.3  # m, added to body radii when predicting contact
PAST_FRONT = 1.0  # m: the nearest point it steers for lies at least this far ahead of its front bumper


class SovarcEgo(Fmi2Slave):
    author = "sovarc"
    description = "sovarc reference ego: IDM + pure pursuit + TTC emergency braking"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.ego_length, self.ego_width, self.ego_wheelbase, self.ego_rear_axle = 4.6, 1.8, 2.76, 3.68
        self.ego_x = self.ego_y = self.ego_heading = self.ego_speed = 0.0
        self.target_speed, self.goal_distance = 10.0, 100.0
        self.path = [[0.0, 0.0] for _ in range(PATH_POINTS)]
        self.obj_count = 0
        self.objects = [dict.fromkeys(OBJECT_FIELDS, 0.0) for _ in range(MAX_OBJECTS)]
        self.accel = self.steer = 0.0
        for name in ("ego_length", "ego_width", "ego_wheelbase", "ego_rear_axle"):
            self.register_variable(Real(name, causality=Fmi2Causality.parameter, variability=Fmi2Variability.tunable))
        for name in ("ego_x", "ego_y", "ego_heading", "ego_speed", "target_speed", "goal_distance"):
            self.register_variable(Real(name, causality=Fmi2Causality.input))
        for k in range(PATH_POINTS):
            for axis in (0, 1):
                self.register_variable(
                    Real(
                        f"path_{'xy'[axis]}_{k + 1}",
                        causality=Fmi2Causality.input,
                        getter=lambda k=k, a=axis: self.path[k][a],
                        setter=lambda v, k=k, a=axis: self.path[k].__setitem__(a, v),
                    )
                )
        self.register_variable(Integer("obj_count", causality=Fmi2Causality.input))
        for k in range(MAX_OBJECTS):
            for field in OBJECT_FIELDS:
                self.register_variable(
                    Real(
                        f"obj_{k + 1}_{field}",
                        causality=Fmi2Causality.input,
                        getter=lambda k=k, f=field: self.objects[k][f],
                        setter=lambda v, k=k, f=field: self.objects[k].__setitem__(f, v),
                    )
                )
        self.register_variable(Real("accel", causality=Fmi2Causality.output))
        self.register_variable(Real("steer", causality=Fmi2Causality.output))

    def do_step(self, current_time, step_size):
        line = _Path([(0.0, 0.0)] + [tuple(p) for p in self.path])
        seen = [o for o in self.objects[: max(0, min(self.obj_count, MAX_OBJECTS))] if _visible(o)]
        self.steer = self._pursue(line)
        accel = self._follow(line, seen)
        if self._time_to_collision(line, seen) < TTC_BRAKE:
            accel = -MAX_DECEL
        self.accel = accel
        return True

    def _pursue(self, line):
        """Pure pursuit from the rear axle towards the path point `reach` metres away."""
        # a bus's front lies further from its rear axle than a car's look-ahead: aim past the front, not at it
        reach = max(6.0, 4.0 + 0.9 * self.ego_speed, self.ego_rear_axle + PAST_FRONT)
        axle = -self.ego_rear_axle
        gx, gy = line.points[-1]
        for px, py in line.points:
            if math.hypot(px - axle, py) >= reach:
                gx, gy = px, py
                break
        alpha = math.atan2(gy, gx - axle)
        distance = max(math.hypot(gx - axle, gy), 1e-3)
        return math.atan(2.0 * self.ego_wheelbase * math.sin(alpha) / distance)

    def _follow(self, line, seen):
        """IDM towards the wanted speed, behind the nearest object on the path."""
        v = max(self.ego_speed, 0.0)
        if self.target_speed < 0.1:  # asked to stand still
            return -min(COMFORT, v / 0.05) if v > 0.0 else 0.0
        wanted = max(min(self.target_speed, math.sqrt(LATERAL / max(line.curvature(40.0), 1e-6))), 1.0)
        free = 1.0 - (v / wanted) ** 4
        leader = None
        for o in seen:
            s, offset, direction = line.locate(o["x"], o["y"])
            if s <= 0.0 or abs(offset) > (self.ego_width + o["width"]) / 2.0 + 0.2:
                continue
            gap = s - o["length"] / 2.0
            if leader is None or gap < leader[0]:
                leader = (gap, o["speed"] * math.cos(math.radians(o["heading"]) - direction))
        cruise = max(ACCEL * free, -COMFORT)  # slowing for a bend or a lower wanted speed is never harsh
        if leader is None:
            return min(cruise, ACCEL)
        gap, lead_speed = leader
        wish = STANDSTILL + v * HEADWAY + v * (v - lead_speed) / (2.0 * math.sqrt(ACCEL * COMFORT))
        interaction = (max(wish, 0.0) / max(gap, 0.1)) ** 2
        return max(min(cruise - ACCEL * interaction, ACCEL), -MAX_DECEL)

    def _time_to_collision(self, line, seen):
        """The first time, within HORIZON, that an object and the ego (along its path) touch."""
        v = max(self.ego_speed, 0.0)
        half = self.ego_length / 2.0
        own = self.ego_width / 2.0 + MARGIN
        best = math.inf
        for o in seen:
            rad = math.radians(o["heading"])
            vx, vy = o["speed"] * math.cos(rad), o["speed"] * math.sin(rad)
            reach = own + o["width"] / 2.0 + MARGIN + (self.ego_length + o["length"]) / 4.0
            if math.hypot(o["x"], o["y"]) > reach + (v + abs(o["speed"])) * HORIZON + half:  # a reversing one too
                continue
            tick = 0.0
            while tick <= min(HORIZON, best):
                ex, ey, eh = line.pose(v * tick - half)
                ox, oy = o["x"] + vx * tick, o["y"] + vy * tick
                if _touch((ex, ey, eh, self.ego_length, own), (ox, oy, rad, o["length"], o["width"] / 2.0 + MARGIN)):
                    best = tick
                    break
                tick += TICK
        return best


def _visible(o):
    return o["x"] > 0.0 and math.hypot(o["x"], o["y"]) <= SIGHT


def _touch(a, b):
    """Two bodies, each two discs along its length, overlap."""
    for ax, ay in _discs(a):
        for bx, by in _discs(b):
            if math.hypot(ax - bx, ay - by) < a[4] + b[4]:
                return True
    return False


def _discs(body):
    x, y, angle, length, _radius = body
    q = length / 4.0
    c, s = math.cos(angle), math.sin(angle)
    return ((x + q * c, y + q * s), (x - q * c, y - q * s))


class _Path:
    """The route ahead in the ego frame, from the front bumper."""

    def __init__(self, points):
        self.points = points
        self.lengths = [math.dist(a, b) for a, b in itertools.pairwise(points)]

    def pose(self, s):
        """(x, y, angle) at arc length s (straight on before the start and past the end)."""
        k = 0
        while k < len(self.lengths) - 1 and s > self.lengths[k]:
            s -= self.lengths[k]
            k += 1
        (ax, ay), (bx, by) = self.points[k], self.points[k + 1]
        n = max(self.lengths[k], 1e-6)
        ux, uy = (bx - ax) / n, (by - ay) / n
        return ax + s * ux, ay + s * uy, math.atan2(uy, ux)

    def locate(self, x, y):
        """(arc length, signed left offset, direction) of the path point nearest to (x, y)."""
        best, done = (math.inf, 0.0, 0.0, 0.0), 0.0
        for (ax, ay), (bx, by), n in zip(self.points, self.points[1:], self.lengths, strict=False):
            n = max(n, 1e-6)
            ux, uy = (bx - ax) / n, (by - ay) / n
            u = max(0.0, min(n, (x - ax) * ux + (y - ay) * uy))
            offset = -(x - ax) * uy + (y - ay) * ux
            distance = math.hypot(x - ax - u * ux, y - ay - u * uy)
            if distance < best[0]:
                best = (distance, done + u, offset, math.atan2(uy, ux))
            done += n
        return best[1], best[2], best[3]

    def curvature(self, within):
        """The sharpest turn per metre over the first `within` metres, measured between chords two
        route points long (so a lane's sideways shift through a junction is no bend). The ego's own
        position, points[0], is left out: steering back onto the route is no bend either."""
        sharpest, done = 0.0, 0.0
        route = self.points[1:]
        for k in range(2, len(route) - 2):
            done = math.dist(route[0], route[k])
            if done > within:
                break
            (ax, ay), (bx, by), (cx, cy) = route[k - 2], route[k], route[k + 2]
            turn = math.atan2(cy - by, cx - bx) - math.atan2(by - ay, bx - ax)
            turn = abs((turn + math.pi) % (2.0 * math.pi) - math.pi)
            span = 0.5 * (math.dist((ax, ay), (bx, by)) + math.dist((bx, by), (cx, cy)))
            sharpest = max(sharpest, turn / max(span, 1e-3))
        return sharpest
