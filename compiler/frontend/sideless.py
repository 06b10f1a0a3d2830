"""A lane change said without its side ("V2, which was switching lanes, rear-ended V1"; "V2 changed lanes and
struck V1"): read as a lane change whose side is not known, not dropped. The IR writes it `change_lane` with no
target, and lowering's assume pass chooses the side with a note (compiler/lower/sides.py).

A report that gives the side anywhere ("changed lanes ... its lane change to the left") says the one move twice:
the side-less mention is then that move, not another.

Only words that name a lane change say one without its side ("changed lanes", "switching lanes", "a lane change",
"merging", "cut in front of", "shifted lanes"), or name the lane entered as one of its own direction beside it
("into the adjacent lane", "crossed the dashed lane line"). A move around another road user, or out of its lane,
with no side said may be made within the lane (a motorcycle splitting lanes), onto the shoulder or into the other
direction's lanes: those stay unread.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.action_words import BESIDE_LANE, LANE_LINE, MERGE_FROM
from sovarc.dsl.ir import Action, ActionKind, Side

_NAMED = re.compile(
    r"\b(?:chang|switch|shift|swap)\w* lanes?\b|\blane[- ]chang|\bmerg(?:es?|ed|ing)\b|\bcut(?:s|ting)? (?:back )?in\b"
    r"|\b(?:in)?to "
    + BESIDE_LANE
    + r"|\benter\w*(?: (?:partially|fully))? "
    + BESIDE_LANE
    + r"|\b(?:cross\w* (?:over )?|across |over )"
    + LANE_LINE
    + MERGE_FROM,
    re.I,
)


def names_a_lane_change(words: str) -> bool:
    """Whether the words that read a lane change name one ("changed lanes"), not only a move sideways."""
    return _NAMED.search(words) is not None


def one_lane_change(found: list[tuple[int, Action]]) -> list[tuple[int, Action]]:
    """The actions read (offset, action), without side-less lane changes when a lane change with its side or
    lane was read for the same vehicle."""
    if not any(a.kind is ActionKind.CHANGE_LANE and a.to is not None for _, a in found):
        return found
    return [(at, a) for at, a in found if not a.sideless]


def said_in_piece(found: list[tuple[int, Action]], start: int, length: int, to: Side | None) -> int | None:
    """Where a lane change to the same side (or none said) was read earlier in one piece (`start`, `length`): one
    read after it there is that move, ended ("As V2 was changing lanes, it entered V1's lane"), not a second."""
    return next(
        (
            at
            for at, a in found
            if a.kind is ActionKind.CHANGE_LANE
            and (a.to is None or to is None or a.to == to)
            and start <= at < start + length
        ),
        None,
    )
