"""Bad input: one clear error naming the file and the reason, and nothing half-written."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.compiler.cli import main
from sovarc.compiler.frontend import FrontEnd, FrontEndError
from sovarc.compiler.frontend.refusals import says_impact
from sovarc.dsl.span import Source

CRASH = (
    "On May [XXX], 2022 at 1:26 PM PST a Waymo Autonomous Vehicle was stopped at a red light on [XXX]. "
    "A passenger car approached from behind and made contact with the rear bumper of the Waymo AV."
)

# A police narrative of our own: each vehicle introduced once with its model year and make.
POLICE = (
    "Vehicle 1, a 2004 Ford Focus, was traveling north in lane one. Vehicle 2, a 2011 Kia Rio, was stopped ahead "
    "in the same lane. The front of Vehicle 1 struck the rear of Vehicle 2."
)


def extract(text: str, name: str = "r.txt") -> object:
    return FrontEnd("none").extract(Source(name, text)).scenario


def test_one_crash_is_read() -> None:
    extract(CRASH)


def test_a_vehicle_introduced_again_as_itself_is_one_report() -> None:
    # the same year and make said twice (the make in other case) is the same vehicle, not a second report
    extract(POLICE + " Vehicle 1, a 2004 FORD, came to rest in the median.")


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("V1 was traveling north on Main Street. V2 was traveling south on Main Street. Both continued.", "no crash"),
        ("The Waymo AV braked to avoid a collision with a passenger car and stopped. Nobody was hurt.", "no crash"),
        ("V1 was traveling north on a two-lane road. It was a sunny day. No collision occurred.", "no crash"),
        ("V1 and V2 passed each other on Main Street without contact.", "no crash"),
        ("V1 was traveling north when V2 turned left in front of it. V1 braked and did not strike V2.", "no crash"),
        (CRASH + "\n" + CRASH.replace("1:26 PM", "4:40 PM"), "more than one report"),
        (CRASH + "\n-----\n" + "V1 was traveling north when V2 struck the rear of V1.", "more than one report"),
        (
            POLICE + " " + POLICE.replace("2004 Ford", "1998 Dodge").replace("2011 Kia", "2001 Buick"),
            "more than one report",
        ),
        (CRASH + " In a separate incident later that day, the Waymo AV was struck by an SUV.", "several crashes"),
        ("El vehículo autónomo estaba detenido cuando un coche lo golpeó por detrás en la calle.", "English"),
    ],
)
def test_bad_input_is_refused_in_one_line_naming_the_file(text: str, reason: str) -> None:
    with pytest.raises(FrontEndError) as caught:
        extract(text, "reports/bad.txt")
    message = str(caught.value)
    assert "reports/bad.txt" in message and reason in message
    assert "\n" not in message


def test_a_refused_report_writes_nothing_and_the_others_are_written(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    good, bad = tmp_path / "good.txt", tmp_path / "two.txt"
    good.write_text(CRASH, encoding="utf-8")
    bad.write_text(CRASH + "\n" + CRASH.replace("1:26 PM", "4:40 PM"), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["extract", str(good), str(bad), "-o", str(out), "--llm", "none"]) == 1
    err = capsys.readouterr().err
    assert "two.txt" in err and "more than one report" in err and "1 of 2 scenario(s) written" in err
    assert sorted(p.name for p in out.iterdir()) == ["good.sov"]


@pytest.mark.parametrize(
    ("sentence", "met"),
    [
        ("V1 did not stop and struck the rear of V2.", True),
        ("The driver never braked; V1 hit V2.", True),
        ("V2 had no time to react and collided with V1.", True),
        ("No collision occurred.", False),
        ("The vehicles never made contact.", False),
        ("V1 swerved to avoid hitting the pedestrian.", False),
    ],
)
def test_a_denied_or_averted_impact_is_no_impact(sentence: str, met: bool) -> None:
    assert says_impact(sentence) is met
