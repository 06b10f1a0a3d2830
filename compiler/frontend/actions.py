"""A participant's driving actions up to the first impact, read from the pieces of text about it.

The conventions are the paper's (and its ground truth's):
- an action the driver intended, planned or was waiting to do is not an action ("waiting to turn left" is a
  stop, not a turn); an evasive move ("braked and steered left to avoid V2") is not one either;
- an intention to go straight through a junction is what the vehicle did: it holds its course into the
  junction, where it is struck, so it is `go_across`;
- a vehicle starts with `follow_lane` when the report shows it moving before its first action; one that was
  stopped, parked or came from off the road starts with that;
- a vehicle the report never shows moving or acting before the impact has `unknown` actions, not a guess.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.action_words import DRIVING_ON, PATTERNS
from sovarc.compiler.frontend.clauses import Piece
from sovarc.compiler.frontend.compass_turns import compass_turns
from sovarc.compiler.frontend.lanes import LANE_USE, lane_change_side
from sovarc.compiler.frontend.resumed import resumed
from sovarc.compiler.frontend.retold import under_way_at_impact
from sovarc.compiler.frontend.sideless import names_a_lane_change, one_lane_change, said_in_piece
from sovarc.compiler.frontend.timing import under_way_first
from sovarc.compiler.frontend.turned import driven_on
from sovarc.compiler.frontend.turnpath import crossed_in_turn, turned_into
from sovarc.compiler.frontend.words import opposite
from sovarc.dsl.ir import UNKNOWN, Action, ActionKind, Heading, RoadKind, Side, Unknown

# A vehicle said to be in the other direction's lane ("V2 in the oncoming lane", "traveling in the opposite
# lane"): moving sideways from there into another's lane is a move onto the wrong side of the road.
_IN_OPPOSING = re.compile(
    r"\b(?:in|from|within) (?:the|an|a) (?:oncoming|opposing|opposite)(?: traffic| travel)? lanes?\b", re.I
)
# Going straight is crossing only where the vehicle's own sentences put it at the junction.
_STRAIGHT = re.compile(
    r"\bgo(?:ing|es)? straight\b|\bstraight (?:through|thru|across|ahead)\b|\bcontinu(?:ed|ing|es|e) straight\b"
    r"|\bproceed(?:ed|ing|s)? straight\b",
    re.I,
)
# A turn said without its side ("before turning", "began the turn") is the one the driver meant to make.
_BARE_TURN = re.compile(
    r"\b(?:turning|turned|began (?:to|its|the) turn|made the turn|making the turn|started (?:to turn|turning)"
    # the turn set going: "began to initiate the turn", "initiated its turn"
    r"|(?:(?:began|started) to )?(?:initiat|execut|commenc)(?:ed|ing|es|e) (?:the|its) turn)\b"
    r"(?! (?:to the |to its )?(?:left|right|around|green|red))",
    re.I,
)
_AFTER = re.compile(r"\bafter (?:being |having )?\w+(?:ing|ed)\b[^,.;]*", re.I)
_MEANT_TURN = re.compile(r"\b(?:turn(?:ing)?|make a|making a) (left|right)\b", re.I)
# On a road with no junction, a vehicle that "entered the roadway" came from off the road.
_ENTERED_ROAD = re.compile(r"\benter(?:ed|ing|s) the (?:road(?:way)?|street|highway)\b", re.I)
# Into the lanes of the other direction: retrograde for a vehicle heading the other way.
_INTO_LANES = re.compile(
    r"\b(?:veer|swerv|cross|drift|went|go|travel|encroach|mov|steer|skid)\w*\b[^.,;]{0,40}?\b(?:in)?to the "
    r"(north|south|east|west)bound (?:travel )?lanes?"
    r"|\benter(?:ed|ing|s) the (north|south|east|west)bound (?:travel )?lane"
    # or travelling in them: "was heading south in the northbound lanes", "in a northbound-only section"
    r"|\b(?:travel\w*|driv\w*|drove|head\w*|going|proceed\w*)\b[^.,;]{0,40}?\b(?:in|on|along|down) (?:the|a|an) "
    r"(north|south|east|west)bound(?:[- ]only)? (?:travel )?(?:lanes?|side|section|portion|roadway)\b",
    re.I,
)
# A vehicle's travel said against the lanes it is in, in one clause: "traveling eastbound in a westbound-only
# section", "heading north in the southbound lanes" (whatever heading was read for it elsewhere)
_AGAINST_LANES = re.compile(
    r"\b(?:travel\w*|driv\w*|drove|head\w*|going|proceed\w*|mov\w*) (?:\w+ )?(north|south|east|west)(?:bound|ward)?\b"
    r"[^.,;]{0,30}?\b(?:in|on|along|down) (?:the|a|an) "
    r"(north|south|east|west)bound(?:[- ]only)? (?:travel )?(?:lanes?|side|section|portion|roadway)\b",
    re.I,
)
# What a driver meant to do: the lead word stays (a vehicle "waiting" stopped), what it meant to do goes.
# What was intended ends where a new clause begins: "waiting for traffic to clear and then proceeded to turn
# left" waited, then turned. A coordinated or subordinate clause, or "and" before a verb of its own, ends it.
_CLAUSE = (
    r"(?=\s*(?:[.,;]|$|\b(?:then|but|when|until|while|before|after|where|as soon as)\b"
    r"|\band (?:then |also |subsequently )?(?:(?:was|were|had|did) )?(?:\w+ed|ran|went|drove|struck|hit|began|came"
    r"|made|took|got|left|swung|cut)\b))"
)
_INTENT = re.compile(
    r"\b(?P<lead>intend(?:ed|ing|s)?|planning|planned|plans|wanted|wanting|was going|were going|about"
    r"|prepar(?:ing|ed|es)|waiting|waited|await(?:ing|ed|s)?|in order|so as|prior"
    r"|(?:an? )?(?:opportunity|chance|opening|gap)"
    # "in anticipation of turning right", "in preparation for a left turn": what it was getting ready to do
    r"|in (?:anticipation|preparation|advance)"
    # in place for a move not begun: "queued to turn left", "lined up to make a right", "positioned to turn"
    r"|queued|lined up|positioned|(?:getting )?ready|poised)"
    # (with where it waited said first: "waiting at the red light to make a right turn")
    r"(?P<what>(?: (?:at|in|behind) (?:the|a|an) (?:[\w-]+ ){0,3}?(?:light|signal|sign|line|lane|intersection))?"
    r" (?:to|on|for|of)\b(?:[^.,;]*?)" + _CLAUSE + ")",
    re.I,
)
# A purpose said after slowing or signalling ("slowed to turn left into a driveway") is what the driver meant
# to do next, not yet done: a vehicle struck from behind as it slowed had not turned.
_PURPOSE = re.compile(
    r"\b(?P<lead>(?:slow|brak|signal|decelerat)\w*(?: down)?(?: in order)?)"
    r"(?P<what> to (?:turn|make|go|enter|change|merge|pull)\b[^.,;]*?" + _CLAUSE + ")",
    re.I,
)
# Why it went into the other direction's lanes ("entered the oncoming lanes to maneuver around V1"): the going
# around is done there, in those lanes, not a second move into a lane of its own direction.
_AROUND_BY = re.compile(
    r"\b(?P<lead>(?:opposing|oncoming)(?: traffic| travel)? lanes?(?: of (?:\[XXX\]|[\w.]+(?: [\w.]+){0,2}))?)"
    r"(?P<what> (?:in order )?to (?:pass|overtake|go around|get around|drive around|move around|maneuver around"
    r"|manoeuvre around)\b[^.,;]*?" + _CLAUSE + ")",
    re.I,
)
# A plan ("intending to", "planned to", "wanted to") is carried out unless the report shows otherwise; waiting,
# preparing or being about to do something says it had not begun.
_PLAN = re.compile(r"^(?:intend|plan|want|was going|were going)", re.I)
_INTO_PLACE = re.compile(
    r"\b(?:in)?to (?:a|an|the|its) (?:[\w-]+ ){0,3}?(?:drive(?:way)?|lot|street|road|alley|entrance)", re.I
)
# A state said before another party's name qualifies that party, not the one the piece is about: "V2 made
# contact with the rear of the stationary V1", "as V2 passed the parked V1".
# So is one before another road user's noun: "around its stopped lead vehicle", "a stopped car ahead".
_QUALIFIED = re.compile(
    r"\b(?:stationary|stopped|parked|standing|slowing|stopping)(?= [VP]\d\b| ?$"
    r"| (?:[\w-]+ )?(?:vehicles?|cars?|traffic|trucks?|bus(?:es)?|vans?|suvs?|sedans?|pickups?)\b)",
    re.I,
)
# A move meant or signalled is not made: "its intended left turn", "signaled a left turn", "indicated a right turn".
_INTENDED_MOVE = re.compile(
    r"\b(?:intended|signal(?:l)?(?:ed|ing|s)?(?: for)?|indicat(?:ed|ing|es)) (?:\w+ ){0,2}"
    r"(?:turn|u-turn|lane change)\b",
    re.I,
)
# What is awaited is not yet done, and "await" takes it as its object: "awaiting a green arrow for a left turn".
# A stop before a move ("stopped before entering the intersection", "came to a stop before making the turn") says
# where it stopped: short of the move, not yet made (a move made after the stop is told again: "then entered").
_STOPPED_BEFORE = re.compile(
    r"\b(?P<lead>(?:stop(?:ped|s)?|halt(?:ed|s)?|to a (?:complete |full )?(?:stop|halt))(?: \w+){0,4}? before)"
    r"(?P<what> \w+ing\b[^.,;]*?" + _CLAUSE + ")",
    re.I,
)
_A_MOVE = re.compile(r"\b(?:turn|u-turn|lane change|merge|pull|pass|overtake|reverse|back up)", re.I)
_AWAITED = re.compile(r"\b(?P<lead>await(?:ing|ed|s)?)(?P<what> (?!(?:to|on|for|of)\b)[^.,;]*?" + _CLAUSE + ")", re.I)
# A negated verb is no action: "had not yet started to turn", "did not stop", "never slowed".
# "failed to stop", "was unable to stop", "without stopping" deny the event as "not" does.
# (not "was not moving": standing, a state said by denying motion)
_NEGATED = re.compile(
    r"(?:\b(?:not|never|failed|fails|failing|unable|without)\b|n't\b)(?! (?:moving|in motion)\b)(?: yet| even)?"
    r"[^.,;]*?" + _CLAUSE,
    re.I,
)
_EVASIVE = re.compile(r"[^.,;]*\b(?:to avoid|evasive)\b[^.,;]*", re.I)
# "intending to go straight through the intersection": the vehicle held its course (see the module's note)
_STRAIGHT_ON = re.compile(r"^ (?:to|on) (?:go|going|continu\w*|proceed\w*|travel\w*|cross\w*)\b", re.I)
_TRAVELLING = re.compile(
    r"\b(?:travel(?:l)?(?:ed|ing|s)?|approach(?:ed|ing|es)?|driving|drove|proceed(?:ed|ing|s)?|head(?:ed|ing)|going"
    r"|negotiat(?:ed|ing)|moving|continu(?:ed|ing)|(?:was|were) (?:north|south|east|west)bound)\b",
    re.I,
)
# What shows the report describing a participant: what it was ("V2, a 2000 Honda"), where it went or how.
_DESCRIBED = re.compile(
    r"\b[VP]\d\b,? (?:(?:was|is) )?(?:an?|the) |\b(?:north|south|east|west)(?:bound|ward)?\b|\blane\b|\bstopped\b"
    r"|\bparked\b|\btravel|\bdriv(?:ing|e)\b|\bturn|\bapproach|\bproceed|\benter|\bpull"
    r"|\bslow(?:ed|ing)\b|\bbrak(?:ed|ing)\b|\bmaneuver|\bmanoeuvr|\bpass(?:ed|ing|es)?\b|\bdrove\b|\baccelerat"
    r"|\bto a (?:\w+ )?stop\b|\bexit(?:ed|ing)\b|\byield(?:ed|ing)\b|\bdepart(?:ed|ing)\b"
    r"|\bback(?:ed|ing)?\b(?! of)|\brevers|\bbackwards?\b",
    re.I,
)
_COMPASS_WORD = re.compile(r"\b(?:north|south|east|west)(?:bound|ward)?\b", re.I)
_MOVING_STRIKER = re.compile(
    r"\bfollow(?:ing|ed)\b|\bfrom behind\b|\bbehind\b|\bpass(?:ed|ing)\b|\bcontinued forward\b", re.I
)
_STOPPED_INSIDE = re.compile(
    r"\bstopped (?:\w+ ){0,3}?in (?:the )?(?:middle of (?:the )?)?(?:intersection|junction)\b", re.I
)
_JUNCTION = re.compile(r"\bintersect|\bjunction\b|\bcross street\b", re.I)
_STANDING = (ActionKind.STOP, ActionKind.DRIVE_INTO, ActionKind.PARKED)
_TURNING = (ActionKind.TURN_LEFT, ActionKind.TURN_RIGHT, ActionKind.U_TURN)
_MANOEUVRES = (ActionKind.TURN_LEFT, ActionKind.TURN_RIGHT, ActionKind.U_TURN, ActionKind.CHANGE_LANE)


def what_was_done(text: str) -> str:
    """The text without what a driver only intended or did to avoid the crash."""

    def intent(m: re.Match[str]) -> str:
        keep = m.group("lead").lower().startswith("intend") and _STRAIGHT_ON.match(m.group("what"))
        return m.group(0) if keep else m.group("lead")

    text = _NEGATED.sub(" ", text)
    text = _EVASIVE.sub(" ", text)
    # (not a participant's own apposition: "V2, a legally parked sedan,")
    text = _QUALIFIED.sub(
        lambda m: m.group() if re.search(r"\b[VP]\d,? (?:an?|the) (?:[\w-]+ )?$", text[: m.start()]) else " ", text
    )
    text = _INTENDED_MOVE.sub(" ", text)
    text = LANE_USE.sub(" ", text)
    text = _PURPOSE.sub(lambda m: m.group("lead"), text)
    text = _AROUND_BY.sub(lambda m: m.group("lead"), text)
    # (blanked, not cut, so that what is read after it keeps its place; only when a move is awaited)
    text = _STOPPED_BEFORE.sub(lambda m: m.group("lead") + " " * len(m.group("what")), text)
    text = _AWAITED.sub(
        lambda m: m.group("lead") + " " * len(m.group("what")) if _A_MOVE.search(m.group("what")) else m.group(0), text
    )
    return _INTENT.sub(intent, text)


def _meant_turn(pieces: list[Piece]) -> ActionKind | None:
    """The one turn the driver meant to make ("intending to turn left"), if the report names one."""
    sides = {m.group(1).lower() for p in pieces for i in _INTENT.finditer(p.text) for m in _MEANT_TURN.finditer(i[0])}
    if len(sides) != 1:
        return None
    return ActionKind.TURN_LEFT if sides == {"left"} else ActionKind.TURN_RIGHT


def _bare_turns(piece: Piece, done: str, side: ActionKind) -> list[tuple[int, Action]]:
    """ "began the turn", "before turning": the meant turn, done; not after "Before V1 ..." (not yet done)."""
    before = piece.context[: max(0, piece.context.find(piece.text))]
    return [
        (piece.at + m.start(), Action(side))
        for m in _BARE_TURN.finditer(done)
        if not re.search(r"\bbefore\s+\w+[^,.;]*$", before + done[: m.start()], re.I)
    ]


def _found(
    pieces: list[Piece], road: RoadKind | Unknown, heading: Heading | Unknown, toward: str | None = None
) -> list[tuple[int, Action]]:
    at_junction = road in (RoadKind.INTERSECTION, RoadKind.T_JUNCTION)
    near = at_junction and any(_JUNCTION.search(p.context) for p in pieces)
    meant = _meant_turn(pieces)
    found: list[tuple[int, Action]] = []
    said = ""  # what was said of it before this piece: where its lane was
    dones = [what_was_done(piece.text) for piece in pieces]
    for piece, done in zip(pieces, dones, strict=True):
        if near:
            found += [(piece.at + m.start(), Action(ActionKind.GO_ACROSS)) for m in _STRAIGHT.finditer(done)]
        if meant is not None:
            found += _bare_turns(piece, done, meant)
        earlier = [m.span() for m in _AFTER.finditer(done)]
        # "pulled out of the parked position": the state it left came before it entered the road
        left_from = [m.span() for k, p in PATTERNS if k is ActionKind.DRIVE_INTO for m in p.finditer(done)]
        for kind, pattern in PATTERNS:
            for m in pattern.finditer(done):
                act, to = kind, None
                if act is ActionKind.CHANGE_LANE and _IN_OPPOSING.search(said + done[: m.start()]):
                    act = ActionKind.RETROGRADE  # out of the oncoming lane into another's: onto the wrong side
                if act is ActionKind.CHANGE_LANE:  # see lanes.lane_change_side
                    side = lane_change_side(done, m.start(), m.end(), said + done[: m.start()]) or toward
                    if side is None and not names_a_lane_change(m.group()):  # see sideless.py
                        continue
                    to = Side(side) if side else None
                if act is ActionKind.GO_ACROSS and not at_junction:
                    continue
                if act in (ActionKind.RETROGRADE, ActionKind.CHANGE_LANE) and crossed_in_turn(piece, m.group()):
                    continue
                if act is ActionKind.RETROGRADE and "wrong" not in m.group().lower() and turned_into(done, m.start()):
                    continue
                # a lane entered right after coming onto the road from off it is where it entered, not a change
                # ("exited a driveway ... entered the rightmost lane")
                if (
                    act is ActionKind.CHANGE_LANE
                    and not names_a_lane_change(m.group())
                    and any(a.kind is ActionKind.DRIVE_INTO for _, a in found)
                ):
                    continue
                # "turning left after being stopped": what the after-clause says came first
                at = piece.at - 1 if any(a <= m.start() < b for a, b in earlier) else piece.at + m.start()
                if act is ActionKind.STOP and (inside := next((a for a, b in left_from if a < m.start() < b), None)):
                    at = piece.at + inside - 1
                if (
                    act is ActionKind.CHANGE_LANE
                    and (named := said_in_piece(found, piece.at, len(piece.text), to)) is not None
                ):
                    at = named  # "was changing lanes ..., it entered V1's lane": one move, said first there
                found.append((at, Action(act, to)))
        if road is RoadKind.STRAIGHT:
            found += [(piece.at + m.start(), Action(ActionKind.DRIVE_INTO)) for m in _ENTERED_ROAD.finditer(done)]
        found += [(piece.at + at, turn) for at, turn in compass_turns(done, heading)]  # "turned onto eastbound X"
        said += done + " "
    # Into the other direction's lanes is wrong-way driving, unless the vehicle turned across them.
    if not isinstance(heading, Unknown) and not any(a.kind in _MANOEUVRES for _, a in found):
        for piece, done in zip(pieces, dones, strict=True):
            found += [
                (piece.at + m.start(), Action(ActionKind.RETROGRADE))
                for m in _INTO_LANES.finditer(done)
                if next(g for g in m.groups() if g).lower() == opposite(heading).value
            ]
    for piece, done in zip(pieces, dones, strict=True):
        found += [
            (piece.at + m.start(), Action(ActionKind.RETROGRADE))
            for m in _AGAINST_LANES.finditer(done)
            if opposite(Heading(m.group(1).lower())) == Heading(m.group(2).lower())
        ]
    if meant is not None:  # one meant to turn and drove into the junction: that is its turn
        found = [(at, Action(meant) if a.kind is ActionKind.GO_ACROSS else a) for at, a in found]
    return found


def _planned_turn(pieces: list[Piece], road: RoadKind | Unknown) -> tuple[int, ActionKind] | None:
    """A turn the driver planned ("intending on turning left at the intersection"), with where it is said, if
    the plan is to turn where a turn can be made: at the junction the crash is at, or into a side road or
    driveway. One side only: two plans say nothing sure."""
    at_junction = road in (RoadKind.INTERSECTION, RoadKind.T_JUNCTION)
    plans = [
        (p.at + i.start(), m.group(1).lower())
        for p in pieces
        for i in (*_INTENT.finditer(_NEGATED.sub(" ", p.text)), *_PURPOSE.finditer(p.text))
        if _PLAN.match(i.group("lead")) or i.re is _PURPOSE
        for m in _MEANT_TURN.finditer(i.group("what"))
        if at_junction or _INTO_PLACE.search(i.group("what"))
    ]
    if len({side for _, side in plans}) != 1:
        return None
    # "had not yet started to turn", "did not turn": the report says the turn was not made
    if any(re.search(r"\bturn", n.group()) for p in pieces for n in _NEGATED.finditer(p.text)):
        return None
    return plans[0][0], ActionKind.TURN_LEFT if plans[0][1] == "left" else ActionKind.TURN_RIGHT


def _carried_out(
    found: list[tuple[int, Action]], plan: tuple[int, ActionKind] | None, struck_behind: bool
) -> list[tuple[int, Action]]:
    """A planned turn was made unless the report shows it was not (see `_planned_turn`): another move made
    instead, a stop after the plan (it stopped short, or waited), or a crash from behind before the turn began
    (the vehicle slowing for its turn is struck in the rear)."""
    if plan is None or struck_behind:
        return found
    at, turn = plan
    if any(a.kind in _MANOEUVRES or a.kind is ActionKind.DRIVE_INTO for _, a in found):
        return found
    if any(a.kind is ActionKind.STOP and where > at for where, a in found):
        return found
    return [*[(w, a) for w, a in found if a.kind is not ActionKind.GO_ACROSS], (at, Action(turn))]


def _waited_turn(
    found: list[tuple[int, Action]], pieces: list[Piece], road: RoadKind | Unknown
) -> list[tuple[int, Action]]:
    """At a junction, one that stopped waiting or preparing to turn ("waiting to turn right onto Elm Street") and
    then moved off ("When the light turned green, V1 proceeded") made the turn it waited to make: moving off is
    that turn, the last thing it did. Not while it stood ("remained stopped"), nor when another move follows."""
    if road not in (RoadKind.INTERSECTION, RoadKind.T_JUNCTION) or len(found) < 2:
        return found
    (_, before), (moved, last) = found[-2], found[-1]
    if before.kind is not ActionKind.STOP or last.kind is not ActionKind.FOLLOW_LANE:
        return found
    waited = [
        (p.at + i.start(), m.group(1).lower())
        for p in pieces
        for i in _INTENT.finditer(p.text)
        if not _PLAN.match(i.group("lead"))
        for m in _MEANT_TURN.finditer(i.group("what"))
    ]
    if len({side for _, side in waited}) != 1 or min(at for at, _ in waited) > moved:
        return found
    turn = ActionKind.TURN_LEFT if waited[0][1] == "left" else ActionKind.TURN_RIGHT
    return [*found[:-1], (moved, Action(turn))]


def read_actions(
    pieces: list[Piece],
    road: RoadKind | Unknown,
    heading: Heading | Unknown,
    struck_first: bool,
    struck_behind: bool = False,
    side_impact: bool = False,
    toward: str | None = None,
) -> tuple[Action, ...] | Unknown:
    """The ordered actions of one participant before the first impact (`pieces` are its pieces before it);
    `struck_first` says whether its front made the impact, `struck_behind` whether its rear was struck,
    `side_impact` whether the crash is front to side, the geometry of a turn across or into another's path (a
    planned turn counts as made only then: see `_carried_out`); `toward` is the side ("left", "right") a lane
    change said without its side went, when the impact shows it ("switched lanes and made contact with the
    driver side of V1": it came from V1's left, so it moved right)."""
    return read_actions_at(pieces, road, heading, struck_first, struck_behind, side_impact, toward)[0]


def read_actions_at(
    pieces: list[Piece],
    road: RoadKind | Unknown,
    heading: Heading | Unknown,
    struck_first: bool,
    struck_behind: bool = False,
    side_impact: bool = False,
    toward: str | None = None,
) -> tuple[tuple[Action, ...] | Unknown, tuple[int, ...]]:
    """`read_actions`, and where each action was read (an offset into the pieces' joined sentences), so a
    reviewer can be shown why it was read."""
    # (a piece in which any action is read describes it: "V2 behind it was switching lanes")
    shown = any(_DESCRIBED.search(p.text) or any(x.search(what_was_done(p.text)) for _, x in PATTERNS) for p in pieces)
    if not shown:  # never described before the impact: not known,
        # unless its front made the impact and it is said to be moving ("V2 following behind V1 struck ...")
        moving = next((p.at + m.start() for p in pieces if (m := _MOVING_STRIKER.search(p.text))), None)
        if struck_first and moving is not None:
            return (Action(ActionKind.FOLLOW_LANE),), (moving,)
        return UNKNOWN, ()
    plan = _planned_turn(pieces, road) if side_impact else None
    found = one_lane_change(_carried_out(_found(pieces, road, heading, toward), plan, struck_behind))
    kinds = {a.kind for _, a in found}
    turning = kinds & set(_MANOEUVRES)
    if turning or ActionKind.DRIVE_INTO in kinds:  # a turning vehicle does not go across
        found = [(at, a) for at, a in found if a.kind is not ActionKind.GO_ACROSS]
    found = under_way_at_impact(resumed(sorted(found, key=lambda item: item[0]), pieces), pieces)
    # Driving in the other direction's lanes goes on through a junction: going across it after is the same travel,
    # still on the wrong side ("traveling eastbound in a westbound-only section ... entered the intersection")
    found = [
        (at, a)
        for i, (at, a) in enumerate(found)
        if a.kind is not ActionKind.GO_ACROSS or i == 0 or found[i - 1][1].kind is not ActionKind.RETROGRADE
    ]
    # One parked that moves off ("began to pull out", "pulled out") enters the road from where it stood.
    found = [
        (at, Action(ActionKind.DRIVE_INTO))
        if a.kind is ActionKind.FOLLOW_LANE and i > 0 and found[i - 1][1].kind is ActionKind.PARKED
        else (at, a)
        for i, (at, a) in enumerate(found)
    ]
    turned = driven_on(found, pieces)  # a turn, then along the road turned onto (see turned.py)
    after_turn = {at for at, _ in turned[len(found) :]}
    found = turned
    # Driving on is said only of a vehicle that moved off again after a stop (see PATTERNS), and only when it
    # did nothing else next: moving off into a turn is the turn. Or of one closing on another from behind after
    # its turn or lane change, the last thing it did (see DRIVING_ON).
    on = {p.at + m.start() for p in pieces for m in DRIVING_ON.finditer(what_was_done(p.text))}
    found = [
        (at, a)
        for i, (at, a) in enumerate(found)
        if a.kind is not ActionKind.FOLLOW_LANE
        or (
            i > 0
            and found[i - 1][1].kind is ActionKind.STOP
            and (i + 1 == len(found) or found[i + 1][1].kind in (ActionKind.STOP, ActionKind.FOLLOW_LANE))
        )
        or (i > 0 and i + 1 == len(found) and found[i - 1][1].kind in _MANOEUVRES and at in on)
        or at in after_turn
    ]
    found = _waited_turn(found, pieces, road)
    # "reversed out of the driveway", "began reversing further out of a parking spot": leaving a place backwards
    # is the reverse, not a drive into the road as well
    backs = [at for at, a in found if a.kind is ActionKind.REVERSE]
    found = [
        (at, a) for at, a in found if a.kind is not ActionKind.DRIVE_INTO or not any(0 <= at - b <= 40 for b in backs)
    ]
    if entered := [at for at, a in found if a.kind is ActionKind.DRIVE_INTO]:
        # It came onto the road from off it: what it did before (parked, stopped) stands, driving does not.
        found = [(at, a) for at, a in found if at >= entered[0] or a.kind in (ActionKind.STOP, ActionKind.PARKED)]
    if any(a.kind is ActionKind.PARKED for _, a in found):
        # Parked is where it started, wherever the report says so ("backed out of a parking space"); standing
        # there is no stop of its own.
        first = min(at for at, _ in found)
        moves = [(at, a) for at, a in found if a.kind not in (ActionKind.PARKED, ActionKind.STOP)]
        found = [(first - 1, Action(ActionKind.PARKED)), *moves]
    if (
        found
        and found[-1][1].kind is ActionKind.STOP
        and struck_first
        and road is RoadKind.INTERSECTION
        and not kinds & set(_MANOEUVRES)
    ):
        # It stopped, then its front struck another: it moved off again, and with no turn it went across.
        found.append((found[-1][0] + 1, Action(ActionKind.GO_ACROSS)))
    ordered: list[Action] = []
    where: list[int] = []
    for i, (at, action) in enumerate(found):
        later = [a for _, a in found[i + 1 :]]
        if ordered and ordered[-1] == action:
            continue
        if action.kind in (*_MANOEUVRES, ActionKind.DRIVE_INTO) and action in later:  # the plan, then the deed
            continue
        ordered.append(action)
        where.append(at)
    # A vehicle on the road drives along its lane first, unless it stood still or came from off the road;
    # one the report shows moving before it stopped drove first.
    moving_at = min((p.at + m.start() for p in pieces for m in _TRAVELLING.finditer(p.text)), default=None)
    if (under_way := under_way_first(pieces)) is not None:  # "When V2 stopped ..., it was traveling north"
        moving_at = min(under_way, moving_at if moving_at is not None else under_way)
    # So did one stopped inside a junction: it drove in to stop there ("after being stopped in the
    # intersection"), unlike one stopped at it (at the light, the stop sign).
    moved_first = (
        bool(ordered)
        and ordered[0].kind is ActionKind.STOP
        and ((moving_at is not None and moving_at < found[0][0]) or any(_STOPPED_INSIDE.search(p.text) for p in pieces))
    )
    # One first shown in the act of a turn ("V2 was a Lincoln that attempted to make a left turn"), with no
    # motion or heading said before it, is not shown driving along its lane first. A lane change is: it is made
    # from a lane driven in ("changed from the right lane").
    heading_at = min((p.at + m.start() for p in pieces for m in _COMPASS_WORD.finditer(p.text)), default=None)
    shown_first = [at for at in (moving_at, heading_at) if at is not None]
    manoeuvre_first = (
        bool(ordered) and ordered[0].kind in _TURNING and (not shown_first or min(shown_first) > found[0][0])
    )
    if (not ordered or ordered[0].kind not in _STANDING or moved_first) and not manoeuvre_first:
        ordered.insert(0, Action(ActionKind.FOLLOW_LANE))
        # read where it was shown moving, else where it was first described
        described = next((p.at + m.start() for p in pieces if (m := _DESCRIBED.search(p.text))), pieces[0].at)
        where.insert(0, moving_at if moving_at is not None else described)
    return tuple(ordered), tuple(where)
