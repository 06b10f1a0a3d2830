"""Where the victim was met, from the damage the narrative says it took.

Fleet narratives often name no part in the impact sentence ("a passenger vehicle reversed into V1") and say
where it was hit in the next one: "V1 sustained minor damage to the driver's side rear door". In a crash of two
road users the victim's damage is where the striker met it, so that part is the crash type's, when the impact
sentence left it unsaid.
"""

from __future__ import annotations

import re
from dataclasses import replace

from sovarc.compiler.frontend.crash import PART, backed, part_kind
from sovarc.dsl.ir import UNKNOWN, Crash

_TOOK = r"(?:sustained|suffered|received|took|had)"
_DAMAGE = r"(?:[\w-]+ ){0,2}?(?:damage|scratch(?:es)?|dents?|scuffs?)"
_HARMED = r"(?:damaged|dented|scratched|scuffed)\b"


def _damaged(victim: str) -> re.Pattern[str]:
    return re.compile(
        rf"\b{victim}\b {_TOOK} {_DAMAGE} (?:to|on) (?:the |its |his |her |it's )?(?P<part>{PART})\b"
        rf"|\b{_DAMAGE} (?:to|on) (?:the )?(?P<of>{PART}) of (?:the )?{victim}\b"
        rf"|\b{_DAMAGE} (?:to|on) {victim}'s (?P<own>{PART})\b"
        # "V1's rear bumper was damaged", "damaging the left door of V1"
        rf"|\b{victim}'s (?P<was>{PART}) (?:was|were) (?:\w+ )?{_HARMED}"
        rf"|\b(?:damaging|denting|scratching) (?:the )?(?P<ing>{PART}) of (?:the )?{victim}\b",
        re.I,
    )


def damaged_part(crash: Crash, sents: list[str], at: int, backing: frozenset[str], ahead: int = 2) -> tuple[Crash, int]:
    """The crash with its type read from the victim's damage when the impact sentence (index `at`) left it
    unknown: the damage said in that sentence or the next `ahead` ones (a striker backing leads with its rear,
    see `crash.backed`); and the index of the sentence the type was read from (`at` when not from damage)."""
    victim, striker = crash.victim, crash.striker
    if crash.type is not UNKNOWN or not isinstance(victim, str) or at < 0:
        return crash, at
    pattern = _damaged(victim)
    for i, sentence in enumerate(sents[at : at + 1 + ahead], at):
        if m := pattern.search(sentence):
            kind = part_kind(next(g for g in m.groups() if g))
            if kind is not None:
                return replace(crash, type=backed(kind, striker in backing)), i
    return crash, at
