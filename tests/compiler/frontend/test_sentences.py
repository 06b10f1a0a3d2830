"""One test of a sentence's start (`sentences.opens_sentence`), read by the front end's readers and the rewrites
alike, on texts written for these tests."""

from __future__ import annotations

import pytest
from sovarc.compiler.frontend.sentences import opens_sentence


@pytest.mark.parametrize(
    ("text", "word"),
    [
        ("V1 stopped.", "V1"),
        ("  V1 stopped.", "V1"),
        ("V2 braked. V1 stopped.", "V1 stopped"),
        ("V2 braked.V1 stopped.", "V1 stopped"),  # (a full stop before a capital, its space left out)
        ('Did V2 brake? "V1 stopped," he said.', "V1 stopped"),
        ("V2 braked! (V1 stopped.)", "V1 stopped"),
    ],
)
def test_a_word_after_a_sentence_end_opens_one(text: str, word: str) -> None:
    assert opens_sentence(text, text.index(word))


@pytest.mark.parametrize(
    ("text", "word"),
    [
        ("V2 braked and V1 stopped.", "V1"),
        ("Ofc. Smith saw V1.", "Smith"),
        ("A van, e.g. V1, stopped.", "V1"),
        ("V2 braked, (V1 stopped).", "V1"),
    ],
)
def test_a_word_inside_a_sentence_opens_none(text: str, word: str) -> None:
    assert not opens_sentence(text, text.index(word))
