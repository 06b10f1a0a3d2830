"""Participants named any way: reports that do not number their road users get numbers by a stated rule.

A report that labels its parties ("a Zoox vehicle (Vehicle 1)", "a passenger car (V2)") keeps its labels:
the phrase a label follows names that party from then on. A report that neither numbers nor labels them
(NHTSA's SGO narratives: "the Waymo AV", "a passenger car", "the SUV") is numbered by rule: the automated
vehicle is V1; the other road users the first impact sentence names are V2, V3, ... in the order it names
them (when it names none besides V1, the last one named before it), and every later mention of one ("the
passenger car", "the car", "the other vehicle") is it. Road users the impact does not involve stay unnamed:
a bystander is no party. `label_parties` returns the rewritten text and a note saying which rule was used,
for the scenario's notes.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.antecedent import name_antecedent
from sovarc.compiler.frontend.kinds import kind_named, said_kind
from sovarc.compiler.frontend.lexicon import BEFORE_OBJECT, INTO_ANYTHING, MEETING_NOUNS, stems
from sovarc.compiler.frontend.overview import SUMMARY, name_overview, overview_users
from sovarc.compiler.frontend.roles import BARE_MAKES, MAKE, MAKES, bare, narrator, partner
from sovarc.compiler.frontend.sentences import narrative_start, sentences
from sovarc.compiler.frontend.words import PLACE_WORDS

# Words that qualify a road user without being one: "a dark colored Nissan passenger car".
_STOP = r"(?!(?:of|the|a|an|and|or|with|to|in|on|at|by|from|for|that|which|who|was|were|is|it|its)\b)"
_MODS = r"(?:" + _STOP + r"[\w.'-]+\s+){0,3}?"  # (a line may break inside the phrase)
# Road users by kind, longest first (kinds.py says which vehicle kind each is; a cyclist is a vehicle): the body
# words kinds.py knows ("a crossover", "a semi", "an e-bike"), and vehicles of a trade ("an ambulance").
_KINDS = (
    r"passenger car|passenger vehicle|pick-?up truck|box truck|heavy truck|semi-truck|semi truck|"
    r"tractor[- ]trailer|semi-trailer|18-wheeler|school bus|station wagon|"
    r"motor coach|sport utility vehicle|pickup|minivan|van|suv|sedan|hatchback|coupe|wagon|truck|bus|"
    r"taxicab|taxi|convertible|limousine|ambulance|crossover|jeep|semi|"
    r"motorcycle|motorcyclist|motorbike|moped|scooter|car|vehicle|pedestrian|bicyclist|cyclist|pedalcyclist|"
    r"bicycle|e-?bike|bike"
)
_PEOPLE = frozenset(("pedestrian",))
_PEDESTRIAN = re.compile(r"\bpedestrian\b", re.I)
# Words introducing a road user that say something of it: its model year, its course ("a westbound SUV").
_DESCRIBED = re.compile(r"\b(?:19|20)\d\d\b|\b(?:north|south|east|west) ?bound\b", re.I)
# A kind's noun that modifies another names a place or a thing, not a road user: "the bike lane", "a bus stop".
_NOT_USER = r"(?! (?:lanes?|paths?|routes?|stops?|shelters?|stations?|racks?|wash|park|parking|share|corrals?)\b)"
# A kind's noun opening a sentence without an article, as police and dispatch notes write ("Motorcycle was
# northbound", "Pickup turned left"): that road user, as "the motorcycle" is (see `roles.bare`).
BARE = bare(_KINDS)
_USER = re.compile(
    r"(?:\b(?:an?|the|another|one)\s+" + _MODS + r"|" + BARE + r")(" + _KINDS + r")s?\b(?![\w-])" + _NOT_USER,
    re.I,
)
_OTHER = re.compile(r"\bthe other (?:vehicle|car|party|road user|motorist|driver)\b", re.I)

# The automated vehicle: "a Waymo Autonomous Vehicle", "the Waymo AV", "the Cruise AV", "the ADS vehicle",
# "the test vehicle", "our vehicle", "the ego", "the subject vehicle".
_AV_WORDS = (
    r"(?:autonomous|automated|self-driving|driverless|ADS(?:[- ]equipped|[- ]operated|[- ]engaged)?|test|subject|"
    r"ego) (?:vehicle|car|truck|shuttle|bus)|AV|ego(?: vehicle)?|robotaxi"
)
_NOT_BRAND = r"(?!(?:The|A|An|When|While|As|Then|And|But|After|Before|At|On|In|Our|Its)\b)"
_AV = re.compile(
    r"\b(?:(?i:a|an|the|our|its) )?(?:" + _NOT_BRAND + r"[A-Z][\w.]*(?:[- ][A-Z][\w.]*)? )?(?i:" + _AV_WORDS + r")"
    r"\b(?![\w-])|\b(?i:our) (?:vehicle|car|truck|shuttle)\b"
)
# "A Zoox vehicle in autonomous mode", "an Aurora truck ... in autonomy": a brand's vehicle, when the report
# says its vehicle drove itself, or was driven in manual mode (a mode only an automated vehicle has).
# (the maker and the kind may come first: "a Local Motors electric Olli shuttle", the model's name before the noun)
_BRAND = re.compile(
    r"\b(?i:an?|the)(?: subject| test| [\w-]+(?: [\w-]+){0,2}?)?? ([A-Z][\w.-]+(?: [A-Z][\w.-]+)?) "
    r"(vehicle|truck|shuttle|car|bus)\b"
)
# A shuttle's fleet number said beside it ("the shuttle (P139)", "the second shuttle on the route, P131,"): the
# operator's name for that one shuttle, a letter or two and its number.
_FLEET_NUMBER = re.compile(r"\bshuttle\b[^.,;()]{0,40}?(?:, |\s*\(\s*)([A-Z]{1,2}\d{2,4})\b(?=\s*[,)])")
# Heads that, with "the", point back to the automated vehicle said with them ("a Navya ARMA shuttle ... the
# shuttle"), unless the report brings in another of its kind ("a pickup truck"). Not "vehicle" or "car": a
# narrative calls any road user that.
_OWN_HEADS = ("shuttle", "truck", "bus")
# Nouns a brand qualifies when it is not the vehicle: "the Zoox fleet", "the Waymo operator".
_BRAND_OF = (
    r"vehicles?|cars?|trucks?|shuttles?|bus(?:es)?|fleet|system|software|drivers?|operators?|employees?|staff|team"
    r"|technicians?|dealer\w*|depot|facility|app|rider|passengers?|specialists?|personnel"
)
_AUTONOMY = re.compile(r"\bautonom|\bADS\b|\bself-driving\b|\bdriverless\b|\bautomated driving\b|\bmanual mode\b", re.I)
# A fleet's name before a car's model, in a sentence saying it drove itself or was in manual mode ("a Nuro Prius
# operating in manual mode", "the Waymo Pacifica was in autonomous mode"): the automated vehicle, named as `_BRAND`
# names it, the model standing for the noun. A carmaker's name before its model is a car ("a Toyota Prius").
_FLEET_MODEL = re.compile(
    r"\b(?i:an?|the) (?!(?:" + MAKES + r")\b)([A-Z][\w.-]+) ([A-Z][a-z][\w-]*)\b(?![\w-])"
    r"(?=[^.]*(?i:" + _AUTONOMY.pattern + r"))"
)

# "(Vehicle 1)", "(V2)", "("Vehicle #1")"
_LABEL = re.compile(r"\s*\(\s*[\"']?(?:vehicle|v|unit)\s*[-#]?\s*(?:no\.?\s*)?(\d)[\"']?\s*\)", re.I)
_LABELLED = re.compile(r"\b(?:(?:an?|the|our) )?(" + _MODS + r"[\w.'-]+)" + _LABEL.pattern, re.I)
# ("the contact area", "the point of impact area": a place on a body, the name of a form's field, not a meeting)
# (not "a collision": a summary's, `overview.SUMMARY`, read only where no sentence says how the parties met)
_IMPACT = re.compile(r"\b(?:" + stems(MEETING_NOUNS) + "|" + INTO_ANYTHING + r")\b", re.I)
# The colours a road user is told apart by ("a white sedan" and "a black sedan" are two).
COLOUR = re.compile(
    r"\b(?:white|black|silver|gr[ae]y|red|blue|green|yellow|orange|brown|gold|tan|beige|maroon|purple)\b", re.I
)
_OCCURRED = re.compile(r"\b(?:collision|crash|impact) (?:\w+ )?(?:occurred|happened|took place)\b", re.I)
# Things a vehicle can hit that the IR has no role for.
THING = re.compile(
    r"\b(?:an?|the) " + _MODS + r"(animal|dog|cat|deer|bird|pole|tree|bollard|curb|barrier|debris|tire shreds|"
    r"cone|gate|sign|fence|wall|hydrant|pothole|shopping cart|object)s?\b",
    re.I,
)


def _replace_phrase(
    text: str, phrase: str, pid: str, introduced: bool = False, said: list[str] | None = None, colour: str = ""
) -> str:
    """Every mention of a party by its words ("the blue SUV", "a SUV", "the SUV's") as its id; a make with the
    model and kind said after it ("the Ford Taurus sedan"). `introduced`: not the words of an introduction kept
    beside the id ("V2, a 1994 Ford Taurus,"). `said` collects the words replaced. `colour`: the party's, which
    tells it apart from another of its kind said with another ("a black sedan" is not "the white sedan")."""

    def put(m: re.Match[str]) -> str:
        if colour and (other := COLOUR.search(m.group())) and other.group().lower() != colour:
            return m.group()
        if said is not None:
            said.append(m.group())
        return pid

    after = r"(?-i:(?:[- ][A-Z0-9][\w.-]*)*)(?:\s+(?:" + _KINDS + r"))?" if phrase[:1].isupper() else ""
    return re.sub(
        (r"(?<![VP]\d, )" if introduced else "")
        + r"(?:\b(?:an?|the|another|that|this)\s+"
        + (_MODS.replace(".", "") if introduced else _MODS)  # (not across a sentence run on: "direction.The")
        # (a bare kind or make, as a police or dispatch note writes it: in reports numbered by the first-named rule
        # only; an automated vehicle's operator does not write so, and SGO's held-out scoring dropped with it)
        + (r"|" + bare(re.escape(phrase)) if introduced else "")
        + r")"
        + r"\s+".join(map(re.escape, phrase.split()))  # (a line may break inside it: "passenger\nvehicle")
        + after
        + r"\b(?![\w-])"
        + _NOT_USER,
        put,
        text,
        flags=re.I,
    )


def _labels(text: str) -> tuple[str, str, dict[str, str]] | None:
    """The report's own labels: "a Zoox vehicle (Vehicle 1)" names V1 "the Zoox vehicle" from then on."""
    found = [m for m in _LABELLED.finditer(text) if not re.fullmatch(r"[VP]\d", m.group(1))]
    if not found:
        return None
    words: dict[str, str] = {}
    for m in found:
        phrase = m.group(1).strip()
        pid = f"V{m.group(2)}"
        if phrase.lower().split()[-1] in _PEOPLE:
            pid = f"P{m.group(2)}"
        words.setdefault(phrase.lower(), pid)
        words.setdefault(phrase.lower().split()[-1], pid)
    text = _LABELLED.sub(lambda m: f"{'P' if m.group(1).lower().split()[-1] in _PEOPLE else 'V'}{m.group(2)}", text)
    heads: dict[str, set[str]] = {}
    for phrase, pid in words.items():
        heads.setdefault(phrase, set()).add(pid)
    for phrase in sorted(heads, key=len, reverse=True):
        if len(heads[phrase]) == 1 and not re.fullmatch(r"vehicle|car", phrase):
            text = _replace_phrase(text, phrase, next(iter(heads[phrase])))
    named = ", ".join(f"{pid} '{p}'" for p, pid in sorted(words.items(), key=lambda kv: kv[1]))
    said: dict[str, str] = {}
    for phrase, pid in words.items():
        if len(phrase) > len(said.get(pid, "")):
            said[pid] = phrase  # the longest words for each: "passenger car", not "car"
    return text, f"participants named by the report's own labels ({named})", said


def _automated(text: str) -> tuple[str, str] | None:
    """Every mention of the automated vehicle as V1, and the words first used for it."""
    first = _AV.search(text)
    brand = _BRAND.search(text) if _AUTONOMY.search(text) else None
    if brand is None and first is None:
        brand = _FLEET_MODEL.search(text)
    if first is None and brand is None:
        return None
    numbers = [m.group(1) for m in _FLEET_NUMBER.finditer(text)]
    if first is not None:
        said = first.group()
        # "the Waymo AVs lane": a possessive written without its apostrophe
        text = re.sub(r"\b((?i:the) (?:[A-Z][\w.]* )?AV)s\b(?= (?!(?:were|are|have|had)\b)[a-z])", r"\1's", text)
        text = _AV.sub("V1", text)
        # the brand alone names it too once it has been said with it: "the Waymo was stopped", "the Waymo's"
        if (b := re.match(r"(?:(?i:an?|the|our|its) )?([A-Z][\w.-]*) ", said)) and not re.match(_AV_WORDS, b[1], re.I):
            text = re.sub(
                r"\b[Tt]he " + re.escape(b[1]) + r"\b(?![\w-])(?! (?:[A-Z]|vehicle|car|truck|shuttle|bus|fleet)\b)",
                "V1",
                text,
            )
        text = re.sub(r"\b(?:an?|the) [A-Z][\w.]* (?:vehicle|car|truck|shuttle)\b(?=\s*\(\"?V1\"?\))", "V1", text)
    if brand is not None and (first is None or brand.start() < first.start() or brand.group(1) in said):
        said = brand.group() if first is None else said
        # with whatever words qualify it: "a stopped Zoox vehicle", "the unoccupied Zoox vehicle"
        text = re.sub(
            r"\b(?i:an?|the)(?: [a-z][\w-]*){0,2}? " + re.escape(f"{brand.group(1)} {brand.group(2)}") + r"\b",
            "V1",
            text,
        )
        # and the brand alone, once said with it: "the Mercedes-Benz vehicle ... the Mercedes-Benz", whatever
        # word follows ("the rear of the Mercedes-Benz approximately 10 seconds later"), unless it is a noun the
        # brand qualifies ("the Zoox fleet", "the Zoox operator") or a model's name
        text = re.sub(
            r"\b[Tt]he " + re.escape(brand.group(1)) + r"\b(?![\w-])(?! (?:[A-Z][\w-]*|" + _BRAND_OF + r")\b)",
            "V1",
            text,
        )
    text = _said_again(text, said, numbers)
    text = re.sub(r"\bV1(?:'s)? \(\s*[\"']?V1[\"']?\s*\)", "V1", text)  # 'a Waymo Autonomous Vehicle ("Waymo AV")'
    return text, said


def _said_again(text: str, said: str, numbers: list[str]) -> str:
    """The automated vehicle said again by its fleet number (`numbers`, read before it was renamed), or by the
    head noun it was introduced with (see `_FLEET_NUMBER`, `_OWN_HEADS`)."""
    for number in dict.fromkeys(numbers) if "shuttle" in said.lower() else ():  # (a bus's may be its route's)
        text = re.sub(r"\b" + number + r"\b", "V1", text)
    head = said.split()[-1].lower() if said.split() else ""
    # (another of its kind, said with any words before the head: "a pickup truck", "a semi-truck")
    if head in _OWN_HEADS and not re.search(r"\b(?:an?|another|one) [^.,;]{0,40}?\b" + head + r"s?\b", text, re.I):
        text = re.sub(r"\b[Tt]he " + head + r"\b(?![\w-])(?!'s? (?:[a-z]+ )?(?:driver|operator))", "V1", text)
    return text


# Kinds said two ways of one road user: "a passenger car" is later "the passenger vehicle", "a pickup truck" "the
# pickup"; a cyclist is later "the bicycle" it rides, a motorcycle "the motorcyclist" who rides it (the IR holds
# the rider and what they ride as one vehicle).
_SAME = {
    "passenger vehicle": "passenger car",
    "pick-up truck": "pickup truck",
    "pickup": "pickup truck",
    "motorcyclist": "motorcycle",
    "sport utility vehicle": "suv",
    "bicycle": "cyclist",
    "bicyclist": "cyclist",
    "pedalcyclist": "cyclist",
}
_SCENE_CLAUSE = re.compile(r"^(?:After|As|While|When|Before|Once|Just after|Following)\b[^,]*, ", re.I)


# A road user introduced by its make, as what a strike met or was made by: "by a red Toyota", "struck a Honda
# Civic" (capitalised and not an acronym, which would be a system's name: "an ADS").
_MAKE = re.compile(
    # (or as the subject of a clause: "At this time, a Chevrolet Camaro ... reversed")
    r"(?:\b(?:by|" + BEFORE_OBJECT + r"|with|into|when|as|while)\s+|^|[,;]\s+)"
    r"(?P<words>(?:[Aa]n?|[Aa]nother)\s+"
    # (its model year before it too: "a 2015 Honda Civic")
    r"(?:(?:[a-z][\w-]*|(?:19|20)\d\d)\s+){0,2}?([A-Z][\w-]*[a-z][\w-]*(?: [A-Z][\w-]*[a-z][\w-]*)?))\b"
)


def _head(m: re.Match[str]) -> str:
    return _SAME.get(m.group(1).lower(), m.group(1).lower())


# Prepositions of place: what follows says where a road user was ("behind the heavy truck", "between V1 and a
# parked car"), not who met whom.
PLACE = re.compile(r"\b(?:" + PLACE_WORDS + r"|between(?: \S+ and)?)\s+$", re.I)


def _others(text: str) -> list[tuple[str, str]]:
    """The other road users in the first impact, as (kind, words first said), in the order it names them."""
    sents = sentences(text)
    impacts = [i for i, s in enumerate(sents) if _IMPACT.search(s) and re.search(r"\bV1\b|\bit\b|\bthem\b", s)]
    impacts = [i for i in impacts if i >= narrative_start(sents)] or impacts  # (not a filing's note)
    summaries = [i for i, s in enumerate(sents) if SUMMARY.search(s) and re.search(r"\bV1\b", s)]
    # a meeting said only as a collision that happened to V1 ("Though V1 had nearly stopped, a collision still
    # occurred, causing damage to the rear of the passenger vehicle"): its other party is named there or before
    occurred = [i for i, s in enumerate(sents) if _OCCURRED.search(s) and re.search(r"\bV1\b", s)]
    for i in impacts + summaries + occurred:
        # "After the pedestrians had crossed, an SUV ... made contact": an opening clause sets the scene
        sentence = sents[i]
        if (scene := _SCENE_CLAUSE.match(sentence)) and _IMPACT.search(sentence[scene.end() :]):
            sentence = sentence[scene.end() :]
        users: list[tuple[str, str]] = []
        for m in _USER.finditer(sentence):
            if re.fullmatch(r"the vehicle", m.group(), re.I) and re.match(r"\s*(?:[.,;)]|$)", sentence[m.end() :]):
                # a bare "the vehicle" points back to a party already named (the automated vehicle, often);
                # one a phrase picks out ("the vehicle immediately behind", "the vehicle that struck") is new
                continue
            if _head(m) not in [h for h, _ in users] and not _OTHER.fullmatch(m.group()):
                users.append((_head(m), m.group()))
        # a road user that only says where another was ("traveling directly behind the heavy truck", "pass between
        # V1 and a parked passenger vehicle") is no party, when the sentence names one besides
        placed = [u for u in users if PLACE.search(sentence[: sentence.find(u[1])])]
        if users:
            return [u for u in users if u not in placed] or users
        if other := _OTHER.search(sentence):  # "the other driver made contact with V1": a vehicle, unnamed
            return [("vehicle", other.group())]
        if make := _MAKE.search(sentence):  # "struck from behind by a red Toyota": a make names a vehicle
            return [(make.group(1), make.group("words"))]
        # "A Toyota Prius was traveling north ... The Toyota Prius made contact": one a make introduced before it
        made = [m for s in sents[:i] for m in _MAKE.finditer(s) if re.search(r"\b[Tt]he " + m[2] + r"\b", sentence)]
        if made:
            return [(made[-1].group(1), made[-1].group("words"))]
        # the road user the overview names ("was in a collision involving a heavy truck"), when it names one; else
        # the last road user introduced before it: "a passenger car", not "the vehicle", which points back to one
        # already named (the automated vehicle itself, often)
        if told := overview_users(sents, _USER):
            return [(_head(told[0]), told[0].group())]
        before = [m for s in sents[:i] for m in _USER.finditer(s) if not m.group().lower().startswith("the ")]
        return [(_head(before[-1]), before[-1].group())] if before else []
    return []


def label_parties(text: str) -> tuple[str, str | None]:
    """The text with its parties numbered (see the module), and the note saying how; unchanged when the
    report numbers them itself."""
    named, note, _ = parties(text)
    return named, note


def parties(text: str) -> tuple[str, str | None, dict[str, str]]:
    """`label_parties`, and the words each party numbered here was first named by ({"V2": "a passenger car"}),
    which say what kind of road user it is."""
    if re.search(r"\bV1\b", _LABEL.sub(" ", text)):
        return text, None, {}  # numbered outside any labels: the report's own numbering
    labelled = _labels(text)
    if labelled is not None:
        if re.search(r"\bV1\b", labelled[0]):
            return labelled
        if (automated := _automated(labelled[0])) is None:
            if (told := narrator(labelled[0])) is None:
                return labelled
            # or the narrator's, the insured's: "the minivan (V2) turned in front of me"
            return told[0], f"{labelled[1]}; the {_teller(told[1])}'s vehicle ('{told[1]}') is V1", labelled[2]
        # It labels the others ("a sedan (Vehicle 2)") but not itself: the automated vehicle is V1.
        note = f"{labelled[1]}; the automated vehicle ('{automated[1]}') is V1"
        return automated[0], note, {**labelled[2], "V1": automated[1]}
    if re.search(r"\b[VP]\d\b", _LABEL.sub(" ", text)):
        # It numbers the others ("rear-ended by Vehicle #2") but not itself: the automated vehicle is V1.
        automated = _automated(text)
        if automated is None and (told := narrator(text)) is not None:
            # or the narrator's, the insured's: "V2 turned left in front of me"
            return told[0], f"participants numbered by rule: the {_teller(told[1])}'s vehicle ('{told[1]}') is V1", {}
        if automated is None:
            return text, None, {}
        note = f"participants numbered by rule: the automated vehicle ('{automated[1]}') is V1"
        return automated[0], note, {"V1": automated[1]}
    automated = _automated(text)
    if automated is None:
        return unnumbered(text) or (text, None, {})
    text, said = automated
    others = _others(text)
    text, named, words_of = _number(text, others, {"V1": said})
    text, words_of = name_overview(text, words_of, _USER)
    text, words_of = name_antecedent(text, words_of, _USER)
    note = f"participants numbered by rule: the automated vehicle ('{said}') is V1"
    if named:
        note += "; the other road users in the first impact are " + ", ".join(named)
    return text, note, words_of


_THE_OTHER = "the other"  # the kind of a party the report names only as "the other vehicle" (see `_impact_users`)


def _number(
    text: str, others: list[tuple[str, str]], words_of: dict[str, str], introduced: bool = False
) -> tuple[str, list[str], dict[str, str]]:
    """Every mention of each of `others` ((kind or make, words first said)) as its id, numbered after those in
    `words_of`; with the list of them for the note, and `words_of` with theirs. `introduced`: an introduction
    with a model year or a course keeps its words beside the id ("V2, a 1994 Ford Taurus,", "V1, a westbound SUV,"),
    as a police report says it, so that what they say is still said of it."""
    named: list[str] = []
    counts = {"V": len([p for p in words_of if p[0] == "V"]), "P": len([p for p in words_of if p[0] == "P"])}
    words_of = dict(words_of)
    for kind, words in others:
        role = "P" if kind in _PEOPLE else "V"
        counts[role] += 1
        pid = f"{role}{counts[role]}"
        named.append(f"{pid} '{words}'")
        words_of[pid] = words
        # "another SUV" is not the SUV named before it ("stopped behind an SUV that was double parked ... another
        # SUV ... made contact"): only what follows it names this one
        start = text.find(words) if words.lower().startswith("another ") else 0
        found = re.search(r"\s+".join(map(re.escape, words.split())), text)  # (a report's spacing may differ)
        if introduced and _DESCRIBED.search(words) and found is not None:
            at, end = found.span()
            words = found.group()
            said = words[0].lower() + words[1:] if not words[1:2].isupper() else words
            if other := re.search(r"\b(?i:the other vehicle), $", text[:at]):  # what "the other vehicle" was
                at, said = other.start(), f"{pid}, {said}"
            elif not re.search(r"\b[VP]\d, $", text[:at]):  # (else the report's own apposition)
                said = f"{pid}, {said}" + ("" if text[end : end + 1] in ",." else ",")
            text = text[:at] + said + text[end:]
            start = at  # (what comes before it is not this one)
        if kind == _THE_OTHER:  # named only as the other one: "the other vehicle", "the other driver"
            text = _OTHER.sub(pid, text)
            continue
        head, tail = text[: max(start, 0)], text[max(start, 0) :]
        said: list[str] = []  # every phrase that now says this party
        hue = m[0].lower() if (m := COLOUR.search(words)) else ""
        for words_for in (kind, *(k for k, canonical in _SAME.items() if canonical == kind)):
            tail = _replace_phrase(tail, words_for, pid, introduced, said, hue)
        if len(kind.split()) > 1 and not any(kind.split()[-1] == k for k, _ in others if k != kind):
            tail = _replace_phrase(tail, kind.split()[-1], pid, introduced, said, hue)  # "the car": "a passenger car"
        if (generic := _GENERIC.get(kind.lower())) and not any(_generic(k) == generic for k, _ in others if k != kind):
            tail = _replace_phrase(tail, generic, pid, introduced, said, hue)  # "the truck" for "a tractor-trailer"
        model = re.search(re.escape(kind) + r" ((?-i:[A-Z][a-z][\w-]*))\b", words) if kind[:1].isupper() else None
        if model and not any(model[1] in w for k, w in others if k != kind):
            tail = _replace_phrase(tail, model[1], pid, introduced, said, hue)  # "the Civic" for "a Honda Civic"
        text = head + tail
        # "a passenger vehicle ... The vehicle made contact": the kind its other words say (see `kinds.said_kind`)
        words_of[pid] = said_kind(words_of[pid], said)
        if role == "V" and len([k for k, _ in others if k not in _PEOPLE]) == 1:
            text = _OTHER.sub(pid, text)
    return text, named, words_of


# Kinds a report calls later by the wider kind they are one of: "a tractor-trailer" is "the truck".
_GENERIC = {"tractor-trailer": "truck", "tractor trailer": "truck", "semi-truck": "truck", "semi truck": "truck"}


def _generic(kind: str) -> str:
    return _GENERIC.get(kind.lower(), kind.lower().split()[-1])


_OF_NUMBERED = re.compile(r"\b[VP]\d,? (?:(?:was|is) )?$")


def _users_in(sentence: str) -> list[tuple[str, str, int]]:
    """The road users a sentence names, as (kind or make, words, where), in its order: by kind ("a northbound
    sedan", "the pickup"), by make ("the Toyota", "a 1998 Ford Taurus"), both ("a Ford pickup": its make)."""
    found: list[tuple[str, str, int]] = []
    makes = list(MAKE.finditer(sentence))
    users = list(_USER.finditer(sentence))

    def overlap(a: re.Match[str], b: re.Match[str]) -> bool:
        return a.start() <= b.start() < a.end() or b.start() <= a.start() < b.end()

    for k in makes:
        # with the kind said after it: "a southbound Ford pickup", "a 1998 Ford Taurus station wagon"
        kind = re.match(r"(?:\s+[a-z][\w-]*)?\s+(?:" + _KINDS + r")\b(?![\w-])", sentence[k.end() :], re.I)
        end = max([k.end() + (kind.end() if kind else 0), *(m.end() for m in users if overlap(k, m))])
        found.append((k["make"], sentence[k.start() : end], k.start()))
    for m in users:
        if any(overlap(k, m) for k in makes):
            continue  # a make's kind: the make names it
        if re.fullmatch(r"the vehicle", m.group(), re.I) or _OTHER.fullmatch(m.group()):
            continue  # a bare "the vehicle" or "the other vehicle" points back to one named
        found.append((_head(m), m.group(), m.start()))
    # (not what a numbered party is said to be: "V1, a 1999 Dodge Caravan,", "V1 was a 1999 Dodge Caravan")
    return sorted((f for f in found if not _OF_NUMBERED.search(sentence[: f[2]])), key=lambda f: f[2])


def _impact_users(text: str, v1: bool) -> list[tuple[str, str]] | str:
    """The road users in the first impact, as (kind or make, words first said), in the order the report first
    names them (V1 apart when `v1`: then the impact is the first sentence that names it); or, when two of them
    are named alike ("a Toyota ... another Toyota"), those words."""
    sents = sentences(text)
    start = narrative_start(sents)
    for i in range(start, len(sents)):
        sentence = sents[i]
        if (scene := _SCENE_CLAUSE.match(sentence)) and _IMPACT.search(sentence[scene.end() :]):
            sentence = sentence[scene.end() :]
        if not _IMPACT.search(sentence) or (v1 and not re.search(r"\b(?:V1|it|them|he|she)\b", sentence)):
            continue
        users: list[tuple[str, str]] = []
        for kind, words, _ in _users_in(sentence):
            if _told(kind, words) not in [_told(*u) for u in users]:
                users.append((kind, words))
        # every mention up to the impact, in order; those that introduce a road user ("a", "another")
        said = [(j, *u) for j in range(start, i + 1) for u in _users_in(sents[j])]
        new: list[tuple[int, str, str]] = []
        for n, (j, k, w, _) in enumerate(said):
            # (a bare kind or make introduces a road user where it is its first mention: see `roles.bare`)
            if re.match(r"(?:an?|another|one) ", w, re.I) or (
                _bare_intro(w) and k.lower() not in {e[1].lower() for e in said[:n]}
            ):
                new.append((j, k, w))
        if len(users) < (1 if v1 else 2) and (other := _OTHER.search(sentence)):
            users.append((_THE_OTHER, other.group()))  # "turned in front of the other vehicle"
        if len(users) < (1 if v1 else 2):
            # it says one of them by a pronoun or as "the driver": the last road user introduced before it
            before = [(k, w) for j, k, w in new if j < i and k.lower() not in [u.lower() for u, _ in users]]
            users = before[-1:] + users
        for kind, _ in users:
            alike = [w for _, k, w in new if k.lower() == kind.lower()]
            # (unless each is told by its own colour: "a white Toyota" and "a black Toyota" are two)
            hues = [_told(kind, w)[1] for w in alike]
            if len(alike) > 1 and not (all(hues) and len(set(hues)) == len(hues)):
                return alike[1]  # a second of one kind or make: its later mentions cannot be told apart
        if not users:
            continue
        # each by the words that introduced it ("a 1984 Yamaha motorcycle", not "the Yamaha"), in the order the
        # report first names them; one told by its colour by the words with that colour
        order = {k.lower(): n for n, (_, k, _, _) in reversed(list(enumerate(said)))}
        order_told = {_told(k, w): n for n, (_, k, w, _) in reversed(list(enumerate(said)))}
        intro = {k.lower(): w for _, k, w in reversed(new)}
        intro_told = {_told(k, w): w for _, k, w in reversed(new)}
        users = [(k, intro_told.get(_told(k, w)) or intro.get(k.lower(), w)) for k, w in users]
        return sorted(users, key=lambda u: order_told.get(_told(*u), order.get(u[0].lower(), len(said))))
    return []


def _told(kind: str, words: str) -> tuple[str, str]:
    """A road user's kind, and the colour its words tell it apart by ("" when none)."""
    return kind.lower(), m.group().lower() if (m := COLOUR.search(words)) else ""


def _bare_intro(words: str) -> bool:
    """Whether a road user's words are its kind or make alone opening a sentence ("Motorcycle was northbound",
    "Honda was stopped": see `roles.bare`), which introduce it where they are its first mention."""
    return re.match(BARE + "|" + bare(BARE_MAKES), words, re.I) is not None


# A person said to drive a vehicle ("a 45-year-old man driving a Honda Civic", "a woman riding a motorcycle"):
# "his car", "her vehicle" said after it is that vehicle, when the report has one such driver.
_DRIVING = re.compile(r"\b(?:driving|drove|operating|riding|rode|behind the wheel of) ([VP]\d)\b")
_HIS_VEHICLE = re.compile(
    r"\b(?:his|her|their) (?:own )?(?:vehicle|car|auto|automobile|truck|pickup|van|minivan|suv|sedan|motorcycle)\b"
    r"(?![\w-])",
    re.I,
)


def _drivers_own(text: str) -> tuple[str, tuple[str, str] | None]:
    """ "A man driving V1 was injured when his car was struck" -> "... when V1 was struck" (see `_DRIVING`); with
    the vehicle's id and the noun first said for it ("car"), if any was."""
    driven = list(_DRIVING.finditer(text))
    if len({m[1] for m in driven}) != 1:
        return text, None
    at, pid = driven[0].end(), driven[0][1]
    own = _HIS_VEHICLE.search(text, at)
    return text[:at] + _HIS_VEHICLE.sub(pid, text[at:]), (pid, own.group().split()[-1]) if own else None


def _teller(said: str) -> str:
    return "insured" if re.search(r"\binsured\b|\bIV\b", said, re.I) else "narrator"


def unnumbered(text: str) -> tuple[str, str, dict[str, str]] | None:
    """The rule for a report that numbers nobody and names no automated vehicle: the narrator's or the insured's
    vehicle is V1 (`roles.narrator`), else the first road user named that takes part in the first impact; the
    other road users in the first impact are V2, ... in the order they are named. Road users outside it are
    bystanders and stay unnamed. None when the first impact names fewer than two road users (or only people)."""
    if _AUTONOMY.search(text):
        return None  # a report of an automated vehicle it does not name: that one is V1, and is not known
    text = partner(text)
    told = narrator(text)
    if told is not None:
        text, said = told
        users = _impact_users(text, v1=True)
        rule = f"the {_teller(said)}'s vehicle ('{said}') is V1"
        first: dict[str, str] = {"V1": said}
    else:
        users = _impact_users(text, v1=False)
        if not users or (isinstance(users, list) and all(k in _PEOPLE for k, _ in users)):
            return None  # (V1 is a vehicle: a pedestrian struck by one the report does not name is no crash read)
        rule = ""
        first = {}
    if isinstance(users, str):
        note = f"participants not numbered: two road users are named alike ('{users}')"
        return text, note, first
    if not first and len(users) < 2 and not (users and users[0][0] not in _PEOPLE and _PEDESTRIAN.search(text)):
        # a crash of road users is two of them at least: one alone is not what this rule can read, unless the other
        # is a pedestrian, whom the report calls so and who is numbered as pedestrians are ("Pedestrian was
        # crossing ... when a westbound SUV turning left struck her": the one vehicle is V1)
        return None
    text, named, words_of = _number(text, users, first, introduced=True)
    text, own = _drivers_own(text)
    if own is not None and own[0] in words_of and kind_named(words_of[own[0]]) is None:
        words_of[own[0]] += f" ({own[1]})"  # "a Honda Civic ... his car": the car it is, where its words say none
    if not first:
        rule = f"the first road user named in the first impact ({named[0]}) is V1"
        named = named[1:]
    note = f"participants numbered by rule: {rule}"
    if named:
        note += "; the other road users in the first impact are " + ", ".join(named)
    # the road users introduced and left unnamed: bystanders, no participants ("a parked van", "an unknown vehicle")
    if bystanders := [w for s in sentences(text) for _, w, _ in _users_in(s) if re.match(r"(?:an?|another) ", w, re.I)]:
        note += "; not in the crash: " + ", ".join(f"'{w}'" for w in dict.fromkeys(bystanders))
    return text, note, words_of


def partner_refusal(named: str, note: str | None) -> str | None:
    """Why a report numbered by rule cannot be read: its automated vehicle hit something the IR has no role
    for ("a pole", "an animal") and no road user; None when it can be. `named` and `note` are what `parties`
    made of the report. A report naming two road users of its crash alike ("a Toyota ... another Toyota") cannot
    be read either: which one each later "the Toyota" is, nothing says."""
    if note is not None and note.startswith("participants not numbered"):
        return (
            f"{note.removeprefix('participants not numbered: ')}, so which one each later mention is cannot be "
            "told; number them (V1, V2, ...) or name them apart"
        )
    if note is None or not note.startswith("participants numbered by rule") or re.search(r"\b(?:V[2-9]|P\d)\b", named):
        return None
    for sentence in sentences(named):
        if _IMPACT.search(sentence) and (m := THING.search(sentence)):
            return (
                f"the crash partner ('{m.group()}') is not a road user; the scenario IR holds vehicles and "
                "pedestrians only"
            )
    return None
