"""Hybrid extraction: rules read what text patterns state exactly, the model reads the motion layer.

1. The rules read the whole report (`rules.extract`): environment, speed
   limit, lane count, road, participant ids, headings and lanes, and their
   own reading of the actions and the crash.
2. The model is asked only the motion layer (`layers`): the sentences about
   the participants up to the first impact, numbered as in the report. It
   answers each participant's actions and the crash in the compact form
   (`prompting`), each fact followed by the numbers of the sentences it was
   read from, constrained to the answer's JSON Schema.
3. The answer is checked against the schema, its facts settled against the
   rules' reading by their evidence (below), and the merged scenario is
   verified. Problems go back to the model in a bounded repair loop.
4. If the model still has no usable answer, the rules' reading stands and a
   note says so. A provider that cannot answer at all (no model, endpoint
   down, timeout) is an error: nothing is invented.

The rule of settlement: a fact stands on a sentence that states it.
- A fact's evidence is the sentence it was read from. It holds when that
  sentence was shown, is about the fact's participant (names it, or carries
  it as "he", "the driver") and states the fact as done, in a piece of the
  sentence that is the participant's own (`clauses.pieces`: "the driver of V1
  stopped, the driver of V2 crossed over" states no stop of V2): a cue word of
  the action not under an intention ("intending to turn left" states no turn),
  for the crash a sentence describing the impact that names the striker and
  victim given.
- The rules' facts hold by construction: each is read from one clause of one
  sentence. The model's are checked; one whose evidence does not hold is
  rejected, whatever the rules read.
- A model fact that holds and that the rules lack is added, in the order of
  its sentence: the model corrects the rules where they dropped or missed a
  stated action. A fact of the rules the model lacks stays: an omission is
  no evidence.
- Two facts that exclude each other (a left against a right turn, a lane
  change against crossing into the oncoming lanes, which is one move out of
  the lane named two ways; standing parked against stopping; two crash types,
  two strikers) where both hold: the rules' stands, since they read
  the exact clause where the model reads a few sentences at once; when the
  rules have none (an unknown crash type, a struck part not named), the
  model's that holds is taken, its type cross-checked against the headings.
- `follow_lane` first is a convention no sentence states (a vehicle shown
  moving); it stays the rules'.
Every disagreement is a note saying which reading was kept and why.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from typing import Any

import jsonschema
from sovarc.compiler.frontend import prompting
from sovarc.compiler.frontend.evidence import Alignment, evidence_of_span, keep_stated
from sovarc.compiler.frontend.layers import Shown, motion_layer, states_action, states_impact
from sovarc.compiler.frontend.prompting import MAX_ACTIONS
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
    """The model's compact answer, as IR values: each participant's actions and the crash, and for each fact
    the sentences it was read from (`evidence`, keyed by fact path: "V2.actions", "crash.type",
    "crash.striker", "crash.victim") with their character spans in the original report (`spans`)."""

    actions: dict[str, tuple[Action, ...]]
    crash: Crash
    evidence: dict[str, tuple[int, ...]] = field(default_factory=dict)
    spans: dict[str, tuple[tuple[int, int], ...]] = field(default_factory=dict)


def _enum_or_unknown(value: Any, kind: type[Any]) -> Any:
    return UNKNOWN if value == "unknown" else kind(value)


def _action(word: str) -> Action:
    name = prompting.ACTION_OF[word]
    if name.startswith("change_lane_"):
        return Action(ActionKind.CHANGE_LANE, Side(name.removeprefix("change_lane_")))
    return Action(ActionKind(name))


def parse_answer(text: str, ids: list[str], shown: Shown) -> Answer:
    """The answer as IR values; AnswerError when it is not JSON or breaks the answer schema."""
    try:
        data = json.loads(text)
    except ValueError as exc:
        raise AnswerError([f"the answer is not JSON ({exc.msg} at character {exc.pos})"]) from None
    validator = jsonschema.Draft7Validator(prompting.answer_schema(ids, shown.numbers()))
    problems = [
        f"{'/'.join(str(p) for p in error.absolute_path) or 'answer'}: {error.message}"
        for error in sorted(validator.iter_errors(data), key=lambda e: list(map(str, e.absolute_path)))
    ]
    for pid in ids:
        items = data.get(pid, []) if isinstance(data, dict) and not problems else []
        words = [i for i in items if isinstance(i, str)]
        if items and (not words or items[: len(words)] != words or len(words) == len(items)):
            problems.append(f"{pid}: the actions first, then the numbers of the sentences that state them")
    if problems:
        raise AnswerError(problems[:8])
    actions, evidence = {}, {}
    for pid in ids:
        words = [i for i in data[pid] if isinstance(i, str)]
        actions[pid] = _dedupe(tuple(_action(w) for w in words[:MAX_ACTIONS]))
        evidence[f"{pid}.actions"] = tuple(dict.fromkeys(i for i in data[pid] if isinstance(i, int)))
    kind, striker, victim, *cited = data["crash"]
    crash = Crash(CrashType(kind), _enum_or_unknown(striker, str), _enum_or_unknown(victim, str))
    for fact in ("type", "striker", "victim"):
        evidence[f"crash.{fact}"] = tuple(dict.fromkeys(cited))
    spans = {path: tuple(s.span for n in numbers if (s := shown.get(n))) for path, numbers in evidence.items()}
    return Answer(actions, crash, evidence, spans)


def _dedupe(actions: tuple[Action, ...]) -> tuple[Action, ...]:
    out: list[Action] = []
    for a in actions:
        if not out or out[-1] != a:
            out.append(a)
    return tuple(out)


def merge(rules: Scenario, answer: Answer, shown: Shown) -> tuple[Scenario, list[str]]:
    """The rules' reading with the model's merged in, each disagreement settled by its evidence (see the
    module docstring); notes name each disagreement and how it was settled."""
    notes: list[str] = []
    people = []
    for p in rules.participants:
        actions, found = _settle_actions(p.id, p.known_actions, answer, shown)
        notes += found
        people.append(replace(p, actions=actions) if actions else p)
    crash = _settle_crash(rules, answer, shown, notes)
    return replace(rules, participants=tuple(people), crash=crash), notes


def _name(a: Action) -> str:
    """The action as the answer names it: its kind, and the side of a lane change (not a target lane)."""
    return f"change_lane_{a.to}" if a.kind is ActionKind.CHANGE_LANE and isinstance(a.to, Side) else a.kind.value


def _stating(shown: Shown, pid: str, numbers: Iterable[int], a: Action) -> list[int]:
    """The sentences among `numbers` that are about `pid` and state `a` as done in a piece of their own."""
    return [
        n
        for n in numbers
        if shown.about(n, pid) and any(states_action(text, _name(a)) for text in shown.pieces_of(n, pid))
    ]


def _family(a: Action) -> str:
    """Actions of one family exclude each other: a turn is left or right, a lane change one side, and a
    vehicle enters the road or leaves it (from a driveway or into one), not both before one impact."""
    families = {
        ActionKind.TURN_LEFT: "turn",
        ActionKind.TURN_RIGHT: "turn",
        ActionKind.DRIVE_INTO: "road edge",
        ActionKind.DRIVE_OFF: "road edge",
        # one move out of the lane: into the next lane or over the centre line into the oncoming ones
        ActionKind.CHANGE_LANE: "out of lane",
        ActionKind.RETROGRADE: "out of lane",
        # standing still: a parked car is stopped, and the model's stop is the rules' parked
        ActionKind.STOP: "standing",
        ActionKind.PARKED: "standing",
    }
    return families.get(a.kind, a.kind.value)


def _settle_actions(
    pid: str, ruled: tuple[Action, ...], answer: Answer, shown: Shown
) -> tuple[tuple[Action, ...], list[str]]:
    """The rules' actions with each action the model adds that its cited sentences state as done, in the
    order of those sentences; an addition its sentences do not state is rejected, one that contradicts a
    rules' action of the same family (left against right) leaves the rules' reading."""
    modelled, cited = answer.actions[pid], answer.evidence.get(f"{pid}.actions", ())
    names = [_name(a) for a in ruled]
    if not ruled or names == [_name(a) for a in modelled]:
        if not ruled and modelled:  # the rules found no action: each the model states with evidence
            kept = tuple(a for a in modelled if _stating(shown, pid, cited, a))
            return kept, [f"{pid} actions: the rules read none; kept the model's {_words(kept)}"] if kept else []
        return ruled, []
    numbers = [s.number for s in shown.sentences]
    where: list[int] = []  # the sentence each rules' action is read from, in order (the one before when unseen)
    for a in ruled:
        found = [n for n in _stating(shown, pid, numbers, a) if not where or n >= where[-1]]
        where.append(found[0] if found else (where[-1] if where else 0))
    out = list(zip(where, ruled, strict=True))
    notes: list[str] = []
    for a in modelled:
        if (
            _name(a) in names or a.kind is ActionKind.FOLLOW_LANE
        ):  # follow_lane is the rules' convention, stated nowhere
            continue
        stated = _stating(shown, pid, cited, a)
        against = [r for r in ruled if _family(r) == _family(a)]
        if not stated:
            notes.append(
                f"{pid} actions: the model's {_name(a)} cites sentence(s) {_cites(cited)}, which do not state it "
                f"of {pid}; rejected"
            )
        elif against and (sided := _side_of(against[0], a)) is not None:  # no contradiction: the side it left open
            out = [(n, sided if r is against[0] else r) for n, r in out]
            notes.append(f"{pid} actions: the rules read a change_lane without its side; kept the model's {_name(a)}")
        elif against:
            notes.append(f"{pid} actions: the model read {_name(a)}, the rules {_name(against[0])}; kept the rules")
        else:
            at = stated[0]
            index = next((i for i, (n, r) in enumerate(out) if n > at and i > 0), len(out))
            out.insert(index, (at, a))
            notes.append(f"{pid} actions: the model's {_name(a)} is stated in sentence {at}; added to the rules'")
    read = {_name(a) for a in modelled}
    kept = [r for _, r in out]
    missing = [a for a in ruled if _name(a) not in read and a.kind is not ActionKind.FOLLOW_LANE and a in kept]
    if missing:
        notes.append(f"{pid} actions: the model did not read {_words(tuple(missing))}; kept the rules'")
    return _dedupe(tuple(a for _, a in out)), notes


def _side_of(ruled: Action, modelled: Action) -> Action | None:
    """The rules' side-less lane change with the side the model gives it, if that is what the two are."""
    return (
        replace(ruled, to=modelled.to)
        if ruled.sideless and modelled.kind is ActionKind.CHANGE_LANE and modelled.to is not None
        else None
    )


def _cites(numbers: tuple[int, ...]) -> str:
    return ", ".join(map(str, numbers)) or "none"


def _settle_crash(rules: Scenario, answer: Answer, shown: Shown, notes: list[str]) -> Crash:
    """The crash the impact sentence states (the rules'), else the model's if its cited sentence describes
    an impact and names the striker it gives; its type is then cross-checked against the headings."""
    got, cited = answer.crash, answer.evidence.get("crash.type", ())
    sentences = [s.text for n in cited if (s := shown.get(n)) is not None]
    named = [who for who in (got.striker, got.victim) if not isinstance(who, Unknown)]
    grounded = any(states_impact(t) and all(re.search(rf"\b{w}\b", t) for w in named) for t in sentences)
    if not grounded:
        notes.append(
            f"crash: the model's {_crash_words(got)} cites sentence(s) {_cites(cited)}, which do not describe "
            "that impact; rejected"
        )
        return rules.crash
    stated = not isinstance(rules.crash.type, Unknown)
    # A sentence the rules read for who struck whom that names no struck part leaves the type unstated.
    unstated = not stated and not isinstance(rules.crash.striker, Unknown)
    crash = rules.crash if stated or unstated else replace(rules.crash, type=got.type)
    if stated and rules.crash.type != got.type:
        notes.append(f"crash: the report states {rules.crash.type}, the model read {got.type}")
    if unstated:
        notes.append(f"crash: the report names no struck part; the model's {got.type} is not kept")
    if not stated and (fixed := _geometry_check(rules, crash.type)) is not None:
        notes.append(f"crash: the model read {crash.type}, but the headings make it {fixed}; kept {fixed}")
        crash = replace(crash, type=fixed)
    if isinstance(crash.striker, Unknown) and not isinstance(got.striker, Unknown):
        crash = replace(crash, striker=got.striker, victim=got.victim)
    elif crash.striker != got.striker:
        notes.append(f"crash: the report states {crash.striker} struck, the model read {got.striker}")
    return crash


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


def _model_evidence(rules: Scenario, merged: Scenario, text: str, answer: Answer) -> Scenario:
    """Evidence for the facts the settled reading took from the model: the sentences its answer cited for
    them (else the range it was shown). The rules' evidence for actions follows each action to its place
    when the model's actions were inserted among them."""
    shown = shown_span(text)

    def cited(path: str) -> tuple[int, int]:
        spans = answer.spans.get(path) or ()
        return (min(a for a, _ in spans), max(b for _, b in spans)) if spans else shown

    provenance = merged.provenance or Provenance()
    moved = list(provenance.evidence)
    added: list[tuple[str, tuple[int, int]]] = []
    for person in merged.participants:
        before = rules.participant(person.id)
        old = before.actions if before is not None else UNKNOWN
        new = person.actions
        if old == new or isinstance(new, Unknown):
            continue
        place = _placed(old if isinstance(old, tuple) else (), new)
        prefix = f"{person.id}.actions["
        moved = [
            replace(e, fact=f"{prefix}{place[int(e.fact[len(prefix) : -1])]}]") if e.fact.startswith(prefix) else e
            for e in moved
            if not e.fact.startswith(prefix) or int(e.fact[len(prefix) : -1]) in place
        ]
        kept = set(place.values())
        added += [(f"{prefix}{n}]", cited(f"{person.id}.actions")) for n in range(1, len(new) + 1) if n not in kept]
    merged = replace(merged, provenance=replace(provenance, evidence=tuple(moved)))
    for f in ("type", "striker", "victim"):
        if getattr(merged.crash, f) != getattr(rules.crash, f) and not isinstance(getattr(merged.crash, f), Unknown):
            added.append((f"crash.{f}", cited(f"crash.{f}")))
    for fact, (start, end) in added:
        merged = attach_evidence(merged, fact, start, end, text, Reader.MODEL)
    return keep_stated(merged)


def _placed(old: tuple[Action, ...], new: tuple[Action, ...]) -> dict[int, int]:
    """Where each of the rules' actions (1-based) sits among the settled ones, which keep the rules' in order."""
    place: dict[int, int] = {}
    i = 0
    for j, action in enumerate(new, 1):
        if i < len(old) and old[i] == action:
            place[i + 1] = j
            i += 1
    return place


def model_reading(
    rules: Scenario, text: str, provider: Provider, max_repairs: int = MAX_REPAIRS
) -> tuple[Scenario, list[str]]:
    """The rules' scenario with the model's reading merged in, repaired until it verifies."""
    merged, notes, _ = read_with_model(rules, text, provider, max_repairs)
    return merged, notes


def read_with_model(
    rules: Scenario, text: str, provider: Provider, max_repairs: int = MAX_REPAIRS
) -> tuple[Scenario, list[str], Answer | None]:
    """The rules' scenario with the model's reading merged in, repaired until it verifies; with the answer,
    whose evidence spans say where in the report each of the model's facts was read."""
    ids = [p.id for p in rules.participants]
    shown = motion_layer(text)
    system = prompting.system_prompt()
    schema = prompting.answer_schema(ids, shown.numbers())
    user = prompting.user_prompt(shown, ids)
    problems: list[str] = []
    for attempt in range(max_repairs + 1):
        answer_text = provider.complete_json(system, user, schema, max_tokens=prompting.answer_budget(ids))
        try:
            answer = parse_answer(answer_text, ids, shown)
            merged, notes = merge(rules, answer, shown)
            problems = [d.message for d in verify(merged) if d.severity is Severity.ERROR]
        except AnswerError as exc:
            problems = exc.problems
        if not problems:
            if attempt:
                notes.append(f"the model's answer was repaired in {attempt} round(s)")
            return _model_evidence(rules, merged, text, answer), notes, answer
        user = prompting.repair_prompt(shown, ids, answer_text.strip(), problems)
    return (
        rules,
        [
            f"the model gave no usable answer after {max_repairs} repair round(s) ({'; '.join(problems)}); "
            "the dynamic layer is the rules' reading"
        ],
        None,
    )
