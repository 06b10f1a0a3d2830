"""The SGO coded-field mapping and scorer: each field's mapping, the split, and `eval extraction --format sgo`."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest
from sovarc.compiler.cli import main
from sovarc.compiler.evaluation import sgo
from sovarc.dsl.ir import ActionKind, CrashType, Lighting, VehicleKind, Weather

AREAS = ("Front", "Front Left", "Front Right", "Rear", "Rear Left", "Rear Right", "Left", "Right", "Top")


def row(**fields: str) -> dict[str, str]:
    base = {"Report ID": "1-1", "Report Version": "1", "Crash With": "Passenger Car", "Narrative - CBI?": "N"}
    for party in ("SV", "CP"):
        for area in AREAS:
            base[f"{party} Contact Area - {area}"] = ""
    base.update({k.replace("_", " "): v for k, v in fields.items()})
    return base


def contact(sv: tuple[str, ...], cp: tuple[str, ...], **fields: str) -> dict[str, str]:
    r = row(**fields)
    for party, areas in (("SV", sv), ("CP", cp)):
        for area in areas:
            r[f"{party} Contact Area - {area}"] = "Y"
    return r


def test_lighting_weather_and_limit_map_to_the_ir() -> None:
    assert sgo.lighting(row(Lighting="Dark - Lighted")).accept == {frozenset((Lighting.DARK, Lighting.STREET_LIGHTS))}
    assert sgo.lighting(row(Lighting="Dawn / Dusk")).accept == {frozenset((Lighting.TWILIGHT,))}
    assert sgo.lighting(row(Lighting="Other, see Narrative")).skip == sgo.NOT_SCORED
    flags = row(**{"Weather - Rain": "Y", "Weather - Cloudy": "Y"})
    assert sgo.weather(flags).accept == {frozenset((Weather.RAINY, Weather.CLOUDY))}
    assert sgo.weather(row(**{"Weather - Unknown": "Y"})).skip == sgo.NOT_SCORED
    assert sgo.speed_limit(row(**{"Posted Speed Limit (MPH)": "25"})).accept == {25}
    assert sgo.speed_limit(row(**{"Posted Speed Limit (MPH)": "0"})).skip == sgo.NOT_SCORED
    assert sgo.road_kind(row(**{"Roadway Type": "Street"})).skip == sgo.NOT_SCORED


def test_movements_map_to_actions_backing_and_parked_included() -> None:
    assert sgo.movement(row(**{"SV Pre-Crash Movement": "Stopped"}), "SV").accept == {ActionKind.STOP}
    assert ActionKind.GO_ACROSS in sgo.movement(row(**{"CP Pre-Crash Movement": "Proceeding Straight"}), "CP").accept
    assert sgo.movement(row(**{"CP Pre-Crash Movement": "Backing"}), "CP").accept == {ActionKind.REVERSE}
    assert ActionKind.PARKED in sgo.movement(row(**{"SV Pre-Crash Movement": "Parked"}), "SV").accept
    assert sgo.movement(row(**{"SV Pre-Crash Movement": "Other, see Narrative"}), "SV").skip == sgo.NOT_SCORED
    # an overtake through the opposing lane is driving in a lane of the opposite direction in the IR
    passing = sgo.movement(row(**{"CP Pre-Crash Movement": "Passing"}), "CP").accept
    assert passing == {ActionKind.FOLLOW_LANE, ActionKind.CHANGE_LANE, ActionKind.RETROGRADE}
    # leaving its lane: off the road, into the other direction's, or into the next lane of its own (a drift)
    departure = sgo.movement(row(**{"CP Pre-Crash Movement": "Lane / Road Departure"}), "CP").accept
    assert departure == {ActionKind.DRIVE_OFF, ActionKind.RETROGRADE, ActionKind.CHANGE_LANE}


def test_the_partner_kind_comes_from_crash_with() -> None:
    assert sgo.partner_kind(row(**{"Crash With": "Non-Motorist: Cyclist"})).accept == {VehicleKind.BICYCLE}
    assert sgo.partner_kind(row(**{"Crash With": "SUV"})).accept == {VehicleKind.CAR}
    assert sgo.partner_kind(row(**{"Crash With": "Heavy Truck"})).accept == {VehicleKind.TRUCK}
    assert sgo.partner_kind(row(**{"Crash With": "Non-Motorist: Pedestrian"})).skip == sgo.NOT_SCORED


@pytest.mark.parametrize(
    ("sv", "cp", "kind", "striker"),
    [
        (("Rear",), ("Front", "Front Left"), CrashType.REAR_END, "CP"),
        (("Front Right",), ("Left",), CrashType.SIDE, "SV"),
        (("Front",), ("Front Left",), CrashType.FRONTAL, None),
        (("Rear Left",), ("Rear Left",), None, None),  # no front in contact: neither is scored
    ],
)
def test_contact_areas_give_crash_type_and_striker(
    sv: tuple[str, ...], cp: tuple[str, ...], kind: CrashType | None, striker: str | None
) -> None:
    crash_type, who = sgo.contact(contact(sv, cp))
    assert crash_type.accept == ({kind} if kind else set())
    assert who.accept == ({striker} if striker else set())


@pytest.mark.parametrize(
    ("sv", "cp", "kind"),
    [
        (("Front",), ("Rear",), CrashType.REAR_END),  # backed into the front of the one behind
        (("Right",), ("Rear Left",), CrashType.SIDE),  # backed out into the other's side
        (("Rear",), ("Rear",), None),  # rear to rear: not scored
    ],
)
def test_a_backing_party_leads_with_its_rear_and_is_the_striker(
    sv: tuple[str, ...], cp: tuple[str, ...], kind: CrashType | None
) -> None:
    crash_type, who = sgo.contact(contact(sv, cp, **{"CP Pre-Crash Movement": "Backing"}))
    assert crash_type.accept == ({kind} if kind else set())
    assert who.accept == ({"CP"} if kind else set())


@pytest.mark.parametrize(
    ("sv_move", "cp_move", "cp", "kind", "striker"),
    [
        # a car parallel parking backs into the stopped automated vehicle's front: the mover strikes, rear first
        ("Stopped", "Parking Maneuver", ("Rear Left",), {CrashType.REAR_END}, {"CP"}),
        # a passing car's side sweeps a parked one's front corner: the mover strikes, with no IR crash type
        ("Parked", "Proceeding Straight", ("Right",), set(), {"CP"}),
        # so does its rear quarter, or a turning trailer's rear corner: it moved forward, its rear did not lead
        ("Parked", "Passing", ("Rear Right",), set(), {"CP"}),
        ("Stopped", "Making Right Turn", ("Rear Left",), set(), {"CP"}),
        # both moving: the front in contact is the striker's, as before
        ("Proceeding Straight", "Changing Lanes", ("Right",), {CrashType.SIDE}, {"SV"}),
        # both standing: nobody moved into the other as far as the codes say, so the areas decide, as before
        ("Stopped", "Parked", ("Rear",), {CrashType.REAR_END}, {"SV"}),
    ],
)
def test_a_party_standing_still_strikes_nobody(
    sv_move: str, cp_move: str, cp: tuple[str, ...], kind: set[CrashType], striker: set[str]
) -> None:
    r = contact(("Front Right",), cp, **{"SV Pre-Crash Movement": sv_move, "CP Pre-Crash Movement": cp_move})
    crash_type, who = sgo.contact(r)
    assert crash_type.accept == kind
    assert crash_type.skip == (None if kind else sgo.NOT_EXPRESSIBLE)
    assert who.accept == striker


NARRATIVE = (
    "A Waymo Autonomous Vehicle was stopped at a red light on [XXX] when a passenger car approached from behind "
    "and made contact with the rear bumper of the Waymo AV. It was raining."
)


def write_csv(path: Path, rows: list[dict[str, str]]) -> Path:
    columns = sorted({k for r in rows for k in r})
    with path.open("w", encoding="utf-8", newline="") as f:
        writer = csv.DictWriter(f, columns)
        writer.writeheader()
        writer.writerows(rows)
    return path


def test_eval_sgo_scores_both_halves(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    coded = {
        "Narrative": NARRATIVE,
        "SV Pre-Crash Movement": "Stopped",
        "CP Pre-Crash Movement": "Proceeding Straight",
        "Lighting": "Daylight",
        "Weather - Rain": "Y",
    }
    # Report ids 1-1 and 1-3 fall in different halves (sha256 parity of the id).
    ids = [i for i in ("1-1", "1-2", "1-3", "1-4", "1-5")]
    halves = {sgo.held_out(i) for i in ids}
    assert halves == {True, False}
    rows = [contact(("Rear",), ("Front",), **coded, **{"Report ID": i}) for i in ids]
    rows.append(row(**{"Report ID": "2-1", "Narrative": "x" * 120, "Crash With": "Animal"}))  # not two-party
    path = write_csv(tmp_path / "sgo.csv", rows)
    assert main(["eval", "extraction", "--format", "sgo", str(path), "--llm", "none", "--json", "-j", "1"]) == 0
    text = capsys.readouterr().out
    assert main(["eval", "extraction", "--format", "sgo", str(path), "--llm", "none", "--json", "-j", "2"]) == 0
    assert capsys.readouterr().out == text  # the same figures from a pool of two workers
    got = json.loads(text)
    assert sum(h["reports"] for h in got.values()) == len(ids)
    for half in got.values():
        attrs = half["attributes"]
        assert half["extracted"] == half["reports"]
        assert attrs["striker"]["right"] == attrs["striker"]["scored"] == half["reports"]
        assert attrs["crash type"]["right"] == half["reports"]
        assert attrs["SV movement"]["right"] == half["reports"]
        assert attrs["weather"]["right"] == half["reports"]


def test_eval_sgo_needs_its_csv(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["eval", "extraction", "--format", "sgo", "--llm", "none"]) == 2
    assert "SGO incident CSV" in capsys.readouterr().err
