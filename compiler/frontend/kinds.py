"""What kind of road user each vehicle is, from the words the report names it by.

English names a road user's kind with a small closed set of head nouns (a pickup, a box truck, a city bus,
a moped, a cyclist) after any number of modifiers (make, model, year, colour). The kind is read from the
head: the last such noun in the words that name the vehicle. Two places say those words:
- an appositive or a copula after its number: "V2, a 2004 Ford F-150 pickup, ...", "V1 was a Honda
  motorcycle", "V2 (a 2010 Blue Bird school bus)";
- the words a report without numbers first named it by ("a passenger car", "a cyclist", "the Aurora truck"),
  which `names.parties` returns.
A make and model alone ("a 2003 Honda Accord") do not say the kind: it stays unknown (staged as a car).
"""

from __future__ import annotations

import re

from sovarc.dsl.ir import VehicleKind

# Each kind's head nouns. Where one noun phrase could match two ("pickup truck", "motor scooter", "dirt
# bike"), the longer, more specific match wins: see `kind_named`.
_HEADS: tuple[tuple[VehicleKind, str], ...] = (
    (VehicleKind.PICKUP, r"pick-?ups?(?: trucks?)?"),
    (VehicleKind.MOTORCYCLE, r"motorcycl\w*|motorbikes?|mopeds?|motor ?scooters?|dirt bikes?|motorized bicycles?"),
    (
        VehicleKind.BICYCLE,
        r"(?:pedal|bi)?cyclists?|bicycl\w*|e-?bikes?|bikes?|(?:e-|electric |kick |stand-up )?scooter(?:ist)?s?",
    ),
    (VehicleKind.BUS, r"(?:school |city |transit |shuttle |charter |passenger )?bus(?:es)?|motor ?coach(?:es)?"),
    (
        VehicleKind.TRUCK,
        r"(?:box|heavy|semi|dump|garbage|refuse|tow|delivery|cement|fire|utility|flatbed|tank|tanker|straight) "
        r"trucks?|semi(?:-?trucks?|-trailers?|s)?|tractor[- ]trailers?|18-wheelers?|tractor trucks?|trucks?",
    ),
    (VehicleKind.VAN, r"(?:mini|cargo |passenger |delivery )?vans?"),
    (
        VehicleKind.CAR,
        r"passenger (?:cars?|vehicles?)|sedans?|coupes?|hatchbacks?|station wagons?|wagons?|convertibles?|suvs?"
        r"|sport utility vehicles?|crossovers?|jeeps?|taxis?|taxicabs?|limousines?|cars?",
    ),
)
_HEAD = [(kind, re.compile(r"\b(?:" + pattern + r")\b(?![\w-])", re.I)) for kind, pattern in _HEADS]
# "V2, a 2004 Ford F-150 pickup", "V1 was a 2-door Honda motorcycle", "V2 (a 2010 Blue Bird school bus)": the
# words after the number up to where the phrase ends (punctuation, a relative pronoun or a verb of its own).
# (an aside in brackets describes as one between commas: "(a 1998 Ford Taurus)", "( a van )")
_APPOSITIVE = re.compile(r"\b(V\d)(?:, |\s*\(\s*| was | is |,? which was )(?:(?:an?|the|one) )?")
_PHRASE_END = re.compile(
    r"[,.;:()]|\b(?:that|which|who|was|were|is|driven|operated|traveling|travelling|with|and)\b", re.I
)
_PHRASE_WORDS = 8


def kind_named(words: str) -> tuple[VehicleKind, int, int] | None:
    """The kind the words name and where its noun is in them: the match that ends last (the head of the
    phrase), the longest there."""
    found = [(m.end(), m.end() - m.start(), kind, m.start()) for kind, head in _HEAD for m in head.finditer(words)]
    if not found:
        return None
    end, _, kind, start = max(found, key=lambda f: (f[0], f[1]))
    return kind, start, end


def stated_kinds(named: str, words: dict[str, str]) -> dict[str, tuple[VehicleKind, tuple[int, int] | None]]:
    """Each vehicle's kind and the span of its noun in the named text: from an appositive there, else from
    the words it was first named by (`words`, from `names.parties`; no span, as the named text has its number
    where those words were)."""
    kinds: dict[str, tuple[VehicleKind, tuple[int, int] | None]] = {}
    for m in _APPOSITIVE.finditer(named):
        pid = m.group(1)
        rest = named[m.end() :]
        cut = _PHRASE_END.search(rest)
        phrase = " ".join(rest[: cut.start() if cut else len(rest)].split()[:_PHRASE_WORDS])
        if pid in kinds or (found := kind_named(phrase)) is None:
            continue
        kind, start, end = found
        offset = m.end() + rest.index(phrase)
        kinds[pid] = (kind, (offset + start, offset + end))
    for pid, said in words.items():
        if pid.startswith("V") and pid not in kinds and (found := kind_named(said)) is not None:
            kinds[pid] = (found[0], None)
    return kinds


# A kind English also calls by a wider one: a pickup is "the truck" too ("a pick-up truck ... the oncoming truck").
_WIDER = {VehicleKind.PICKUP: VehicleKind.TRUCK}


def said_kind(words: str, said: list[str]) -> str:
    """The words a road user was named by (`words`), with the noun that says its kind when another phrase the
    report calls it by (`said`) says it better. A later mention often names no kind, or a wider one ("a passenger
    vehicle ... The vehicle made contact", "a pick-up truck ... the oncoming truck"): the phrases that name one say
    it, when they agree (a pickup and "the truck" agree, as a pickup). The noun is added in brackets ("the
    oncoming truck (pick-up truck)"), so what `words` say of the road user besides ("oncoming") stays said."""
    named = [(found[0], phrase[found[1] : found[2]]) for phrase in (words, *said) if (found := kind_named(phrase))]
    kinds = {kind for kind, _ in named}
    kinds -= {_WIDER[kind] for kind in kinds if _WIDER.get(kind) in kinds}
    own = kind_named(words)
    if len(kinds) != 1 or (own is not None and own[0] in kinds):
        return words
    return f"{words} ({next(noun for kind, noun in named if kind in kinds)})"
