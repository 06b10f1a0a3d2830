"""A picture of one test run (PNG): the lanes around it, every actor's track, the ego's route and
where the bodies were when the run ended."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from sovarc.compiler.geometry.bodies import Box
from sovarc.targets.fmu.harness import Run
from sovarc.targets.verdict import Verdict

NPC_COLOURS = ("#d62728", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22")
EGO_COLOUR = "#1f77b4"


def render_run(run: Run, verdict: Verdict, out: Path) -> Path:
    # matplotlib loads here, not with the module: it is slow to import and only a run's picture needs it.
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import pyplot as plt
    from matplotlib.patches import Polygon

    fig, ax = plt.subplots(figsize=(7, 7), dpi=100)
    try:
        for lane in run.lanes:
            xs, ys = zip(*lane, strict=True)
            ax.plot(xs, ys, color="#cccccc", linewidth=6, solid_capstyle="butt", zorder=1)
        route = run.task.route.points
        ax.plot(route[:, 0], route[:, 1], "--", color=EGO_COLOUR, linewidth=0.8, zorder=2, label="ego route")
        goal = run.task.route.point_at(run.task.goal)
        ax.plot(*goal, marker="*", color=EGO_COLOUR, markersize=12, zorder=5, label="goal")
        others = [name for name in run.tracks if name != run.ego]
        for k, name in enumerate([run.ego, *others]):
            track = run.tracks[name]
            colour = EGO_COLOUR if name == run.ego else NPC_COLOURS[(k - 1) % len(NPC_COLOURS)]
            label = f"{name} (ego)" if name == run.ego else name
            ax.plot(track.x, track.y, color=colour, linewidth=2 if name == run.ego else 1.2, zorder=3, label=label)
            box = Box.of(track.body, float(track.x[-1]), float(track.y[-1]), float(track.heading[-1])).corners()
            box = box[3:] + box[:3]  # from the front-right corner, as the pictures were always drawn
            ax.add_patch(Polygon(box, closed=True, facecolor=colour, edgecolor="black", alpha=0.8, zorder=4))
        if run.contact is not None:
            ego = run.ego_track
            ax.plot(float(ego.x[-1]), float(ego.y[-1]), marker="X", color="black", markersize=12, zorder=6)
        _frame(ax, run)
        status = "PASS" if verdict.passed else f"FAIL ({verdict.facts.get('failure')})"
        ax.set_title(f"{verdict.scenario} at {verdict.site}\nego {run.ego}: {status}, ended by {run.ended}", fontsize=9)
        ax.set_aspect("equal")
        ax.legend(loc="upper right", fontsize=7)
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        out.parent.mkdir(parents=True, exist_ok=True)
        fig.savefig(out, format="png", metadata={"Software": None})
    finally:
        plt.close(fig)
    return out


def _frame(ax: object, run: Run) -> None:
    """Zoom onto the tracks with a margin."""
    xs = np.concatenate([t.x for t in run.tracks.values()])
    ys = np.concatenate([t.y for t in run.tracks.values()])
    centre_x, centre_y = (xs.min() + xs.max()) / 2.0, (ys.min() + ys.max()) / 2.0
    half = max(xs.max() - xs.min(), ys.max() - ys.min(), 40.0) / 2.0 + 15.0
    ax.set_xlim(centre_x - half, centre_x + half)  # type: ignore[attr-defined]
    ax.set_ylim(centre_y - half, centre_y + half)  # type: ignore[attr-defined]
