"""How the metamorphic benchmark's rewrites (`rewrites.py`) find and rename the participants: every way the
reports number a vehicle, read as V1, V2, ... and given back its own words. Kept apart so that the rewrite
modules share one reading of a name."""

from __future__ import annotations

import re
from collections.abc import Callable

from sovarc.compiler.frontend.sentences import opens_sentence

WORDS = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")
ORDINALS = ("zeroth", "first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth")
DIGIT_OF = {w: i for i, w in enumerate(WORDS)}
DIGIT_OF.update({o: i for i, o in enumerate(ORDINALS)})


def digit(word: str) -> int:
    return int(word) if word.isdigit() else DIGIT_OF[word.lower()]


# ---- participant naming -----------------------------------------------------------------------------------
# Every way the reports number a vehicle: V1, V-1, V 1, Vehicle #1, Vehicle # 1, Vehicle 1, Vehicle one,
# Vehicle No. 1, Unit 1, Unit #1.
VEHICLE = re.compile(
    r"\bV(?:-| )?(?P<v>\d)\b(?![\w-])"
    r"|\b(?i:vehicle)\s*(?:#\s*|(?i:no\.)\s*|(?i:number)\s+)?(?P<w>\d|(?i:one|two|three|four|five|six))\b(?![\w-])"
    r"|\b(?i:unit)\s*#?\s*(?P<u>\d)\b(?![\w-])"
)


def cased(words: str, text: str, at: int) -> str:
    """`words`, capitalised where they open a sentence of `text` at `at`."""
    return words[0].upper() + words[1:] if opens_sentence(text, at) else words


def through_v(rewrite: Callable[[str], str]) -> Callable[[str], str]:
    """A rewrite written for "V1" names, for a report naming its vehicles any way: the names are read as V1, V2,
    ... and each is given back its own words afterwards (the rewrites keep the names' order)."""

    def run(text: str) -> str:
        said = [m.group() for m in VEHICLE.finditer(text)]
        out = rewrite(renamed(lambda n: f"V{n}")(text))
        names = iter(said)
        restored = re.sub(r"\bV\d\b", lambda m: next(names, m.group()), out)
        return restored if len(re.findall(r"\bV\d\b", out)) == len(said) else out

    return run


def renamed(form: Callable[[int], str]) -> Callable[[str], str]:
    def rewrite(text: str) -> str:
        return VEHICLE.sub(lambda m: form(digit(m.group("v") or m.group("w") or m.group("u"))), text)

    return rewrite


# any of those names, matched in place (in a longer pattern)
ANY_NAME = (
    r"(?:V(?:-| )?\d|(?i:vehicle)\s*(?:#\s*|(?i:no\.)\s*|(?i:number)\s+)?(?:\d|(?i:one|two|three|four|five|six))"
    r"|(?i:unit)\s*#?\s*\d)(?![\w-])"
)
