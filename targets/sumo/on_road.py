"""The SUMO oracle's road check for a vehicle that reverses: its body, as SUMO placed it, stays on
the road until the impact.

A reversing car (backing along a lane or out of a parking space, or a leg of a three-point turn) is
the one move whose body the lane-line check does not bound: it may swing its rear over a kerb with
no lane beside it. Each corner of the body, moved in by the lane-line tolerance (a bumper may
overhang the kerb that much), must lie on a lane of the road: within half a lane's width of the
centre line of a lane vehicles drive (a sidewalk is no road).
"""

from __future__ import annotations

from sovarc.compiler.crashes import LINE_TOLERANCE
from sovarc.compiler.geometry.bodies import Box
from sovarc.compiler.plan import Plan
from sovarc.targets.sumo.network import Network
from sovarc.targets.sumo.replay import Trace
from sovarc.targets.verdict import Finding

SEARCH = 6.0  # m around a corner in which lanes are looked for (wider than any lane)


def reversing(plan: Plan) -> list[str]:
    """The participants whose plan moves them backwards at some step."""
    return [t.participant for t in plan.trajectories if any(s.speed < 0.0 for s in t.samples)]


def on_road_finding(plan: Plan, trace: Trace, network: Network, until: float) -> Finding | None:
    """None when no participant reverses (the finding is only made for those that do)."""
    who = reversing(plan)
    if not who:
        return None
    for k, time in enumerate(trace.times):
        if time >= until - 1e-9:
            break
        for name in who:
            t = plan.trajectory(name)
            pose = trace.poses[name][k]
            if pose is None:
                continue
            body = Box.of(t.body, pose.x, pose.y, pose.angle)
            for x, y in body.corners(shrink=LINE_TOLERANCE):
                if not on_road(network, x, y):
                    message = f"{name}'s body leaves the road at ({x:.1f}, {y:.1f}), as SUMO placed it"
                    return Finding("on_road", False, message, time)
    names = " and ".join(who)
    return Finding("on_road", True, f"{names}, reversing, keeps its body on the road until the impact")


def on_road(network: Network, x: float, y: float) -> bool:
    """Whether the point lies on a lane vehicles drive (within half its width of its centre line)."""
    return any(
        network.reaches(lane, x, y, lane.width / 2.0) for lane in network.near(x, y, SEARCH) if not lane.pedestrian_only
    )
