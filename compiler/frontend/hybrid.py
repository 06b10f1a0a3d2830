"""Hybrid extraction: rules read what text patterns state exactly, the model reads the dynamic layer.

1. The rules read the whole report (`rules.extract`): environment, speed
   limit, lane count, participant ids, and their own reading of the rest.
2. The model answers the compact form (`prompting`) for the prepared
   narrative, constrained to the answer's JSON Schema.
3. The answer is checked against the schema, merged with the rules' reading
   (each fact from the source that is right more often, disagreements
   noted), and the merged scenario is verified. Problems go back to the model
   in a bounded repair loop.
4. If the model still has no usable answer, the rules' reading stands and a
   note says so. A provider that cannot answer at all (no model, endpoint
   down, timeout) is an error: nothing is invented.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, replace
from typing import Any

import jsonschema
from sovarc.compiler.frontend import prompting
from sovarc.compiler.frontend.evidence import Alignment, evidence_of_span, keep_stated
from sovarc.compiler.frontend.providers.base import Provider
from sovarc.compiler.frontend.text import prepare, sentences, up_to_first_impact
from sovarc.dsl import verify
from sovarc.dsl.errors import Severity
from sovarc.dsl.ir import (
    UNKNOWN,
    Action,
    ActionKind,
    Crash,
    CrashType,
    Heading,
    Provenance,
    Reader,
    Role,
    Scenario,
    Side,
    Unknown,
)

MAX_REPAIRS = 2


class AnswerError(Exception):
    """The model's answer cannot be used as it is; each problem is one line for the repair prompt."""

    def __init__(self, problems: list[str]) -> None:
        super().__init__("; ".join(problems))
        self.problems = problems


@dataclass(frozen=True)
class Answer:
    """The model's compact answer, as IR values: each participant's actions, and the crash."""

    actions: dict[str, tuple[Action, ...]]
    crash: Crash


def _enum_or_unknown(value: Any, kind: type[Any]) -> Any:
    return UNKNOWN if value == "unknown" else kind(value)


def _action(word: str) -> Action:
    if word.startswith("change_lane_"):
        return Action(ActionKind.CHANGE_LANE, Side(word.removeprefix("change_lane_")))
    return Action(ActionKind(word))


def parse_answer(text: str, ids: list[str]) -> Answer:
    """The answer as IR values; AnswerError when it is not JSON or breaks the answer schema."""
    try:
        data = json.loads(text)
    except ValueError as exc:
        raise AnswerError([f"the answer is not JSON ({exc.msg} at character {exc.pos})"]) from None
    validator = jsonschema.Draft202012Validator(prompting.answer_schema(ids))
    problems = [
        f"{'/'.join(str(p) for p in error.absolute_path) or 'answer'}: {error.message}"
        for error in sorted(validator.iter_errors(data), key=lambda e: list(map(str, e.absolute_path)))
    ]
    if problems:
        raise AnswerError(problems[:8])
    actions = {pid: _dedupe(tuple(_action(a) for a in p["actions"])) for pid, p in data["participants"].items()}
    c = data["crash"]
    crash = Crash(CrashType(c["type"]), _enum_or_unknown(c["striker"], str), _enum_or_unknown(c["victim"], str))
    return Answer(actions, crash)


def _dedupe(actions: tuple[Action, ...]) -> tuple[Action, ...]:
    out: list[Action] = []
    for a in actions:
        if not out or out[-1] != a:
            out.append(a)
    return tuple(out)


def merge(rules: Scenario, answer: Answer) -> tuple[Scenario, list[str]]:
    """The rules' reading with the model's merged in; notes name each disagreement and which reading was kept.

    Each fact comes from the reader that gets it right more often (measured on the NMVCCS reports, see the
    README): the rules keep the environment, the road, headings and lanes, and the actions, which they read
    clause by clause in report order (a disagreement is noted; the small model adds actions the report does
    not state and misorders them). The crash is the rules' when a sentence states it ("the front of V1 struck
    the rear of V2"), its type left unknown when that sentence names no struck part; else (or for who struck
    whom after a bare "head-on") the model's, its type cross-checked against the headings.
    """
    notes: list[str] = []
    people = []
    for p in rules.participants:
        ruled, modelled = p.known_actions, answer.actions[p.id]
        if ruled and ruled != modelled:
            notes.append(
                f"{p.id} actions: the model read {_words(modelled)}, the rules {_words(ruled)}; kept the rules"
            )
        people.append(p)
    stated = not isinstance(rules.crash.type, Unknown)
    # A sentence the rules read for who struck whom that names no struck part leaves the type unstated.
    unstated = not stated and not isinstance(rules.crash.striker, Unknown)
    crash = rules.crash if stated or unstated else replace(rules.crash, type=answer.crash.type)
    if stated and rules.crash.type != answer.crash.type:
        notes.append(f"crash: the report states {rules.crash.type}, the model read {answer.crash.type}")
    if unstated:
        notes.append(f"crash: the report names no struck part; the model's {answer.crash.type} is not kept")
    if not stated and (fixed := _geometry_check(rules, crash.type)) is not None:
        notes.append(f"crash: the model read {crash.type}, but the headings make it {fixed}; kept {fixed}")
        crash = replace(crash, type=fixed)
    if isinstance(crash.striker, Unknown) and not isinstance(answer.crash.striker, Unknown):
        crash = replace(crash, striker=answer.crash.striker, victim=answer.crash.victim)
    elif crash.striker != answer.crash.striker:
        notes.append(f"crash: the report states {crash.striker} struck, the model read {answer.crash.striker}")
    return replace(rules, participants=tuple(people), crash=crash), notes


_AXIS = {Heading.NORTH: 0, Heading.SOUTH: 0, Heading.EAST: 1, Heading.WEST: 1}


def _geometry_check(rules: Scenario, said: CrashType | Unknown) -> CrashType | None:
    """A rear-end crash needs two vehicles heading the same way: with crossing headings it is a side crash,
    with opposite ones (and no turn) a frontal one. None when the headings do not contradict the type."""
    vehicles = [p for p in rules.participants if p.role is Role.VEHICLE]
    if said is not CrashType.REAR_END or len(vehicles) != 2:
        return None
    a, b = (p.heading for p in vehicles)
    if isinstance(a, Unknown) or isinstance(b, Unknown) or a == b:
        return None
    return CrashType.SIDE if _AXIS[a] != _AXIS[b] else CrashType.FRONTAL


def _words(actions: tuple[Action, ...]) -> str:
    return "[" + ", ".join(a.kind.value for a in actions) + "]"


def _crash_words(c: Crash) -> str:
    return f"{c.type} by {c.striker} into {c.victim}"


def attach_evidence(scenario: Scenario, fact: str, start: int, end: int, report: str, reader: Reader) -> Scenario:
    """The scenario with the report's characters `start`..`end` as the evidence of `fact` (a path such as
    `crash.type`), read by `reader`; evidence another reader gave that fact is replaced, since its reading
    was not kept."""
    provenance = scenario.provenance or Provenance()
    kept = tuple(e for e in provenance.evidence if e.fact != fact)
    found = evidence_of_span(report, fact, start, end, reader)
    return replace(scenario, provenance=replace(provenance, evidence=(*kept, found)))


def shown_span(text: str) -> tuple[int, int]:
    """The report's characters the model is shown: from the start to the end of the first impact's sentence.

    The model's answer names no sentence for each fact yet, so this range is the evidence of every fact the
    model's reading gives."""
    sents = up_to_first_impact(sentences(prepare(text)))
    found = Alignment(" ".join(sents), text).span(0, len(" ".join(sents)))
    return found if found is not None else (0, len(text))


def _model_evidence(rules: Scenario, merged: Scenario, text: str) -> Scenario:
    """Evidence for the facts the model's reading gave (those where the merged scenario is not the rules')."""
    start, end = shown_span(text)
    for f in ("type", "striker", "victim"):
        if getattr(merged.crash, f) != getattr(rules.crash, f) and not isinstance(getattr(merged.crash, f), Unknown):
            merged = attach_evidence(merged, f"crash.{f}", start, end, text, Reader.MODEL)
    return keep_stated(merged)


def model_reading(
    rules: Scenario, text: str, provider: Provider, max_repairs: int = MAX_REPAIRS
) -> tuple[Scenario, list[str]]:
    """The rules' scenario with the model's reading merged in, repaired until it verifies."""
    ids = [p.id for p in rules.participants]
    narrative = prompting.prepared_narrative(text)
    system = prompting.system_prompt()
    schema = prompting.answer_schema(ids)
    user = prompting.user_prompt(narrative, ids)
    problems: list[str] = []
    for attempt in range(max_repairs + 1):
        answer_text = provider.complete_json(system, user, schema, max_tokens=prompting.answer_budget(ids))
        try:
            merged, notes = merge(rules, parse_answer(answer_text, ids))
            problems = [d.message for d in verify(merged) if d.severity is Severity.ERROR]
        except AnswerError as exc:
            problems = exc.problems
        if not problems:
            if attempt:
                notes.append(f"the model's answer was repaired in {attempt} round(s)")
            return _model_evidence(rules, merged, text), notes
        user = prompting.repair_prompt(narrative, ids, answer_text.strip(), problems)
    return rules, [
        f"the model gave no usable answer after {max_repairs} repair round(s) ({'; '.join(problems)}); "
        "the dynamic layer is the rules' reading"
    ]
