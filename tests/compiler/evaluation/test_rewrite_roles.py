"""The rewrites of reports that number nobody (`compiler/evaluation/rewrite_roles.py`) keep the meaning: where a
make would name two vehicles, a vehicle is named before it is introduced, a third road user or a pedestrian is
in the report, or someone already speaks in the first person, the report is left as it is. Sentences of our own."""

from __future__ import annotations

import pytest
from sovarc.compiler.evaluation.rewrites import rewrite

UNCHANGED = [
    # two Fords: "the Ford" would name either
    ("unnumbered", "V1, a 1996 Ford Escort, was stopped. V2, a 2000 Ford Taurus, was behind. V2 struck V1."),
    # a mention before its introduction
    ("unnumbered", "The limit for V1 was 30 mph. V1, a 1996 Honda Civic, was towed. V2, a 1999 Kia Rio, left."),
    # a third road user introduced by the same make
    ("unnumbered", "V1, a 1996 Honda Civic, stopped behind a Honda Accord. V2, a 1999 Kia Rio, struck V1."),
    ("unnumbered", "V1, a 1996 Honda Civic, and V3, a 1999 Kia Rio, and V2, a 2001 Ford Focus, met."),
    ("first_person", "V1 struck P1, a pedestrian."),
    ("first_person", 'V1 struck V2. The driver of V2 said "I did not see V1".'),
    ("insurer", "The insured driver of V1 struck V2."),
    ("insurer", "Driver #1 was in V1, which struck V2."),
]


@pytest.mark.parametrize(("name", "text"), UNCHANGED, ids=[f"{c[0]}-{i}" for i, c in enumerate(UNCHANGED)])
def test_left_as_it_is_where_the_meaning_could_change(name: str, text: str) -> None:
    assert rewrite(name, text) == text


def test_a_label_after_the_words_that_say_it_is_dropped() -> None:
    text = "V1, a 2003 Honda Pilot, was traveling east. V2, a 1998 Kia Rio, struck V1. The Honda Pilot (V1) was towed."
    assert rewrite("unnumbered", text) == (
        "A 2003 Honda Pilot was traveling east. A 1998 Kia Rio struck the Honda. The Honda Pilot was towed."
    )


def test_a_pronoun_is_the_first_person_only_where_v1_was_named_last() -> None:
    text = "V1 was stopped. He waited. V2 struck V1. The driver of V2 said that she did not see V1."
    assert rewrite("first_person", text) == (
        "My vehicle was stopped. I waited. V2 struck my vehicle. The driver of V2 said that she did not see my vehicle."
    )
