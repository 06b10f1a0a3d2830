"""Extraction accuracy per attribute, in the form of the SoVAR paper's Table 3.

Both sides are scenario IR: the ground truth is imported with
`frontend.truth`, so the scoring compares facts, not spellings. Weather and
lighting compare as sets, everything else exactly; a case's action sequence
is right only if every vehicle's whole sequence is, in order (a vehicle the
truth leaves `unknown` must be `unknown`). As in the paper, an attribute is
scored per report, and DrivingActions is the sequence of behaviours: a
turn's or lane change's target lane (`turn_left(to: 2)`) is not compared,
since lanes are what RunningLanes measures.

The ground truth's vocabulary is SoVAR's, which has no twilight and no
parked vehicle: it writes dusk and dawn as dark, and a parked vehicle as
stopped. Ours is compared in its terms (`in_truth_terms`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, replace
from pathlib import Path

from sovarc.compiler.evaluation.reading import FrontEndSpec, front_end
from sovarc.compiler.frontend.truth import import_truth_file
from sovarc.dsl import SovarcError, read_source
from sovarc.dsl.ir import ActionKind, Lighting, Participant, Scenario, Speed, Unknown

ATTRIBUTES: tuple[str, ...] = (
    "Weather",
    "Light",
    "LaneNum",
    "SpeedLimit",
    "CollisionLocation",
    "DrivingActions",
    "CrashType",
    "DrivingDirections",
    "RunningLanes",
    "ParticipantsNumber",
)
EXTRA: tuple[str, ...] = ("Striker",)

# SoVAR with GPT-4 on the same 90 reports (the paper's Table 3), for comparison.
SOVAR_GPT4 = {
    "Weather": 76.7,
    "Light": 94.4,
    "LaneNum": 90.0,
    "SpeedLimit": 100.0,
    "CollisionLocation": 100.0,
    "DrivingActions": 75.6,
    "CrashType": 93.3,
    "DrivingDirections": 93.3,
    "RunningLanes": 75.6,
    "ParticipantsNumber": 100.0,
}


def _vehicles(s: Scenario) -> dict[str, Participant]:
    return {p.id: p for p in s.participants}


def _per_vehicle(got: Scenario, truth: Scenario, fact: Callable[[Participant], object]) -> tuple[bool, str]:
    mine, theirs = _vehicles(got), _vehicles(truth)
    wrong = [
        f"{vid}: {_show(fact(mine[vid])) if vid in mine else 'missing'} ≠ {_show(fact(p))}"
        for vid, p in theirs.items()
        if vid not in mine or fact(mine[vid]) != fact(p)
    ]
    return not wrong, "; ".join(wrong)


def _show(value: object) -> str:
    if isinstance(value, tuple):
        return "[" + ", ".join(_show(v) for v in value) + "]"
    return str(value)


def _same_speed(a: Speed | Unknown, b: Speed | Unknown) -> bool:
    if isinstance(a, Unknown) or isinstance(b, Unknown):
        return a == b
    return abs(a.to_mps() - b.to_mps()) < 0.5  # 48 km/h and 30 mph are the same sign


def _kinds(p: Participant) -> object:
    return p.actions if isinstance(p.actions, Unknown) else tuple(a.kind.value for a in p.actions)


_TRUTH_WORDS = {Lighting.TWILIGHT: Lighting.DARK, ActionKind.PARKED: ActionKind.STOP}


def in_truth_terms(s: Scenario) -> Scenario:
    """The scenario in the ground truth's vocabulary (see the module): twilight is dark, parked is a stop."""
    light = s.environment.lighting
    if not isinstance(light, Unknown):
        s = replace(s, environment=replace(s.environment, lighting=tuple({_TRUTH_WORDS.get(x, x) for x in light})))
    people = tuple(
        replace(p, actions=tuple(replace(a, kind=_TRUTH_WORDS.get(a.kind, a.kind)) for a in p.actions))
        if not isinstance(p.actions, Unknown)
        else p
        for p in s.participants
    )
    return replace(s, participants=people)


def score_case(got: Scenario, truth: Scenario) -> dict[str, tuple[bool, str]]:
    """attribute -> (right?, what differed)."""

    def same(a: object, b: object) -> tuple[bool, str]:
        return a == b, "" if a == b else f"{_show(a)} ≠ {_show(b)}"

    got = in_truth_terms(got)

    return {
        "Weather": same(got.environment.weather, truth.environment.weather),
        "Light": same(got.environment.lighting, truth.environment.lighting),
        "LaneNum": same(got.road.lanes, truth.road.lanes),
        "SpeedLimit": (
            _same_speed(got.road.speed_limit, truth.road.speed_limit),
            f"{_show(got.road.speed_limit)} ≠ {_show(truth.road.speed_limit)}",
        ),
        "CollisionLocation": same(got.road.kind, truth.road.kind),
        "DrivingActions": _per_vehicle(got, truth, _kinds),
        "CrashType": same(got.crash.type, truth.crash.type),
        "DrivingDirections": _per_vehicle(got, truth, lambda p: p.heading),
        "RunningLanes": _per_vehicle(got, truth, lambda p: p.lane),
        "ParticipantsNumber": same(len(got.participants), len(truth.participants)),
        "Striker": same(got.crash.striker, truth.crash.striker),
    }


@dataclass
class Report:
    cases: dict[str, dict[str, tuple[bool, str]]] = field(default_factory=dict)

    def add(self, name: str, got: Scenario, truth: Scenario) -> None:
        self.cases[name] = score_case(got, truth)

    def accuracy(self, attribute: str) -> float:
        scored = [c[attribute][0] for c in self.cases.values()]
        return 100.0 * sum(scored) / len(scored) if scored else 0.0

    def mean(self) -> float:
        return sum(self.accuracy(a) for a in ATTRIBUTES) / len(ATTRIBUTES)

    def failures(self) -> list[tuple[str, str, str]]:
        return [
            (name, attr, why) for name, case in sorted(self.cases.items()) for attr, (ok, why) in case.items() if not ok
        ]

    def to_json(self) -> dict[str, object]:
        return {
            "cases": len(self.cases),
            "accuracy": {a: round(self.accuracy(a), 1) for a in (*ATTRIBUTES, *EXTRA)},
            "mean": round(self.mean(), 1),
            "failures": [{"case": c, "attribute": a, "why": w} for c, a, w in self.failures()],
        }

    def table(self) -> str:
        head = ["attribute", *ATTRIBUTES, "mean", *EXTRA]
        ours = [
            "sovarc",
            *(f"{self.accuracy(a):.1f}" for a in ATTRIBUTES),
            f"{self.mean():.1f}",
            *(f"{self.accuracy(a):.1f}" for a in EXTRA),
        ]
        paper = [
            "SoVAR GPT-4",
            *(f"{SOVAR_GPT4[a]:.1f}" for a in ATTRIBUTES),
            f"{sum(SOVAR_GPT4.values()) / len(SOVAR_GPT4):.1f}",
            *("-" for _ in EXTRA),
        ]
        rows = [head, ours, paper]
        widths = [max(len(r[i]) for r in rows) for i in range(len(head))]
        return "\n".join("  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows)


@dataclass(frozen=True)
class ExtractionTask:
    """One report and its ground truth, for an executor (plain data: see `reading`)."""

    spec: FrontEndSpec
    truth: str
    report: str


def extraction_tasks(truths: Iterable[Path], reports: Path, spec: FrontEndSpec) -> list[ExtractionTask]:
    """A task per ground truth: the report beside it is reports/<category>/<n>.txt."""
    return [ExtractionTask(spec, str(path), str(reports / path.parent.name / f"{path.stem}.txt")) for path in truths]


def run_extraction_task(task: ExtractionTask) -> tuple[str, dict[str, tuple[bool, str]] | None, str | None]:
    """(the case's name, its scores per attribute, or the error as a person reads it)."""
    try:
        truth = import_truth_file(Path(task.truth)).scenario
        got = front_end(task.spec).extract(read_source(Path(task.report), "crash report")).scenario
    except SovarcError as exc:
        return Path(task.truth).stem, None, exc.render()
    return truth.name, score_case(got, truth), None
