"""What a scenario asks of a site: per participant, a heading, lanes and a junction manoeuvre.

Facts written `unknown` ask for nothing. Lanes are counted from the right-most lane as 1.
"""

from __future__ import annotations

from dataclasses import dataclass

from sovarc.dsl.ir import Action, ActionKind, Heading, Participant, Role, Scenario, Side

# The first of these in a participant's actions happens at the junction; what it needs is
# a connection of one of these SUMO directions from the participant's arm. A U-turn needs
# only a two-way arm: a vehicle can turn on the road even where SUMO built no turnaround.
JUNCTION_MOVES: dict[ActionKind, frozenset[str]] = {
    ActionKind.TURN_LEFT: frozenset({"l", "L"}),
    ActionKind.TURN_RIGHT: frozenset({"r", "R"}),
    ActionKind.GO_ACROSS: frozenset({"s"}),
    ActionKind.U_TURN: frozenset({"t"}),
}

HEADING_DEGREES: dict[Heading, int] = {Heading.NORTH: 0, Heading.EAST: 90, Heading.SOUTH: 180, Heading.WEST: 270}


@dataclass(frozen=True)
class Need:
    """What one participant needs from a site."""

    participant: str
    heading: Heading | None  # None: unknown, so it is not tied to an arm
    placed: bool  # starts in a lane of an arm: a vehicle with a heading, or a pedestrian walking in a lane
    lane: int | None  # start lane; None when unknown
    lanes: int  # lanes its start arm needs in its direction (start lane, lane changes); 0 for none stated
    move: ActionKind | None  # its first junction manoeuvre, if any
    to_lanes: int  # lanes needed where the manoeuvre leads (its `to`, lane changes after it); 0 for none
    against_start: bool  # drives against traffic on its start arm (needs the opposite lanes)
    against_after: bool  # drives against traffic after its manoeuvre

    def describe(self) -> str:
        """'V1 heading west: 4 lanes, turn_left into lane 1', for error messages."""
        parts = []
        if self.lanes:
            parts.append(f"{self.lanes} lane{'s' if self.lanes > 1 else ''}")
        if self.move is not None:
            parts.append(self.move.value + (f" into lane {self.to_lanes}" if self.to_lanes else ""))
        if self.against_start or self.against_after:
            parts.append("opposite lanes")
        where = f"heading {self.heading.value}" if self.heading else "heading unknown"
        return f"{self.participant} {where}: {', '.join(parts) or 'any lane'}"


def scenario_needs(scenario: Scenario) -> tuple[Need, ...]:
    return tuple(participant_need(p) for p in scenario.participants)


def participant_need(p: Participant) -> Need:
    heading = p.heading if isinstance(p.heading, Heading) else None
    lane = p.lane if isinstance(p.lane, int) else None
    placed = heading is not None and (p.role is Role.VEHICLE or lane is not None)
    current, lanes = lane, lane or 0
    move: ActionKind | None = None
    to_lanes = 0
    against_start = against_after = False
    for action in p.actions:
        if move is None:
            if action.kind in JUNCTION_MOVES:
                move = action.kind
                to_lanes = action.to if isinstance(action.to, int) else 0
            elif action.kind is ActionKind.CHANGE_LANE:
                current, needed = _change_lane(current, action)
                lanes = max(lanes, needed)
            elif action.kind is ActionKind.RETROGRADE:
                against_start = True
        elif action.kind is ActionKind.CHANGE_LANE:
            to_lanes = max(to_lanes, action.to if isinstance(action.to, int) else 2)
        elif action.kind is ActionKind.RETROGRADE:
            against_after = True
    return Need(p.id, heading, placed, lane, lanes, move, to_lanes, against_start, against_after)


def _change_lane(current: int | None, action: Action) -> tuple[int | None, int]:
    """The lane after a lane change, and the lanes the change needs."""
    if isinstance(action.to, int):
        return action.to, action.to
    if action.to is Side.LEFT:
        target = (current or 1) + 1
        return target, target
    # to the right: from a known lane one lane down; from an unknown lane, at least two lanes
    return (current - 1 if current and current > 1 else None), max(current or 2, 2)
