"""A picture of a plan, and the same scene as data for the report's animation.

What a reviewer checks at a glance: the site's lanes with their lane lines, each participant's body
at intervals up to impact and at impact (facing its heading), its path, the collision area C_A and
the impact point, with a legend naming the striker and the victim.

Bodies are `geometry.bodies.Box` of the plan's own bodies (the vehicle model's sizes): the picture
and the animation draw the kernel's corners, never corners of their own. Lanes are the SUMO lanes
of the plan's network: a lane's borders are its centre line offset by half its width.
"""

from __future__ import annotations

import io
import math
import os
from dataclasses import dataclass
from typing import Any

from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.geometry.bodies import Box
from sovarc.compiler.geometry.polyline import Polyline
from sovarc.compiler.maps import RoadMap
from sovarc.compiler.plan import Plan, Trajectory

# Striker, victim, then any other participant, in plan order.
STRIKER, VICTIM = "#d62728", "#1f77b4"
OTHERS = ("#2ca02c", "#9467bd", "#ff7f0e", "#8c564b")
GROUND, ASPHALT, WALKWAY = "#eef1e8", "#9aa0a6", "#d6d6d6"
LINE, CENTRE_LINE, CROSSING = "#ffffff", "#f2c200", "#e4e4e4"
AREA = "#ffcc00"
FRAME_STEP = 0.1  # s between the animation's frames
CLOSE_S = 2.0  # s before impact the close-up shows
LABEL_BOX = {"boxstyle": "round,pad=0.15", "facecolor": "white", "alpha": 0.8, "linewidth": 0}
DPI = 100  # fixed: same plan, same bytes


@dataclass(frozen=True)
class View:
    """The square window both the picture and the animation show: every path, and the impact."""

    cx: float
    cy: float
    half: float  # m from the centre to each side

    def near(self, shape: Any, margin: float = 20.0) -> bool:
        reach = self.half + margin
        return any(abs(x - self.cx) < reach and abs(y - self.cy) < reach for x, y in shape)


@dataclass(frozen=True)
class Lanes:
    """The lanes in a view: filled areas, and the lines painted on them."""

    asphalt: tuple[tuple[tuple[float, float], ...], ...]  # lane outlines, where vehicles drive
    walkways: tuple[tuple[tuple[float, float], ...], ...]  # sidewalks and walking areas
    crossings: tuple[tuple[tuple[float, float], ...], ...]  # pedestrian crossings, painted over the road
    lines: tuple[tuple[str, tuple[tuple[float, float], ...]], ...]  # (style, shape): edge, divider, centre


@dataclass(frozen=True)
class Actor:
    """A participant as drawn: name, what it is in the crash, colour."""

    trajectory: Trajectory
    label: str  # 'striker' / 'victim' / 'other'
    colour: str


def view_of(plan: Plan) -> View:
    cx, cy = plan.impact.point
    xs = [s.x for t in plan.trajectories for s in t.samples] + [cx]
    ys = [s.y for t in plan.trajectories for s in t.samples] + [cy]
    half = max(max(xs) - min(xs), max(ys) - min(ys), 50.0) / 2 + 8.0
    return View((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2, half)


def actors_of(plan: Plan) -> list[Actor]:
    others = iter(OTHERS * len(plan.trajectories))
    actors = []
    for t in plan.trajectories:
        if t.participant == plan.impact.striker:
            actors.append(Actor(t, "striker", STRIKER))
        elif t.participant == plan.impact.victim:
            actors.append(Actor(t, "victim", VICTIM))
        else:
            actors.append(Actor(t, "other", next(others)))
    return actors


def lanes_in(road_map: RoadMap, view: View) -> Lanes:
    """Each lane near the view as an outline; on a road (not a junction), its lane lines: a solid edge
    line at the kerb (the right; the left where traffic keeps left), dashed dividers between lanes of one
    direction, and on the other side a centre line (yellow) where traffic comes the other way, else an
    edge line."""
    asphalt, walkways, crossings, lines = [], [], [], []
    for edge in sorted(road_map.net.getEdges(withInternal=True), key=lambda e: e.getID()):
        lanes = edge.getLanes()
        if not any(view.near(lane.getShape()) for lane in lanes):
            continue
        internal = edge.getFunction() in ("internal", "crossing", "walkingarea")
        opposite = not internal and any(
            e.getToNode() == edge.getFromNode() for e in edge.getToNode().getOutgoing() if e is not edge
        )
        driving = [lane for lane in lanes if not _walkway(lane)]
        for lane in lanes:
            try:
                centre = Polyline(lane.getShape())
            except ValueError:  # a lane of one point (a degenerate walking area)
                continue
            half = lane.getWidth() / 2.0
            left, right = centre.offset(-half).points, centre.offset(half).points
            outline = _shape([*left, *right[::-1]])
            if edge.getFunction() == "crossing":
                crossings.append(outline)
            else:
                (walkways if _walkway(lane) else asphalt).append(outline)
            if internal or _walkway(lane):
                continue
            # lane 0 is at the kerb: on the right, or on the left where traffic keeps left
            kerb, inner = (left, right) if road_map.keeps_left else (right, left)
            if lane is driving[0]:
                lines.append(("edge", _shape(kerb)))
            if lane is driving[-1]:
                lines.append(("centre" if opposite else "edge", _shape(inner)))
            else:
                lines.append(("divider", _shape(inner)))
    return Lanes(tuple(asphalt), tuple(walkways), tuple(crossings), tuple(lines))


def _walkway(lane: Any) -> bool:
    return bool(lane.allows("pedestrian") and not lane.allows("passenger"))


def _shape(points: Any) -> tuple[tuple[float, float], ...]:
    return tuple((float(x), float(y)) for x, y in points)


def ghost_times(plan: Plan) -> list[float]:
    """When the bodies are drawn before impact: about six times, on whole seconds."""
    every = max(1.0, math.ceil(plan.impact.time / 6.0))
    count = int(plan.impact.time / every - 1e-9)
    return [k * every for k in range(count + 1)]


def body_at(t: Trajectory, time: float) -> Box:
    at = t.at(time)
    return Box.of(t.body, at.x, at.y, at.heading)


def close_view(plan: Plan) -> View:
    """The close-up: the impact and every body over the last CLOSE_S seconds before it."""
    points = [plan.impact.point]
    for t in plan.trajectories:
        for time in [*close_times(plan), plan.impact.time]:
            points.extend(body_at(t, time).corners())
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    half = max(max(xs) - min(xs), max(ys) - min(ys), 16.0) / 2 + 3.0
    return View((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2, half)


def close_times(plan: Plan) -> list[float]:
    """The close-up's bodies before impact: every half second over the last CLOSE_S seconds."""
    return [plan.impact.time - k * 0.5 for k in range(int(CLOSE_S / 0.5), 0, -1) if plan.impact.time - k * 0.5 >= 0]


def draw_plan(plan: Plan, road_map: RoadMap) -> bytes:
    """The PNG bytes (matplotlib's Agg backend: no display needed; same plan, same bytes): the whole
    plan on the left, bodies every few seconds; the last seconds before impact close up on the right."""
    # matplotlib loads here, not with the module: it takes longer to import than most commands
    # take to run, and only a command that draws needs it.
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, FancyArrow, Patch, Polygon, Rectangle

    view, close = view_of(plan), close_view(plan)
    lanes = lanes_in(road_map, view)
    actors = actors_of(plan)
    fig, (whole, near) = plt.subplots(1, 2, figsize=(10, 5.6), dpi=DPI, width_ratios=(1, 1))
    for ax, shown, ghosts, labelled in (
        (whole, view, ghost_times(plan), False),
        (near, close, close_times(plan), True),
    ):
        ax.set_facecolor(GROUND)
        for outline in lanes.walkways:
            ax.add_patch(Polygon(outline, closed=True, facecolor=WALKWAY, edgecolor=WALKWAY, linewidth=0.3, zorder=1))
        for outline in lanes.asphalt:
            ax.add_patch(Polygon(outline, closed=True, facecolor=ASPHALT, edgecolor=ASPHALT, linewidth=0.3, zorder=2))
        for outline in lanes.crossings:
            ax.add_patch(
                Polygon(outline, closed=True, facecolor=CROSSING, edgecolor=LINE, linewidth=0, hatch="///", zorder=3)
            )
        for style, shape in lanes.lines:
            xs, ys = zip(*shape, strict=True)
            colour = CENTRE_LINE if style == "centre" else LINE
            dashes = (0, (6, 6)) if style == "divider" else "solid"
            ax.plot(xs, ys, color=colour, linewidth=1.0, linestyle=dashes, zorder=3)
        ix, iy = plan.impact.point
        ax.add_patch(Circle((ix, iy), plan.impact.radius, facecolor=AREA, edgecolor="#b38f00", alpha=0.55, zorder=4))
        for actor in actors:
            t = actor.trajectory
            until = [s for s in t.samples if s.t <= plan.impact.time]
            ax.plot([s.x for s in until], [s.y for s in until], color=actor.colour, linewidth=1.2, zorder=5)
            ax.plot([until[0].x], [until[0].y], marker="o", color=actor.colour, markersize=4, zorder=5)
            for k, time in enumerate(ghosts):
                box = body_at(t, time)
                alpha = 0.15 + 0.3 * k / max(len(ghosts), 1)
                ax.add_patch(
                    Polygon(box.corners(), facecolor=actor.colour, edgecolor=actor.colour, alpha=alpha, zorder=6)
                )
                if labelled or k % 2 == 0:  # the close-up counts back from impact: its times need not be round
                    text = f"-{round(plan.impact.time - time, 1):g}" if labelled else f"{time:g}"
                    ax.annotate(text, box.centre, fontsize=6, color="#222222", ha="center", va="center", zorder=7)
            box = body_at(t, plan.impact.time)
            ax.add_patch(Polygon(box.corners(), facecolor=actor.colour, edgecolor="black", linewidth=0.8, zorder=8))
            _arrow(ax, FancyArrow, box, shown.half / 40.0)
            ax.annotate(t.participant, box.centre, fontsize=9, fontweight="bold", color=actor.colour,
                        xytext=(10, 10), textcoords="offset points", zorder=10,
                        bbox=LABEL_BOX)  # fmt: skip
        ax.plot([ix], [iy], marker="x", color="black", markersize=9, markeredgewidth=2, zorder=11)
        ax.set_xlim(shown.cx - shown.half, shown.cx + shown.half)
        ax.set_ylim(shown.cy - shown.half, shown.cy + shown.half)
        ax.set_aspect("equal")
        ax.tick_params(labelsize=7)
    whole.add_patch(Rectangle((close.cx - close.half, close.cy - close.half), 2 * close.half, 2 * close.half,
                              fill=False, edgecolor="black", linestyle="--", linewidth=0.8, zorder=12))  # fmt: skip
    whole.set_title(f"whole plan (m): bodies at {', '.join(f'{g:g}' for g in ghost_times(plan))} s", fontsize=9)
    near.set_title(f"close-up (m): bodies every 0.5 s over the last {CLOSE_S:g} s (label: s before impact)", fontsize=9)
    handles = [Patch(facecolor=a.colour, edgecolor="black", label=_legend_name(a)) for a in actors] + [
        Patch(facecolor=AREA, alpha=0.55, edgecolor="#b38f00", label=f"collision area (r {plan.impact.radius:.1f} m)"),
        Line2D([], [], marker="x", color="black", linestyle="none", markeredgewidth=2, label="impact point"),
        Line2D([], [], color="black", marker=">", markersize=5, label="heading at impact"),
        Patch(facecolor="#888888", alpha=0.3, label="body earlier (label: time)"),
        Line2D([], [], color="#555555", marker="o", markersize=4, label="path from its start"),
    ]
    fig.legend(handles=handles, loc="lower center", ncol=4, fontsize=8, frameon=False)
    title = f"{plan.scenario.name} on {plan.site} ({plan.kind.value})"
    impact = plan.impact
    crash = f"{impact.type.value} crash at {impact.time:.1f} s: {impact.striker} strikes {impact.victim}"
    fig.suptitle(f"{title}\n{crash}", fontsize=10)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", metadata={"Software": None})  # no version string in the bytes
    plt.close(fig)
    return buffer.getvalue()


def _arrow(ax: Any, arrow: Any, box: Box, size: float) -> None:
    """The heading: from the body's centre forward, past its front (`size`: the head, in m, for the panel's scale)."""
    (fx, fy), _ = box.axes
    cx, cy = box.centre
    reach = box.length / 2.0 + 2.0 * size
    ax.add_patch(arrow(cx, cy, fx * reach, fy * reach, width=size / 5.0, head_width=size, head_length=size,
                       length_includes_head=True, color="black", zorder=9))  # fmt: skip


def _legend_name(actor: Actor) -> str:
    t = actor.trajectory
    kind = t.body.vclass
    return f"{actor.label} {t.participant} ({kind})" if actor.label != "other" else f"{t.participant} ({kind})"


def write_picture(plan: Plan, road_map: RoadMap, path: str | os.PathLike[str]) -> None:
    write_atomic(path, draw_plan(plan, road_map))


# --- the animation's data: the same view, lanes and bodies, as plain numbers --------------------


def _flat(points: Any, digits: int = 2) -> list[float]:
    return [_r(v, digits) for p in points for v in p]


def _r(value: float, digits: int = 2) -> float:
    rounded = round(float(value), digits)
    return 0.0 if rounded == 0 else rounded


def scene(plan: Plan, road_map: RoadMap) -> dict[str, Any]:
    """The animation's scene: the picture's view and lanes, and per participant its body's corners
    (the kernel's Box) every FRAME_STEP seconds from 0 to impact. JSON-ready and rounded, so the
    same plan gives the same bytes."""
    view = view_of(plan)
    lanes = lanes_in(road_map, view)
    frames = round(plan.impact.time / FRAME_STEP)
    times = [min(k * FRAME_STEP, plan.impact.time) for k in range(frames)] + [plan.impact.time]
    actors = []
    for actor in actors_of(plan):
        t = actor.trajectory
        actors.append({
            "name": t.participant,
            "label": actor.label,
            "colour": actor.colour,
            "path": _flat((s.x, s.y) for s in t.samples if s.t <= plan.impact.time),
            "boxes": [_flat(body_at(t, time).corners()) for time in times],
            "speeds": [_r(t.at(time).speed * 3.6, 1) for time in times],
        })  # fmt: skip
    return {
        "view": [_r(view.cx), _r(view.cy), _r(view.half)],
        "asphalt": [_flat(o) for o in lanes.asphalt],
        "walkways": [_flat(o) for o in lanes.walkways],
        "crossings": [_flat(o) for o in lanes.crossings],
        "lines": [[style, _flat(shape)] for style, shape in lanes.lines],
        "impact": {
            "t": _r(plan.impact.time),
            "x": _r(plan.impact.point[0]),
            "y": _r(plan.impact.point[1]),
            "r": _r(plan.impact.radius),
        },
        "step": FRAME_STEP,
        "actors": actors,
    }
