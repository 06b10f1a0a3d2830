"""Who backed into the impact, and what that says of the crash: a vehicle backing leads with its rear."""

from __future__ import annotations

from dataclasses import replace

from sovarc.dsl.ir import ActionKind, Crash, CrashType, Participant


def backing(people: list[Participant]) -> frozenset[str]:
    """The vehicles backing at the impact: their last action is the reverse."""
    return frozenset(p.id for p in people if p.known_actions and p.known_actions[-1].kind is ActionKind.REVERSE)


def backing_leads(people: list[Participant], crash: Crash) -> Crash:
    """A vehicle backing into the impact leads with its rear. The crash readers take a front for the striking
    face, so "the rear of V2 struck the front of V1" reads as V1's front into V2's rear: the faces of a rear-end
    crash, with the striker the wrong way round when V2 was the one backing and V1 was not."""
    if crash.type is not CrashType.REAR_END or not isinstance(crash.striker, str) or not isinstance(crash.victim, str):
        return crash
    backers = backing(people)
    if crash.victim in backers and crash.striker not in backers:
        return replace(crash, striker=crash.victim, victim=crash.striker)
    return crash
