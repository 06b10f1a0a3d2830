"""Emit a plan as an OpenSCENARIO XML scenario (`scenario.xosc`) beside its OpenDRIVE road network.

    emit_files(plan, out_dir, version="1.3", ego=None) -> Emitted(xosc, xodr, notes)

`notes` are diagnostics: warnings for what the format cannot say (never dropped silently) and
notes for values the format requires but the report does not state. Both are also written as
comments at the top of the .xosc.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.plan import Plan
from sovarc.dsl.errors import Diagnostic, Severity
from sovarc.dsl.ir import Role
from sovarc.targets.openscenario.bodies import osc_body
from sovarc.targets.openscenario.entities import Actor, entities_element
from sovarc.targets.openscenario.environment import environment_element
from sovarc.targets.openscenario.provenance import Options, file_header, parameter_declarations
from sovarc.targets.openscenario.roadnet import write_road_network
from sovarc.targets.openscenario.storyboard import storyboard_element
from sovarc.targets.openscenario.versions import DEFAULT_VERSION, Dialect, dialect
from sovarc.targets.openscenario.xml import comment, el, to_bytes

SCENARIO_FILE = "scenario.xosc"


@dataclass(frozen=True)
class Emitted:
    xosc: Path
    xodr: Path
    notes: tuple[Diagnostic, ...]

    @property
    def unsupported(self) -> tuple[Diagnostic, ...]:
        """What the IR says and the file cannot."""
        return tuple(n for n in self.notes if n.severity is Severity.WARNING)


def choose_ego(plan: Plan, ego: str | None = None) -> str:
    """The participant marked as ego: the one asked for; else the striker when it is a vehicle,
    else the victim when it is, else the first vehicle, else the first participant."""
    names = [t.participant for t in plan.trajectories]
    if ego is not None:
        if ego not in names:
            raise ValueError(f"ego {ego!r} is not a participant of the plan ({', '.join(names)})")
        return ego
    vehicles = [t.participant for t in plan.trajectories if t.role is Role.VEHICLE]
    for name in (plan.impact.striker, plan.impact.victim, *vehicles, *names):
        if name in vehicles or not vehicles:
            return name
    return names[0]


def _actors(plan: Plan, ego: str) -> tuple[list[Actor], list[Diagnostic]]:
    notes: list[Diagnostic] = []
    actors: list[Actor] = []
    for trajectory in plan.trajectories:
        body, note = osc_body(trajectory.body)
        participant = plan.scenario.participant(trajectory.participant)
        if note:
            span = participant.meta.span if participant else None
            notes.append(Diagnostic(f"{trajectory.participant}: {note}", span, Severity.WARNING))
        actors.append(Actor(trajectory, participant, body, trajectory.participant == ego))
    planned = {a.name for a in actors}
    for p in plan.scenario.participants:
        if p.id not in planned:
            notes.append(Diagnostic(f"{p.id} has no trajectory in the plan: not in the scenario",
                                    p.meta.span, Severity.WARNING))  # fmt: skip
    actors.sort(key=lambda a: not a.ego)  # ego first: players follow the first entity by default
    return actors, notes


def build_document(plan: Plan, xodr_name: str, options: Options, d: Dialect) -> tuple[bytes, list[Diagnostic]]:
    """The .xosc bytes and the notes about it."""
    actors, notes = _actors(plan, options.ego)
    environment, env_notes = environment_element(plan.scenario.environment, d)
    notes += env_notes
    root = el(
        "OpenSCENARIO",
        None,
        file_header(plan, d),
        parameter_declarations(plan, options),
        el("CatalogLocations"),
        el("RoadNetwork", None, el("LogicFile", {"filepath": xodr_name})),
        entities_element(plan, actors, d),
        storyboard_element(plan, actors, environment, d),
    )
    leading = [comment(f"sovarc {n.severity}: {n.message}" + (f" ({n.span})" if n.span else "")) for n in notes]
    return to_bytes(root, leading), notes


def emit_files(plan: Plan, out_dir: str | Path, version: str = DEFAULT_VERSION, ego: str | None = None) -> Emitted:
    """Write scenario.xosc and the road network into out_dir (created if missing)."""
    d = dialect(version)
    options = Options(d.version, choose_ego(plan, ego))
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    xodr = write_road_network(plan.network, out)
    data, notes = build_document(plan, xodr.name, options, d)
    xosc = out / SCENARIO_FILE
    write_atomic(xosc, data)
    return Emitted(xosc, xodr, tuple(notes))


def emit(plan: Plan, out_dir: str | Path, version: str = DEFAULT_VERSION, ego: str | None = None) -> Path:
    """Write scenario.xosc and its .xodr into out_dir; return the .xosc path."""
    return emit_files(plan, out_dir, version, ego).xosc


__all__ = ["SCENARIO_FILE", "Emitted", "build_document", "choose_ego", "emit", "emit_files"]
