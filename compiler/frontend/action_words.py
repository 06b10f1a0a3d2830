"""The words that say each driving action, one pattern per action kind, for actions.py to find in a clause.

Each pattern matches what a writer says a vehicle did; whether it was done (not intended, not evasive, before
the impact) is actions.py's question, not these patterns'.
"""

from __future__ import annotations

import re

from sovarc.compiler.frontend.lanes import NUMBER
from sovarc.dsl.ir import ActionKind

TURN_WORDS = (
    # (not a head turned to look: "his head was turned left", "with her head turning left")
    r"(?<!\bhead )(?<!\bhead was )(?<!\bheads were )(?<!\bhead is )\bturn(?:ed|ing|s)? (?:to the |to its )?{0}\b"
    # (not a turn approached: "approached a right turn onto Oak Street" names the turn ahead, not yet begun)
    r"|(?<!approached a )(?<!approaching a )(?<!approaches a )"
    r"\b{0}[- ](?:hand[- ])?turn(?:ing|s)?\b(?![- ](?:only|lanes?|signal|arrow|bay|pocket))"
    # "made a left", and the idioms that say the same: "took a right", "hung a left onto Elm Street"
    r"|\b(?:make|makes|made|making|take|takes|took|taken|taking|hang|hangs|hung|hanging) a {0}\b"
    r"(?![- ](?:lane|turn lane|hand lane))"
    # "went left at the intersection", "headed right onto Elm Street": a side taken at a junction is a turn
    r"|\b(?:went|go(?:es|ing)?|head(?:ed|ing)|proceed(?:ed|ing)|swung|cut) {0} (?:at|onto|into|on) (?:the|a|an) "
    r"(?:[\w-]+ ){{0,2}}(?:intersection|junction|street|road(?:way)?|avenue|drive(?:way)?|lot|ramp)\b"
)
# The line between the two directions, however it is named: "the double yellow line", "the solid double-yellow
# lines", "the yellow center line", "the centerline", "the centre divider", "the center lane line".
CENTRE_LINE = (
    r"(?:(?:solid|painted|two|twin) )*(?:double[- ]?yellow(?: (?:cent(?:er|re) )?(?:lines?|stripes?|markings?))?"
    r"|yellow (?:cent(?:er|re) )?(?:lines?|stripes?|markings?)|cent(?:er|re)[- ]?(?:lane )?(?:line|divider|stripe)s?)"
)
# A lane of its own direction beside the one it was in, named by where it lies ("the adjacent lane", "the next
# lane", "the right adjacent lane", "the neighboring lane"): going into it is a lane change, whichever side.
BESIDE_LANE = (
    r"(?:the |an? |its )?(?:(?:left|right)(?:most)?[- ](?:hand )?)?(?:adjacent|next|neighbou?ring|other|parallel)"
    r"(?: (?:travel|through|traffic))? lanes?\b"
)
# A lane line within one direction (not the centre line, nor the edge or fog line at the shoulder): crossing it
# is going into the next lane of its own direction.
LANE_LINE = (
    r"(?:the |a )?(?:(?:single|double|solid|dashed|broken|skip|painted) )*(?:lane (?:line|divider|marking|stripe)s?"
    r"|(?:white (?:lane )?|dashed |broken |skip )(?:line|stripe)s?)\b"
)
# A lane of the other direction, from the vehicle's point of view: "the oncoming lane", "the opposing lane of
# travel", "the opposite traffic lanes".
_OPPOSING_LANE = r"(?:oncoming|opposing|opposite)(?: direction| traffic| travel)? (?:travel )?lanes?\b"
# Where a merge into a road's lanes comes from: "from the on-ramp", "from an acceleration lane".
MERGE_FROM = r"|\bfrom (?:the |an? )?(?:[\w-]+ )?(?:on-?ramp|entrance ramp|acceleration lane|merge lane)\b"
# The move under way at the impact after a turn or a lane change: closing on another from behind is driving on
# in that one's lane, behind it, so the turn or lane change was over ("turned onto Elm Street and approached V1
# from behind"). Passing is not: a pass is often the lane change or the turn itself ("changed lanes passing V1
# on the left"; "made a left turn in front of V1. As it passed V1, ..."), as NHTSA codes it.
DRIVING_ON = re.compile(r"\bapproach(?:ed|es)\b[^.,;]{0,30}?\bfrom behind\b", re.I)
PATTERNS: list[tuple[ActionKind, re.Pattern[str]]] = [
    # Backing: "backed out of a driveway", "was reversing", "began to back up", "put the car in reverse".
    # "Traffic was backed up" is a queue, not a move.
    (
        ActionKind.REVERSE,
        re.compile(
            r"\b(?:back(?:ed|ing)|revers(?:ed|ing|es|e)) (?:out|into|in|toward|towards|away|from|down|across|onto"
            r"|through|along|around|to|straight)\b|(?<!was )(?<!were )(?<!\w-)\bback(?:ed|ing) up\b"
            r"|\b(?:began|begin|started|start|attempt\w*|tried|trying) (?:to )?(?:back|revers)\w*"
            r"|\b(?:in|into) reverse\b|\breversing\b|\bwas backing\b"
            # "reversed, and", "reversed at a low speed": the verb on its own (not "reversed direction")
            r"|\breversed\b(?! (?:its |the )?(?:direction|course|decision|order))"
            # "began to roll backwards", "moved backward", "rolled back into"
            r"|\b(?:roll|rolled|rolling|rolls|mov\w*|drift\w*|went|go(?:es|ing)?|came|travel\w*|slid\w*|dr[oi]ve\w*)"
            r"(?: \w+)? (?:backwards?|rearwards?)\b"
            r"|\broll(?:s|ed|ing)? back\b"
            # the move as a noun ("a reverse maneuver", "its backing movement"), reverse parking, and the gear
            # ("shifted to reverse", "engaged reverse gear"); "backed" ending its clause ("the car backed.")
            r"|\b(?:reverse|reversing|backing)[- ](?:maneuver|manoeuvre|movement|motion|park\w*)\b"
            r"|\b(?:shift\w*|engag\w*|select\w*) (?:(?:it|the \w+|its \w+) )?(?:to |in |into )?reverse\b"
            r"|\bbacked(?=[.,;]| and\b| when\b| as\b| while\b)",
            re.I,
        ),
    ),
    # Parked: where it started, at the kerb or in a parking space ("was parked", "out of a parking space").
    (
        ActionKind.PARKED,
        re.compile(
            # (not "parked" said of other road users: "rows of parked cars", "vehicles parked at the curb")
            r"(?<!\bvehicles )(?<!\bcars )(?<!\btrucks )\bparked\b"
            r"(?! (?:[a-z]+ )?(?:cars|vehicles|trucks|vans|suvs|buses|motorcycles|bikes|bicycles|trailers)\b)"
            r"|\bout of (?:a|the|its|an) (?:[\w-]+ )?(?:parking (?:space|spot|stall|place)|parking lane"
            r"|parallel[- ]parking (?:space|spot))",
            re.I,
        ),
    ),
    # (a turn about made in parts, "a three-point turn", "a K-turn", is a U-turn too)
    (
        ActionKind.U_TURN,
        re.compile(
            r"\bu-?\s?turn|\bturn(?:ed|ing)? around\b|\b(?:three|3|multi|multiple)[- ]point turn\b|\bk-turn\b", re.I
        ),
    ),
    (ActionKind.TURN_LEFT, re.compile(TURN_WORDS.format("left"), re.I)),
    # A turn across another's path or across the oncoming lanes: where traffic keeps right, only a left turn
    # crosses them ("turned across the path of V1", "turning across oncoming traffic")
    (
        ActionKind.TURN_LEFT,
        re.compile(
            r"\bturn(?:ed|ing|s)? (?:\w+ )?across (?:the |its |[VP]\d's )(?:\w+ )?path\b"
            r"|\bturn(?:ed|ing|s)? (?:\w+ )?across (?:the )?(?:oncoming|opposing) (?:traffic|lanes?)\b",
            re.I,
        ),
    ),
    (ActionKind.TURN_RIGHT, re.compile(TURN_WORDS.format("right"), re.I)),
    (  # "a lane change" as a noun, not a lane named before the verb ("V2 in the left lane changed lanes")
        ActionKind.CHANGE_LANE,
        re.compile(
            # ("shifted lanes", "swapped lanes"; "lane changed" as a verb, but not "the left lane changing lanes")
            r"\b(?:chang|switch|shift|swap)(?:es?|ed|ing|ped|ping|s)? lanes?\b"
            r"|\blane[- ]chang(?:es?|ed|ing)\b(?! lanes?\b)"
            r"|\bmerg(?:es?|ed|ing)\b"
            # cutting in is moving into a lane just ahead of one in it: "cut in front of V1", "cut in ahead of it"
            r"|\bcut(?:s|ting)? (?:back )?in\b(?!to\b)" + MERGE_FROM,
            # coming onto a road from its on-ramp is merging into its lanes: "entering the freeway from the on-ramp"
            re.I,
        ),
    ),
    (  # "changed from the left lane into the right lane", "moved right toward the exit lane"
        ActionKind.CHANGE_LANE,
        re.compile(
            r"\b(?:mov|merg|swerv|steer|veer|drift|chang|pull|maneuver|manoeuvr)\w*(?: \w+){0,6}? (?:in)?to the "
            r"(?:[\w-]+ )?(?:left|right)(?:most)?(?: (?:adjacent|turn|travel|through))? lane\b"
            r"|\b(?:mov|merg|swerv|steer|veer|drift)\w* (?:over )?(?:to the )?(?:left|right) (?:in)?to(?:ward)? "
            r"(?:the|an?) (?:\w+ ){0,2}lane\b",
            re.I,
        ),
    ),
    # Into the lane beside it, said with any verb of going sideways or into a place: "crossed into the adjacent
    # lane", "entered the left adjacent lane", "shifted into the next lane", "went into the adjacent lane". (A lane
    # named only by its side may be where a turn or a driveway exit lands, "turned right and went into the right
    # lane", "entered the rightmost lane": those stay with the verbs of a sideways move above.)
    (
        ActionKind.CHANGE_LANE,
        re.compile(
            r"\b(?:cross|shift|cut|transition|weav|encroach|intrud|nudg|mov|merg|swerv|veer|drift|slid|went|go|came|come"
            r"|travel)\w*(?: (?:over|back|partially|fully|slightly|sideways|laterally))* (?:in)?to "
            + BESIDE_LANE
            + r"|\benter(?:ed|ing|s)?(?: (?:partially|fully))? "
            + BESIDE_LANE
            # into another's lane, however intruding: "encroached on V1's lane", "encroaching upon its lane"
            + r"|\b(?:encroach|intrud)\w* (?:on|upon|in|into) (?:[VP]\d's|the|its) (?:travel )?lane\b"
            # over a lane line of its own direction: "crossed the dashed lane line", "crossing over a solid white
            # line", "veered across the lane line" (not the centre line, and not "the lane line on the left side", a
            # coded departure to the left)
            r"|\b(?:cross(?:ed|ing|es)? (?:over )?|across |over )" + LANE_LINE + r"(?! (?:to|on) (?:the )?left)",
            re.I,
        ),
    ),
    # Sideways into a lane named by its number: "veered to the right crossing over lane two into lane one",
    # "moved into the number two lane". Reports number the lanes of one direction, so a numbered lane
    # (with no other direction named) is a lane of its own road side: a lane change.
    (
        ActionKind.CHANGE_LANE,
        re.compile(
            r"\b(?:mov|merg|swerv|steer|veer|drift|cross|chang|pull|cut)\w*\b[^.;]{0,50}?\b(?:in)?to (?:the )?"
            r"(?:number " + NUMBER + r"[- ]lane|lane (?:number |#)?" + NUMBER + r")\b"
            r"(?! (?:of )?(?:the )?(?:north|south|east|west)bound)",
            re.I,
        ),
    ),
    (
        ActionKind.RETROGRADE,
        re.compile(
            # the line between the directions, however it is named: "the center lane line", "the centre divider"
            r"\bcross(?:ed|ing|es)? (?:over )?(?:the |a )?" + CENTRE_LINE + r"|\bleft of cent(?:er|re)\b"
            r"|\b(?:across|over|straddl\w*) the "
            + CENTRE_LINE
            + r"|\binto (?:the )?(?:opposing|oncoming|opposite)(?: direction| traffic| travel)? (?:lanes?|traffic)"
            r"|\bwrong[- ](?:way|side|direction)\b"
            # against the direction the traffic there goes: "drove against traffic", "against the flow of traffic"
            r"|\bagainst (?:the )?(?:flow of |oncoming |opposing )?traffic\b"
            r"|\bover the left (?:side )?(?:double yellow|lane line|cent(?:er|re))"
            r"|\bover the lane line on (?:the )?left side|\blane departure to the left"
            r"|\bcross(?:ed|ing) (?:over )?(?:the )?(?:\w+ )?lane lines? (?:to|on) the left"
            # (not over a lane line or into a lane of its own direction: "crossed over into the right lane")
            r"|\bcrossed over\b(?! the (?:curb|median)| "
            + LANE_LINE
            + r"| (?:in)?to (?:"
            + BESIDE_LANE
            + r"|(?:the |an? )?(?:[\w-]+ )?(?:left|right)(?:most)?(?: (?:adjacent|turn|travel|through))? lane\b))",
            re.I,
        ),
    ),
    (
        ActionKind.DRIVE_INTO,
        re.compile(
            r"\bpull(?:ed|ing|s)? (?:out )?(?:of|from) (?:a|the|an|its) (?:private |[\w-]+ (?=parking))?"
            r"(?:drive(?:way)?|parking|lot|parked)"
            r"|\b(?:exit(?:ed|ing|s)?|leav(?:ing|es)|left|came out of|emerg(?:ed|ing|es) from|pull(?:ed|ing)? out of"
            r"|proceed(?:ed|ing)? out of"
            r"|(?<!backed )(?<!backing )(?<!reversed )(?<!reversing )out of) (?:a|the|an|its) (?:private )?"
            r"(?:drive(?:way)?|parking|lot|service station|gas station|business|alley|shopping|store|restaurant"
            r"|plaza|premises|property|residence|garage)"
            r"|\bpull(?:ed|ing|s)? (?:out )?(?:onto|into) the (?:road(?:way)?|street|highway|traffic|\w+ lane)\b"
            r"|\bpull(?:ed|ing|s)? (?:out )?(?:in)?to (?:the )?(?:flow of )?traffic\b"
            r"|\bpull(?:ed|ing|s)? (?:out )?(?:in)?to (?:the|a) (?:travel|traffic) lane\b"
            r"|\bfrom (?:a|the) (?:private )?(?:drive(?:way)?|parking (?:lot|garage|structure))\b"
            # into the flow of traffic, or onto the road itself, from wherever it stood off it: "attempting to
            # enter traffic", "maneuvered into the roadway" (not "into the intersection": that is crossing)
            r"|\benter(?:ed|ing|s)? (?:the )?(?:flow of )?traffic\b"
            r"|\b(?:maneuver|manoeuvr|pull|mov)\w* (?:out )?(?:in)?to the (?:road(?:way)?|street)\b"
            r"|\bre-?enter(?:ed|ing|s) the (?:road|roadway|street|travel lane)"
            # from the curb, a parking space or the shoulder onto the road: "pulled away from the curb",
            # "departing a parking space", "pulled out of the parked position"
            r"|\b(?:pull|depart|leav|left|exit)\w* (?:away |out |off )?(?:from |of )?(?:the |a |an |its )?"
            r"(?:curb(?:side)?|kerb|(?:[\w-]+ )?parking (?:space|spot|stall|position)|parked position"
            # or any place at the road's edge where vehicles stand: "pulled away from the bus stop", "pulled out of
            # the loading zone"
            r"|loading (?:zone|dock|area|bay)|bus (?:stop|zone|bay)|(?:pick-?up|drop-?off|passenger) (?:zone|area)"
            r"|taxi stand|shoulder)\b"
            # into the traffic it joined from the kerb or the shoulder: "merged into traffic from the curb"
            r"|\b(?:pull|merg|mov|accelerat|drove|driv|came|start)\w*\b[^.,;]{0,30}?\bfrom (?:the|a) "
            r"(?:curb(?:side)?|kerb|shoulder|(?:[\w-]+ )?parking (?:space|spot|stall))\b"
            r"|\benter(?:ed|ing|s) the road(?:way)? from\b",
            re.I,
        ),
    ),
    (
        ActionKind.DRIVE_OFF,
        re.compile(
            r"\bran off the road|\bdeparted the road|\bleft the road|\bonto the shoulder"
            r"|\bover the right (?:lane |edge |fog )?line"
            r"|\b(?:went|ran|drove|drifted|veered|travell?ed|departed) off the right side of the road"
            # off the road's surface, said with any verb of going: "veered off the roadway", "went off the road"
            r"|\b(?:went|ran|drove|drifted|veered|swerved|careened|skidded|slid|travell?ed|rolled) off (?:of )?the "
            r"(?:road(?:way)?|street|pavement)\b"
            # up over the kerb: "mounted the curb", "jumped the curb", "drove onto the sidewalk"
            r"|\b(?:mount|jump|hopp|climb)\w* (?:up )?(?:onto |over )?the (?:curb|kerb)\b"
            r"|\bup (?:onto|on) the (?:curb|kerb)\b"
            r"|\b(?:went|ran|drove|drifted|veered|swerved|careened|skidded|slid|travell?ed|rolled) (?:up )?onto the "
            r"(?:sidewalk|curb|kerb|median|grass)\b"
            # off the road into a place to stand: "pulled into a parking space", "was pulling into a driveway"
            r"|\bpull(?:ed|ing|s)? (?:forward )?(?:in)?to (?:a|an|the|its) (?:[\w-]+ ){0,2}?"
            r"(?:parking (?:space|spot|stall|lot|garage)|driveway|space|spot|stall)\b"
            # parking, said as under way: "was parallel parking", "attempting to park" (into a space: off the road)
            r"|\b(?:was|were|is|while|began|started) (?:parallel[- ])?parking\b"
            r"(?! (?:lots?|spaces?|spots?|stalls?|garages?|lanes?|structures?|areas?|brakes?|enforcement)\b)"
            r"|\battempt(?:ed|ing|s)? to (?:parallel[- ])?park\b",
            re.I,
        ),
    ),
    (
        ActionKind.GO_ACROSS,
        re.compile(
            r"\bcontinu(?:ed|ing|es|e) (?:through|thru|across|on through)\b"
            r"|\bcross(?:ed|ing|es)? (?:over )?(?:the|an|this) intersection|\b(?:through|thru|across) the intersection"
            r"|\bproceed(?:ed|ing|s)? (?:through|thru|across)\b|\benter(?:ed|ing|s) the intersection\b"
            r"|\binto the intersection\b|\battempt(?:ed|ing)? to cross\b"
            r"|\b(?:through|ran|run|running) (?:a|the) (?:red|yellow|green|steady red) (?:light|signal|indication)\b"
            r"|\b(?:through|ran|run|running|past|disregard\w*) (?:a|the) stop sign\b",  # into the junction
            re.I,
        ),
    ),
    (
        ActionKind.STOP,
        re.compile(
            # (not "nearly stopped", "came to a near stop": it was still moving)
            r"(?<!\bnearly )(?<!\balmost )\bstopped\b"
            r"|\b(?:came|come|comes|coming) to a (?:complete |full |sudden )?stop\b"
            r"|\bmade a (?:complete |full )?stop\b|\bslowed to a stop\b|\bwait(?:ing|ed)\b|\bawaiting\b"
            r"|\bstationary\b|\bat a standstill\b|\bstopping\b"
            # "brought the vehicle to a stop", "braked to a halt", "halted", "was sitting at the light"
            r"|\bto a (?:complete |full |sudden |quick |gradual |slow |controlled )?(?:stop|halt)\b|\bhalted\b"
            r"|\bidling\b"
            # pulled over to the kerb is standing there: "was pulled over for a pick-up", "pulled over at the curb"
            r"|\b(?:was|were|is|remained) pulled over\b"
            r"|\bpull(?:ed|ing|s)? over (?:\w+ )?(?:at|to|against|along|near|beside|by|onto) (?:the|a) "
            r"(?:[\w-]+ )?(?:curb|kerb|side|shoulder)\b"
            # standing in a line of traffic or still, however said: "was queued behind traffic", "stood still",
            # "was at rest", "held its position at the stop line"
            r"|\b(?:was|were|sat|remained|stood|stayed) (?:\w+ )?queued\b|\b(?:standing|stood|remained|sat) still\b"
            # (not "came to rest": where a vehicle ended after the crash)
            r"|\b(?:was|were|remained|sat) at rest\b"
            # "was at a complete stop", "was motionless", "paused at the stop sign", "was standing at the light",
            # "sat at the red light", "was not moving" (a state, kept from the negations: see actions._NEGATED)
            r"|\b(?:was|were|remained|sat) at a (?:complete |full |dead )?stop\b|\bmotionless\b|\bpaus(?:ed|ing)\b"
            # (not "was in the left lane": where it was, moving or not)
            r"|\b(?:stood|standing|sat|sitting) (?:at|in|behind) (?:the|a) (?:[\w-]+ ){0,2}"
            r"(?:light|signal|lane|intersection|traffic|sign|line|crosswalk|queue)\b"
            r"|\bnot (?:moving|in motion)\b"
            r"|\b(?:held|holding|hold|maintained|maintaining) (?:its|their|his|her) (?:stopped )?position\b"
            r"|\bsitting (?:at|in) (?:the|a) (?:[\w-]+ ){0,2}(?:light|signal|lane|intersection|traffic|sign)\b",
            re.I,
        ),
    ),
    # Moving off again after a stop: it drives along its lane ("began to move forward", "proceeded forward").
    (
        ActionKind.FOLLOW_LANE,
        re.compile(
            r"\b(?:began|begin|begins|beginning|started|starting|start) (?:to )?(?:mov|roll|proceed|accelerat|creep|"
            # ("began to pull out": moving off from where it stood, not "pull over", "pull into a space")
            r"advanc|go\b|pass|drive|driving|pull(?= out\b(?! of\b| onto\b| into\b)))\w*"
            r"|\b(?:proceed|mov|pull|continu|drove|inch)\w* (?:\w+ly )?(?:forward|ahead)\b"
            # (with how it moved, "pulled slightly forward", or where to: "then proceeded westbound")
            r"|\bproceed(?:ed|s)? (?:north|south|east|west)(?:bound|ward)?\b"
            r"|\bpass(?:ed|es)\b|\bovert(?:ook|akes)\b|\bproceed(?:ed|s)? to\b"
            # an attempt is the move under way when the impact cut it short: "attempted to pass V1 when ..."
            r"|\battempt(?:ed|ing|s)? to (?:pass|overtake|proceed)\b"
            # "pulled out" with nowhere said: moving off from where it stood (not "pulled out to pass", "pulled out
            # from behind V1": a move sideways)
            r"|\bpull(?:ed|s|ing)? out\b(?! (?:of|onto|into|to|from|around|and pass|in front)\b)"
            # closing on another from behind (see DRIVING_ON)
            r"|" + DRIVING_ON.pattern,
            re.I,
        ),
    ),
    # Out of its own lane sideways, toward a lane it names or the one it left says: "veered out of its lane"
    (
        ActionKind.CHANGE_LANE,
        re.compile(
            r"\b(?:veer|swerv|drift|mov|came|went|slid|shift)\w* (?:\w+ )?out of (?:its|their|his|her|the) "
            r"(?:own |travel )?lane\b"
            r"|\b(?:left|depart(?:ed|ing|s)?|exit(?:ed|ing|s)?|leav(?:es|ing)) (?:its|their|his|her) "
            r"(?:own |travel )?lane\b"
            # across two lanes at once: "was straddling two lanes", "straddled the lane line"
            r"|\bstraddl\w* (?:the |two |both |multiple )*(?:travel )?lanes\b|\bstraddl\w* "
            + LANE_LINE
            # sideways into another road user: "veered toward V1", "drifted into V1", "swerved into the side of V1"
            + r"|\b(?:veer|swerv|drift|nudg|shift|slid)\w*(?: over| back| slightly)? (?:toward|towards|into) "
            r"(?:the (?:side of |left side of |right side of )?)?[VP]\d\b",
            re.I,
        ),
    ),
    # Into the lane another road user is in, or the one between: a lane change, its side said by the lane left
    # ("V2 in the left adjacent lane ... entered V1's lane")
    (
        ActionKind.CHANGE_LANE,
        re.compile(
            # ("entered V1's lane": enter takes the place entered as its object, with no "into")
            # ("encroached into V1's lane": to intrude into another's space; "drifted right into V1's lane")
            r"\b(?:(?:enter|cross|mov|merg|drift|veer|swerv|cut|came|come|travel|encroach)\w* (?:over |left |right )?"
            r"(?:in)?to "
            r"|enter(?:ed|ing|s)? )"
            r"(?:[VP]\d's (?:travel )?lane|the lane (?:in which|where|that|occupied by) [VP]\d"
            r"|the (?:center|centre|middle) (?:travel )?lane)\b"
            # back into a lane it had left ("exited the bus lane ... reentered the bus lane"): not the travel lane,
            # which is the road one comes back onto from off it
            r"|\bre-?enter(?:ed|ing|s) (?:the|its) (?!travel\b)(?:[\w/-]+ ){0,2}?lane\b",
            re.I,
        ),
    ),
    # Around another road user, to one side: "maneuvered around the left side of V1", "steered around V1 using
    # the left turn lane": a lane change to the side it names
    (
        ActionKind.CHANGE_LANE,
        re.compile(
            r"\b(?:maneuver|manoeuvr|steer|swerv|mov|go|went|veer|drove|driv|pull|cut)\w* (?:\w+ )?around\b"
            # (not by way of the other direction's lanes: "went around V1 through the oncoming lane" is one move
            # there, read below)
            r"(?![^.,;]{0,40}?\b(?:using|through|via|by way of|in|into) (?:the |an? )?" + _OPPOSING_LANE + ")"
            # or toward its side from behind it: "began to accelerate toward the right side of V1"
            r"|\b(?:accelerat|steer|swerv|mov|veer|pull|drove|driv|head)\w* (?:\w+ )?towards? the (?:left|right) side "
            r"of [VP]\d\b",
            re.I,
        ),
    ),
    # Into the other direction's lane, said as entering it: "entered the opposing lane of travel to pass".
    (
        ActionKind.RETROGRADE,
        re.compile(
            r"\b(?:enter\w*|mov\w*|cross\w*|went|go\w*) (?:in)?to (?:the )?(?:opposing|oncoming) lanes?\b"
            r"|\benter(?:ed|ing|s)? (?:the )?(?:opposing|oncoming) (?:lanes?|traffic)\b"
            # passing by way of the other direction's lane: "passed V1 by driving in the oncoming traffic lane"
            # travelling in them: "was traveling in the opposing lane", "drove partially in the oncoming lane"
            r"|\b(?:travel\w*|driv\w*|drove|proceed\w*|head\w*|going|was|were)(?: \w+ly)? (?:partially |fully )?"
            r"(?:in|within) (?:the |an? )?"
            + _OPPOSING_LANE
            +
            # (or around it that way: "went around the stopped car through the oncoming lane")
            r"|\b(?:pass\w*|overt\w*|around)\b[^.;]{0,40}?\b(?:in|into|using|through|via|by way of) (?:the |an )?"
            + _OPPOSING_LANE,
            re.I,
        ),
    ),
]
