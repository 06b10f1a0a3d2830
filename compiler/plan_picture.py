"""A picture of a plan: the site's lanes, each participant's path, start and position at
impact, and the collision area C_A, so that a person can check the plan at a glance."""

from __future__ import annotations

import io
import os

from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.geometry.bodies import Box
from sovarc.compiler.maps import RoadMap
from sovarc.compiler.plan import Plan

COLOURS = ("#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b")


def draw_plan(plan: Plan, road_map: RoadMap) -> bytes:
    """The PNG bytes (matplotlib's Agg backend: no display needed; same plan, same bytes)."""
    # matplotlib loads here, not with the module: it takes longer to import than most commands
    # take to run, and only a command that draws needs it.
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Polygon

    fig, ax = plt.subplots(figsize=(7, 7), dpi=100)
    cx, cy = plan.impact.point
    xs = [s.x for t in plan.trajectories for s in t.samples] + [cx]
    ys = [s.y for t in plan.trajectories for s in t.samples] + [cy]
    half = max(max(xs) - min(xs), max(ys) - min(ys), 60.0) / 2 + 10.0
    mx, my = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    for edge in road_map.net.getEdges(withInternal=True):
        for lane in edge.getLanes():
            shape = lane.getShape()
            if not any(abs(x - mx) < half + 50 and abs(y - my) < half + 50 for x, y in shape):
                continue
            xs_, ys_ = zip(*shape, strict=True)
            ax.plot(xs_, ys_, color="#bbbbbb", linewidth=lane.getWidth() * 72 / (2 * half) * 7 * 0.9, zorder=1)
    ax.add_patch(Circle((cx, cy), plan.impact.radius, color="#ffcc00", alpha=0.6, zorder=3))
    for k, t in enumerate(plan.trajectories):
        colour = COLOURS[k % len(COLOURS)]
        ax.plot([s.x for s in t.samples], [s.y for s in t.samples], color=colour, linewidth=1.5, zorder=4)
        ax.plot(t.samples[0].x, t.samples[0].y, "o", color=colour, zorder=5)
        at = t.at(plan.impact.time)
        box = Box.of(t.body, at.x, at.y, at.heading).corners()
        box = box[3:] + box[:3]  # from the front-right corner, as the pictures were always drawn
        ax.add_patch(Polygon(box, color=colour, zorder=6))
        ax.annotate(t.participant, (t.samples[0].x, t.samples[0].y), fontsize=9, color=colour, zorder=7)
    ax.set_xlim(mx - half, mx + half)
    ax.set_ylim(my - half, my + half)
    ax.set_aspect("equal")
    ax.set_title(f"{plan.scenario.name} on {plan.site}\nimpact at {plan.impact.time:.1f} s", fontsize=10)
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", metadata={"Software": None})
    plt.close(fig)
    return buffer.getvalue()


def write_picture(plan: Plan, road_map: RoadMap, path: str | os.PathLike[str]) -> None:
    write_atomic(path, draw_plan(plan, road_map))
