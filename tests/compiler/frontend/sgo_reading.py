"""What the SGO reading tests share: a narrative read by the rules front end, a participant by id, its actions."""

from __future__ import annotations

from sovarc.compiler.frontend import FrontEnd
from sovarc.dsl.ir import ActionKind, Participant, Scenario
from sovarc.dsl.span import Source


def read(text: str) -> Scenario:
    return FrontEnd("none").extract(Source("sgo.txt", text)).scenario


def kinds(p: Participant) -> list[ActionKind]:
    assert isinstance(p.actions, tuple)
    return [a.kind for a in p.actions]


def by_id(s: Scenario, pid: str) -> Participant:
    return next(p for p in s.participants if p.id == pid)
