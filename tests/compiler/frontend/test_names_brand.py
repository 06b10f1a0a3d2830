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


def test_a_brand_vehicle_driving_itself_is_v1_by_its_brand_alone_too() -> None:
    """ "The Acme vehicle" (no AV word; the report says it drove itself) names it; so does "the Acme" later."""
    text, _ = label_parties(
        "The Acme vehicle was driving in autonomous mode through a parking lot and stopped. A sedan reversed and "
        "made contact with the left door of the Acme."
    )
    assert "of V1." in text and "The Acme" not in text and "the Acme" not in text


def test_a_make_opening_a_clause_is_the_crash_partner() -> None:
    text, note = label_parties(
        "The Acme vehicle was driving in autonomous mode and stopped. Then, a Buick Regal parked beside the "
        "vehicle, reversed out and made contact with the Acme vehicle."
    )
    assert "Then, V2 parked beside the vehicle" in text
    assert note is not None and "V2 'a Buick Regal'" in note


def test_the_contact_area_field_is_no_impact() -> None:
    """An update's note about the form's "CONTACT AREA" field is no meeting: the partner is the one the crash
    sentence names."""
    text, note = label_parties(
        "This update corrects the CONTACT AREA for the Waymo AV. A Waymo Autonomous Vehicle was in a collision "
        "involving a sedan. The Waymo AV was stopped when a sedan reversed. The rear of the sedan then made contact "
        "with the side of the Waymo AV."
    )
    assert note is not None and "V2 'the sedan'" in note
    assert "The rear of V2 then made contact with the side of V1" in text


def test_a_bare_the_vehicle_points_back_and_a_described_one_is_new() -> None:
    _, back = label_parties(
        "The Acme vehicle was driving in autonomous mode. A Buick Regal parked to the right of the vehicle, "
        "reversed and made contact with the Acme vehicle."
    )
    assert back is not None and "V2 'A Buick Regal'" in back
    text, new = label_parties(
        "The Waymo AV was stopped at a red light. The vehicle immediately behind the Waymo AV accelerated and made "
        "contact with the rear bumper of the Waymo AV."
    )
    assert new is not None and "V2 'The vehicle'" in new and "V2 immediately behind V1" in text


def test_a_brand_vehicle_driven_in_manual_mode_is_the_automated_vehicle() -> None:
    """Manual mode is a mode only an automated vehicle has: "an Acme vehicle ... in manual mode" is V1."""
    text, note = label_parties(
        "An Acme vehicle was being driven in manual mode on [XXX] when contact was made with the mirror of a parked "
        "van."
    )
    assert text.startswith("V1 was being driven") and note is not None and "V2 'a parked van'" in note


def test_a_brand_vehicle_with_no_word_of_automation_is_not_taken_for_one() -> None:
    """It is numbered by the rule for any report that numbers nobody (the first road user in the first impact is
    V1), not as an automated vehicle."""
    _, note = label_parties("An Acme vehicle was driven on [XXX] when it struck a parked van.")
    assert note is not None and "automated" not in note and "first road user" in note
