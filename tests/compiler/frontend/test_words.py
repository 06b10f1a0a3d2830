"""The front end's shared words: counts said in words or digits, and the compass the readers turn on."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend.words import COMPASS, number, opposite, turned
from sovarc.dsl.ir import Heading


@pytest.mark.parametrize(("word", "count"), [("3", 3), ("three", 3), ("Eight", 8), ("single", 1), ("ONE", 1)])
def test_a_count_is_read_from_digits_or_words(word: str, count: int) -> None:
    assert number(word) == count


def test_an_unknown_number_word_is_an_error_not_a_guess() -> None:
    with pytest.raises(KeyError):
        number("several")


def test_the_compass_runs_clockwise_and_turns_by_quarters() -> None:
    assert COMPASS == (Heading.NORTH, Heading.EAST, Heading.SOUTH, Heading.WEST)
    # a right turn is a quarter clockwise: heading north, it leaves east; a left turn from west leaves south
    assert turned(Heading.NORTH, 1) is Heading.EAST
    assert turned(Heading.WEST, -1) is Heading.SOUTH
    assert [opposite(h) for h in COMPASS] == [Heading.SOUTH, Heading.WEST, Heading.NORTH, Heading.EAST]
    assert all(opposite(opposite(h)) is h and turned(h, 4) is h for h in COMPASS)
