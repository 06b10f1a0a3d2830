"""Who did what in fleet narratives, each reading on narratives written for these tests (the automated vehicle
and the road user it met, named in words): a party backing, impacts said as a move into the other, lane changes
said by the lane or side used, attempts cut short, opening participles."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.crash import read_sentence
from sovarc.compiler.frontend.names import label_parties
from sovarc.compiler.frontend.text import describes_impact
from sovarc.dsl.ir import ActionKind, CrashType, Scenario, Side, Unknown
from sovarc.dsl.span import Source

OPENING = (
    "On March [XXX], 2025 at 4:05 PM PT a Waymo Autonomous Vehicle (Waymo AV) was in a collision involving a sedan. "
)


def read(text: str) -> Scenario:
    return FrontEnd("none").extract(Source("sgo.txt", text)).scenario


def kinds(s: Scenario, pid: str) -> list[ActionKind]:
    p = next(p for p in s.participants if p.id == pid)
    return [] if isinstance(p.actions, Unknown) else [a.kind for a in p.actions]


@pytest.mark.parametrize(
    ("impact", "crash"),
    [
        # its rear into the other's front: rear_end with the backing one the striker (the IR's convention)
        ("the sedan reversed and made contact with the front of the Waymo AV", CrashType.REAR_END),
        (
            "the sedan began to back up, and the rear of the sedan made contact with the front of the Waymo AV",
            CrashType.REAR_END,
        ),
        (
            "the sedan began backing up and its rear bumper made contact with the front bumper of the Waymo AV",
            CrashType.REAR_END,
        ),
        # its rear into the other's rear: back to back
        ("the sedan reversed slowly into the rear bumper of the Waymo AV", CrashType.FRONTAL),
        # its rear into a side
        ("the sedan backed into the driver side door of the Waymo AV", CrashType.SIDE),
    ],
)
def test_a_backing_party_leads_with_its_rear(impact: str, crash: CrashType) -> None:
    s = read(OPENING + f"The Waymo AV was stopped at a red light on [XXX] when {impact}.")
    assert kinds(s, "V2")[-1] is ActionKind.REVERSE
    assert (s.crash.striker, s.crash.victim, s.crash.type) == ("V2", "V1", crash)


def test_a_party_driving_forward_into_the_objects_front_is_struck() -> None:
    """The contrast: with nobody backing, the only part named being the object's front says the object's
    front met the subject (which came across its path)."""
    s = read(
        OPENING + "The Waymo AV was traveling north on [XXX] when the sedan pulled across its lane and made contact "
        "with the front of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V1", "V2")


def test_in_front_of_is_a_place_not_a_part() -> None:
    crash = read_sentence(
        "V2 in front of V1 began to roll backwards, and the rear of V2 made contact with the front of V1.",
        backing=frozenset({"V2"}),
    )
    assert crash is not None and (crash.striker, crash.type) == ("V2", CrashType.REAR_END)
    crash = read_sentence("V2 directly in front of V1 reversed and made contact with the front of V1.")
    assert crash is not None and crash.striker == "V2"  # "front of V1" after "in" names no owner of the strike


@pytest.mark.parametrize(
    "sentence",
    [
        "V2 reversed at a low speed from an adjacent driveway into the right rear bumper of V1.",
        "V2 backed into V1.",
        "V2 riding on the wrong side of the street rode into the front bumper of V1.",
        "V2 approaching in the adjacent lane collided into the passenger side doors of V1.",
        "V1 braked hard but was unable to avoid contact with V2.",
    ],
)
def test_a_move_into_the_other_is_an_impact(sentence: str) -> None:
    assert describes_impact(sentence)


@pytest.mark.parametrize(
    "sentence",
    [
        "V2 drove into the intersection behind V1.",
        "V2 drifted into V1's lane.",
        "V2 began reversing into the path of V1.",
        "V1 braked to avoid contact with V2.",
    ],
)
def test_a_move_into_a_place_is_no_impact(sentence: str) -> None:
    assert not describes_impact(sentence)


def test_an_unavoidable_contact_ends_what_each_did_before() -> None:
    s = read(
        OPENING + "The Waymo AV was traveling west on [XXX] and entered the intersection to proceed straight. The "
        "sedan traveling east made a sharp left turn in front of the Waymo AV. The Waymo AV detected the sedan and "
        "braked, but was unable to avoid contact with the sedan."
    )
    assert kinds(s, "V2")[-1] is ActionKind.TURN_LEFT


def test_a_participant_after_a_preposition_is_an_object() -> None:
    """ "parked perpendicular to V1 moved backward": what follows is the parked vehicle's doing, not V1's."""
    s = read(
        OPENING + "The Waymo AV stopped in a parking lot to let a passenger out. The sedan, parked perpendicular "
        "to the Waymo AV, moved backward and its rear bumper made contact with the passenger side of the "
        "Waymo AV."
    )
    assert kinds(s, "V1") == [ActionKind.STOP]
    assert kinds(s, "V2")[-1] is ActionKind.REVERSE
    assert (s.crash.striker, s.crash.type) == ("V2", CrashType.SIDE)


@pytest.mark.parametrize(
    ("said", "side"),
    [
        ("was switching lanes to the left", Side.LEFT),
        ("attempted to maneuver around the Waymo AV using the right turn lane", Side.RIGHT),
        ("maneuvered around the passenger side of the Waymo AV", Side.RIGHT),  # the driver sits on the left
        ("began a lane-change around the driver side of the Waymo AV", Side.LEFT),
    ],
)
def test_a_lane_change_said_by_the_lane_or_side_used(said: str, side: Side) -> None:
    s = read(
        OPENING + f"The Waymo AV was stopped in a queue of traffic when the sedan behind it {said}, and the "
        "passenger side of the sedan made contact with the rear driver side of the Waymo AV."
    )
    p = next(p for p in s.participants if p.id == "V2")
    assert (ActionKind.CHANGE_LANE, side) in [(a.kind, a.to) for a in p.known_actions]


def test_an_attempt_cut_short_by_the_impact_is_the_move() -> None:
    """ "attempted to pass V1 when ..." is the passing under way, after its stop: it drove on."""
    s = read(
        OPENING + "The Waymo AV was stopped at a red light. The sedan that was stopped behind the Waymo AV "
        "attempted to pass the Waymo AV on the left when the front of the sedan made contact with the rear "
        "driver side of the Waymo AV."
    )
    assert kinds(s, "V2") == [ActionKind.STOP, ActionKind.FOLLOW_LANE]


def test_an_opening_participle_is_the_main_subjects() -> None:
    """ "While moving into the left lane ..., V2 made contact": the opening clause is V2's, not the last
    sentence's V1."""
    s = read(
        OPENING + "The Waymo AV came to a stop in a queue of traffic. While moving into the left lane to get around "
        "the Waymo AV, the sedan made contact with the rear left sensor of the Waymo AV."
    )
    assert kinds(s, "V1") == [ActionKind.STOP]
    assert kinds(s, "V2")[-1] is ActionKind.CHANGE_LANE


def test_a_preposition_in_ing_opens_no_participle() -> None:
    """ "During the left turn, V2 made contact": the turn is the last sentence's subject's, not V2's."""
    s = read(
        OPENING + "The Waymo AV was waiting to turn left and then proceeded with the left turn. During the left "
        "turn, the sedan made contact with the front bumper of the Waymo AV."
    )
    assert kinds(s, "V1")[-1] is ActionKind.TURN_LEFT
    assert ActionKind.TURN_LEFT not in kinds(s, "V2")


def test_a_partner_named_by_its_make_is_the_crash_partner() -> None:
    """ "struck from behind by a grey Honda": a make names a vehicle; "The vehicle" before it points back to the
    automated vehicle, it introduces nobody."""
    named, note = label_parties(
        "A Motional AV was operating in autonomous mode. The vehicle was waiting in a right-turn lane.\n"
        "While stopped, the AV was struck from behind by a\ngrey Honda at low speed. The Honda left the scene."
    )
    assert note is not None and "V2 'a grey Honda'" in note
    assert "The vehicle was waiting" in named  # not V2
    assert "struck from behind by V2" in named and "V2 left the scene" in named


def test_an_acronym_after_an_article_is_no_make() -> None:
    named, _ = label_parties("The Waymo AV was stopped at a light when it was struck by an ADS test fleet's sedan.")
    assert "V2" in named and "an ADS" not in named.replace("V2", "")  # the sedan, by its kind noun


def test_the_automated_vehicle_said_with_words_before_its_brand() -> None:
    s = read(
        "A stopped Zoox vehicle in autonomous mode was struck by a passenger vehicle that approached it from "
        "behind. The Zoox vehicle's rear bumper was damaged."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


def test_other_road_users_parked_are_not_the_subject_parked() -> None:
    """ "a narrow street with rows of parked cars": the cars were parked, the automated vehicle drove and stopped."""
    s = read(
        OPENING + "The Waymo AV was traveling north on [XXX], a narrow street with rows of parked cars on both "
        "sides. The Waymo AV slowed to a stop to yield to the sedan. As the sedan passed the stopped Waymo AV, the "
        "driver side of the sedan made contact with the rear driver side of the Waymo AV."
    )
    assert kinds(s, "V1") == [ActionKind.FOLLOW_LANE, ActionKind.STOP]


def test_a_vehicle_said_parked_is_parked() -> None:
    s = read(OPENING + "The Waymo AV was parked at the curb when the sedan backed into the front of the Waymo AV.")
    assert kinds(s, "V1") == [ActionKind.PARKED]


def test_road_users_in_a_with_phrase_are_an_aside() -> None:
    """ "..., with vehicles parked at the curb in both directions, and came to a stop": the stop is the subject's."""
    s = read(
        OPENING + "The Waymo AV was traveling west on a narrow portion of [XXX], with vehicles parked at the curb in "
        "both directions, and came to a stop to let the sedan pass. As the sedan passed, the front driver side of "
        "the sedan made contact with the rear driver side of the Waymo AV."
    )
    assert kinds(s, "V1")[-1] is ActionKind.STOP


@pytest.mark.parametrize(
    "said", ["crossing the center lane line", "crossing over the centre divider", "across the center-line"]
)
def test_over_the_line_between_the_directions_is_the_wrong_side(said: str) -> None:
    s = read(
        OPENING + f"The Waymo AV was traveling east on [XXX] when the sedan turned right onto [XXX], {said}, and "
        "the front of the sedan struck the left side of the Waymo AV."
    )
    assert kinds(s, "V2")[-1] is ActionKind.RETROGRADE


def test_a_center_lane_is_no_line_between_the_directions() -> None:
    s = read(
        OPENING + "The Waymo AV was traveling east on [XXX] in the center lane when the sedan behind it, also in "
        "the center lane, made contact with the rear of the Waymo AV."
    )
    assert ActionKind.RETROGRADE not in kinds(s, "V2")


@pytest.mark.parametrize(
    "impact",
    [
        "While the Waymo AV remained stopped, the sedan pulled forward and the rear of its trailer made contact "
        "with the front bumper of the Waymo AV",
        "The sedan swung wide and its passenger side made contact with the front corner of the stationary Waymo AV",
    ],
)
def test_a_party_standing_still_is_struck_whatever_part_is_named_first(impact: str) -> None:
    """The crash readers take a named front for the striking face; a vehicle said to stand still at the impact
    struck nobody, so the one that moved is the striker."""
    s = read(OPENING + f"The Waymo AV was traveling west on [XXX] and came to a stop behind the sedan. {impact}.")
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


def test_a_moving_party_named_by_its_front_still_strikes() -> None:
    s = read(
        OPENING + "The Waymo AV was traveling west on [XXX] when the front of the Waymo AV made contact with the "
        "rear of the stationary sedan."
    )
    assert (s.crash.striker, s.crash.victim) == ("V1", "V2")


def test_a_side_gone_around_is_the_way_not_the_part_met() -> None:
    """ "around the left side of V1" says where the other went; the part met is the one the contact names."""
    s = read(
        OPENING + "While the Waymo AV remained stopped, the sedan maneuvered around the left side of the Waymo AV "
        "and the front passenger side of the sedan made contact with the rear driver side of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.type) == ("V2", CrashType.REAR_END)


def test_its_part_after_a_move_into_the_other_is_the_others() -> None:
    """In "the sedan reversed into the Waymo AV, making contact with its front bumper", the contact's subject is
    the sedan (the Waymo AV is the object of "into"), so "its" is the Waymo AV's: a reversing rear into a front."""
    s = read(
        OPENING + "The Waymo AV came to a stop behind the sedan. The sedan reversed into the Waymo AV, making "
        "contact with its front bumper."
    )
    assert (s.crash.striker, s.crash.victim, s.crash.type) == ("V2", "V1", CrashType.REAR_END)


def test_the_side_a_party_passed_on_is_no_part_met() -> None:
    s = read(
        OPENING + "The Waymo AV began a left lane change, and the front passenger side of the sedan, which was "
        "passing the Waymo AV on the left side, made contact with the front driver side of the Waymo AV."
    )
    assert s.crash.type is CrashType.FRONTAL


def test_an_animal_struck_first_is_not_the_crash() -> None:
    """The crash is the first impact between road users; what the sedan did before it counts."""
    s = read(
        OPENING + "The Waymo AV was traveling north on [XXX] when a dog ran into the road and the front of the Waymo "
        "AV made contact with the dog. The Waymo AV came to a stop. The sedan traveling directly behind the "
        "Waymo AV then made contact with the rear of the stationary Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim, s.crash.type) == ("V2", "V1", CrashType.REAR_END)
    assert kinds(s, "V2") == [ActionKind.FOLLOW_LANE]


def test_a_party_whose_actions_end_standing_is_struck() -> None:
    """Stopped for a pickup in an earlier clause, the Waymo AV stood at the impact; the sedan passing it moved
    into it, though the only part named is the Waymo AV's front corner."""
    s = read(
        OPENING + "The Waymo AV was stopped on [XXX] for a passenger pickup when the sedan behind it maneuvered to "
        "pass the Waymo AV on the left. As it did so, the passenger side of the sedan made contact with the front "
        "driver side corner of the Waymo AV."
    )
    assert (s.crash.striker, s.crash.victim) == ("V2", "V1")


@pytest.mark.parametrize(
    "impact",
    [
        # the sentence names it the agent: it moved off again
        "The Waymo AV was stopped at the light when the sedan pulled out and was struck by the front of the Waymo AV",
        # the sentence makes its front the subject of the strike
        "The Waymo AV was stopped at the light when the sedan pulled out. The front of the Waymo AV made contact "
        "with the side of the sedan",
    ],
)
def test_a_party_said_to_strike_with_its_front_keeps_striking(impact: str) -> None:
    s = read(OPENING + impact + ".")
    assert s.crash.striker == "V1"


def test_another_road_users_state_is_not_the_subjects() -> None:
    """ "around its stopped lead vehicle": the stop is the lead vehicle's, the lane change the subject's."""
    s = read(
        OPENING + "The Waymo AV began a right lane change to proceed around its stopped lead vehicle and made "
        "contact with the sedan traveling in the right adjacent lane."
    )
    assert kinds(s, "V1")[-1] is ActionKind.CHANGE_LANE
