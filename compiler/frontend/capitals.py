"""A report written in capitals, read as a writer in sentence case would have written it.

Agencies export their narratives in capitals ("VEH 1 WAS TRAVELING N/B ON SR 42"). The readers' patterns tell
codes and names by their case (a make is capitalised, "N/B" is a direction only in capitals, "V1" is a label),
so such a report is respelt in sentence case first: words in lower case, a sentence's first word capitalised,
and the tokens whose capitals carry meaning kept in them: codes joined to a number or a slash ("V1", "N/B",
"I-95"), compass codes ("NB", "EBL"), a route's prefix before its number ("SR 42"), single letters (a label's
"B", the compass's "N") but the article "a", a label's letter after its noun ("CAR A WAS"), and the names the
readers know by their capital: a make after its model year ("A 2005 FORD TAURUS", and "THE FORD" after it), a
street's name before its kind ("ELM ST"), days and months.

Only the case of letters changes, never the number of characters: the respelt report aligns character for
character with the report's own text (`evidence.Alignment`), so evidence still quotes the report as written.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.sentences import opens_sentence

# A report is in capitals when nearly all its words are: a sentence-case report with a few codes or a shouted
# word ("the sign said STOP") is not.
_WORD = re.compile(r"\b[A-Za-z]{2,}\b")
_SHARE = 0.8
_FEWEST = 5

_RUN = re.compile(r"[A-Za-z]+")


def _words(said: str) -> frozenset[str]:
    return frozenset(said.split())


_COMPASS_CODES = _words("NB SB EB WB NE NW SE SW NBL SBL EBL WBL NBD SBD EBD WBD")
# a route's prefix before its number: "SR 42", "US 1", "I 95", "CR 12", "RT 9", "HWY 30"
_ROUTES = _words("SR US I IH CR FM SH RT RTE HWY")
# a label's letter after its noun: "CAR A", "VEHICLE B", "UNIT A"
_LABELLED = _words("CAR VEHICLE VEH UNIT DRIVER DRV PEDESTRIAN PED")
# what may follow a label's letter ("CAR A WAS", "CAR A, ...", "CAR A'S"), unlike an article's noun ("CAR A FEW")
_AFTER_LABEL = re.compile(
    r"^(?:[.,;:!?)'\"]|$|\s+(?:WAS|WERE|IS|HAD|HAS|AND|OR|THEN|IN|ON|AT|TO|WITH|FROM|INTO|AS|WHICH|THAT|WHO|"
    r"BY|FOR|WHILE|WHEN|STRUCK|HIT|IMPACTED|CONTACTED|COLLIDED|STOPPED|TURNED|DID|COULD|WOULD|[A-Z]+ED)\b)"
)
_NAMED = _words(
    "MONDAY TUESDAY WEDNESDAY THURSDAY FRIDAY SATURDAY SUNDAY JANUARY FEBRUARY APRIL JUNE JULY AUGUST "
    "SEPTEMBER OCTOBER NOVEMBER DECEMBER"
)
# a street's kind after its name: "ELM ST", "PARK AVENUE" (not "the road": a common noun is no name)
_STREET = re.compile(r"\b((?:[A-Z]+ ){1,2})(ST|AVE|RD|BLVD|PKWY|STREET|AVENUE|BOULEVARD|PARKWAY)\b(?![\w-])")
_NOT_NAME = _words(
    "ON OF THE A AN AT TO ONTO FROM NEAR AND OR IN INTO ALONG ACROSS N S E W NB SB EB WB NORTHBOUND "
    "SOUTHBOUND EASTBOUND WESTBOUND NORTH SOUTH EAST WEST WAS WERE"
)
# a make and model after the model year: "A 2005 FORD TAURUS SEDAN" (the body word is a common noun)
_MADE = re.compile(r"\b(?:19|20)\d\d ((?:[A-Z][A-Z-]* ?){1,3})")
_COMMON = _words(
    "PICKUP TRUCK VAN MINIVAN BUS MOTORCYCLE SEDAN COUPE WAGON HATCHBACK SUV TRACTOR TRAILER SEMI JEEP "
    "CAR VEHICLE WAS WERE IS AND WITH THAT WHICH DRIVEN OPERATED TRAVELING TRAVELLING PASSENGER UTILITY "
    "SPORT DOOR MODEL YEAR IN ON AT THE A AN OF"
)


def in_capitals(text: str) -> bool:
    """Whether the report is written in capitals (see `_SHARE`)."""
    words = _WORD.findall(text)
    return len(words) >= _FEWEST and sum(w.isupper() for w in words) >= _SHARE * len(words)


def sentence_case(text: str) -> str:
    """The report in sentence case when it is written in capitals (see above); else the report as it is. Only
    letters' case changes: the result has the report's length, character for character."""
    if not in_capitals(text):
        return text
    keep = _kept(text)
    titled = _titled(text)
    latin = {s for m in _LATIN.finditer(text) for s in range(m.start(), m.end())}
    out = list(text)
    for m in _RUN.finditer(text):
        s, e = m.span()
        if s in keep:
            continue
        word = m.group().lower()
        if s in titled or (opens_sentence(text, s) and s not in latin):
            word = word[0].upper() + word[1:]
        out[s:e] = word
    return "".join(out)


# "E.G.", "I.E.": Latin abbreviations, in lower case (their letters are no labels)
_LATIN = re.compile(r"\b(?:E\.G|I\.E)\.")


def _kept(text: str) -> set[int]:
    """Where the runs of letters kept in capitals start (see above)."""
    keep: set[int] = set()
    latin = {s for m in _LATIN.finditer(text) for s in range(m.start(), m.end())}
    for m in _RUN.finditer(text):
        s, e = m.span()
        if s in latin:
            continue
        word, before, after = m.group(), text[max(0, s - 1) : s], text[e : e + 2]
        if before == "'":
            continue  # "D1'S", "DON'T": an ending, in lower case
        joined = before in ("/",) or before.isdigit() or after[:1] in ("/",) or after[:1].isdigit()
        joined = joined or (after[:1] == "-" and after[1:2].isdigit())  # "I-95"
        route = word in _ROUTES and re.match(r" ?#?\d", text[e : e + 3]) is not None
        noun = re.search(r"\b(\w+)\s*#?\s*$", text[max(0, s - 16) : s])
        label = (
            len(word) == 1 and noun is not None and noun[1] in _LABELLED and _AFTER_LABEL.match(text[e:]) is not None
        )
        letter = len(word) == 1 and word != "A"
        if joined or route or label or letter or word in _COMPASS_CODES:
            keep.add(s)
    return keep


def _titled(text: str) -> set[int]:
    """Where the names the readers know by their capital start (see above): their first letter is capitalised."""
    starts = {m.start() for m in _RUN.finditer(text) if m.group() in _NAMED}
    for m in _STREET.finditer(text):
        names = [w for w in re.finditer(r"[A-Z]+", m.group(1))]
        while names and names[0].group() in _NOT_NAME:
            names.pop(0)
        if names:
            starts |= {m.start(1) + w.start() for w in names} | {m.start(2)}
    makes: set[str] = set()
    for m in _MADE.finditer(text):
        for w in re.finditer(r"[A-Z][A-Z-]*", m.group(1)):
            if w.group() in _COMMON:
                break
            starts.add(m.start(1) + w.start())
            makes.add(w.group())
    # the same make or model named again ("THE HONDA", "THE FORD ESCAPE"): the same name
    if makes:
        said = "|".join(sorted(map(re.escape, makes), key=len, reverse=True))
        for m in re.finditer(r"\bTHE ((?:(?:" + said + r")\b ?){1,2})", text):
            starts |= {m.start(1) + w.start() for w in re.finditer(r"[A-Z][A-Z-]*", m.group(1))}
    return starts
