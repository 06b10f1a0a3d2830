"""Actions read as the language states them (issue 18): kinds of language, each with reports written here.

- auxiliary verbs of starting, proceeding and attempting carry the main verb's action;
- what was waited for or intended ends where a new clause begins, and a negated verb is no action;
- a planned turn was made unless the report shows it was not (another move, a stop after the plan, a crash
  from behind);
- going the wrong way is read from who is in whose lane, not only from its usual words;
- a lane said in words is read against the road's lanes in the vehicle's direction.
"""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend.actions import read_actions_at
from sovarc.compiler.frontend.clauses import pieces
from sovarc.compiler.frontend.rules import extract
from sovarc.dsl.ir import Heading, RoadKind, Unknown

CROSS = "The crash occurred at a four-leg intersection. V1 was traveling south. "


def _actions(text: str) -> dict[str, list[str]]:
    s = extract(text, "t")
    return {p.id: [] if isinstance(p.actions, Unknown) else [a.kind.value for a in p.actions] for p in s.participants}


def _lanes(text: str) -> dict[str, object]:
    return {p.id: p.lane for p in extract(text, "t").participants}


STRUCK = " The front of V1 struck the right side of V2."


@pytest.mark.parametrize(
    "said",
    [
        "V2 was traveling north and proceeded to make a left turn.",
        "V2 was traveling north and began to turn left.",
        "V2 was traveling north. V 2 initiated a left turn in front of V1.",
        "V2 was traveling north and attempted to turn left.",
        "V2 was traveling north and started a left turn.",
        "V2 was traveling north and went left at the intersection.",
    ],
)
def test_auxiliaries_of_starting_and_attempting_carry_the_turn_and_a_side_taken_at_a_junction_is_one(said: str) -> None:
    assert _actions(CROSS + said + STRUCK)["V2"] == ["follow_lane", "turn_left"]


def test_a_wait_ends_where_the_next_clause_begins() -> None:
    text = CROSS + "V2 was stopped facing north waiting for traffic to clear and then proceeded to turn left." + STRUCK
    assert _actions(text)["V2"] == ["stop", "turn_left"]


def test_a_negated_start_is_no_action() -> None:
    text = (
        CROSS + "V2 was eastbound. The driver of V2 was planning to turn right but had not yet started to turn."
        " The front of V2 struck the right side of V1."
    )
    assert _actions(text)["V2"] == ["follow_lane"]


def test_a_planned_turn_at_the_crash_junction_was_made() -> None:
    text = (
        CROSS + "V2 was traveling northbound intending on turning left at the intersection. The driver of V2 did"
        " not see V1." + STRUCK
    )
    assert _actions(text)["V2"] == ["follow_lane", "turn_left"]


@pytest.mark.parametrize(
    ("said", "crash"),
    [  # waiting says it had not begun; a stop after the plan; a crash from behind before the turn
        ("V2 was traveling north and was waiting to turn left.", STRUCK),
        ("V2 was traveling north intending to turn left and stopped for traffic.", STRUCK),
        (
            "V2 was traveling south ahead of V1, intending to turn left at the intersection.",
            " The front of V1 struck the back of V2.",
        ),
    ],
)
def test_a_plan_not_carried_out_is_no_turn(said: str, crash: str) -> None:
    assert "turn_left" not in _actions(CROSS + said + crash)["V2"]


ROAD = "The crash occurred on a two-lane undivided roadway with one lane in each direction. "


@pytest.mark.parametrize(
    "said",
    [
        "V1 was traveling east. V2 was traveling west. V1 entered oncoming traffic and the front of V1 struck the"
        " front of V2.",
        "V1 was traveling east. V1 partially left the right side of the roadway and overcompensated. V1 then made"
        " contact with V2, which was traveling in the opposite direction.",
        "V1 was traveling east. V2 was traveling west. V1 drifted across the roadway and its front struck the"
        " front of V2.",
    ],
)
def test_the_vehicle_shown_leaving_its_side_toward_an_opposed_one_is_retrograde(said: str) -> None:
    s = extract(ROAD + said, "t")
    got = {p.id: [a.kind.value for a in p.known_actions] for p in s.participants}
    assert got == {"V1": ["follow_lane", "retrograde"], "V2": ["follow_lane"]}
    assert [str(p.heading) for p in s.participants] == ["east", "west"]  # "the opposite direction" of V1
    assert str(s.crash.type) == "frontal"


@pytest.mark.parametrize(
    "said",
    [  # nobody shown moving sideways; both shown; going the same way
        "V1 was traveling east. V2 was traveling west. The front of V1 struck the front of V2.",
        "V1 was traveling east and swerved. V2 was traveling west and veered. The front of V1 struck the front of V2.",
        "V1 was traveling east and drifted. V2 was traveling east. The front of V1 struck the back of V2.",
    ],
)
def test_no_wrong_way_where_the_situation_does_not_say_who(said: str) -> None:
    assert all("retrograde" not in acts for acts in _actions(ROAD + said).values())


@pytest.mark.parametrize(
    ("road", "said", "lanes"),
    [
        (
            "The crash occurred on a six-lane roadway with three lanes in each direction. ",
            "V1 was traveling north in the inside lane. V2 was traveling north in the curb lane ahead of V1.",
            {"V1": 3, "V2": 1},
        ),
        (
            "The crash occurred on a six-lane roadway with three lanes in each direction. ",
            "V1 was traveling north in the middle lane. V2 was traveling north in lane three ahead of V1.",
            {"V1": 2, "V2": 3},
        ),
        (
            "The crash occurred on a three-lane one-way street. ",
            "V1 was traveling north in the left lane. V2 was traveling north in the second lane from the left"
            " ahead of V1.",
            {"V1": 3, "V2": 2},
        ),
        (
            "The crash occurred on a six-lane roadway with three lanes in each direction. ",
            "V1 was traveling north in the second lane from the curb. V2 was traveling north in the outer lane"
            " ahead of V1.",
            {"V1": 2, "V2": 1},
        ),
        (  # two-way: half the lanes are the vehicle's direction
            "The crash occurred on a four-lane undivided roadway. ",
            "V1 was traveling north in the left lane. V2 was traveling north in the right lane ahead of V1.",
            {"V1": 2, "V2": 1},
        ),
    ],
)
def test_a_lane_in_words_is_read_against_the_lanes_of_its_direction(road: str, said: str, lanes: dict) -> None:
    assert _lanes(road + said + " The front of V1 struck the back of V2.") == lanes


def test_a_one_way_cross_street_says_nothing_of_a_vehicles_own_road() -> None:
    text = (
        "The crash occurred at a four-leg intersection of a four-lane two-way road and a one-way street."
        " V1 was traveling north in the left lane. V2 was traveling west on the one-way street."
        " The front of V2 struck the left side of V1."
    )
    assert _lanes(text)["V1"] == 2


def test_a_vehicle_first_shown_in_its_manoeuvre_is_not_shown_driving_first() -> None:
    text = (
        "The crash occurred on a two-way roadway with one lane in each direction. V1 was traveling east."
        " V2 was a sedan that began a left turn into a driveway. The front of V1 struck the right side of V2."
    )
    assert _actions(text)["V2"] == ["turn_left"]
    moving = text.replace("V2 was a sedan that began", "V2 was traveling west and began")
    assert _actions(moving)["V2"] == ["follow_lane", "turn_left"]


@pytest.mark.parametrize("purpose", ["slowed to turn left into a driveway", "signaled to make a left turn into a lot"])
def test_a_purpose_after_slowing_is_not_yet_done_when_struck_from_behind(purpose: str) -> None:
    text = (
        "The crash occurred on a two-way roadway with one lane in each direction. V2 was traveling south ahead of V1"
        f" and {purpose}. The front of V1 struck the back of V2."
    )
    assert _actions(text)["V2"] == ["follow_lane"]
    slowed = text.replace(purpose, "slowed to a stop")  # the stop itself stays
    assert _actions(slowed)["V2"] == ["follow_lane", "stop"]


@pytest.mark.parametrize(
    ("said", "acts"),
    [
        ("went through the stop sign without stopping", ["follow_lane", "go_across"]),
        ("failed to stop and ran the stop sign", ["follow_lane", "go_across"]),
        ("was brought to a stop at the stop sign, then proceeded through the intersection", ["stop", "go_across"]),
    ],
)
def test_failing_or_going_without_is_negation_and_a_stop_is_said_many_ways(said: str, acts: list[str]) -> None:
    text = (
        "The crash occurred at a four-leg intersection. V1 was traveling south and " + said + "."
        " V2 was traveling east. The front of V1 struck the left side of V2."
    )
    got = _actions(text)["V1"]
    assert got[-len(acts) :] == acts
    assert ("stop" in got) == ("stop" in acts)


def test_each_action_keeps_the_clause_it_was_read_from() -> None:
    from_sents = ["V2 was stopped facing north.", "V2 then began to turn left and was struck by the front of V1."]
    parts = [p for p in pieces(from_sents, ["V1", "V2"]) if "V2" in p.who]
    actions, ats = read_actions_at(parts, RoadKind.INTERSECTION, Heading.NORTH, False)
    assert not isinstance(actions, Unknown)
    clause = [next(p for p in reversed(parts) if p.at <= at) for at in ats]
    assert [(a.kind.value, p.text) for a, p in zip(actions, clause, strict=True)] == [
        ("stop", "V2 was stopped facing north."),
        ("turn_left", "V2 then began to turn left and was struck by the front of V1."),
    ]
