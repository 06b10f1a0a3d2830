"""Facts that no road can reconcile, found once, before any site is searched.

    check_headings(scenario)     raises UnsatError naming the facts

A crash type fixes the angle between the two headings at impact (`CRASH_ANGLES`: rear_end within
45 degrees, frontal at least 100). A vehicle whose actions never turn it (see `KEEPS_HEADING`)
meets its partner at its reported compass heading, give or take a swerve. So a rear_end between
vehicles heading opposite ways, or a frontal crash between vehicles heading the same way, fails on
every site; without this check each site would be tried, and each would fail with the same cause
in other words.
"""

from __future__ import annotations

from sovarc.compiler.crashes import CRASH_ANGLES, needs
from sovarc.compiler.lower.assume import COMPASS
from sovarc.dsl.errors import Diagnostic, Severity, UnsatError
from sovarc.dsl.ir import ActionKind, CrashType, Heading, Participant, Role, Scenario

# Actions after which a vehicle still heads the way it started, within a swerve.
KEEPS_HEADING = frozenset(
    {ActionKind.FOLLOW_LANE, ActionKind.CHANGE_LANE, ActionKind.GO_ACROSS, ActionKind.STOP, ActionKind.RETROGRADE}
)
SWERVE = 35.0  # degrees a lane change or a swerve onto the oncoming lane turns a vehicle, at most


def check_headings(scenario: Scenario) -> None:
    crash = scenario.crash
    if crash.type not in (CrashType.REAR_END, CrashType.FRONTAL):
        return
    pair = [scenario.participant(pid) for pid in (crash.striker, crash.victim) if isinstance(pid, str)]
    if len(pair) != 2 or not all(p is not None and _holds_heading(p) for p in pair):
        return
    striker, victim = pair
    assert striker is not None and victim is not None
    quarters = (COMPASS.index(striker.heading) - COMPASS.index(victim.heading)) % 4  # type: ignore[arg-type]
    apart = 90.0 * min(quarters, 4 - quarters)
    low, high = CRASH_ANGLES[crash.type.value]
    if max(0.0, apart - 2 * SWERVE) <= high and min(180.0, apart + 2 * SWERVE) >= low:
        return
    # Relative to the victim the striker moves the way it heads less the victim's way: closing head-on,
    # its front meets the victim's front or a side first; going the same way, the rear or a side.
    if crash.type is CrashType.REAR_END:
        how, reach, never = "closing on each other", "front or a side", "rear"
    else:
        how, reach, never = "going the same way", "rear or a side", "front"
    message = (
        f"{needs(crash.type, striker.id, victim.id)}, but {striker.id} heads {striker.heading} and {victim.id} "
        f"{victim.heading}, and neither turns: {how}, {striker.id}'s front can reach {victim.id}'s {reach}, "
        f"never its {never}: no road can stage it"
    )
    notes = [
        Diagnostic(
            f"{p.id} heads {p.heading} and then: {', '.join(a.kind.value for a in p.known_actions)}",
            p.meta.where("heading"),
            severity=Severity.NOTE,
        )
        for p in pair
        if p is not None
    ]
    hint = (
        "vehicles heading opposite ways meet front to front (frontal) or front into a side (side); a blow "
        f"to {victim.id}'s rear corner as they pass is {striker.id} entering {victim.id}'s side: a side crash"
        if crash.type is CrashType.REAR_END
        else "vehicles heading the same way meet front into rear (rear_end) or front into a side (side)"
    )
    raise UnsatError([Diagnostic(message, crash.meta.where("type"), hint=hint), *notes])


def _holds_heading(p: Participant) -> bool:
    return (
        p.role is Role.VEHICLE
        and isinstance(p.heading, Heading)
        and bool(p.known_actions)
        and all(a.kind in KEEPS_HEADING for a in p.known_actions)
    )
