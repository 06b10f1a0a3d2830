"""Words every reader of the front end counts and steers by: number words, ordinals, the compass and
the prepositions of place.

One table each: the readers' patterns say which of the words they accept ("lane one", "two lanes in
each direction", "Vehicle three"); the values are the same wherever a word is read.
"""

from __future__ import annotations

from sovarc.dsl.ir import Heading

# "a single lane in each direction" counts one, as "one lane" does.
NUMBER_WORDS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "single": 1}
ORDINALS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5}
COMPASS = tuple(Heading)  # north, east, south, west: clockwise, a quarter turn apart
# Prepositions of place: the road user after one says where another was ("behind the heavy truck", "next to V1"),
# not who met whom.
PLACE_WORDS = r"behind|ahead of|in front of|next to|beside|alongside"


def number(word: str) -> int:
    """A count said in digits or in words ("3", "three", "Single")."""
    return int(word) if word.isdigit() else NUMBER_WORDS[word.lower()]


def turned(heading: Heading, quarters: int) -> Heading:
    """The heading `quarters` quarter turns clockwise of `heading` (negative: anticlockwise)."""
    return COMPASS[(COMPASS.index(heading) + quarters) % 4]


def opposite(heading: Heading) -> Heading:
    """The way back: two vehicles heading opposite ways meet head-on."""
    return turned(heading, 2)
