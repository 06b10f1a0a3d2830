"""A big SUMO network cut down to the part a scenario drives on, with its geometry unchanged.

SUMO loads a whole city network for every replay, and a 2000-edge network costs about as much
to load as the replay itself. A scenario only needs the roads around its trajectories, so a big
map travels cropped: every junction inside the box is kept whole (its internal lanes, requests
and traffic light), with every edge that touches it; an edge that only crosses the box is kept
too. A junction at the far end of a kept edge becomes a dead end. Nothing kept is recomputed:
lane shapes, widths and ids are the map's own bytes, so the oracle judges the same lanes the
plan was made on. (`netconvert --keep-edges.in-boundary` recomputes junction shapes at the
cut, by up to 25 m on the DRT city network, which would move lanes under a planned trajectory.)
"""

from __future__ import annotations

import functools
import itertools
from dataclasses import dataclass

from lxml import etree

CROP_ABOVE = 1000  # edges (internal ones included): smaller maps travel whole
MARGIN = 60.0  # m of road kept around the trajectories
SNAP = 100.0  # m: boxes snap outward to this grid, so scenarios on one site share a crop


@dataclass(frozen=True)
class Box:
    x0: float
    y0: float
    x1: float
    y1: float

    @classmethod
    def around(cls, points: list[tuple[float, float]]) -> Box:
        """The snapped box holding `points` with MARGIN to spare."""
        xs, ys = [p[0] for p in points], [p[1] for p in points]

        def down(v: float) -> float:
            return (v // SNAP) * SNAP

        return cls(
            down(min(xs) - MARGIN), down(min(ys) - MARGIN), down(max(xs) + MARGIN) + SNAP, down(max(ys) + MARGIN) + SNAP
        )

    def holds(self, x: float, y: float) -> bool:
        return self.x0 <= x <= self.x1 and self.y0 <= y <= self.y1

    def meets(self, p: tuple[float, float], q: tuple[float, float]) -> bool:
        """Whether the segment pq has a point in the box (Liang-Barsky clipping)."""
        t0, t1 = 0.0, 1.0
        dx, dy = q[0] - p[0], q[1] - p[1]
        for step, room in ((-dx, p[0] - self.x0), (dx, self.x1 - p[0]), (-dy, p[1] - self.y0), (dy, self.y1 - p[1])):
            if step == 0.0:
                if room < 0.0:
                    return False
                continue
            t = room / step
            if step < 0.0:
                t0 = max(t0, t)
            else:
                t1 = min(t1, t)
            if t0 > t1:
                return False
        return True


def needs_crop(data: bytes) -> bool:
    return data.count(b"<edge ") > CROP_ABOVE


@functools.lru_cache(maxsize=32)
def crop(data: bytes, box: Box, routes: frozenset[str] = frozenset()) -> bytes:
    """The network `data` (a .net.xml) cut down to `box` as described above. The junctions at
    both ends of each edge in `routes` are kept whole too, so every route stays connected even
    where it runs on past the trajectories (a crash 200 m before the junction its route crosses)."""
    root = etree.fromstring(data, etree.XMLParser(remove_comments=False, huge_tree=True))
    junctions = {j.get("id"): j for j in root.iter("junction")}
    full = {jid for jid, j in junctions.items() if not jid.startswith(":") and box.holds(_f(j, "x"), _f(j, "y"))}
    edges = list(root.iter("edge"))
    full |= {str(e.get(end)) for e in edges if e.get("id") in routes for end in ("from", "to")}
    kept: set[str] = set()
    for edge in edges:
        eid = edge.get("id", "")
        if edge.get("function") in {"internal", "walkingarea", "crossing"}:
            if _owner(eid, 1) in full:
                kept.add(eid)
        elif edge.get("from") in full or edge.get("to") in full or _crosses(edge, box):
            kept.add(eid)
    normal_kept = [edge for edge in edges if edge.get("id") in kept and not edge.get("function")]
    ends = {edge.get(end) for edge in normal_kept for end in ("from", "to")}
    for edge in edges:
        if edge.get("id") not in kept:
            _drop(edge)
    kept_lanes = {lane.get("id") for edge in edges if edge.get("id") in kept for lane in edge.iter("lane")}
    for jid, junction in junctions.items():
        if jid.startswith(":"):
            if _owner(jid, 2) not in full:
                _drop(junction)
        elif jid not in full and jid not in ends:
            _drop(junction)
        elif jid not in full:
            _dead_end(junction, kept_lanes)
    # a link through a dead end has no request left to govern it
    through = {edge.get("id"): edge.get("to") for edge in edges if not edge.get("function")}
    lights: set[str] = set()
    for connection in list(root.iter("connection")):
        source, via = connection.get("from"), connection.get("via")
        governed = source not in through or through[source] in full
        if source in kept and connection.get("to") in kept and (not via or via in kept_lanes) and governed:
            if tl := connection.get("tl"):
                lights.add(tl)
        else:
            _drop(connection)
    for logic in list(root.iter("tlLogic")):
        if logic.get("id") not in lights:
            _drop(logic)
    for ring in list(root.iter("roundabout")):
        if not set(ring.get("edges", "").split()) <= kept:
            _drop(ring)
    return etree.tostring(root, encoding="UTF-8", xml_declaration=True) + b"\n"


def _f(element: etree._Element, name: str) -> float:
    return float(element.get(name, "nan"))


def _owner(internal_id: str, parts: int) -> str:
    """The junction an internal edge (':J_3', parts=1) or internal junction (':J_3_0', parts=2) belongs to."""
    return internal_id[1:].rsplit("_", parts)[0]


def _crosses(edge: etree._Element, box: Box) -> bool:
    for lane in edge.iter("lane"):
        points = [tuple(map(float, p.split(",")[:2])) for p in lane.get("shape", "").split()]
        if any(box.meets(p, q) for p, q in itertools.pairwise(points)):
            return True
    return False


def _dead_end(junction: etree._Element, kept_lanes: set[str]) -> None:
    """A junction at the cut: it only ends the kept edges that reach it."""
    junction.set("type", "dead_end")
    junction.set("incLanes", " ".join(lane for lane in junction.get("incLanes", "").split() if lane in kept_lanes))
    junction.set("intLanes", "")
    for request in junction.findall("request"):
        _drop(request)


def _drop(element: etree._Element) -> None:
    """Remove `element`, keeping the whitespace that followed it out of the way of the next one."""
    parent = element.getparent()
    if parent is None:
        return
    previous = element.getprevious()
    tail = element.tail
    parent.remove(element)
    if previous is not None:
        previous.tail = tail
    else:
        parent.text = tail
