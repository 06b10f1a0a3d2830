"""A crash on an earlier leg of a turn in legs: the route cut where that leg ends.

A three-point turn (kturn.py) swings the car across the road on its first forward leg, and back
across on its reverse leg; on a road of one lane each way that is where it meets the traffic it
turns across, a car coming up behind it in its own lane or one coming the other way. Lowering
puts a crash on a route's last leg (solve.py), and a turn's last leg ends it facing back. A crash
on leg k is the same problem on the route that ends where leg k does: the legs after it are never
driven (the crash stops them), and the car stands where the leg ends, which every stage reads as
a turn's change of gear. On a reverse leg the car leads with its rear, as a car backing along the
road does (Route.backs_at_end): the crash type reads with front and rear swapped, as every oracle
judges a body moving backwards (crashes.backing_at).

After the crash the car brakes to stand where the leg ends (synthesis), at its usual rate at the
most: so it is met no nearer the leg's end than it brakes to rest from walking pace (`room`).

Tried after every staging of the whole turn (lowering's last pass, so a plan that planned before is
unchanged), from the first leg on: the first leg that meets the partner is where they meet, since
the crash ends the turn.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace

from sovarc.compiler.lower.contact import Contact
from sovarc.compiler.lower.route import MANOEUVRE_SPEED, Manoeuvre, Route
from sovarc.compiler.vehicles import model


def earlier_legs(route: Route) -> Iterator[tuple[Route, str]]:
    """The route cut at the end of each leg of its turns in legs but their last, in order, with a
    note saying which leg the crash is on; none for a route without such a turn."""
    for m in route.manoeuvres:
        if m.backing:
            continue
        for j, end in enumerate(m.stops[1:]):  # leg j runs from stops[j] to stops[j + 1]
            way = "forward" if m.gears[j] > 0 else "reversing"
            note = (
                f"{route.participant.id} is met on leg {j + 1} of its {len(m.gears)}-leg turn ({way}): "
                "the crash ends the turn there"
            )
            yield ended_at(route, end), note


def ended_at(route: Route, end: float) -> Route:
    """The route up to arc length `end`, a stop of one of its turns in legs: the line cut there, its
    turns' legs after it dropped and its events past it too."""
    # the stop where the cut leg ends is never reached either: the crash comes first
    events = [replace(e, hi=min(e.hi, end)) for e in route.events if e.lo < end - 1e-6]
    manoeuvres = tuple(_cut(m, end) for m in route.manoeuvres if m.lo < end - 1e-6)
    return replace(
        route,
        line=route.line.sub(0.0, end),
        events=events,
        start_hi=min(route.start_hi, end),
        start_lo=min(route.start_lo, end),
        notes=list(route.notes),
        caps=None,
        manoeuvres=manoeuvres,
        trail=None,
    )


def _cut(m: Manoeuvre, end: float) -> Manoeuvre:
    if m.hi <= end + 1e-6:
        return m
    keep = m.s <= end + 1e-6
    stops = tuple(x for x in m.stops if x < end - 1e-6)
    return Manoeuvre(m.index, m.s[keep], m.heading[keep], stops, m.gears[: len(stops)], m.backing)


def room(route: Route) -> float:
    """m a turn's leg must run on past the crash: the car brakes from walking pace at its usual rate."""
    return MANOEUVRE_SPEED**2 / (2.0 * model(route.body).limits.stop_decel)


def brakes_in_time(cut: Route, contact: Contact, striker: bool) -> bool:
    """Whether the participant whose route is `cut` (ended_at) meets the other where it can still
    brake to rest before its leg ends."""
    at = contact.hi if striker else max(contact.victim_s(contact.lo), contact.victim_s(contact.hi))
    return at <= cut.line.length - room(cut)
