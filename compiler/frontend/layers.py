"""What the model is shown, layer by layer, and how a fact's cited sentences are checked.

The paper asks in three layers: environment; road network and traffic
guidance; each participant's motion. The rules read the first two exactly
(weather and light words, posted limits, lane counts, the road kind,
headings), and the model's answers there added nothing on the shared reports,
so only the motion layer is asked: the sentences that name a participant (or
refer back to one: "he", "the driver"), up to and including the first impact.
Sentences that only describe the road, the weather or the aftermath are not
sent, which is most of the saving in what the model reads.

Each shown sentence keeps the number it has in the whole report (1-based) and
its character span in the original text, so a fact the model cites by number
points at the words it was read from.

The checks are the evidence side of the cross-check in `hybrid`: a cited
sentence must exist among those shown, name the participant the fact is
about, and state the fact (a cue word of the action, not under an intention
such as "intending to turn left").
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from difflib import SequenceMatcher
from functools import cached_property

from sovarc.compiler.frontend.clauses import Piece, pieces
from sovarc.compiler.frontend.sentences import sentences
from sovarc.compiler.frontend.text import describes_impact, first_impact, prepare

_NAMED = re.compile(r"\b[VP]\d\b")
# A sentence that carries the last participant without naming it.
_BACK_REFERENCE = re.compile(r"^(?:\w+ ){0,3}?(?:he|she|it|they|the driver|this vehicle|the vehicle)\b", re.I)


@dataclass(frozen=True)
class Sentence:
    number: int  # 1-based, in the whole prepared report
    text: str  # as prepared: participants named V1, P1
    span: tuple[int, int]  # characters [start, end) in the original report


@dataclass(frozen=True)
class Shown:
    """The motion layer's view of one report: the numbered sentences the model reads."""

    sentences: tuple[Sentence, ...]

    def numbers(self) -> list[int]:
        return [s.number for s in self.sentences]

    def get(self, number: int) -> Sentence | None:
        return next((s for s in self.sentences if s.number == number), None)

    def about(self, number: int, pid: str) -> bool:
        """Sentence `number` is shown and names `pid`, or carries it ("he", "the driver") from the sentence
        before it that names only `pid`."""
        for i, s in enumerate(self.sentences):
            if s.number != number:
                continue
            if _NAMED.search(s.text):
                return re.search(rf"\b{pid}\b", s.text) is not None
            before = next((b for b in reversed(self.sentences[:i]) if _NAMED.search(b.text)), None)
            return before is not None and set(_NAMED.findall(before.text)) == {pid}
        return False

    @cached_property
    def _pieces(self) -> list[Piece]:
        """The shown sentences cut at each subject (`clauses.pieces`), in their order so that "he"
        carries the last subject: computed once, since every evidence check reads them."""
        texts = [s.text for s in self.sentences]
        return pieces(texts, sorted({name for text in texts for name in _NAMED.findall(text)}))

    def pieces_of(self, number: int, pid: str) -> list[str]:
        """The pieces of sentence `number` that are `pid`'s own doing."""
        index = next((i for i, s in enumerate(self.sentences) if s.number == number), None)
        return [p.text for p in self._pieces if p.sentence == index and pid in p.who]

    def text(self) -> str:
        return "\n".join(f"[{s.number}] {s.text}" for s in self.sentences)


def motion_layer(report: str) -> Shown:
    """The sentences naming a participant (or carrying one by "he", "the driver"), up to the first impact."""
    prepared = sentences(prepare(report))
    last = first_impact(prepared)
    spans = _original_spans(report, prepared)
    shown: list[Sentence] = []
    carried = False
    for i, text in enumerate(prepared[: last + 1] if last >= 0 else prepared):
        named = bool(_NAMED.search(text))
        if named or (carried and _BACK_REFERENCE.search(text)):
            shown.append(Sentence(i + 1, text, spans[i]))
        carried = named or (carried and bool(_BACK_REFERENCE.search(text)))
    return Shown(tuple(shown))


def _original_spans(report: str, prepared: list[str]) -> list[tuple[int, int]]:
    """Each prepared sentence's span in the original text: preparing renames participants ("Vehicle #1" to
    "V1"), so the offsets are carried over through the longest matching blocks of the two texts."""
    joined, starts = "", []
    for s in prepared:
        starts.append(len(joined))
        joined += s + " "
    blocks = SequenceMatcher(None, joined, report, autojunk=False).get_matching_blocks()

    def where(offset: int) -> int:
        for a, b, size in blocks:
            if a <= offset < a + size:
                return b + offset - a
            if a > offset:  # inside a rewritten stretch: the start of the next matching block
                return b
        return len(report)

    spans = []
    for s, start in zip(prepared, starts, strict=True):
        begin, end = where(start), where(start + len(s) - 1) + 1
        spans.append((begin, max(begin, end)))
    return spans


# "turned left", "made a left-hand turn", "a left turn": not "the left-turn lane" or "a left turn signal".
_TURN = (
    r"\bturn\w*\s+(?:\w+\s+){{0,2}}?{side}\b|\b{side}[- ]hand turn"
    r"|\b{side}[- ]turn(?!(?:ing)?[- ](?:only )?(?:lane|signal|arrow|bay|pocket))"
)
# Cue words of each action: a sentence that states the action uses one of them.
_CUES: dict[str, str] = {
    "follow_lane": r"travel|driv|drove|proceed|head|going|moving|approach|bound|negotiat|continu|accelerat|"
    r"operat|ran\b|rode|riding|came|coming|went",
    "turn_left": _TURN.format(side="left"),
    "turn_right": _TURN.format(side="right"),
    "change_lane": r"\blanes?\b|merg|swerv|veer|steer",
    "go_across": r"intersection|junction|through|across|straight|cross|enter|red (?:light|signal)|proceed",
    "stop": r"\bstop|slow|wait|park|stand|stationary|queue|halt|yield",
    "u_turn": r"\bu[- ]?turn|turn\w* around",
    "drive_into": r"pull|exit|enter|driveway|parking|shoulder|merg|onto|from (?:a|the|its)",
    "drive_off": r"\boff\b|shoulder|ditch|depart|leav|left the road|curb|roadside",
    "retrograde": r"oncoming|opposite|wrong|cent(?:er|re)|yellow|median|into the (?:north|south|east|west) ?bound|"
    r"other lane|crossed over",
    "cross": r"cross|walk|ran\b|running|enter|step|dart",
    "walk": r"walk|jog|ran\b|running|along|standing",
    "reverse": r"\bback|revers|rearward",
    "parked": r"\bpark|stationary|standing|unoccupied|curb",
}
# An action under one of these words was meant or feared, not done ("intending to turn left").
_INTENTION = re.compile(
    r"\b(?:intend\w*|plann\w*|want\w*|wait\w*|about to|prepar\w*|signal\w*|desir\w*|to avoid|in order to|"
    r"would|could not|unable to)\b(?:\W+\w+){0,4}\W*$",
    re.I,
)


def cue(action: str) -> re.Pattern[str]:
    key = "change_lane" if action.startswith("change_lane") else action
    return re.compile(_CUES[key], re.I)


# A move made to avoid the crash is evasive, and the paper's conventions drop it ("steered left to avoid V2").
_EVASIVE = re.compile(r"^\w*(?:\W+\w+){0,5}?\W+(?:to avoid|avoid\w*|evasive|in an attempt to)\b", re.I)


def states_action(sentence: str, action: str) -> bool:
    """The sentence states `action` as done: one of its cue words, not under an intention nor evasive."""
    return any(
        not _INTENTION.search(sentence[: m.start()]) and not _EVASIVE.search(sentence[m.start() :])
        for m in cue(action).finditer(sentence)
    )


def states_impact(sentence: str) -> bool:
    return describes_impact(sentence)
