"""The metamorphic benchmark's tense rewrite (`rewrites.REWRITES["present_tense"]`): a narrative told in the
present says what one told in the past does. Kept apart from `rewrites.py` for its verb table's length."""

from __future__ import annotations

import re

from sovarc.compiler.frontend.lexicon import IMPACT_VERBS


def in_case_of(like: str, word: str) -> str:
    """`word` capitalised as `like` is (a rewritten word that opens a sentence still opens it)."""
    return word[0].upper() + word[1:] if like[0].isupper() else word


# ---- tense ------------------------------------------------------------------------------------------------
# Some narratives tell the crash in the present ("V1 is traveling north ... V2 turns left and strikes V1"). The
# past forms of the verbs crash narratives use, and their present (third person); a past participle after a
# form of "be" or "have", an article or "to" stays ("was stopped", "a stopped car", "had slowed").
_PRESENT = {
    "was": "is",
    "were": "are",
    "had": "has",
    "came": "comes",
    "made": "makes",
    "began": "begins",
    "drove": "drives",
    "saw": "sees",
    "went": "goes",
    "ran": "runs",
    "stated": "states",
    "turned": "turns",
    "stopped": "stops",
    "slowed": "slows",
    "braked": "brakes",
    "steered": "steers",
    "swerved": "swerves",
    "entered": "enters",
    "accelerated": "accelerates",
    "attempted": "attempts",
    "started": "starts",
    "changed": "changes",
    "pulled": "pulls",
    "backed": "backs",
    "continued": "continues",
    "passed": "passes",
    "merged": "merges",
    "approached": "approaches",
    "proceeded": "proceeds",
    "traveled": "travels",
    "travelled": "travels",
    "crossed": "crosses",
    "failed": "fails",
    "departed": "departs",
    "rotated": "rotates",
    "occurred": "occurs",
    "looked": "looks",
    "yielded": "yields",
    "moved": "moves",
    "veered": "veers",
}
# the verbs of impact as the front end's lexicon writes them ("sideswiped" -> "sideswipes", "hit" -> "hits")
_PRESENT.update(
    {v.past.replace("-", j): v.third.replace("-", j) for v in IMPACT_VERBS if " " not in v.base for j in ("-", "")}
)
_PAST = re.compile(r"\b(?:" + "|".join(_PRESENT) + r")\b", re.I)
_PARTICIPLE_AFTER = re.compile(
    r"\b(?:was|were|is|are|be|been|being|had|has|have|a|an|the|to|not|just)\s+(?:\w+ly\s+)?$", re.I
)


def present_tense(text: str) -> str:
    """ "V1 was traveling north when V2 turned left and struck V1" -> "V1 is traveling north when V2 turns left
    and strikes V1"."""

    def one(m: re.Match[str]) -> str:
        word = m.group()
        if _PARTICIPLE_AFTER.search(text[max(0, m.start() - 30) : m.start()]) and word.lower() not in (
            "was",
            "were",
            "had",
        ):
            return word
        return in_case_of(word, _PRESENT[word.lower()])

    return _PAST.sub(one, text)
