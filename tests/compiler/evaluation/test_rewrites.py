"""Each rewrite of the metamorphic benchmark on sentences of our own: it changes only its variation's words,
keeps the rest, is deterministic, and leaves a text it does not fit unchanged."""

from __future__ import annotations

import pytest
from sovarc.compiler.evaluation.rewrites import REWRITES, rewrite

CASES = [
    ("v_short", "Vehicle #1 struck Vehicle # 2 and Vehicle two's door.", "V1 struck V2 and V2's door."),
    ("vehicle_hash", "V1 struck V2's rear.", "Vehicle #1 struck Vehicle #2's rear."),
    ("vehicle_number", "V-1 struck Unit 2.", "Vehicle 1 struck Vehicle 2."),
    ("vehicle_word", "V1 struck V2.", "Vehicle one struck Vehicle two."),
    ("unit", "Vehicle No. 1 struck V2.", "Unit 1 struck Unit 2."),
    ("v_dash", "V1 struck V2.", "V-1 struck V-2."),
    ("v_space", "V1 struck V2.", "V 1 struck V 2."),
    (
        "possessive_of",
        "V2's right front contacted V1's left side.",
        "The right front of V2 contacted the left side of V1.",
    ),
    ("of_possessive", "The front of V1 struck the rear of V2.", "V1's front struck V2's rear."),
    ("driver_possessive", "The driver of V1 steered left.", "V1's driver steered left."),
    ("of_possessive", "It struck the left rear of V2, a parked van.", "It struck the left rear of V2, a parked van."),
    ("split_and", "The limit for V1 and V2 was 45 mph.", "The limit for V1 and V2 was 45 mph."),
    ("speed_upper", "a limit of 48 kmph (30 mph)", "a limit of 48 KMPH (30 MPH)"),
    ("speed_words", "a limit of 48 km/h (30 mph)", "a limit of 48 kilometers per hour (30 miles per hour)"),
    ("speed_kph", "a limit of 48 KMPH (30 MPH)", "a limit of 48 kph (30 mph)"),
    ("speed_km_h", "a limit of 48 kph", "a limit of 48 km/h"),
    ("mph_only", "a posted limit of 48 kmph (30 mph).", "a posted limit of 30 mph."),
    ("mph_first", "a posted limit of 48 kmph (30 mph).", "a posted limit of 30 mph (48 kmph)."),
    (
        "compass_plain",
        "V1 was traveling northbound on the northbound lanes.",
        "V1 was traveling north on the northbound lanes.",
    ),
    ("compass_bound", "V1 was heading west.", "V1 was heading westbound."),
    ("compass_heading", "V1 was traveling southbound.", "V1 was heading south."),
    ("compass_direction", "V1 was traveling eastbound.", "V1 was traveling in an easterly direction."),
    (
        "compass_abbreviated",
        "V1 was traveling northbound in the northbound lanes.",
        "V1 was traveling N/B in the N/B lanes.",
    ),
    ("lane_digit", "V1 was in lane one; V2 was in the second lane of travel.", "V1 was in lane 1; V2 was in lane 2."),
    ("lane_hash", "V1 was in lane two.", "V1 was in lane #2."),
    ("lane_word", "V1 was in lane #3.", "V1 was in lane three."),
    (
        "lane_ordinal",
        "V1 was in lane one and moved into lane #2.",
        "V1 was in the first lane and moved into the second lane.",
    ),
    (
        "count_digits",
        "a two-lane road with three lanes at a four-way stop",
        "a 2-lane road with 3 lanes at a 4-way stop",
    ),
    ("count_words", "a 2-lane road with 3 lanes", "a two-lane road with three lanes"),
    (
        "driver_of",
        "V1 was traveling north. V2 was a 1999 Ford.",
        "The driver of V1 was traveling north. V2 was a 1999 Ford.",
    ),
    ("driver_dropped", "The driver of Vehicle #2 slowed.", "Vehicle #2 slowed."),
    (
        "split_and",
        "V2 proceeded to turn left and the front of V1 struck V2.",
        "V2 proceeded to turn left. The front of V1 struck V2.",
    ),
    ("split_and", "V2 stopped, and then V2 turned left.", "V2 stopped. Then V2 turned left."),
    ("join_then", "V2 stopped at the sign. V2 turned left.", "V2 stopped at the sign, and then V2 turned left."),
    ("travelling", "V1 was traveling north and traveled on.", "V1 was travelling north and travelled on."),
    ("proceeding", "Traveling north, V1 was traveling fast.", "Proceeding north, V1 was proceeding fast."),
    ("turn_verb", "V2 made a left turn after making a right-hand turn.", "V2 turned left after turning right."),
    ("turn_noun", "V2 turned left, intending to turn right.", "V2 made a left turn, intending to make a right turn."),
    ("turn_hand", "V2 made a left turn.", "V2 made a left-hand turn."),
    ("junction", "Intersections: a T-intersection.", "Junctions: a T-junction."),
    (
        "writer_police",
        "The driver of V1 stopped at the two-lane road. V1 was traveling northbound in lane one at 48 kmph (30 mph).",
        "Driver #1 stops at the 2-lane road. Unit 1 is traveling N/B in lane #1 at 30 mph.",
    ),
    (
        "writer_british",
        "V1 was traveling northbound on the roadway at the intersection, at 30 mph.",
        "Vehicle 1 was travelling in a northerly direction on the carriageway at the junction, at 30 miles per hour.",
    ),
    (
        "writer_terse",
        "V1 was traveling north at 30 mph. V1 made a left turn. V2 stopped.",
        "V-1 was northbound at 30 MPH. It turned left; V-2 stopped.",
    ),
    (
        "british_spelling",
        "V1 maneuvered over the center line to the curb.",
        "V1 manoeuvred over the centre line to the kerb.",
    ),
    ("carriageway", "The roadway had two roadways.", "The carriageway had two carriageways."),
    ("signal_light", "a traffic signal-controlled crossing", "a traffic light-controlled crossing"),
    ("compass_was", "V1 was traveling northbound and V2 was heading west.", "V1 was northbound and V2 was westbound."),
    ("driver_number", "The driver of V2 then stopped.", "Driver #2 then stopped."),
    ("pronoun_subject", "V2 stopped at the sign. V2 then turned left.", "V2 stopped at the sign. It then turned left."),
    ("pronoun_subject", "V2 stopped behind V1. V2 then turned left.", "V2 stopped behind V1. V2 then turned left."),
    ("pronoun_subject", "Vehicle #2 stopped. V2 turned.", "Vehicle #2 stopped. It turned."),
    ("semicolons", "V1 was traveling north. V2 was traveling east.", "V1 was traveling north; V2 was traveling east."),
    (
        "turn_executed",
        "V2 made a left turn, making a right-hand turn.",
        "V2 executed a left turn, executing a right-hand turn.",
    ),
    ("intending_on", "V2 was intending to turn left.", "V2 was intending on turning left."),
    ("impact_passive", "The front of V1 struck the rear of V2.", "The rear of V2 was struck by the front of V1."),
    ("impact_passive", "Then V1 hit V2 on the side.", "Then V2 was hit by V1 on the side."),
    ("impact_passive", "Vehicle #1 struck V2.", "V2 was struck by Vehicle #1."),
    (
        "present_tense",
        "V1 was traveling north when V2 turned left and struck V1. V2 was stopped; a stopped car had slowed.",
        "V1 is traveling north when V2 turns left and strikes V1. V2 is stopped; a stopped car has slowed.",
    ),
    (
        "impact_collided",
        "The front of V1 struck V2. V2 was struck by V1.",
        "The front of V1 collided with V2. V2 was struck by V1.",
    ),
    ("impact_impacted", "V1 struck V2, which was hit by V3.", "V1 impacted V2, which was impacted by V3."),
    (
        "came_to_stop",
        "V2 stopped at the sign behind a stopped car.",
        "V2 came to a stop at the sign behind a stopped car.",
    ),
    ("braked", "The driver applied the brakes.", "The driver braked."),
    ("braked", "The driver braked.", "The driver applied the brakes."),
    (
        "aside_parenthesis",
        "V2, a 1998 Ford Taurus sedan, was traveling north.",
        "V2 (a 1998 Ford Taurus sedan) was traveling north.",
    ),
    # how sentences are built, and what a participant is called after its introduction (`rewrite_clauses.py`)
    (
        "clause_after",
        "As V2 entered the intersection, its left side was struck by V1. As V1 turned, V2 braked.",
        "V2's left side was struck by V1 as V2 entered the intersection. V2 braked as V1 turned.",
    ),
    (
        "clause_fronted",
        "Vehicle #1 was turning left when it was struck by V2. V2 braked as V1 turned.",
        "When Vehicle #1 was struck by V2, it was turning left. As V1 turned, V2 braked.",
    ),
    (
        "place_after",
        "At the intersection, the front of V2 struck V1.",
        "The front of V2 struck V1 at the intersection.",
    ),
    (
        "join_after",
        "V2 stopped at the sign. V2 then turned left.",
        "After V2 stopped at the sign, V2 then turned left.",
    ),
    (
        "while_participle",
        "V1 was attempting a U-turn when it was struck by V2.",
        "While attempting a U-turn, V1 was struck by V2.",
    ),
    ("then_first", "V1 stopped. V1 then turned left.", "V1 stopped. Then V1 turned left."),
    (
        "rear_ended",
        "The front of V1 struck the rear of V2. V2 impacted the back of V3 with its front.",
        "V1 rear-ended V2. V2 rear-ended V3.",
    ),
    ("crashed_into", "V1 struck V2, which was hit by V3.", "V1 crashed into V2, which was hit by V3."),
    ("road_word", "The roadway had two roadways.", "The road had two roads."),
    ("three_leg", "at a T-intersection", "at a three-leg intersection"),
    (
        "part_with",
        "The front of V1 struck the left side of V2.",
        "V1 struck the left side of V2 with its front.",
    ),
    ("struck_in_side", "V1 struck the left side of V2.", "V1 struck V2 in the left side."),
    (
        "stationary",
        "V2 was stopped at the light; V1 was stopped by police.",
        "V2 was stationary at the light; V1 was stopped by police.",
    ),
    ("decelerated", "V2 slowed down for slowing traffic.", "V2 decelerated for slowing traffic."),
    (
        "kind_which",
        "V1, a 1996 Honda Civic, was traveling east.",
        "V1 was a 1996 Honda Civic, which was traveling east.",
    ),
    (
        "kind_aside",
        "V1 was a 1996 Honda Civic that was traveling east. V2 was a 1999 Ford Taurus traveling west.",
        "V1, a 1996 Honda Civic, was traveling east. V2, a 1999 Ford Taurus, was traveling west.",
    ),
    (
        "make_names",
        "Vehicle #1, a 1996 Honda Civic, was behind V2, a 2002 GMC Envoy. Vehicle #1 struck V2.",
        "Vehicle #1, a 1996 Honda Civic, was behind V2, a 2002 GMC Envoy. The Honda struck the GMC.",
    ),
    ("vehicle_ordinal", "Vehicle #1 struck V2's rear.", "The first vehicle struck the second vehicle's rear."),
    ("police_abbrev", "Vehicle #1 was traveling approximately 30 mph.", "Veh. #1 was traveling approx. 30 mph."),
    (
        "lane_curb",
        "V1 was in the right lane, left of the right lane line.",
        "V1 was in the curb lane, left of the right lane line.",
    ),
    (
        "writer_adjuster",
        "V1, a 1996 Honda Civic, was traveling east in the right lane. V2, a 1998 Ford, stopped. V2 turned left.",
        "V1 was a 1996 Honda Civic, which was traveling east in the curb lane. After V2, a 1998 Ford, stopped, "
        "the Ford turned left.",
    ),
    # how the road and its conditions are said (`rewrite_road.py`)
    (
        "limit_posted_at",
        "The road had a posted speed limit of 48 kmph (30 mph). The posted speed limit was 35 MPH.",
        "The road was posted at 48 kmph (30 mph). The speed limit was posted at 35 MPH.",
    ),
    (
        "lanes_each_way",
        "a two-lane, two-way roadway and a four lane undivided road",
        "a two-way roadway with one lane in each direction and an undivided road with two lanes in each direction",
    ),
    (
        "lanes_total",
        "a two-way roadway with one lane in each direction and a divided road with two lanes of travel in each "
        "direction",
        "a two-lane, two-way roadway and a four-lane, divided road",
    ),
    ("dark_lighted", "It was dark, but lighted.", "It was dark-lighted."),
    ("all_caps", "V1 struck V2's left side.", "V1 STRUCK V2'S LEFT SIDE."),
    ("veh_caps", "Vehicle #1 struck V2.", "VEH 1 struck VEH 2."),
    ("letters", "V1 struck Vehicle #2.", "Vehicle A struck Vehicle B."),
    ("car_letters", "V1 struck V2.", "Car A struck Car B."),
    ("driver_short", "The driver of V1 said the driver of Vehicle #2 stopped.", "D1 said D2 stopped."),
    (
        "form_abbrev",
        "V2 failed to yield the right of way to V1 in the left lane at the intersection, approximately 30 feet "
        "into the eastbound lane, made a right turn and faced the opposite direction in the lane.",
        "V2 FTYROW to V1 in the LT LN at the INTX, APPROX 30 feet into the EBL, made a RT turn and faced the OPP "
        "DIR in the LN.",
    ),
    (
        "writer_agency",
        "The driver of V1 was traveling northbound in the left lane. V1 struck V2.",
        "D1 WAS TRAVELING N/B IN THE LT LN. VEH 1 STRUCK VEH 2.",
    ),
    # reports that number nobody (`rewrite_roles.py`)
    (
        "unnumbered",
        "Vehicle #1, a 2003 Honda Pilot, was traveling east. V2 was a 1998 Ford Taurus traveling west. V2 struck V1.",
        "A 2003 Honda Pilot was traveling east. A 1998 Ford Taurus was traveling west. The Ford struck the Honda.",
    ),
    (
        "first_person",
        "V1 was traveling east. The driver of V1 stated that he braked. V2 struck the left side of V1.",
        "My vehicle was traveling east. I stated that I braked. V2 struck the left side of my vehicle.",
    ),
    (
        "insurer",
        "V1 was traveling east. The driver of V1 braked. The driver of V2 stated that V2 struck V1.",
        "The insured vehicle was traveling east. Our insured braked. The claimant stated that the claimant vehicle "
        "struck the insured vehicle.",
    ),
    # terse and lettered styles (`rewrite_styles.py`)
    (
        "bare_names",
        "V1, a 2003 Honda Civic sedan, was traveling east. V2 was a 1998 Ford F-150 pickup that was stopped. V1 "
        "struck the rear of V2.",
        "A 2003 Honda Civic sedan was traveling east. A 1998 Ford F-150 pickup was stopped. Sedan struck the rear "
        "of the pickup.",
    ),
    (
        "driver_letters",
        "The driver of V1 braked. V1 struck V2's left side.",
        "Driver A braked. Driver A's vehicle struck Driver B's left side.",
    ),
]


@pytest.mark.parametrize(("name", "before", "after"), CASES, ids=[f"{c[0]}-{i}" for i, c in enumerate(CASES)])
def test_each_rewrite_says_the_same_in_its_other_words(name: str, before: str, after: str) -> None:
    assert rewrite(name, before) == after


def test_every_rewrite_is_shown_on_a_sentence() -> None:
    assert {c[0] for c in CASES} == set(REWRITES)


@pytest.mark.parametrize("name", sorted(REWRITES))
def test_a_text_without_the_variation_is_left_as_it_is(name: str) -> None:
    text = "Clear weather on a weekend."
    # (capitals are every text's variation: the whole report in them is its rewrite)
    assert rewrite(name, text) == (text.upper() if name in ("all_caps", "writer_agency") else text)


def test_keeps_the_names_of_a_report_that_mixes_them() -> None:
    # the rewrites written for V1 give each name its own words back
    text = "Vehicle #1 was traveling north. V2, a 1997 Nissan Pathfinder, was stopped."
    assert (
        rewrite("aside_parenthesis", text)
        == "Vehicle #1 was traveling north. V2 (a 1997 Nissan Pathfinder) was stopped."
    )
    assert (
        rewrite("driver_of", text)
        == "The driver of Vehicle #1 was traveling north. V2, a 1997 Nissan Pathfinder, was stopped."
    )


def test_a_pair_joined_by_and_is_not_split() -> None:
    text = "The crash occurred between V1 and V2 at the intersection."
    assert rewrite("split_and", text) == text


def test_a_road_direction_is_not_a_course() -> None:
    text = "The northbound lanes were dry."
    assert rewrite("compass_plain", text) == text
    assert rewrite("compass_direction", text) == text


def test_deterministic() -> None:
    text = "V1 was traveling northbound in lane one at 45 mph and V2 made a left turn. V2 stopped. V2 turned."
    for name in REWRITES:
        assert rewrite(name, text) == rewrite(name, text)
