"""Semantic rules of a scenario: the checks a grammar cannot make.

Each rule is one small function yielding diagnostics with the span of the
offending fact; `verify` runs them all so the user sees every problem at once.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from dataclasses import fields

from sovarc.dsl.errors import Diagnostic, Severity, VerifyError
from sovarc.dsl.ir import ACTION_SPECS, FACT_PATH, ActionKind, Role, Scenario, Side, Unknown
from sovarc.dsl.parser import is_plain_name

Rule = Callable[[Scenario], Iterator[Diagnostic]]

_SHA256 = re.compile(r"[0-9a-f]{64}")


def _has_participants(s: Scenario) -> Iterator[Diagnostic]:
    if not s.participants:
        yield Diagnostic(
            "the scenario has no participants",
            s.meta.span,
            hint="add a `vehicle V1 { ... }` or `pedestrian P1 { ... }` block",
        )


def _names_writable(s: Scenario) -> Iterator[Diagnostic]:
    # IR built from JSON (say, by a model) may carry ids the text form cannot spell.
    named = [("scenario name", s.name, s.meta.span)] + [("participant id", p.id, p.meta.span) for p in s.participants]
    for what, name, span in named:
        if not is_plain_name(name):
            yield Diagnostic(
                f"{what} '{name}' is not a plain name",
                span,
                hint="use letters, digits, '_' or '-', starting with a letter, and no keyword",
            )


def _unique_ids(s: Scenario) -> Iterator[Diagnostic]:
    seen: dict[str, int] = {}
    for p in s.participants:
        if p.id in seen:
            first = s.participants[seen[p.id]].meta.span
            yield Diagnostic(
                f"participant '{p.id}' is defined twice",
                p.meta.span,
                hint=f"first defined at line {first.line}" if first else None,
            )
        seen.setdefault(p.id, s.participants.index(p))


def _crash_pair(s: Scenario) -> Iterator[Diagnostic]:
    c, ids = s.crash, [p.id for p in s.participants]
    for role in ("striker", "victim"):
        pid = getattr(c, role)
        if isinstance(pid, Unknown):
            if len(s.participants) > 1:
                yield Diagnostic(f"the crash {role} is unknown", c.meta.where(role), Severity.WARNING)
        elif pid not in ids:
            yield Diagnostic(
                f"crash {role} '{pid}' is not a participant",
                c.meta.where(role),
                hint="participants: " + (", ".join(ids) or "none"),
            )
    if not isinstance(c.striker, Unknown) and c.striker == c.victim:
        yield Diagnostic(f"'{c.striker}' cannot strike itself: striker and victim must differ", c.meta.where("victim"))


def _speeds_positive(s: Scenario) -> Iterator[Diagnostic]:
    limit = s.road.speed_limit
    if not isinstance(limit, Unknown) and limit.value <= 0:
        yield Diagnostic("the speed limit must be positive", s.road.meta.where("speed_limit"))


def _lanes_in_road(s: Scenario) -> Iterator[Diagnostic]:
    lanes = s.road.lanes
    if isinstance(lanes, Unknown):
        return
    for p in s.participants:
        if not isinstance(p.lane, Unknown) and p.lane > lanes:
            yield Diagnostic(
                f"{p.id} starts in lane {p.lane}, but the road has {lanes} lanes",
                p.meta.where("lane"),
                hint="lanes are counted from the right-most lane, from 1",
            )
        for a in p.known_actions:
            if isinstance(a.to, int) and a.to > lanes:
                yield Diagnostic(
                    f"{p.id} {a.kind} targets lane {a.to}, but the road has {lanes} lanes", a.meta.where("to")
                )


def _actions_fit(s: Scenario) -> Iterator[Diagnostic]:
    for p in s.participants:
        if p.actions == ():
            yield Diagnostic(
                f"{p.id} has no actions",
                p.meta.where("actions"),
                hint="use follow_lane for a participant that just drives on, or `actions unknown`",
            )
        for a in p.known_actions:
            spec = ACTION_SPECS[a.kind]
            if p.role not in spec.roles:
                allowed = " or ".join(sorted(r.value for r in spec.roles))
                yield Diagnostic(f"{a.kind} is an action of a {allowed}, but {p.id} is a {p.role}", a.meta.span)
            if spec.to == "required" and a.to is None:
                yield Diagnostic(
                    f"{a.kind} needs a target lane",
                    a.meta.span,
                    hint=f"write {a.kind}(to: N) with the lane number, or left/right",
                )
            elif spec.to == "none" and a.to is not None:
                yield Diagnostic(f"{a.kind} takes no target lane", a.meta.where("to"))
            elif isinstance(a.to, Side) and a.kind is not ActionKind.CHANGE_LANE:
                yield Diagnostic(f"{a.kind}(to: ...) takes a lane number, not a side", a.meta.where("to"))


def _kind_of_vehicle(s: Scenario) -> Iterator[Diagnostic]:
    for p in s.participants:
        if p.role is Role.PEDESTRIAN and not isinstance(p.kind, Unknown):
            yield Diagnostic(
                f"{p.id} is a pedestrian, which has no vehicle kind",
                p.meta.where("kind"),
                hint="a cyclist is `vehicle ID { kind bicycle ... }`",
            )


def _parked_first(s: Scenario) -> Iterator[Diagnostic]:
    """`parked` is where a vehicle starts: its first action. What follows is how it leaves (`reverse`, `drive_into`)."""
    for p in s.participants:
        for n, a in enumerate(p.known_actions):
            if a.kind is ActionKind.PARKED and n > 0:
                yield Diagnostic(
                    f"{p.id} is parked only after {p.known_actions[n - 1].kind}",
                    a.meta.span,
                    hint="`parked` is a vehicle's first action; a vehicle that parks and stays is `stop`",
                )


def _sha256_form(s: Scenario) -> Iterator[Diagnostic]:
    p = s.provenance
    if p is not None and not isinstance(p.sha256, Unknown) and not _SHA256.fullmatch(p.sha256):
        yield Diagnostic("sha256 must be 64 lower-case hex digits", p.meta.where("sha256"))


def _fact_nodes(s: Scenario) -> dict[str, object]:
    """The nodes a fact's path starts from: the sections by name, the participants by id."""
    return {"road": s.road, "environment": s.environment, "crash": s.crash, **{q.id: q for q in s.participants}}


def _assumed_paths(s: Scenario) -> Iterator[Diagnostic]:
    p = s.provenance
    if p is None:
        return
    nodes = _fact_nodes(s)
    for path in p.assumed:
        head, _, rest = path.partition(".")
        node = nodes.get(head)
        if node is None or rest not in {f.name for f in fields(node)} - {"meta"}:
            yield Diagnostic(f"assumed fact '{path}' names no field of this scenario", p.meta.where("assumed"))


def _evidence_paths(s: Scenario) -> Iterator[Diagnostic]:
    """Evidence names a fact the scenario has (an action by its number, from 1), and quotes as many characters
    as its span holds."""
    p = s.provenance
    if p is None:
        return
    nodes = _fact_nodes(s)
    for e in p.evidence:
        m = FACT_PATH.fullmatch(e.fact)
        node = nodes.get(m["head"]) if m else None
        where = e.meta.span or p.meta.where("evidence")
        if m is None or node is None or m["field"] not in {f.name for f in fields(node)} - {"meta", "id"}:
            yield Diagnostic(f"evidence for '{e.fact}' names no fact of this scenario", where)
        elif m["index"] is not None and (
            m["field"] != "actions" or not 1 <= int(m["index"]) <= len(node.known_actions)  # type: ignore[attr-defined]
        ):
            yield Diagnostic(f"evidence for '{e.fact}' names no action of {m['head']}", where)
        if e.end - e.start != len(e.quote):
            yield Diagnostic(
                f"evidence for '{e.fact}' spans {e.end - e.start} characters but quotes {len(e.quote)}", where
            )


RULES: tuple[Rule, ...] = (
    _has_participants,
    _names_writable,
    _unique_ids,
    _crash_pair,
    _speeds_positive,
    _lanes_in_road,
    _actions_fit,
    _kind_of_vehicle,
    _parked_first,
    _sha256_form,
    _assumed_paths,
    _evidence_paths,
)


def verify(scenario: Scenario) -> list[Diagnostic]:
    """Every diagnostic of every rule, in source order."""
    found = [d for rule in RULES for d in rule(scenario)]
    return sorted(found, key=lambda d: (d.span is None, d.span or ("", 0, 0)))


def verify_or_raise(scenario: Scenario) -> list[Diagnostic]:
    """Raise VerifyError if any rule found an error; return the warnings otherwise."""
    found = verify(scenario)
    errors = [d for d in found if d.severity is Severity.ERROR]
    if errors:
        raise VerifyError(found)
    return found
