"""Where a road user came from is behind it: "coming from the south" says it heads north."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend.rules import extract
from sovarc.dsl.ir import Heading

TURNER = "V1 was traveling east through the intersection when V2, {said}, turned left and struck the side of V1."


@pytest.mark.parametrize(
    ("said", "heading"),
    [
        ("coming from the south", Heading.NORTH),
        ("approaching from the west", Heading.EAST),
        ("which came from the north", Heading.SOUTH),
        ("traveling from the east", Heading.WEST),
    ],
)
def test_where_a_vehicle_came_from_is_behind_it(said: str, heading: Heading) -> None:
    v2 = extract(TURNER.format(said=said), "t").participant("V2")
    assert v2 is not None and v2.heading is heading


@pytest.mark.parametrize("said", ["coming from the south side of the road", "approaching from the north leg"])
def test_a_place_on_that_side_is_no_course(said: str) -> None:
    v2 = extract(TURNER.format(said=said), "t").participant("V2")
    assert v2 is not None and v2.heading is not Heading.NORTH and v2.heading is not Heading.SOUTH


def test_a_heading_said_outright_comes_first() -> None:
    text = "V2 was traveling north, coming from the south side street, and struck V1, which was traveling east."
    v2 = extract(text, "t").participant("V2")
    assert v2 is not None and v2.heading is Heading.NORTH


@pytest.mark.parametrize(
    ("said", "heading"),
    [("crossing from south to north", Heading.NORTH), ("walking from the east side to the west", Heading.WEST)],
)
def test_a_course_said_by_its_two_ends_heads_to_the_second(said: str, heading: Heading) -> None:
    p1 = extract(f"P1 was {said} when V1, traveling south, struck P1.", "t").participant("P1")
    assert p1 is not None and p1.heading is heading
