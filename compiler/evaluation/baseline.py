"""The random baseline: the same ego task, among random but plausible NPCs on the same site.

This is the paper's "Random" method. Each NPC keeps its body and drives a random path of the site's
lanes at a random steady speed: at a junction, a random connection (in on one arm's lane, through the
junction, out on another's), reaching the junction at a random time within the plan's duration; on a
straight road, a random lane of a random direction from a random point. A pedestrian walks across the
site's centre in a random direction. Nothing depends on the crash the report describes.

The NPCs are drawn here, on the map the plan was staged on; the FMU target runs the plans it is given
(`run_test_results(plan, tests=random_tests(plan, road_map, seed, egos(plan)), method="random")`).
"""

from __future__ import annotations

import math
import random
from collections.abc import Iterable
from dataclasses import replace

import numpy as np
from sovarc.compiler.geometry.polyline import Point, Polyline
from sovarc.compiler.maps import RoadMap, Site, find_sites
from sovarc.compiler.plan import Plan, Sample, Segment, Trajectory
from sovarc.dsl.errors import OracleError
from sumolib.net import Net

SPEED_RANGE = (0.5, 1.0)  # share of the lane's speed limit an NPC drives at
WALK = (1.0, 1.6)  # m/s, a pedestrian's pace
CLEARANCE = 10.0  # m an NPC starts away from the ego and from the other NPCs
TRIES = 30
PATH_GAP = 0.05  # m: an NPC's path drops each point this near the last one it kept (as the FMU target's routes)


def random_tests(plan: Plan, road_map: RoadMap, seed: int, egos: Iterable[str]) -> dict[str, Plan]:
    """For each participant that takes a turn as the ego, the plan of its random test."""
    return {ego: random_npcs(plan, road_map, ego, seed) for ego in egos}


def random_npcs(plan: Plan, road_map: RoadMap, ego: str, seed: int) -> Plan:
    """The plan with every participant but `ego` replaced by a random one on the same site of `road_map`."""
    site, net = _site(road_map, plan.site), road_map.net
    # one draw per test: keyed by the scenario too, or every scenario staged on a site would get the
    # same NPCs for the same ego, and one lucky or unlucky draw would count once per scenario
    rng = random.Random(f"{seed}:{plan.scenario.name}:{plan.site}:{ego}")
    mine = plan.trajectory(ego)
    taken: list[Point] = [(mine.samples[0].x, mine.samples[0].y)]
    trajectories = []
    for t in plan.trajectories:
        if t.participant == ego:
            trajectories.append(t)
            continue
        for _ in range(TRIES):
            npc = _random_trajectory(plan, t, site, net, rng)
            start = (npc.samples[0].x, npc.samples[0].y)
            if all(math.dist(start, p) >= CLEARANCE for p in taken):
                break
        taken.append((npc.samples[0].x, npc.samples[0].y))
        trajectories.append(npc)
    notes = (*plan.notes, f"random baseline: NPCs other than {ego} drawn at random (seed {seed})")
    return replace(plan, trajectories=tuple(trajectories), notes=notes)


def _site(road_map: RoadMap, site_id: str) -> Site:
    site = next((s for s in find_sites(road_map) if s.id == site_id), None)
    if site is None:
        raise OracleError(f"the random baseline needs the plan's site {site_id}, which {road_map.name} does not have")
    return site


def _random_trajectory(plan: Plan, template: Trajectory, site: Site, net: Net, rng: random.Random) -> Trajectory:
    if template.body.vclass == "pedestrian":
        return _walker(plan, template, site, rng)
    if site.connections:
        link = rng.choice(site.connections)
        parts = [link.from_lane, *link.path, link.to_lane]
        shapes = [net.getLane(lane).getShape() for lane in parts]
        arrive_at = Polyline(shapes[0], min_gap=PATH_GAP).length
        limit = net.getLane(link.from_lane).getSpeed()
        speed = rng.uniform(*SPEED_RANGE) * limit
        start = max(arrive_at - speed * rng.uniform(1.0, max(plan.duration, 1.5)), 0.0)
        edges = tuple(dict.fromkeys(net.getLane(lane).getEdge().getID() for lane in parts))
    else:
        arm = rng.choice([a for a in site.arms if a.incoming])
        lane = rng.choice(arm.incoming)
        # a straight site's lane may run on several SUMO lanes (a road split at lane sections)
        parts, shapes, edges = list(lane.lanes), [lane.shape], lane.edges
        speed = rng.uniform(*SPEED_RANGE) * lane.speed
        start = rng.uniform(0.0, 0.6 * lane.length)
    points = [p for shape in shapes for p in shape]
    path = Polyline(points, min_gap=PATH_GAP)
    samples = _drive(path, start, speed, plan)
    end = speed * plan.duration
    segment = Segment("random", start, start + end, 0.0, plan.duration, speed)
    return Trajectory(
        template.participant, template.role, template.body, samples, tuple(parts), edges, (segment,), None
    )


def _walker(plan: Plan, template: Trajectory, site: Site, rng: random.Random) -> Trajectory:
    heading = rng.uniform(0.0, 360.0)
    pace = rng.uniform(*WALK)
    cross_at = rng.uniform(1.0, max(plan.duration, 1.5))  # s when it passes the centre
    cx, cy = site.centre
    rad = math.radians(heading)
    back = pace * cross_at
    start = (cx - back * math.sin(rad), cy - back * math.cos(rad))
    path = Polyline([start, (cx + 30.0 * math.sin(rad), cy + 30.0 * math.cos(rad))])
    samples = _drive(path, 0.0, pace, plan)
    segment = Segment("random", 0.0, pace * plan.duration, 0.0, plan.duration, pace)
    return Trajectory(template.participant, template.role, template.body, samples, (), (), (segment,), None)


def _drive(path: Polyline, start: float, speed: float, plan: Plan) -> tuple[Sample, ...]:
    count = len(plan.trajectories[0].samples)
    times = np.arange(count) * plan.step
    s = start + speed * times
    points = path.points_at(s)
    return tuple(
        Sample(float(t), float(x), float(y), path.heading(float(at)), speed)
        for t, (x, y), at in zip(times, points, s, strict=True)
    )
