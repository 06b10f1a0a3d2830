"""Medians a car can drive across, read from an OpenDRIVE map's own lanes and objects.

netconvert keeps a road's car lanes and drops what lies between its two directions (shoulders,
border strips, a median lane): in the SUMO network a divided road is two carriageways with a gap,
whatever the gap is. What it is decides what can happen there. Two directions parted by flat
ground (a painted island, shoulders, a grass strip) and nothing on it are one road: a car that
leaves its lanes to the left runs on into the oncoming ones (a cross-median crash), and a car may
turn or U-turn across it. A barrier, a guardrail, a kerb or a planted island stops it: those are
two one-way roads. The file says which: between a road's innermost car lanes of each direction,
every lane must be of a flat kind, raised by no `height` and edged by no kerb mark, and no object
that stands up (by its type or name) may lie in that band. A median drawn as the gap between two
roads of one direction each is not described at all, and is not taken to be crossable.

`open_medians` gives the SUMO edges (netconvert names a road's edges by its id, '-' for its
right-hand side, '.<s>' for a lane section) whose road has such a median all along it.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from pathlib import Path
from xml.etree import ElementTree

# Lane kinds that are ground a car can drive over, not lanes it drives in (OpenDRIVE 1.4-1.8).
FLAT = frozenset({"shoulder", "border", "none", "median", "restricted"})
# Lane kinds netconvert builds as car lanes: the first of them, going out from the centre, ends a
# median; any other kind before it (a path, a bike lane, a rail, a kerb) makes it no open ground.
CAR_LANES = frozenset(
    {"driving", "stop", "bidirectional", "onramp", "offramp", "entry", "exit", "connectingramp", "mwyentry", "mwyexit"}
)
KERB_MARKS = frozenset({"curb"})  # a road mark that is a raised edge, not paint
RAISED = 0.12  # m: a lane raised this much or more (OpenDRIVE <height>) is a kerbed island
# An object whose type or name says it stands up; paint and surface patches do not.
STANDING = re.compile(
    r"barrier|rail|guard|fence|wall|bollard|pole|post|pillar|column|tree|vegetation|bush|building|"
    r"obstacle|curb|kerb|island|jersey|delineator|cone",
    re.IGNORECASE,
)
SLACK = 0.1  # m: an object this close to the median's edge stands in it


def open_medians(xodr: Path, edge_ids: Iterable[str]) -> frozenset[str]:
    """The edges among `edge_ids` whose OpenDRIVE road has a crossable median all along it."""
    roads = _open_roads(ElementTree.parse(xodr).getroot())
    return frozenset(e for e in edge_ids if road_of(e) in roads)


def road_of(edge_id: str) -> str:
    """The OpenDRIVE road an edge netconvert made belongs to ('-12.30.5' -> '12')."""
    return edge_id.removeprefix("-").split(".", 1)[0]


def _open_roads(root: ElementTree.Element) -> set[str]:
    found = set()
    for road in root.iter("road"):
        try:
            if _road_open(road):
                found.add(road.get("id", ""))
        except ValueError:
            continue  # a number the file garbles: nothing is known of that road's median
    return found


def _road_open(road: ElementTree.Element) -> bool:
    """Whether every lane section of the road has a crossable median."""
    lanes = road.find("lanes")
    if lanes is None:
        return False
    sections = lanes.findall("laneSection")
    offsets = sorted(((float(o.get("s", "0")), o) for o in lanes.findall("laneOffset")), key=lambda x: x[0])
    objects = road.findall("objects/object")
    starts = [float(sec.get("s", "0")) for sec in sections] + [float(road.get("length", "0"))]
    spans = zip(sections, starts, starts[1:], strict=False)
    return bool(sections) and all(_section_open(sec, lo, hi, offsets, objects) for sec, lo, hi in spans)


def _section_open(
    section: ElementTree.Element,
    lo: float,
    hi: float,
    offsets: list[tuple[float, ElementTree.Element]],
    objects: list[ElementTree.Element],
) -> bool:
    """Whether a lane section has both directions, with only flat, unobstructed ground between."""
    left = _median(section.findall("left/lane"), key=lambda n: n)
    right = _median(section.findall("right/lane"), key=lambda n: -n)
    if left is None or right is None:
        return False  # a one-way road, or a median of something else (a path, a rail, a kerb)
    centre = section.find("center/lane/roadMark")
    if centre is not None and centre.get("type", "").lower() in KERB_MARKS:
        return False
    offset = _offset(offsets, lo)
    band = (offset - right - SLACK, offset + left + SLACK)  # t across the median
    return not any(_stands_in(o, band, lo, hi) for o in objects)


def _median(lanes: list[ElementTree.Element], key: Callable[[int], int]) -> float | None:
    """The width of the flat ground between the centre line and a side's first car lane, or None
    when that side has no car lane or something other than flat ground lies before it."""
    width = 0.0
    for lane in sorted(lanes, key=lambda lane: key(int(lane.get("id", "0")))):
        kind = lane.get("type", "").lower()
        if kind in CAR_LANES:
            return width
        if kind not in FLAT or _raised(lane):
            return None
        if any(m.get("type", "").lower() in KERB_MARKS for m in lane.findall("roadMark")):
            return None
        width += max((float(w.get("a", "0")) for w in lane.findall("width")), default=0.0)
    return None


def _raised(lane: ElementTree.Element) -> bool:
    return any(max(float(h.get("inner", "0")), float(h.get("outer", "0"))) >= RAISED for h in lane.findall("height"))


def _offset(offsets: list[tuple[float, ElementTree.Element]], s: float) -> float:
    """The road's lane offset (the centre line's shift) at `s`."""
    here = [o for start, o in offsets if start <= s + 1e-9]
    if not here:
        return 0.0
    o = here[-1]
    ds = s - float(o.get("s", "0"))
    a, b, c, d = (float(o.get(k, "0")) for k in "abcd")
    return a + b * ds + c * ds**2 + d * ds**3


def _stands_in(obj: ElementTree.Element, band: tuple[float, float], lo: float, hi: float) -> bool:
    """Whether an object that stands up lies in the band of t, somewhere from s = lo to hi."""
    if not STANDING.search(obj.get("type", "") + " " + obj.get("name", "")):
        return False
    half = max(float(obj.get("width", "0") or 0.0), 2.0 * float(obj.get("radius", "0") or 0.0)) / 2.0
    spots = [(float(obj.get("s", "0")), 0.0, float(obj.get("t", "0")), float(obj.get("t", "0")))]
    for r in obj.findall("repeat"):
        t0 = float(r.get("tStart", obj.get("t", "0")))
        spots.append((float(r.get("s", "0")), float(r.get("length", "0")), t0, float(r.get("tEnd", t0))))
    for s, length, t0, t1 in spots:
        if s > hi or s + length < lo:
            continue
        if min(t0, t1) - half <= band[1] and max(t0, t1) + half >= band[0]:
            return True
    return False
