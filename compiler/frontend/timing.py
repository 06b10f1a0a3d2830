"""When a motion said in the progressive happened, in a sentence that opens on a time clause.

"When V2 stopped to let traffic pass, it was traveling north": the main clause's progressive says what was under
way when the time clause's event happened, so the motion came first, though it is said after. (The same facts
as "V2 was traveling north when it stopped", where the words are in the events' order.) "After V2 stopped, it
was traveling north" is not one: "after" orders the motion second.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.clauses import Piece

_SIMULTANEOUS = re.compile(r"^(?:When|As|While|Just as)\b")
# the main clause, after the time clause's comma, on the same participant: "..., it was traveling north" (the
# piece it begins, or the rest of the time clause's piece)
_UNDER_WAY = re.compile(
    r"(?:^|, )(?:it|he|she|they|[VP]\d) (?:was|were) (?:travel(?:l)?ing|driving|proceeding|heading|going|moving|"
    r"approaching|negotiating|continuing)\b"
)


def under_way_first(pieces: list[Piece]) -> int | None:
    """Where a motion under way at a time clause's event is placed: at the first piece of its sentence, which the
    time clause opens; None when no piece says one."""
    found = [
        min(q.at for q in pieces if q.sentence == p.sentence)
        for p in pieces
        if _SIMULTANEOUS.match(p.context) and _UNDER_WAY.search(p.text)
    ]
    return min(found, default=None)
