"""The automated vehicle named by its brand alone once it has been introduced with it, and its possessive written
without an apostrophe ("the Waymo AVs lane"), on sentences written for these tests."""

from __future__ import annotations

from sovarc.compiler.frontend.names import label_parties


def test_the_brand_alone_is_the_automated_vehicle() -> None:
    text, _ = label_parties(
        "A Waymo Autonomous Vehicle (Waymo AV) was in a collision involving a sedan. While the Waymo was stopped, "
        "the sedan reversed toward the Waymo's front bumper."
    )
    assert "While V1 was stopped" in text and "V1's front bumper" in text


def test_an_apostrophe_left_out_is_still_a_possessive() -> None:
    text, _ = label_parties(
        "The Waymo AV was in a collision involving a sedan. The sedan swerved into the Waymo AVs lane and made "
        "contact with the Waymo AVs driver side."
    )
    assert "into V1's lane" in text and "with V1's driver side" in text


def test_the_brands_fleet_is_not_the_vehicle() -> None:
    text, _ = label_parties("The Waymo AV was in a collision involving a sedan. The Waymo fleet was not affected.")
    assert "The Waymo fleet" in text


def test_labels_for_the_others_leave_the_automated_vehicle_v1() -> None:
    text, note = label_parties(
        "The Waymo AV was stopped at a light with a sedan (Vehicle 2) behind it. The sedan then made contact with "
        "the rear of the Waymo AV."
    )
    assert text.startswith("V1 was stopped") and "V2 then made contact with the rear of V1" in text
    assert note is not None and "the automated vehicle ('The Waymo AV') is V1" in note
