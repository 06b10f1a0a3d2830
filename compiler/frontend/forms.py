"""Police forms' abbreviations in a narrative, written out: "RT LN" is the right lane, "INTX" the intersection,
"OPP DIR" the opposite direction, "FTYROW" failed to yield the right of way, "EBL" the eastbound lane, "VEH"
a vehicle, "PED" a pedestrian, "DRV" a driver, "APPROX" approximately.

Each is written out only where it can mean nothing else: a word of its own, and for the short ones that are
other words too ("RT 9" is a route, "LT. SMITH" a lieutenant, "Elm Ln" a street) only beside the words it goes
with ("RT TURN", "TURNED LT", "THE LEFT LN", "LN 2", "OPP DIR"). A full stop after one is dropped only inside a
sentence (before a word in lower case or a number), so sentences still end where they did.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from sovarc.compiler.frontend.sentences import opens_sentence

_STOP = r"(?:\.(?=\s+(?-i:[a-z0-9])))?"  # an abbreviation's full stop inside a sentence


def _said(token: str, word: str, first: bool) -> str:
    """The word in the token's case: "Rt" -> "Right", "RT" or "rt" -> "right"; a sentence's `first` word in
    capitals ("DRV 1 STATED ...") is capitalised as the sentence's first word is."""
    titled = token[:1].isupper() and (token[1:2].islower() or first)
    return word[0].upper() + word[1:] if titled else word


def _sub(pattern: str, word: Callable[[re.Match[str]], str], flags: int = re.I) -> Callable[[str], str]:
    """A rule writing out the abbreviation the pattern's group `ab` matches (its other words stay)."""
    compiled = re.compile(pattern, flags)

    def one(m: re.Match[str]) -> str:
        s, e = m.start("ab") - m.start(), m.end("ab") - m.start()
        return m.group()[:s] + _said(m["ab"], word(m), opens_sentence(m.string, m.start("ab"))) + m.group()[e:]

    return lambda text: compiled.sub(one, text)


_SIDE = {"rt": "right", "lt": "left"}
_POINT = {"N": "north", "S": "south", "E": "east", "W": "west"}
_LANE_BEFORE = (
    r"\b(?:left|right|rt|lt|turn|travel|through|thru|center|centre|middle|inside|outside|curb|passing|same|"
    r"adjacent|wrong|opposing|other|bike|parking|the|his|her|its|their|first|second|third|fourth|northbound|"
    r"southbound|eastbound|westbound) "
)
_DIRECTION_BEFORE = (
    r"\b(?:opp|opposite|same|other|the|an?|his|her|its|their|one|each|either|northbound|southbound|eastbound|"
    r"westbound|north|south|east|west|[NSEW]|northerly|southerly|easterly|westerly) "
)
_SIDE_AFTER = (
    r"\s+(?:turn\w*|lanes?|lns?|side|front|rear|shoulder|hand|curb|edge|of|corner|quarter|door|fender|bumper)\b"
)
_SIDE_BEFORE = r"\b(?:turn|turned|turning|turns|veered|veering|swerved|swerving|steered|steering|to|the|a) "
_SIDE_WORD = r"(?P<ab>\b(?P<side>rt|lt)\b" + _STOP + r")(?!\s*#?\s*\d)"

# Police narratives' abbreviations with their full stops inside a sentence: "Veh. #1", "VEH 2", "approx. 30 mph".
_VEH_NUMBERED = re.compile(r"\b([Vv])(?:eh|EH)\.?(?=\s*(?:#|no\.)?\s*\d(?![\w-]))")
_APPROX_STOP = re.compile(r"\b([Aa])pprox\.(?!\w)")

_RULES: tuple[Callable[[str], str], ...] = (
    lambda text: _VEH_NUMBERED.sub(r"\1ehicle", text),
    lambda text: _APPROX_STOP.sub(r"\1pproximately", text),
    # "FTYROW", "FTY": the code for the driver's error the narrative names
    _sub(r"(?P<ab>\bFTYROW\b)", lambda m: "failed to yield the right of way"),
    _sub(r"(?P<ab>\bFTY\b)", lambda m: "failed to yield"),
    # "EBL": the eastbound lane, in capitals only (in lower case it is no code)
    _sub(r"(?P<ab>\b(?P<p>[NSEW])BL\b)", lambda m: f"{_POINT[m['p']]}bound lane", 0),
    _sub(r"(?P<ab>\b(?:intx|intxn|intersec|inters|inter)\b" + _STOP + r")(?!-)", lambda m: "intersection"),
    _sub(r"(?P<ab>\bopp\b" + _STOP + r")(?!-)", lambda m: "opposite"),
    _sub(_DIRECTION_BEFORE + r"(?P<ab>\bdir\b" + _STOP + r")(?![\w-])", lambda m: "direction"),
    # "RT TURN", "RT SIDE", "TURNED LT" (not "RT 9", a route)
    _sub(_SIDE_WORD + r"(?=" + _SIDE_AFTER + r")", lambda m: _SIDE[m["side"].lower()]),
    _sub(_SIDE_BEFORE + _SIDE_WORD + r"(?![\w-])", lambda m: _SIDE[m["side"].lower()]),
    # "THE LEFT LN", "LN 2", "BOTH LNS"
    _sub(_LANE_BEFORE + r"(?P<ab>\bln(?P<s>s?)\b" + _STOP + r")(?![\w-])", lambda m: "lane" + m["s"].lower()),
    _sub(r"(?P<ab>\bln(?P<s>s?)\b" + _STOP + r")(?=\s*#?\s*\d)", lambda m: "lane" + m["s"].lower()),
    # a vehicle, a pedestrian and a driver unnumbered ("THE VEH", "BOTH VEHS", "THE PED", "DRV 1 STATED")
    _sub(r"(?P<ab>\bveh(?P<s>s?)\b" + _STOP + r")(?![\w-])", lambda m: "vehicle" + m["s"].lower()),
    _sub(r"(?P<ab>\bped(?P<s>s?)\b" + _STOP + r")(?![\w-])", lambda m: "pedestrian" + m["s"].lower()),
    _sub(r"(?P<ab>\bdrvr?\b" + _STOP + r")(?![\w-])", lambda m: "driver"),
    # "APPROX 30 MPH": without its full stop ("approx." with its stop: the rules at the top)
    _sub(r"(?P<ab>\bapprox\b)(?![.\w-])", lambda m: "approximately"),
)


def police_forms(text: str) -> str:
    """The narrative with police forms' abbreviations written out (see above)."""
    for rule in _RULES:
        text = rule(text)
    return text
