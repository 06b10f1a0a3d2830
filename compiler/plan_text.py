"""The plan in a readable text form: what `sovarc lower` writes and `--dump-ir-after=lower` prints.

One header block for the site and the impact, then one block per participant: the lanes it
may use, each action's stretch and times, and a trajectory digest every second.
"""

from __future__ import annotations

from sovarc.compiler.plan import Plan, Trajectory


def render_plan(plan: Plan) -> str:
    impact = plan.impact
    lines = [
        f"plan {plan.scenario.name}",
        f"  map        {plan.map}  sha256 {plan.map_sha256[:12]}",
        f"  site       {plan.site} ({plan.kind.value}), report compass turned {plan.rotation} degrees",
        f"  impact     t = {impact.time:.2f} s at ({impact.point[0]:.2f}, {impact.point[1]:.2f}), "
        f"C_A radius {impact.radius:.1f} m: {impact.striker} strikes {impact.victim} ({impact.type.value})",
        f"  sampling   every {plan.step:g} s for {plan.duration:.1f} s, seed {plan.seed}",
    ]
    for note in plan.notes:
        lines.append(f"  note       {note}")
    for trajectory in plan.trajectories:
        lines += _participant(trajectory, plan)
    return "\n".join(lines) + "\n"


def _participant(t: Trajectory, plan: Plan) -> list[str]:
    head = f"{t.participant} ({t.role.value}, {t.body.length:g} x {t.body.width:g} m)"
    out = ["", head]
    if t.edges:
        out.append(f"  edges   {' '.join(t.edges)}")
    if t.lanes:
        out.append(f"  lanes   {' '.join(t.lanes)}")
    if t.impact_s is not None:
        out.append(f"  at impact: {t.impact_s:.1f} m along its path")
    for segment in t.segments:
        out.append(
            f"  action {segment.action:<16} {segment.start_s:7.1f} .. {segment.end_s:7.1f} m"
            f"   t {segment.start_t:6.2f} .. {segment.end_t:6.2f} s"
        )
    out.append("  t(s)      x(m)       y(m)   heading  speed(m/s)")
    every = max(1, round(1.0 / plan.step))
    picked = list(t.samples[::every])
    if picked[-1] is not t.samples[-1]:
        picked.append(t.samples[-1])
    for s in picked:
        out.append(f"  {s.t:5.1f} {s.x:10.2f} {s.y:10.2f} {s.heading:8.1f} {s.speed:10.2f}")
    return out
