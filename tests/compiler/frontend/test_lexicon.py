"""One lexicon of impact verbs (`frontend/lexicon.py`), read alike by every reader, on sentences written for these
tests: a glancing verb is an impact wherever an impact is looked for, in every form, and a word only built like
one ("a speed bump", "the contact area") is none."""

from __future__ import annotations

import re

import pytest
from sovarc.compiler.frontend.crash import read_sentence
from sovarc.compiler.frontend.lexicon import IMPACT_VERBS, IMPACT_WORD, Form, forms, stems, striking, struck
from sovarc.compiler.frontend.refusals import says_impact
from sovarc.compiler.frontend.text import describes_impact, in_past
from sovarc.dsl.ir import Crash, CrashType


def _says(pattern: str, text: str) -> bool:
    return re.search(r"\b" + pattern + r"\b", text, re.I) is not None


def test_every_verb_has_its_five_forms() -> None:
    clip = next(v for v in IMPACT_VERBS if v.base == "clip")
    assert (clip.third, clip.past, clip.participle, clip.ing) == ("clips", "clipped", "clipped", "clipping")
    swipe = next(v for v in IMPACT_VERBS if v.base == "side-swipe")
    assert _says(forms((Form.PAST,)), "V2 sideswiped V1") and _says(forms((Form.PAST,)), "V2 side-swiped V1")
    assert _says(forms((Form.ING,)), "side swiping V1") and swipe.ing == "side-swiping"


@pytest.mark.parametrize(
    "sentence",
    [
        "V2 sideswiped V1 as it merged.",
        "V2 clipped the mirror of V1.",
        "V1 was grazed by V2.",
        "V2 brushed against V1.",
        "V2 scraped the side of V1.",
        "V2 bumped into V1 at low speed.",
        "V2 is hitting V1.",
        "V2 proceeded to make contact with V1.",
    ],
)
def test_a_glancing_blow_describes_an_impact(sentence: str) -> None:
    assert describes_impact(sentence)


@pytest.mark.parametrize(
    "sentence",
    [
        "V1 slowed for a speed bump.",
        "V1 updated the contact area of V2 in the form.",
        "V2 was a non-contact vehicle.",
        "V1 steered left to avoid sideswiping V2.",
        "V2 did not clip V1.",
    ],
)
def test_words_only_built_like_an_impact_say_none(sentence: str) -> None:
    assert not describes_impact(sentence)


def test_the_refusals_net_is_wider_than_the_readers() -> None:
    """A report is refused as no crash only when no word in it could say one ("the bumper")."""
    assert says_impact("V1's rear bumper was damaged by V2.") and not describes_impact("V1's bumper was damaged.")
    assert _says(stems(), "a scrape") and not _says(IMPACT_WORD, "a scrape")


def test_active_and_passive_forms() -> None:
    assert _says(striking(), "V2 brushed against V1") and _says(striking(), "V2 collided with V1")
    assert not _says(striking(), "V1 and V2 collided")  # no object: who struck is not said
    assert not _says(striking(), "the impact") and not _says(striking(), "a speed bump")
    assert _says(struck(), "was clipped") and not _says(struck(), "was made contact")


def test_a_strike_told_in_the_present_is_read_in_the_past() -> None:
    assert in_past("V2 sideswipes V1. V1 is grazed by V3.") == "V2 sideswiped V1. V1 was grazed by V3."
    assert read_sentence("V2 bumped the rear of V1.") == Crash(CrashType.REAR_END, "V2", "V1")


def test_a_strike_not_avoided_is_made_in_any_verb() -> None:
    assert read_sentence("V2 could not avoid sideswiping V1.") == Crash(CrashType.SIDE, "V2", "V1")
    assert read_sentence("V2 failed to avoid colliding with the rear of V1.") == Crash(CrashType.REAR_END, "V2", "V1")
