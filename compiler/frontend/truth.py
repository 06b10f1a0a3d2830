"""Ground truth in the SoVAR study's JSON form, imported as scenario IR.

The form is described in shared/data/README.md. It is lossy in places (no
speeds, weather words with typos, a speed limit as a bare number or a string
with a unit); each repair made on the way in is returned as a note, never
applied silently.
"""

from __future__ import annotations

import hashlib
import json
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sovarc.dsl import Diagnostic, ParseError, read_source
from sovarc.dsl.ir import (
    UNKNOWN,
    Action,
    ActionKind,
    Crash,
    CrashType,
    Environment,
    Heading,
    Lighting,
    Participant,
    Provenance,
    Road,
    RoadKind,
    Role,
    Scenario,
    Speed,
    SpeedUnit,
    Unknown,
    Weather,
)
from sovarc.dsl.span import Span

_ACTIONS = {
    "follow lane": ActionKind.FOLLOW_LANE,
    "turn left": ActionKind.TURN_LEFT,
    "turn right": ActionKind.TURN_RIGHT,
    "change lane": ActionKind.CHANGE_LANE,
    "go across": ActionKind.GO_ACROSS,
    "stop": ActionKind.STOP,
    "turn around": ActionKind.U_TURN,
    "retrograde": ActionKind.RETROGRADE,
    "drive off": ActionKind.DRIVE_OFF,
    "drive into": ActionKind.DRIVE_INTO,
}
_TAKES_LANE = {ActionKind.TURN_LEFT, ActionKind.TURN_RIGHT, ActionKind.CHANGE_LANE, ActionKind.U_TURN}
_LIGHTING = {"bright": Lighting.DAYLIGHT, "dark": Lighting.DARK, "light": Lighting.STREET_LIGHTS}
_LIGHTING_TYPOS = {"birght": "bright"}
_HEADINGS = {1: Heading.NORTH, 2: Heading.EAST, 3: Heading.SOUTH, 4: Heading.WEST}
_IMPACT = {1: CrashType.FRONTAL, 2: CrashType.SIDE, 3: CrashType.REAR_END}
_SPEED = re.compile(r"\s*(\d+(?:\.\d+)?)\s*(kmph|kph|km/h|mph)?\s*", re.IGNORECASE)


@dataclass(frozen=True)
class Imported:
    scenario: Scenario
    notes: tuple[str, ...]  # repairs made on the way in


class _Importer:
    def __init__(self, origin: str) -> None:
        self.origin = origin
        self.notes: list[str] = []
        self.errors: list[str] = []

    def words(self, value: Any, vocab: dict[str, Any], field: str) -> tuple[Any, ...] | Unknown:
        if value == "unknown" or value == ["unknown"] or value == []:
            return UNKNOWN
        if not isinstance(value, list):
            self.errors.append(f'{field}: expected a list or "unknown", got {value!r}')
            return UNKNOWN
        out = []
        for word in value:
            fixed = _LIGHTING_TYPOS.get(word, word) if field == "lighting" else word
            if fixed != word:
                self.notes.append(f"{field}: read misspelt '{word}' as '{fixed}'")
            if fixed in vocab:
                out.append(vocab[fixed])
            else:
                self.errors.append(f"{field}: unknown word {word!r}")
        return tuple(out) if out else UNKNOWN

    def speed_limit(self, value: Any, report: str | None = None) -> Speed | Unknown:
        if value in (0, "0", None, "unknown"):
            return UNKNOWN
        m = _SPEED.fullmatch(str(value))
        if not m:
            self.errors.append(f"speedlimit: cannot read {value!r}")
            return UNKNOWN
        number = float(m.group(1))
        unit = SpeedUnit.MPH if (m.group(2) or "").lower() == "mph" else SpeedUnit.KMH
        if m.group(2) is None and report is not None and _stated_in_mph_only(m.group(1), report):
            # a bare number is "in the unit the report states first" (shared/data/README.md)
            unit = SpeedUnit.MPH
            self.notes.append(f"speedlimit: bare {m.group(1)} read in mph, the only unit the report states it in")
        return Speed(int(number) if number.is_integer() else number, unit)

    def action(self, vid: str, i: int, item: Any) -> Action | None:
        if not isinstance(item, list) or not item:
            self.notes.append(f"{vid}: behaviour {i + 1} is empty; dropped")
            return None
        name, args = item[0], item[1:]
        kind = _ACTIONS.get(name)
        if kind is None:
            self.notes.append(f"{vid}: behaviour {i + 1} {name!r} is not an action; dropped")
            return None
        to = args[0] if args and isinstance(args[0], int) and args[0] > 0 else None
        if to is not None and kind not in _TAKES_LANE:
            self.notes.append(f"{vid}: {name} takes no lane; dropped its lane {to}")
            to = None
        if kind is ActionKind.CHANGE_LANE and to is None:
            self.errors.append(f"{vid}: change lane without a target lane")
        return Action(kind, to)

    def participant(self, vid: str, info: dict[str, Any]) -> Participant:
        found = [self.action(vid, i, b) for i, b in enumerate(info.get("behaviors", []))]
        actions: tuple[Action, ...] | Unknown = tuple(a for a in found if a is not None)
        if not actions:
            self.notes.append(f"{vid}: no known behaviour; actions are unknown")
            actions = UNKNOWN
        lane = info.get("laneNumber", 0)
        return Participant(
            vid,
            Role.VEHICLE,
            _HEADINGS.get(info.get("direction", 0), UNKNOWN),
            lane if isinstance(lane, int) and lane > 0 else UNKNOWN,
            UNKNOWN,
            actions,
        )


def _stated_in_mph_only(number: str, report: str) -> bool:
    units = {u.lower() for u in re.findall(r"\b" + re.escape(number) + r"\s*-?\s*(km/?h|kmph|kph|mph)\b", report, re.I)}
    return units == {"mph"}


def import_truth(
    data: dict[str, Any], name: str, origin: str = "<truth>", report: Path | None = None, report_text: str | None = None
) -> Imported:
    """One ground-truth record as a Scenario, with notes on every repair; `report` is recorded as its provenance,
    `report_text` (else that report's text) tells the unit of a bare speed-limit number."""
    imp = _Importer(origin)
    if data.get("T") == "yes":
        kind = RoadKind.T_JUNCTION
    elif data.get("intersection") == "yes":
        kind = RoadKind.INTERSECTION
    else:
        kind = RoadKind.STRAIGHT
    lanes = data.get("laneCount", 0)
    cars = data.get("carInformation", {})
    participants = tuple(imp.participant(vid, cars[vid]) for vid in sorted(cars))
    striker = data.get("striker")
    others = [p.id for p in participants if p.id != striker]
    crash = Crash(
        _IMPACT.get(data.get("impactPart", 0), UNKNOWN),
        striker if striker in cars else UNKNOWN,
        others[0] if striker in cars and len(others) == 1 else UNKNOWN,
    )
    provenance = None
    if report is not None and report.is_file():
        provenance = Provenance(str(report), hashlib.sha256(report.read_bytes()).hexdigest(), "truth", UNKNOWN)
        report_text = report_text or report.read_text(encoding="utf-8", errors="replace")
    scenario = Scenario(
        name,
        provenance,
        Environment(
            imp.words(data.get("weather"), {w.value: w for w in Weather}, "weather"),
            imp.words(data.get("lighting"), _LIGHTING, "lighting"),
        ),
        Road(
            kind,
            lanes if isinstance(lanes, int) and lanes > 0 else UNKNOWN,
            imp.speed_limit(data.get("speedlimit"), report_text),
        ),
        participants,
        crash,
    )
    if imp.errors:
        raise ParseError([Diagnostic(e, Span.whole_file(origin)) for e in imp.errors])
    return Imported(scenario, tuple(imp.notes))


def import_truth_file(path: Path, reports_root: Path | None = None) -> Imported:
    """Import `.../truth/<category>/<n>.json`; the scenario is named `<category>_<n>`, and its provenance
    points at `<reports_root>/<category>/<n>.txt` when that exists. Without `reports_root` the report beside
    `truth/` (as in shared/data) is still read, for the unit of a bare speed limit."""
    source = read_source(path, "ground-truth JSON file")
    try:
        data = json.loads(source.text)
    except json.JSONDecodeError as exc:
        raise ParseError(
            Diagnostic(f"invalid JSON: {exc.msg}", Span(source.name, exc.lineno, exc.colno, exc.lineno, exc.colno + 1))
        ) from None
    if not isinstance(data, dict) or "carInformation" not in data:
        raise ParseError(Diagnostic("not a ground-truth record (no carInformation)", Span.whole_file(source.name)))
    category = path.parent.name
    report = reports_root / category / f"{path.stem}.txt" if reports_root else None
    beside = path.resolve().parents[1].parent / "reports" / category / f"{path.stem}.txt"
    text = beside.read_text(encoding="utf-8", errors="replace") if report is None and beside.is_file() else None
    return import_truth(data, f"{category}_{path.stem}", source.name, report, text)
