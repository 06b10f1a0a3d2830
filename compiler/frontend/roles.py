"""Road users named by their part in the telling, not by number: the narrator, the insured, the claimant, a make.

An insurer's description, a driver's own statement or a crash database's summary names the road users by role:
the narrator ("I was driving east", "my front hit", "in front of me"), the insurer's client ("our insured", "the
insured vehicle", "IV") and the party claiming against it ("the claimant vehicle", "CV", "the other vehicle",
"OV"). The narrator's vehicle, or the insured's, is the one the account is told from: V1 (`narrator`). The
claimant's is the other party of the crash, said as "the other vehicle" and "the other driver" (`partner`), which
`names` numbers with the other road users of the first impact. A road user may also be named by its make ("the
Toyota", "a southbound Ford pickup"): `MAKE` finds those, as `names._USER` finds kinds.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.sentences import opens_sentence

# The nouns a road user's own vehicle is said with: "my car", "the insured's pickup truck", "her SUV".
_OWN = r"(?:vehicle|car|auto|automobile|truck|pickup(?: truck)?|van|minivan|suv|sedan|motorcycle|jeep)"

# The insured's vehicle and the insured, said before the narrator's words (an adjuster writes "our insured", not
# "I", for the client): longest first.
_INSURED_VEHICLE = re.compile(r"\b(?:(?:our|the) )?insured(?:'s)? (?:(?:driver|party)'s )?" + _OWN + r"\b", re.I)
_INSURED_VEHICLE_CASED = re.compile(r"\b(?:the )?IV\b(?!-)")  # (an acronym: "iv" is no vehicle)
_INSURED_OWN = re.compile(r"\b(?:our|the) insured(?: driver| party)?'s\b", re.I)  # "our insured's phone"
_INSURED = re.compile(r"\b(?:our|the) insured(?: driver| party)?\b(?![\w-])", re.I)

# The narrator: "I" (not "I-95", a road), "me", "my" and "myself" (not in capitals: "ME" is a medical examiner).
_I = re.compile(r"\bI\b(?![-.]?\d)(?!-)")
_MY_VEHICLE = re.compile(r"\b[Mm]y (?:own )?(?i:" + _OWN + r")\b")
_MY = re.compile(r"\b[Mm]y\b")
_ME = re.compile(r"\b(?:[Mm]e|[Mm]yself)\b")
# The other party's vehicle in a first-person account: the narrator says "my car", so "her car" is the other's.
_THEIR_VEHICLE = re.compile(r"\b(?:his|her|their) " + _OWN + r"\b", re.I)

# The party claiming against the insured, and the other party however an account says it.
_CLAIMANT_VEHICLE = re.compile(
    r"\b(?:the |a )?(?:claimant|other party)(?:'s)? (?:(?:driver|party)'s )?" + _OWN + r"\b"
    r"|\b(?:the )?other driver's " + _OWN + r"\b",
    re.I,
)
_CLAIMANT_VEHICLE_CASED = re.compile(r"\b(?:the )?(?:CV|OV)\b(?!-)")
_CLAIMANT = re.compile(r"\b(?:the )?(?:claimant|other party)(?: driver)?\b(?![\w-])", re.I)


def _sub(pattern: re.Pattern[str], words: str, text: str) -> str:
    """Each match as `words`, capitalised where it opens a sentence."""
    return pattern.sub(lambda m: words[0].upper() + words[1:] if opens_sentence(text, m.start()) else words, text)


def narrator(text: str) -> tuple[str, str] | None:
    """The text with the insured's or the narrator's vehicle as V1 (the insured as "the driver of V1", the
    narrator's "I" as V1), and the words first said for it; None when the report has neither."""
    insured = _INSURED_VEHICLE.search(text) or _INSURED_VEHICLE_CASED.search(text) or _INSURED.search(text)
    if insured is not None:
        text = _sub(_INSURED_VEHICLE, "V1", text)
        text = _sub(_INSURED_VEHICLE_CASED, "V1", text)
        text = _sub(_INSURED_OWN, "V1's", text)
        return _sub(_INSURED, "the driver of V1", text), insured.group()
    said = _MY_VEHICLE.search(text) or _I.search(text)
    if said is None:
        return None
    text = _sub(_THEIR_VEHICLE, "the other vehicle", text)
    text = _sub(_MY_VEHICLE, "V1", text)
    text = _sub(_MY, "V1's", text)
    text = _sub(_ME, "V1", text)
    # "I" as "V1", word for word (the clause reader takes the driver's clause as the vehicle's), so that the
    # evidence aligns each word with the report's
    text = _sub(_I, "V1", text)
    return text, said.group()


def partner(text: str) -> str:
    """The claimant and the other party, in whatever words, as "the other vehicle" and "the other driver"."""
    text = _sub(_CLAIMANT_VEHICLE, "the other vehicle", text)
    text = _sub(_CLAIMANT_VEHICLE_CASED, "the other vehicle", text)
    return _sub(_CLAIMANT, "the other driver", text)


# Makes a road user is named by ("the Toyota", "a 1998 Ford Taurus", "a southbound Ford pickup"). A make names a
# vehicle only as a noun phrase's head or before its model, so a capitalised word that is not one (a street's name,
# "the Interstate") is never taken for a road user.
MAKES = (
    "Acura|Audi|BMW|Buick|Cadillac|Chevrolet|Chevy|Chrysler|Dodge|Fiat|Ford|Freightliner|GMC|Harley-Davidson|Harley|"
    "Honda|Hummer|Hyundai|Infiniti|Infinity|International|Isuzu|Jaguar|Jeep|Kawasaki|Kenworth|Kia|Land Rover|Lexus|"
    "Lincoln|Mack|Mazda|Mercedes-Benz|Mercedes|Mercury|Mini|Mitsubishi|Nissan|Oldsmobile|Peterbilt|Plymouth|Pontiac|"
    "Porsche|Ram|Saab|Saturn|Scion|Subaru|Suzuki|Tesla|Toyota|Volkswagen|VW|Volvo|Yamaha"
)


def bare(words: str) -> str:
    """Where `words` (a pattern) open a sentence without an article, as police and dispatch notes write a road
    user ("Motorcycle was northbound", "Honda struck the sedan"): capitalised, and followed by a lower-case word
    or a stop, so that neither a label ("Vehicle one", "Car A") nor a name ("Van Ness Avenue") is taken for one."""
    return (
        r"(?:(?<![\s\S])|(?<=[.!?;] )|(?<=[.!?]  )|(?<=\n))(?-i:(?=[A-Z][a-z]|SUVs?\b))"
        r"(?=(?i:" + words + r")s?(?![\w-])(?:[,.;]|$|\s+(?!(?i:one|two|three|four|five|six)\b)(?-i:[a-z])))"
    )


# Makes that are words or names too ("International", "Mini", "Lincoln"): only with an article.
BARE_MAKES = "|".join(
    m
    for m in MAKES.split("|")
    if m not in ("International", "Mini", "Ram", "Mercury", "Saturn", "Jaguar", "Lincoln", "Mack", "Infinity")
)
# (words before the make: a year, a colour, a heading, "parked and unoccupied"; after it, the model's capitalised or
# numbered words; or the make alone opening a sentence: see `bare`)
MAKE = re.compile(
    r"(?:\b(?:[Aa]n?|[Tt]he|[Aa]nother)\s+(?:(?!(?:of|the|a|an|or|was|were|is)\b)[\w.'-]+\s+){0,4}?|"
    + bare(BARE_MAKES)
    + r")(?P<make>"
    + MAKES
    + r")(?P<model>(?:[- ](?:[A-Z0-9][\w.-]*))*)\b(?![\w-])"
)
