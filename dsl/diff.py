"""Semantic diff: what changed between two scenarios, said by meaning, not by line."""

from __future__ import annotations

import difflib
from dataclasses import dataclass, fields
from typing import Any

from sovarc.dsl.ir import Participant, Provenance, Scenario, Unknown, fact_key
from sovarc.dsl.printer import format_action, format_speed, format_words


@dataclass(frozen=True)
class Change:
    """One changed fact; `path` names it (`V2.actions[2]`), `old`/`new` are None when absent."""

    path: str
    old: str | None
    new: str | None
    message: str

    def to_json(self) -> dict[str, Any]:
        return {"path": self.path, "old": self.old, "new": self.new, "message": self.message}


def _show(value: Any) -> str:
    if isinstance(value, (tuple, Unknown)):
        return format_words(value)
    if hasattr(value, "unit"):
        return format_speed(value)
    return str(value)


def _changed(path: str, label: str, old: Any, new: Any) -> Change:
    return Change(path, _show(old), _show(new), f"{label}: {_show(old)} → {_show(new)}")


def _node_fields(prefix: str, a: Any, b: Any, skip: frozenset[str] = frozenset()) -> list[Change]:
    out = []
    for f in fields(a):
        if f.name in skip or not f.compare:
            continue
        old, new = getattr(a, f.name), getattr(b, f.name)
        if old != new:
            out.append(_changed(f"{prefix}.{f.name}", f"{prefix}.{f.name}", old, new))
    return out


def _show_actions(p: Participant) -> str:
    return "unknown" if isinstance(p.actions, Unknown) else ", ".join(format_action(a) for a in p.actions)


def _actions(p: Participant, q: Participant) -> list[Change]:
    if isinstance(p.actions, Unknown) or isinstance(q.actions, Unknown):
        if p.actions == q.actions:
            return []
        return [_changed(f"{p.id}.actions", f"{p.id} actions", _show_actions(p), _show_actions(q))]
    old, new = [format_action(a) for a in p.actions], [format_action(a) for a in q.actions]
    out: list[Change] = []
    matcher = difflib.SequenceMatcher(a=old, b=new, autojunk=False)
    for op, i1, i2, j1, j2 in matcher.get_opcodes():
        if op == "equal":
            continue
        if op == "replace" and i2 - i1 == j2 - j1:
            for k in range(i2 - i1):
                n = i1 + k + 1
                out.append(
                    Change(
                        f"{p.id}.actions[{n}]",
                        old[i1 + k],
                        new[j1 + k],
                        f"{p.id} action {n}: {old[i1 + k]} → {new[j1 + k]}",
                    )
                )
            continue
        for i in range(i1, i2):
            out.append(Change(f"{p.id}.actions[{i + 1}]", old[i], None, f"{p.id} action {i + 1}: removed {old[i]}"))
        for j in range(j1, j2):
            out.append(Change(f"{q.id}.actions[{j + 1}]", None, new[j], f"{q.id} action {j + 1}: added {new[j]}"))
    return out


def _evidence(pa: Provenance, pb: Provenance) -> list[Change]:
    """Evidence that changed, one change per fact: the spans each reader gave it, before and after."""

    def shown(p: Provenance) -> dict[str, str]:
        out: dict[str, list[str]] = {}
        for e in p.evidence:
            out.setdefault(e.fact, []).append(f'{e.reader} {e.start}..{e.end} "{e.quote}"')
        return {fact: "; ".join(spans) for fact, spans in out.items()}

    old, new = shown(pa), shown(pb)
    facts = sorted(set(old) | set(new), key=fact_key)
    return [
        Change(
            f"evidence.{fact}",
            old.get(fact),
            new.get(fact),
            f"evidence of {fact}: {old.get(fact, 'none')} → {new.get(fact, 'none')}",
        )
        for fact in facts
        if old.get(fact) != new.get(fact)
    ]


def diff(a: Scenario, b: Scenario, evidence: bool = False) -> list[Change]:
    """The changes that turn `a` into `b`, in the printer's order of facts. Evidence (why a fact was read) is
    not a fact: its changes are listed only when `evidence` is true."""
    out: list[Change] = []
    if a.name != b.name:
        out.append(_changed("name", "name", a.name, b.name))
    pa, pb = a.provenance, b.provenance
    if pa != pb:
        if pa is None or pb is None:
            out.append(
                Change(
                    "provenance",
                    None if pa is None else "present",
                    None if pb is None else "present",
                    "provenance: " + ("added" if pa is None else "removed"),
                )
            )
        else:
            out += _node_fields("provenance", pa, pb, skip=frozenset({"evidence"}))
            if evidence:
                out += _evidence(pa, pb)
    out += _node_fields("environment", a.environment, b.environment)
    out += _node_fields("road", a.road, b.road)
    old_ids = [p.id for p in a.participants]
    new_ids = [p.id for p in b.participants]
    for p in a.participants:
        q = b.participant(p.id)
        if q is None:
            out.append(Change(p.id, p.role.value, None, f"{p.id}: removed ({p.role})"))
            continue
        out += _node_fields(p.id, p, q, skip=frozenset({"id", "actions"}))
        out += _actions(p, q)
    for q in b.participants:
        if q.id not in old_ids:
            out.append(
                Change(
                    q.id,
                    None,
                    q.role.value,
                    f"{q.id}: added ({q.role}, {_show_actions(q)})",
                )
            )
    common_old = [i for i in old_ids if i in new_ids]
    common_new = [i for i in new_ids if i in old_ids]
    if common_old != common_new:
        out.append(
            Change(
                "participants",
                ", ".join(common_old),
                ", ".join(common_new),
                f"participant order: {', '.join(common_old)} → {', '.join(common_new)}",
            )
        )
    out += _node_fields("crash", a.crash, b.crash)
    return out
