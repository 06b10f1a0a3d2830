"""The rules' dynamic layer: who did what, in which order, and who struck whom.

Every sentence here is invented for the test, in the style of a police crash summary.
"""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend.clauses import by_participant, pieces
from sovarc.compiler.frontend.crash import read_sentence
from sovarc.compiler.frontend.defaults import apply_defaults
from sovarc.compiler.frontend.rules import extract
from sovarc.compiler.frontend.text import first_impact, name_parked, normalize_names, resolve_aliases, sentences
from sovarc.dsl.ir import UNKNOWN, Action, ActionKind, Crash, CrashType, Lighting, Scenario


def _actions(text: str) -> dict[str, object]:
    s = extract(text, "t")
    return {
        p.id: [a.kind.value for a in p.actions] if isinstance(p.actions, tuple) else "unknown" for p in s.participants
    }


def _reading(text: str) -> Scenario:
    return extract(text, "t")


# --- who a piece of text is about ---------------------------------------------------------------


def test_an_object_does_not_take_the_rest_of_the_sentence() -> None:
    text = "V1 was traveling north behind V2 and turned left into a driveway. V2 was northbound."
    mine = by_participant(pieces(sentences(text), ["V1", "V2"]), ["V1", "V2"])
    assert "turned left" in " ".join(p.text for p in mine["V1"])
    assert "turned left" not in " ".join(p.text for p in mine["V2"])


def test_pronouns_and_the_driver_carry_the_last_subject() -> None:
    text = (
        "The crash occurred at a four-leg intersection. V1 was northbound. V2 was eastbound. "
        "The driver stopped for the sign. As he crossed the intersection he was struck in the left side by V1."
    )
    assert _actions(text)["V2"] == ["follow_lane", "stop", "go_across"]


def test_another_road_users_doings_are_nobodys() -> None:
    text = (
        "V1 was westbound at a T-intersection and stopped as a non-contact delivery truck was making a right "
        "turn. The front of V2 struck the rear of V1. V2 was westbound."
    )
    assert _actions(text)["V1"] == ["follow_lane", "stop"]


def test_another_road_user_named_again_by_its_noun_is_still_nobody() -> None:
    text = (
        "V1, a 2003 Buick, was northbound and stopped at the sign. A non-contact delivery van was turning right. "
        "The view of V1 was blocked by the van making the turn. V1 began to turn left. V2 struck V1."
    )
    assert _actions(text)["V1"] == ["follow_lane", "stop", "turn_left"]


def test_a_turn_after_before_is_done_unless_before_names_who() -> None:
    meant = "V1 was westbound intending to turn left. "
    assert _actions(meant + "The driver did not see V2 before turning. V2 struck V1.")["V1"][-1] == "turn_left"
    assert _actions(meant + "Before V1 began the turn, V2 struck V1.")["V1"] == ["follow_lane"]


def test_a_sentence_about_the_road_is_nobodys() -> None:
    text = (
        "V1, a 2001 Saab, was traveling west. The roadway had a center lane used for left turns in both "
        "directions. V1 hit V2."
    )
    assert _actions(text)["V1"] == ["follow_lane"]


def test_what_an_after_clause_says_came_first() -> None:
    text = "V1, a 2006 Honda, was making a left turn after being stopped at the stop sign. V2 struck V1."
    assert _actions(text)["V1"] == ["stop", "turn_left"]


def test_a_clause_about_traffic_ends_at_then() -> None:
    text = "At the intersection V1 was traveling east, stopped for traffic, then turned left. V2 hit V1."
    assert _actions(text)["V1"] == ["follow_lane", "stop", "turn_left"]


def test_both_vehicles_is_each_of_them() -> None:
    text = (
        "The crash occurred at a four-way intersection. V1 was southbound. V2 was westbound. Both vehicles "
        "entered the intersection and the front of V1 struck the right side of V2."
    )
    assert _actions(text) == {"V1": ["follow_lane", "go_across"], "V2": ["follow_lane", "go_across"]}


def test_an_object_described_on_the_spot_is_its_description() -> None:
    text = (
        "V1 was eastbound. The front of V1 struck the left side of V2, a 2011 Kia that was pulling out of a driveway."
    )
    assert _actions(text)["V2"] == ["drive_into"]


# --- actions ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "v1"),
    [
        # waiting is a stop; the turn it waited for is not an action
        ("V1 was stopped in the left lane waiting to turn left when V2 struck V1 in the rear.", ["stop"]),
        # a meant straight-on course into a junction is crossing it
        (
            "At the intersection V1 was eastbound, intending to go straight through the intersection. "
            "The front of V2 struck V1 in the left side.",
            ["follow_lane", "go_across"],
        ),
        # evasive moves are not actions
        ("V1 was westbound. V1 braked and swerved left to avoid V2. V2 struck V1.", ["follow_lane"]),
        # a turn said without its side is the one meant
        (
            "V1 was northbound intending to turn right. V1 slowed and began the turn. V2 struck V1.",
            ["follow_lane", "turn_right"],
        ),
        (
            "At the intersection V1 was southbound, made a complete stop at the stop sign, then continued "
            "through the intersection. V2 struck V1.",
            ["follow_lane", "stop", "go_across"],
        ),
        # into the other direction's lanes is wrong-way driving
        (
            "V1 was traveling eastbound and drifted into the westbound lane. V1 struck V2.",
            ["follow_lane", "retrograde"],
        ),
        ("V1 was eastbound and drove across the double yellow line. V1 hit V2.", ["follow_lane", "retrograde"]),
        (
            "V1, a 2002 Ford, was eastbound (the wrong direction) on the one-way street. V1 hit V2.",
            ["follow_lane", "retrograde"],
        ),
        # from a parked position onto the road
        ("V1 was parked at the curb and pulled out into the travel lane. V2 struck V1.", ["parked", "drive_into"]),
        # a left-turn lane is a lane, not a turn
        ("V1 was traveling south in the left turn lane. V2 struck V1.", ["follow_lane"]),
        ("V1 changed from the right lane into the left lane. V1 struck V2.", ["follow_lane", "change_lane"]),
        ("V1 was westbound, then made a U-turn. V2 struck V1.", ["follow_lane", "u_turn"]),
        ("V1, a 1999 Buick, ran off the road to the right. V1 struck V2.", ["follow_lane", "drive_off"]),
    ],
)
def test_actions_up_to_the_first_impact(text: str, v1: list[str]) -> None:
    assert _actions(text)["V1"] == v1


@pytest.mark.parametrize(
    ("text", "v2"),
    [
        ("V1 was stopped. V2 backed out of a parking space and struck V1.", ["parked", "reverse"]),
        ("V1 was stopped. V2 reversed out of a driveway and struck the side of V1.", ["follow_lane", "reverse"]),
        (
            "V1 was stopped. V2 reversed, and the rear of V2 made contact with the front of V1.",
            ["follow_lane", "reverse"],
        ),
        ("V1 was stopped. V2 began to roll backwards and struck V1.", ["follow_lane", "reverse"]),
        ("V1 was stopped. V2 was parked in the lane ahead of V1.", ["parked"]),
        ("V2 was stopped in traffic that was backed up. V1 struck V2.", ["stop"]),  # a queue, not a move
    ],
)
def test_backing_and_parked_are_read_as_reverse_and_parked(text: str, v2: list[str]) -> None:
    assert _actions(text)["V2"] == v2


def test_a_vehicle_backing_into_the_one_behind_it_is_the_striker() -> None:
    """Its rear leads: "the rear of V2 struck the front of V1" is a rear-end crash that V2 made."""
    s = _reading("V1 was stopped behind V2. V2 began to back up and the rear of V2 struck the front of V1.")
    assert s.crash == Crash(CrashType.REAR_END, "V2", "V1")
    assert s.participant("V2").known_actions[-1].kind is ActionKind.REVERSE


def test_a_stopped_striker_at_a_crossing_went_across() -> None:
    text = (
        "The crash occurred at a four-leg intersection. V1 was traveling west. V2 was northbound and stopped at "
        "the stop sign. The front of V2 struck the left side of V1."
    )
    assert _actions(text)["V2"] == ["follow_lane", "stop", "go_across"]


def test_a_vehicle_never_described_before_the_impact_has_unknown_actions() -> None:
    s = _reading("V1, a 2001 Mazda, was traveling north. As he crossed the road he was struck by the front of V2.")
    v2 = s.participant("V2")
    assert (v2.actions, v2.heading, v2.lane) == (UNKNOWN, UNKNOWN, UNKNOWN)


def test_a_pedestrian_met_only_after_the_first_impact_is_no_participant() -> None:
    s = _reading("V1 was northbound. The front of V1 struck the side of V2. V1 then struck a pedestrian on the curb.")
    assert [p.id for p in s.participants] == ["V1", "V2"]


def test_what_follows_the_impact_is_not_an_action() -> None:
    text = "V1 was northbound. The front of V1 struck the rear of V2. V1 then turned right and stopped."
    assert _actions(text)["V1"] == ["follow_lane"]


# --- the crash --------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("sentence", "crash"),
    [
        ("The front of V2 struck the left side of V1.", (CrashType.SIDE, "V2", "V1")),
        ("V1 was struck in the right side by the front of V2.", (CrashType.SIDE, "V2", "V1")),
        ("V1's front impacted V2's rear.", (CrashType.REAR_END, "V1", "V2")),
        ("V2 struck V1 in the rear with its front.", (CrashType.REAR_END, "V2", "V1")),
        ("As V1 turned, its left side was struck by the front of V2.", (CrashType.SIDE, "V2", "V1")),
        ("V1 impacted the front left of V2 with its front left.", (CrashType.FRONTAL, "V1", "V2")),
        ("V2 rear-ended V1.", (CrashType.REAR_END, "V2", "V1")),
        ("V1 was stopped when it was rear-ended by V2.", (CrashType.REAR_END, "V2", "V1")),
        (
            "V1 made a left turn in front of V2 and the front of V2 struck the right side of V1.",
            (CrashType.SIDE, "V2", "V1"),
        ),
        ("V1 passed V2 on the left, contacting its front to the left side of V2.", (CrashType.SIDE, "V1", "V2")),
        ("V1 and V2 collided head-on.", (CrashType.FRONTAL, UNKNOWN, UNKNOWN)),
        ("V1's right plane made contact with V2's front plane.", (CrashType.SIDE, "V2", "V1")),
        ("The front of V2 struck the right rear area of V1.", (CrashType.REAR_END, "V2", "V1")),
        ("V1 ran off the road and struck a tree with its front.", (CrashType.FRONTAL, "V1", UNKNOWN)),
        ("The front of V1 struck P1 from behind.", (CrashType.REAR_END, "V1", "P1")),
    ],
)
def test_the_crash_a_sentence_states(sentence: str, crash: tuple[object, object, object]) -> None:
    assert read_sentence(sentence) == Crash(*crash)


def test_a_pronoun_means_the_carried_subject() -> None:
    got = read_sentence("He was contacted on the right side by the front of V2.", carry="V1")
    assert got == Crash(CrashType.SIDE, "V2", "V1")


def test_a_sentence_without_an_impact_states_no_crash() -> None:
    assert read_sentence("V1 was traveling north in lane two.") is None


def test_a_pedestrian_crossing_is_struck_from_the_side() -> None:
    s = _reading("V1 was eastbound. P1 was crossing the street in the crosswalk. The front of V1 struck P1.")
    assert (s.crash.type, s.participant("P1").known_actions[0].kind) == (CrashType.SIDE, "cross")
    walking = _reading("V1 was eastbound. P1 was walking along the edge of the road. The front of V1 struck P1.")
    assert walking.participant("P1").known_actions[0].kind == "walk"
    along = _reading(
        "V1 was northbound. P1 was walking northbound in the bike lane. The front of V1 hit the back of P1."
    )
    assert (along.participant("P1").known_actions[0].kind, along.participant("P1").heading) == ("walk", "north")
    assert along.crash.type == CrashType.REAR_END
    into = _reading("V1 was southbound when P1 walked into the roadway. The front of V1 struck P1.")
    assert into.participant("P1").known_actions[0].kind == "cross"


# --- headings and lanes -------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "v1"),
    [
        ("V1, a 2003 Ford, was in its northbound lane traveling south. V1 hit V2.", "south"),
        ("V1 was stopped facing north, waiting to turn left to go west. V2 struck V1.", "north"),
        # the destination is not the heading (not west); a left turn to it says where it came from
        ("V1 stopped at the sign, then turned left to travel westbound. V2 struck V1.", "north"),
        ("The road has two westbound and two eastbound lanes. V1 was in the left lane. V2 struck V1.", "unknown"),
        ("V1 was traveling northwest on the county road. V2 struck V1.", "north"),
    ],
)
def test_the_heading_is_the_vehicles_own_course(text: str, v1: str) -> None:
    assert str(_reading(text).participant("V1").heading) == v1


def test_after_the_impact_only_a_verb_of_motion_gives_a_heading() -> None:
    s = _reading(
        "V1, a 2004 Kia, was stopped. V2 struck V1. V1 spun and came to rest facing east in the east bound lane."
    )
    assert s.participant("V1").heading == UNKNOWN
    assert _reading("V1 was traveling in the east bound lane. V1 hit V2.").participant("V1").heading == "east"


def test_head_on_with_a_wrong_way_vehicle_the_other_came_the_other_way() -> None:
    s = apply_defaults(_reading("V1 was westbound and crossed the centerline. The front of V1 struck the front of V2."))
    assert s.participant("V2").heading == "east" and "V2.heading" in s.provenance.assumed


def test_heading_and_lane_may_come_after_the_impact() -> None:
    s = _reading("V1 was northbound. The front of V2 struck V1. V2, a 2007 bus, was traveling eastbound in lane one.")
    assert (s.participant("V2").heading, s.participant("V2").lane) == ("east", 1)


def test_the_scene_gives_heading_and_lane_to_vehicles_that_state_none() -> None:
    text = (
        "The crash occurred in the right lane of the northbound lanes. V1, a 2002 Kia, stopped for a red light. "
        "V2, a 1998 Audi, was behind V1 and could not stop. V2 rear-ended V1."
    )
    s = _reading(text)
    assert [(p.heading, p.lane) for p in s.participants] == [("north", 1), ("north", 1)]
    assert s.crash == Crash(CrashType.REAR_END, "V2", "V1")


def test_a_lane_it_came_to_rest_in_or_a_road_count_is_not_its_lane() -> None:
    rest = _reading("V1, a 2001 Audi, was westbound. V2 struck V1. V1 rotated and came to rest in lane two.")
    assert rest.participant("V1").lane == UNKNOWN
    road = _reading("V1 turned from a driveway onto a northbound 5-lane two-way roadway. V2 struck V1.")
    assert road.participant("V1").lane == UNKNOWN


def test_lane_numbers_in_their_forms() -> None:
    for phrase, lane in [("lane #2", 2), ("the number one lane", 1), ("the second travel lane", 2)]:
        assert _reading(f"V1 was traveling east in {phrase}. V2 struck V1.").participant("V1").lane == lane


def test_a_vehicles_own_road_with_one_lane_each_way_puts_it_in_lane_one() -> None:
    text = (
        "The crash occurred where a road with two lanes in each direction crosses a smaller street. V1 was "
        "traveling north on the street with one lane in each direction. V2 was eastbound. V2 struck V1."
    )
    assert _reading(text).participant("V1").lane == 1


def test_the_same_lane_is_shared() -> None:
    text = "V1 was traveling west in lane two. V2 was stopped in the same lane ahead of V1. V1 struck V2 in the rear."
    assert _reading(text).participant("V2").lane == 2


# --- names --------------------------------------------------------------------------------------


def test_a_make_or_model_names_its_participant() -> None:
    text = normalize_names("Vehicle 1 was a 2004 Honda Civic. Vehicle 2, a 2001 Ford Ranger pickup, was east.")
    named = resolve_aliases(text + " The light turned green and the Civic turned left. The pickup struck the Honda.")
    assert named.endswith("the V1 turned left. V2 struck V1.".replace("the V1", "V1"))


def test_an_ambiguous_word_names_nobody() -> None:
    two_fords = "V1, a 2004 Ford Focus, was east. V2, a 2006 Ford Escape, was west. The Ford turned."
    assert resolve_aliases(two_fords).endswith("The Ford turned.")
    bus = "V2, a 2001 Blue Bird school bus, was east. A non-contact school bus was slowing. The bus turned right."
    assert resolve_aliases(bus).endswith("The bus turned right.")


def test_an_unnumbered_parked_vehicle_that_is_hit_is_a_participant() -> None:
    text = name_parked("V1 was westbound. The front of V1 struck the left side of a legally parked sedan.")
    assert "V2, a legally parked sedan," in text
    s = _reading("V1 was westbound. The front of V1 struck the left side of a legally parked sedan.")
    assert (s.crash, s.participant("V2").known_actions) == (
        Crash(CrashType.SIDE, "V1", "V2"),
        (Action(ActionKind.PARKED),),
    )


@pytest.mark.parametrize(
    "sentence",
    [
        "V2 braked and steered left to avoid a collision with V1.",
        "V1 slowed behind a non-contact vehicle.",
        "A two-vehicle collision occurred involving V1 and V2.",
    ],
)
def test_no_impact_in_these_sentences(sentence: str) -> None:
    assert first_impact([sentence]) == -1


def test_a_cyclist_is_a_vehicle_of_kind_bicycle_with_the_kind_read_from_its_words() -> None:
    s = extract(
        "The Waymo AV was traveling north at dusk. A cyclist in the bike lane turned left across the path of the "
        "Waymo AV, and the front of the Waymo AV made contact with the left side of the cyclist.",
        "c",
    )
    assert [(p.id, str(p.role), str(p.kind)) for p in s.participants] == [
        ("V1", "vehicle", "unknown"),
        ("V2", "vehicle", "bicycle"),
    ]
    assert s.environment.lighting == (Lighting.TWILIGHT,)
    assert s.crash == Crash(CrashType.SIDE, "V1", "V2")


@pytest.mark.parametrize(
    ("described", "kind"),
    [
        ("a 2004 Ford F-150 pickup truck", "pickup"),
        ("a 2010 Blue Bird school bus", "bus"),
        ("a 2015 Freightliner tractor-trailer", "truck"),
        ("a 2008 Honda Odyssey minivan", "van"),
        ("a 2012 Harley-Davidson motorcycle", "motorcycle"),
        ("a 2003 Honda Accord", "unknown"),  # a make and model do not say the kind
    ],
)
def test_the_kind_is_the_head_noun_of_the_words_that_describe_the_vehicle(described: str, kind: str) -> None:
    s = extract(f"V1, {described}, was traveling east. V2 was stopped ahead. V1 struck the rear of V2.", "k")
    assert str(s.participant("V1").kind) == kind
