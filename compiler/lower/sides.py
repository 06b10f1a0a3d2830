"""The side of a lane change the report does not give ("V2 changed lanes and struck V1"): a named choice.

A side-less `change_lane` says a vehicle moved into a neighbour lane of its own direction and not which one.
Lowering needs a side, so it is chosen here, and the choice is noted:
- a lane changer that strikes, or is struck by, a partner going its way (a side-swipe or a rear-end) moved
  into the partner's lane: that is how two cars in one direction come to touch. Its side is toward the
  partner's lane when both lanes are known; when one is known the other is planned beside it; when neither
  is, the changer is planned in lane 1 and the partner in lane 2;
- any other lane change goes toward a lane that surely exists: from lane 1 (the right-most lane of its
  direction, where an unknown lane is planned) only the lane on its left is one of its direction; from a
  higher lane the one below it is.
A lane change with its side, between such a pair whose lanes are not both known, places them the same way
(beside each other, the changer on the side it comes from). Runs after the headings are chosen and before the
lanes are (assume.py), so that the lanes it plans are kept.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Protocol

from sovarc.dsl.ir import ActionKind, CrashType, Heading, Participant, Side


class _Known(Protocol):
    people: dict[str, Participant]
    striker: str
    victim: str
    crash: CrashType
    notes: list[str]

    def partner(self, p: Participant) -> Participant | None: ...


def sideless(p: Participant) -> bool:
    return any(a.sideless for a in p.known_actions)


def choose_sides(known: _Known) -> None:
    """Give every side-less lane change a side; for a pair that meets in one lane, plan their unknown lanes
    beside each other, the side known or not."""
    for pid in list(known.people):
        p = known.people[pid]
        partner = known.partner(p)
        changes = [a for a in p.known_actions if a.kind is ActionKind.CHANGE_LANE]
        if partner is not None and len(changes) == 1 and _meets_in_one_lane(p, partner, known):
            if changes[0].to is None:
                known.people[pid] = _toward(p, partner, known)
            elif isinstance(changes[0].to, Side):
                known.people[pid] = _beside(p, partner, changes[0].to, known)
        elif sideless(p):
            known.people[pid] = _choose(p, known)


def _beside(p: Participant, partner: Participant, side: Side, known: _Known) -> Participant:
    """A lane change to a known side into the partner's lane: the lane of the pair not known is planned beside
    the other's (the changer in lane 1 or 2 when neither is known)."""
    step = 1 if side is Side.LEFT else -1
    mine, theirs = p.lane, partner.lane
    if isinstance(mine, int) and not isinstance(theirs, int) and mine + step >= 1:
        known.people[partner.id] = _placed(partner, mine + step, f"the lane {p.id} changes into", known, theirs)
    elif isinstance(theirs, int) and not isinstance(mine, int) and theirs - step >= 1:
        p = _placed(p, theirs - step, f"beside {partner.id}, whose lane it changes into", known, mine)
    elif not isinstance(mine, int) and not isinstance(theirs, int):
        start = 1 if side is Side.LEFT else 2
        p = _placed(p, start, f"changing {side.value} into {partner.id}'s lane", known, mine)
        known.people[partner.id] = _placed(partner, start + step, f"the lane {p.id} changes into", known, theirs)
    return p


def _choose(p: Participant, known: _Known) -> Participant:
    lane = p.lane if isinstance(p.lane, int) else 1
    actions = []
    for a in p.known_actions:
        if a.sideless:
            side = Side.LEFT if lane <= 1 else Side.RIGHT
            why = (
                "from lane 1, the right-most of its direction, only the lane on its left is one of its direction"
                if side is Side.LEFT
                else f"from lane {lane} the lane below it is one of its direction"
            )
            known.notes.append(f"{p.id} change_lane side unknown: planned to the {side.value} ({why})")
            a = replace(a, to=side)
        if a.kind is ActionKind.CHANGE_LANE:
            lane = a.to if isinstance(a.to, int) else lane + (1 if a.to is Side.LEFT else -1)
        actions.append(a)
    return replace(p, actions=tuple(actions))


def _meets_in_one_lane(p: Participant, partner: Participant, known: _Known) -> bool:
    """p strikes or is struck by its partner, both going one way, in a side-swipe or a rear-end."""
    same_way = isinstance(p.heading, Heading) and p.heading == partner.heading
    pair = {known.striker, known.victim} == {p.id, partner.id}
    return same_way and pair and known.crash in (CrashType.SIDE, CrashType.REAR_END)


def _toward(p: Participant, partner: Participant, known: _Known) -> Participant:
    mine, theirs = p.lane, partner.lane
    why = f"into {partner.id}'s lane: it {'strikes' if known.striker == p.id else 'is struck by'} {partner.id}"
    why += f", both going {p.heading}, in a {known.crash.value} crash"
    if isinstance(mine, int) and isinstance(theirs, int) and mine != theirs:
        side = Side.LEFT if theirs > mine else Side.RIGHT
        known.notes.append(f"{p.id} change_lane side unknown: planned to the {side.value} ({why})")
    elif isinstance(mine, int):
        side = Side.LEFT if mine <= 1 else Side.RIGHT
        lane = mine + (1 if side is Side.LEFT else -1)
        known.notes.append(f"{p.id} change_lane side unknown: planned to the {side.value} ({why}; from lane {mine})")
        known.people[partner.id] = _placed(partner, lane, f"the lane {p.id} changes into", known, theirs)
    elif isinstance(theirs, int):
        side = Side.RIGHT if theirs <= 1 else Side.LEFT
        start = theirs + (1 if side is Side.RIGHT else -1)
        known.notes.append(f"{p.id} change_lane side unknown: planned to the {side.value} ({why}, in lane {theirs})")
        p = _placed(p, start, f"beside {partner.id}, whose lane it changes into", known, mine)
    else:
        side = Side.LEFT
        known.notes.append(
            f"{p.id} change_lane side unknown: planned to the {side.value} ({why}; neither lane is known: "
            f"from lane 1, the right-most, into lane 2)"
        )
        p = _placed(p, 1, "the right-most, changing into the lane on its left", known, mine)
        known.people[partner.id] = _placed(partner, 2, f"the lane {p.id} changes into", known, theirs)
    actions = tuple(replace(a, to=side) if a.kind is ActionKind.CHANGE_LANE else a for a in p.known_actions)
    return replace(p, actions=actions)


def _placed(p: Participant, lane: int, why: str, known: _Known, was: object) -> Participant:
    """p in `lane`, noted, when its lane was unknown; as it was when the report gave it."""
    if isinstance(was, int):
        return p
    known.notes.append(f"{p.id} lane unknown: planned in lane {lane} ({why})")
    return replace(p, lane=lane)
