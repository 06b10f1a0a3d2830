"""Reports the front end refuses whole, with one line that names the file and the reason.

A scenario holds one crash from one report. Text that is several reports run together, that describes
several separate crashes, or that describes no crash at all cannot become one scenario; guessing one from
it would be a silent error, so it is refused before anything is read (`FrontEnd.extract`). Non-English text
is refused by `text.check_narrative`.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.choice import FrontEndError
from sovarc.compiler.frontend.lexicon import INTO_ANYTHING, stems
from sovarc.compiler.frontend.text import first_impact, prepare, sentences, without_non_impacts

_MONTH = (
    r"(?:January|February|March|April|May|June|July|August|September|October|November|December"
    r"|Jan|Feb|Mar|Apr|Aug|Sept?|Oct|Nov|Dec)\.?"
)
# A report's dated opening: "On May [XXX], 2022 at 1:26 PM PST", "On 3/4/2021 at 14:05".
_OPENING = re.compile(
    r"(?:^|[.!?]\s+|\n\s*)On " + r"(?:" + _MONTH + r"\s*(?:\[XXX\]|\d{1,2})?,? \d{4}|\d{1,2}/\d{1,2}/\d{2,4})"
    r",? at \d{1,2}:\d{2}",
    re.I,
)
# A separator line between pasted reports: "-----", "=====", "Report 2:", "Case 2".
_SEPARATOR = re.compile(r"\n\s*(?:[-=*_]{4,}|(?:report|case|narrative)\s*(?:#|no\.?)?\s*\d+\s*:?)\s*\n", re.I)
# A crash said to be another one, not a later impact of the same crash.
_OTHER_CRASH = re.compile(
    r"\b(?:a|another|the) (?:separate|second|different|unrelated|later|subsequent) (?:crash|incident|accident)\b"
    r"(?! (?:sequence|event))",
    re.I,
)


def refuse(text: str, name: str, named: str | None = None) -> None:
    """Raise FrontEndError when the text is not one report of one crash; `named` is its prepared text, when the
    caller has it."""
    named = prepare(text) if named is None else named
    if len(_OPENING.findall(text)) > 1 or _blocks_with_impacts(text) > 1 or _reintroduced(named):
        raise FrontEndError(
            f"{name}: the file holds more than one report (each report opens with its own date and time, the "
            "reports are separated by a line, or a vehicle label is introduced twice as two different vehicles); "
            "give one report per file; nothing to extract"
        )
    if m := _OTHER_CRASH.search(text):
        raise FrontEndError(
            f"{name}: the report describes several crashes ('{m.group()}'); a scenario holds one crash: give "
            "each crash its own report; nothing to extract"
        )
    # (a text that names no road user at all gets the front end's own refusal, which says what it looked for)
    if re.search(r"\b[VP]\d\b", named) and first_impact(sentences(named)) < 0 and not says_impact(text):
        raise FrontEndError(
            f"{name}: the report describes no crash: no sentence says that road users met (struck, collided, "
            "made contact, ...); nothing to extract"
        )


# A road user introduced with its model year and make: "V1, a 2003 Honda Pilot", "V2 a 1992 GMC".
_INTRODUCED = re.compile(r"\b([VP]\d+)\b,? an? (\d{4}) ([A-Z][\w-]*)")


def _reintroduced(named: str) -> bool:
    """Whether one label is introduced as two different vehicles (another year or make): a report introduces
    each road user once, so the second introduction opens another report run on after the first."""
    seen: dict[str, set[tuple[str, str]]] = {}
    for label, year, make in _INTRODUCED.findall(named):
        seen.setdefault(label, set()).add((year, make.lower()))
    return any(len(vehicles) > 1 for vehicles in seen.values())


def _blocks_with_impacts(text: str) -> int:
    """How many separator-delimited blocks each describe an impact of their own."""
    blocks = _SEPARATOR.split(text)
    return sum(1 for b in blocks if first_impact(sentences(prepare(b))) >= 0) if len(blocks) > 1 else 1


# Every way a report says road users met, the rules' readings aside ("clipped", "bumped", "reversed into").
_IMPACT_WORD = re.compile(r"\b(?:" + stems() + "|" + INTO_ANYTHING + r")\b", re.I)


def says_impact(text: str) -> bool:
    """Whether any sentence says road users met, in words the rules may not read (their refusal then says
    more than "no crash" could)."""
    return any(_IMPACT_WORD.search(without_non_impacts(s)) for s in sentences(text))
