"""NHTSA SGO incident reports as ground truth: the project's mapping from their coded fields to the IR.

NHTSA's Standing General Order incident file codes, beside each narrative, the scene (lighting, weather
flags, posted speed limit, roadway type) and both parties: the automated subject vehicle (SV) and its crash
partner (CP), each with a pre-crash movement and the areas of it in contact. The narratives are written by
the fleets, not by NHTSA's coders, so these fields are an independent truth for a front end that reads them.

The mapping (one function per field, each saying what it cannot map):
- lighting: Daylight is {daylight}; Dark - Lighted is {dark, street_lights}; Dark - Not Lighted and Dark -
  Unknown Lighting are {dark}; Dawn / Dusk is {twilight}; anything else is not scored;
- weather: the set of flags set (Clear, Cloudy, Rain, Snow, Fog/Smoke, Severe Wind); Unknown or Other only
  is not scored;
- speed limit: the posted limit in mph; blank or 0 is not scored;
- road kind: Intersection is `intersection`; the other roadway types (Street, Highway, Parking Lot...) do
  not say whether a junction was near, so they are not scored;
- pre-crash movement, compared with the party's last action before the impact: Proceeding Straight is
  follow_lane or go_across; Stopped is stop; Making Left / Right / U-Turn, Changing Lanes (and Merging),
  Entering Traffic (drive_into), Crossing into Opposing Lane and Traveling Wrong Way (retrograde), Lane /
  Road Departure (drive_off, retrograde, or change_lane: a drift into the next lane of its direction),
  Passing (follow_lane, change_lane, or retrograde: an overtake by way of the opposing lane is driving in a
  lane of the opposite direction), a pedestrian Crossing Roadway
  (cross) or Moving on Sidewalk (walk), Backing (reverse), Parked (parked, or stop: NHTSA codes a vehicle
  standing in its lane for a passenger as parked), a Parking Maneuver (reverse, drive_into or drive_off: out
  of a space or into one). Other / Unknown are not scored;
- crash type and striker from the contact areas: a party's front is Front, Front Left or Front Right; its
  rear Rear, Rear Left or Rear Right; its side Left or Right. The striker is the party whose front is in
  contact when the other's is not; the crash type is the other's part (rear: rear_end, side: side), and
  front to front is frontal with no striker scored. A party backing leads with its rear: its rear against
  the other's front is rear_end, against the other's side is side, and it is the striker. A party coded
  Stopped or Parked strikes nobody when the other moved: the mover is the striker; the mover's rear against
  the standing front is rear_end only when its move can lead with the rear (see `_standing_struck`);
- the crash partner's kind, from "Crash With": Passenger Car and SUV are car, Pickup Truck pickup, Van van,
  Bus bus, Heavy Truck truck, Motorcycle motorcycle, Non-Motorist: Cyclist bicycle; the others (a
  pedestrian, a first responder's vehicle of any kind) are not scored.

The automated vehicle is SV. The front end's stated rule makes it V1; the crash partner is V1's partner in
the crash, else the other participant.
"""

from __future__ import annotations

import csv
import hashlib
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from sovarc.compiler.evaluation.reading import FrontEndSpec, front_end
from sovarc.compiler.frontend.refusals import says_impact
from sovarc.dsl.ir import ActionKind, CrashType, Lighting, Participant, Scenario, Speed, Unknown, VehicleKind, Weather
from sovarc.dsl.span import Source

# Crash partners the IR holds as road users, so the crash has two parties.
TWO_PARTY = frozenset(
    (
        "Passenger Car",
        "SUV",
        "Pickup Truck",
        "Heavy Truck",
        "Van",
        "Bus",
        "Motorcycle",
        "First Responder Vehicle",
        "Non-Motorist: Cyclist",
        "Non-Motorist: Pedestrian",
    )
)


def read_pool(path: Path) -> dict[str, dict[str, str]]:
    """Two-party rows with a readable narrative (not confidential, no "[REDACTED", at least 100 characters),
    the highest Report Version per Report ID."""
    latest: dict[str, dict[str, str]] = {}
    with path.open(encoding="utf-8", newline="") as f:
        for row in csv.DictReader(f):
            text = row.get("Narrative") or ""
            if row.get("Crash With") not in TWO_PARTY or row.get("Narrative - CBI?") == "Y":
                continue
            if "[REDACTED" in text.upper() or len(text.strip()) < 100:
                continue
            old = latest.get(row["Report ID"])
            if old is None or int(row["Report Version"] or 0) > int(old["Report Version"] or 0):
                latest[row["Report ID"]] = row
    return latest


def held_out(report_id: str) -> bool:
    """The split: odd first byte of sha256(Report ID) is held out (never read while tuning)."""
    return hashlib.sha256(report_id.encode("utf-8")).digest()[0] % 2 == 1


def halves(pool: dict[str, dict[str, str]]) -> dict[str, list[dict[str, str]]]:
    return {
        "development": [r for i, r in sorted(pool.items()) if not held_out(i)],
        "held-out": [r for i, r in sorted(pool.items()) if held_out(i)],
    }


# What a coded field says, for one attribute: the accepted IR values, or why it is not scored.
NOT_SCORED = "not scored"
NOT_EXPRESSIBLE = "not expressible"


@dataclass(frozen=True)
class Expected:
    accept: frozenset[object] = frozenset()
    skip: str | None = None  # NOT_SCORED or NOT_EXPRESSIBLE


_SKIP = Expected(skip=NOT_SCORED)
_INEXPRESSIBLE = Expected(skip=NOT_EXPRESSIBLE)

_LIGHTING = {
    "Daylight": frozenset((Lighting.DAYLIGHT,)),
    "Dark - Lighted": frozenset((Lighting.DARK, Lighting.STREET_LIGHTS)),
    "Dark - Not Lighted": frozenset((Lighting.DARK,)),
    "Dark - Unknown Lighting": frozenset((Lighting.DARK,)),
    "Dawn / Dusk": frozenset((Lighting.TWILIGHT,)),
}
_WEATHER = {
    "Weather - Clear": Weather.CLEAR,
    "Weather - Cloudy": Weather.CLOUDY,
    "Weather - Rain": Weather.RAINY,
    "Weather - Snow": Weather.SNOWY,
    "Weather - Fog/Smoke": Weather.FOGGY,
    "Weather - Severe Wind": Weather.WINDY,
}
_K = ActionKind
_MOVEMENT: dict[str, frozenset[ActionKind] | None] = {
    "Proceeding Straight": frozenset((_K.FOLLOW_LANE, _K.GO_ACROSS)),
    "Stopped": frozenset((_K.STOP,)),
    "Making Left Turn": frozenset((_K.TURN_LEFT,)),
    "Making Right Turn": frozenset((_K.TURN_RIGHT,)),
    "Making U-Turn": frozenset((_K.U_TURN,)),
    "Changing Lanes": frozenset((_K.CHANGE_LANE,)),
    "Merging": frozenset((_K.CHANGE_LANE,)),
    # an overtake is made in the next lane of its own direction or in the opposing one ("entered the opposing
    # lane of travel to pass"): the IR says the latter as driving in a lane of the opposite direction
    "Passing": frozenset((_K.FOLLOW_LANE, _K.CHANGE_LANE, _K.RETROGRADE)),
    "Entering Traffic": frozenset((_K.DRIVE_INTO,)),
    "Crossing into Opposing Lane": frozenset((_K.RETROGRADE,)),
    "Traveling Wrong Way": frozenset((_K.RETROGRADE,)),
    # leaving its lane: off the road (drive_off), into the other direction's lane (retrograde), or drifting into
    # the next lane of its own direction, which NHTSA codes here when unintended (Changing Lanes is the intended
    # move) and the IR, which has no intent, says as change_lane, as the rules read "drifted into V1's lane"
    "Lane / Road Departure": frozenset((_K.DRIVE_OFF, _K.RETROGRADE, _K.CHANGE_LANE)),
    "NM Crossing Roadway": frozenset((_K.CROSS,)),
    "NM Moving on Sidewalk": frozenset((_K.WALK,)),
    "NM in Roadway - Other": frozenset((_K.WALK, _K.CROSS)),
    "Backing": frozenset((_K.REVERSE,)),
    # NHTSA codes a vehicle standing for a passenger pick-up or drop-off as Parked, in its lane or at the kerb;
    # its narratives say "stopped in-lane for a drop-off", which the IR says as a stop.
    "Parked": frozenset((_K.PARKED, _K.STOP)),
    "Parking Maneuver": frozenset((_K.REVERSE, _K.DRIVE_INTO, _K.DRIVE_OFF)),
}
_PARTNER_KIND = {
    "Passenger Car": VehicleKind.CAR,
    "SUV": VehicleKind.CAR,
    "Pickup Truck": VehicleKind.PICKUP,
    "Van": VehicleKind.VAN,
    "Bus": VehicleKind.BUS,
    "Heavy Truck": VehicleKind.TRUCK,
    "Motorcycle": VehicleKind.MOTORCYCLE,
    "Non-Motorist: Cyclist": VehicleKind.BICYCLE,
}
# Coded moves that can lead with the rear besides Backing: parking into a space backwards.
_REAR_LEADS = frozenset(("Parking Maneuver",))
_FRONT = ("Front", "Front Left", "Front Right")
_REAR = ("Rear", "Rear Left", "Rear Right")
_SIDE = ("Left", "Right")


def lighting(row: dict[str, str]) -> Expected:
    said = _LIGHTING.get(row.get("Lighting", ""))
    return Expected(frozenset((said,))) if said else _SKIP


def weather(row: dict[str, str]) -> Expected:
    flags = frozenset(w for column, w in _WEATHER.items() if row.get(column) == "Y")
    return Expected(frozenset((flags,))) if flags else _SKIP


def speed_limit(row: dict[str, str]) -> Expected:
    said = (row.get("Posted Speed Limit (MPH)") or "").strip()
    return Expected(frozenset((int(said),))) if said.isdigit() and int(said) > 0 else _SKIP


def road_kind(row: dict[str, str]) -> Expected:
    return Expected(frozenset(("intersection",))) if row.get("Roadway Type") == "Intersection" else _SKIP


def movement(row: dict[str, str], party: str) -> Expected:
    """`party` is "SV" or "CP"."""
    said = row.get(f"{party} Pre-Crash Movement", "")
    if said not in _MOVEMENT:
        return _SKIP
    kinds = _MOVEMENT[said]
    return _INEXPRESSIBLE if kinds is None else Expected(frozenset(kinds))


def _areas(row: dict[str, str], party: str) -> set[str]:
    prefix = f"{party} Contact Area - "
    return {k[len(prefix) :] for k, v in row.items() if k.startswith(prefix) and v == "Y"}


def _part(areas: set[str]) -> str | None:
    """The struck party's part: rear or side, None when the areas name both or neither."""
    rear, side = bool(areas & set(_REAR)), bool(areas & set(_SIDE))
    return "rear" if rear and not side else "side" if side and not rear else None


def partner_kind(row: dict[str, str]) -> Expected:
    said = _PARTNER_KIND.get(row.get("Crash With", ""))
    return Expected(frozenset((said,))) if said else _SKIP


def _backing(row: dict[str, str]) -> tuple[Expected, Expected]:
    """(crash type, striker) of a crash one party backed into: its rear leads (see the module)."""
    backing = [party for party in ("SV", "CP") if row.get(f"{party} Pre-Crash Movement") == "Backing"]
    if len(backing) != 1:
        return _SKIP, _SKIP
    party = backing[0]
    other = _areas(row, "CP" if party == "SV" else "SV")
    if not _areas(row, party) & set(_REAR):
        return _SKIP, _SKIP
    if other & set(_FRONT) and not other & set(_SIDE):
        return Expected(frozenset((CrashType.REAR_END,))), Expected(frozenset((party,)))
    if _part(other) == "side":
        return Expected(frozenset((CrashType.SIDE,))), Expected(frozenset((party,)))
    return _SKIP, _SKIP


def _standing_struck(row: dict[str, str], striker: str) -> tuple[Expected, Expected] | None:
    """The party whose front the areas put in contact stood still (Stopped or Parked) while the other moved:
    the IR's striker is the one that moved into the other, so it is the mover, whatever part of the standing
    party it touched. The mover's rear against the standing front is a reversing striker's rear_end when its
    coded move can lead with the rear (a Parking Maneuver: into a space backwards; Backing is read before,
    see `_backing`). Its side against that front (a passing car's side sweeping a stopped car's front corner),
    or the rear of one coded moving forward (a turning truck's trailer swinging its rear corner into a stopped
    car's front, a passing car's rear quarter clipping it), is no crash type of the IR, whose types are a
    striker's leading face meeting the victim: neither party led into the other, so it is not expressible.
    None when the rule does not apply."""
    mover = "CP" if striker == "SV" else "SV"
    standing = ("Stopped", "Parked")
    if row.get(f"{striker} Pre-Crash Movement") not in standing:
        return None
    if row.get(f"{mover} Pre-Crash Movement") not in _MOVEMENT or row.get(f"{mover} Pre-Crash Movement") in standing:
        return None  # the other stood too, or what it did is not coded
    part = _part(_areas(row, mover))
    reversing = row.get(f"{mover} Pre-Crash Movement") in _REAR_LEADS
    kind = (
        Expected(frozenset((CrashType.REAR_END,)))
        if part == "rear" and reversing
        else _SKIP
        if not part
        else _INEXPRESSIBLE
    )
    return kind, Expected(frozenset((mover,)))


def contact(row: dict[str, str]) -> tuple[Expected, Expected]:
    """(crash type, striker) from the contact areas; the striker as "SV" or "CP"."""
    if "Backing" in (row.get("SV Pre-Crash Movement"), row.get("CP Pre-Crash Movement")):
        return _backing(row)
    sv, cp = _areas(row, "SV"), _areas(row, "CP")
    sv_front, cp_front = bool(sv & set(_FRONT)), bool(cp & set(_FRONT))
    if sv_front and cp_front:
        return Expected(frozenset((CrashType.FRONTAL,))), _SKIP
    if sv_front == cp_front:
        return _SKIP, _SKIP
    if standing := _standing_struck(row, "SV" if sv_front else "CP"):
        return standing
    striker, other = ("SV", cp) if sv_front else ("CP", sv)
    part = _part(other)
    kind = {"rear": CrashType.REAR_END, "side": CrashType.SIDE}.get(part or "")
    return (Expected(frozenset((kind,))) if kind else _SKIP), Expected(frozenset((striker,)))


def expected(row: dict[str, str]) -> dict[str, Expected]:
    """What the coded fields say, per attribute."""
    crash_type, striker = contact(row)
    return {
        "crash type": crash_type,
        "striker": striker,
        "SV movement": movement(row, "SV"),
        "CP movement": movement(row, "CP"),
        "CP kind": partner_kind(row),
        "lighting": lighting(row),
        "weather": weather(row),
        "speed limit": speed_limit(row),
        "intersection": road_kind(row),
    }


ATTRIBUTES: tuple[str, ...] = (
    "crash type",
    "striker",
    "SV movement",
    "CP movement",
    "CP kind",
    "lighting",
    "weather",
    "speed limit",
    "intersection",
)


def parties(s: Scenario) -> tuple[Participant | None, Participant | None]:
    """(SV, CP): V1, and V1's partner in the crash, else the other participant."""
    by_id = {p.id: p for p in s.participants}
    sv = by_id.get("V1")
    c = s.crash
    partner = c.victim if c.striker == "V1" else c.striker if c.victim == "V1" else None
    cp = by_id.get(partner) if isinstance(partner, str) else None
    if cp is None:
        cp = next((p for p in s.participants if p.id != "V1"), None)
    return sv, cp


def _last_action(p: Participant | None) -> object:
    if p is None:
        return "missing"
    return p.actions[-1].kind if not isinstance(p.actions, Unknown) and p.actions else p.actions


def read_facts(s: Scenario) -> dict[str, object]:
    """What a scenario says, per attribute, in the terms `expected` uses."""
    sv, cp = parties(s)
    role = {sv.id if sv else None: "SV", cp.id if cp else None: "CP"}
    limit = s.road.speed_limit
    mph = round(limit.to_mps() / 0.44704) if isinstance(limit, Speed) else limit
    env = s.environment
    return {
        "crash type": s.crash.type,
        "striker": role.get(s.crash.striker, s.crash.striker) if isinstance(s.crash.striker, str) else "unknown",
        "SV movement": _last_action(sv),
        "CP movement": _last_action(cp),
        "CP kind": "missing" if cp is None else cp.kind,
        "lighting": env.lighting if isinstance(env.lighting, Unknown) else frozenset(env.lighting),
        "weather": env.weather if isinstance(env.weather, Unknown) else frozenset(env.weather),
        "speed limit": mph,
        "intersection": s.road.kind.value,
    }


@dataclass
class Tally:
    """Counts for one attribute on one half."""

    right: int = 0
    scored: int = 0
    unknown: int = 0  # scored, and the front end said unknown
    inexpressible: int = 0
    wrong: list[tuple[str, str, str]] = field(default_factory=list)  # (report, got, coded)

    def percent(self) -> float:
        return 100.0 * self.right / self.scored if self.scored else 0.0


@dataclass
class HalfScore:
    reports: int = 0
    extracted: int = 0
    two_parties: int = 0
    refusals: list[tuple[str, str]] = field(default_factory=list)
    silent: int = 0  # refused narratives that say no impact in any words
    tallies: dict[str, Tally] = field(default_factory=lambda: {a: Tally() for a in ATTRIBUTES})

    def no_crash(self) -> int:
        """Refusals of narratives that say no impact at all."""
        return self.silent

    def add(self, report_id: str, row: dict[str, str], got: Reading) -> None:
        self.reports += 1
        if isinstance(got, str):
            self.refusals.append((report_id, got))
            self.silent += not says_impact(row["Narrative"])
            return
        facts, people = got
        self.extracted += 1
        self.two_parties += people == 2
        for attribute, want in expected(row).items():
            tally = self.tallies[attribute]
            if want.skip == NOT_EXPRESSIBLE:
                tally.inexpressible += 1
            if want.skip is not None:
                continue
            tally.scored += 1
            value = facts[attribute]
            if value in want.accept:
                tally.right += 1
                continue
            tally.unknown += isinstance(value, Unknown)
            tally.wrong.append((report_id, _show(value), " or ".join(sorted(_show(v) for v in want.accept))))


def _show(value: object) -> str:
    if isinstance(value, frozenset):
        return "{" + ", ".join(sorted(str(v) for v in value)) + "}"
    return str(value)


# What a front end made of one narrative: the facts `expected` compares and how many participants it
# found, or why it refused (plain data, so it comes back from an executor's worker).
Reading = tuple[dict[str, object], int] | str


@dataclass(frozen=True)
class SgoTask:
    spec: FrontEndSpec
    report_id: str
    narrative: str


def run_sgo_task(task: SgoTask) -> Reading:
    """One narrative read by the task's front end (see `reading`)."""
    try:
        got = front_end(task.spec).extract(Source(f"sgo_{task.report_id}.txt", task.narrative)).scenario
    except Exception as exc:  # a refusal or an internal error: both count as not extracted, with the reason
        return f"{type(exc).__name__}: {exc}"
    return read_facts(got), len(got.participants)


def score_rows(rows: Iterable[dict[str, str]], readings: Iterable[Reading]) -> HalfScore:
    """Score each row's reading (in the rows' order)."""
    score = HalfScore()
    for row, got in zip(rows, readings, strict=True):
        score.add(row["Report ID"], row, got)
    return score


def _cell(right: int, scored: int, extra: str = "") -> str:
    pct = f"{100.0 * right / scored:5.1f}" if scored else "    -"
    return f"{pct} ({right}/{scored}{extra})"


def table(scores: dict[str, HalfScore]) -> str:
    """Per attribute, each half's percentage and the counts behind it."""
    names = list(scores)
    lines = [f"{'attribute':<16}" + "".join(f"{n:>36}" for n in names)]
    lines.append(f"{'extracted':<16}" + "".join(f"{_cell(s.extracted, s.reports):>36}" for s in scores.values()))
    # GM's duplicate filings of Cruise reports are boilerplate whose crash description is cut off: refusing a
    # narrative that describes no crash is right, so the share among those that describe one is shown too
    said = [(s.extracted, s.reports - s.no_crash()) for s in scores.values()]
    lines.append(f"{'  crash said':<16}" + "".join(f"{_cell(e, n):>36}" for e, n in said))
    lines.append(
        f"{'two participants':<16}" + "".join(f"{_cell(s.two_parties, s.extracted):>36}" for s in scores.values())
    )
    for attribute in ATTRIBUTES:
        cells = []
        for s in scores.values():
            t = s.tallies[attribute]
            extra = f", {t.unknown} unknown" if t.unknown else ""
            extra += f"; {t.inexpressible} n/e" if t.inexpressible else ""
            cells.append(_cell(t.right, t.scored, extra))
        lines.append(f"{attribute:<16}" + "".join(f"{c:>36}" for c in cells))
    lines.append(
        "\n(right/scored among extracted reports; unknown: the front end said unknown; n/e: not expressible in "
        "the IR yet, not scored)"
    )
    return "\n".join(lines)


def to_json(scores: dict[str, HalfScore]) -> dict[str, object]:
    return {
        name: {
            "reports": s.reports,
            "extracted": s.extracted,
            "two_participants": s.two_parties,
            "attributes": {
                a: {
                    "right": t.right,
                    "scored": t.scored,
                    "unknown": t.unknown,
                    "not_expressible": t.inexpressible,
                    "wrong": [{"report": r, "got": g, "coded": c} for r, g, c in t.wrong],
                }
                for a, t in s.tallies.items()
            },
            "refused": [{"report": r, "why": w} for r, w in s.refusals],
        }
        for name, s in scores.items()
    }
