"""The clause and naming rewrites (`compiler/evaluation/rewrite_clauses.py`) keep the meaning: where a move could
change what a pronoun refers to or what a phrase qualifies, or a new name could point at two participants, the
sentence is left as it is. Sentences of our own."""

from __future__ import annotations

import pytest
from sovarc.compiler.evaluation.rewrites import rewrite

UNCHANGED = [
    # a pronoun in the time clause would come before (or lose) the one it refers to
    ("clause_after", "As he turned, V2 struck V1."),
    ("clause_after", "As V1 entered the intersection, V2 struck it."),
    # a main clause of two events: the moved clause would time only the last
    ("clause_after", "As V1 entered the intersection, V2 braked and V1 struck V2."),
    # "when" as what an event was, not a time clause
    ("clause_fronted", "The critical event for V1 was when it traveled over the line."),
    # another's words: the time clause may be theirs
    ("clause_fronted", "The driver stated that V1 was going straight when V2 turned."),
    # "it" after "the driver of V1" is not its subject
    ("clause_fronted", "The driver of V1 was turning when it was struck."),
    ("place_after", "At the intersection, V1 proceeded through and V2 struck V1."),
    # a pronoun, a state, or a sentence of two events is not joined to the next
    ("join_after", "It stopped at the sign. V2 turned left."),
    ("join_after", "V2 was stopped at the sign. V2 turned left."),
    ("join_after", "V2 stopped and looked both ways. V2 turned left."),
    ("while_participle", "V1 was turning when V2 struck it."),
    # two Fords: "the Ford" would name either
    ("make_names", "V1, a 1996 Ford Escort, and V2, a 2000 Ford Taurus, met. V1 struck V2."),
    # a mention before the introduction, and the report's own label, stay
    ("make_names", "The limit for V1 was 30 mph. V1, a 1996 Honda Civic, was towed. The Honda Civic (V1) left."),
    ("kind_aside", "V1 was a vehicle that was traveling east."),
    # a bare side is no noun to be struck "in"; an aside on the struck vehicle would follow the part
    ("struck_in_side", "V2 contacted the left of V1."),
    ("struck_in_side", "V1 struck the rear of V2, a parked car."),
    ("stationary", "V1 was stopped by the police."),
    ("lane_curb", "V1 crossed the right lane line."),
    # a limit not followed by its speed; an odd count of lanes (a centre turn lane) is no count in each direction
    ("limit_posted_at", "The roadway had a posted speed limit of unknown value."),
    ("lanes_each_way", "a three-lane, two-way roadway"),
]


@pytest.mark.parametrize(("name", "text"), UNCHANGED, ids=[f"{n}-{i}" for i, (n, _) in enumerate(UNCHANGED)])
def test_a_sentence_the_rewrite_could_change_the_meaning_of_is_left_as_it_is(name: str, text: str) -> None:
    assert rewrite(name, text) == text


def test_a_move_keeps_each_name_in_its_own_words() -> None:
    text = "Unit 2 struck Vehicle #1 as Vehicle #1 entered the intersection."
    assert rewrite("clause_fronted", text) == "As Vehicle #1 entered the intersection, Unit 2 struck Vehicle #1."


def test_a_time_clause_on_it_takes_the_name_with_its_kind() -> None:
    text = "V1, a 1995 Toyota Camry, was traveling east when it went over the right lane line."
    assert rewrite("clause_fronted", text) == (
        "When V1, a 1995 Toyota Camry, went over the right lane line, it was traveling east."
    )


def test_sentences_written_without_a_space_are_rewritten_each() -> None:
    text = "It was dry.V1, a 1996 Honda Civic, was traveling east.V2 stopped."
    assert rewrite("kind_which", text) == "It was dry.V1 was a 1996 Honda Civic, which was traveling east.V2 stopped."


def test_a_make_opening_a_sentence_is_capitalised() -> None:
    text = "V1, a 1996 Honda Civic, was traveling east. V1 stopped; then V1 turned."
    assert (
        rewrite("make_names", text)
        == "V1, a 1996 Honda Civic, was traveling east. The Honda stopped; then the Honda turned."
    )
