"""The lanes of a SUMO network, read once, as the geometry kernel's lane map.

Only what the SUMO target needs: each lane's centre line, width and edge, and which lane
follows an internal (junction) lane. A plain ElementTree pass is several times faster than
sumolib's full network and keeps big city networks cheap. Which lane a point is on (`locate`,
`spot`) is the kernel's (compiler/geometry/lanes.py), shared with lowering.
"""

from __future__ import annotations

import functools
import io
from collections.abc import Iterable
from pathlib import Path
from xml.etree import ElementTree

from sovarc.compiler.geometry.lanes import Lane, LaneMap, Point, Spot

__all__ = ["Lane", "Network", "Spot", "read_network"]


class Network(LaneMap):
    """A SUMO network's lanes (the kernel's lane map) and which lane follows a junction's lane."""

    def __init__(self, lanes: Iterable[Lane], successors: dict[str, str], predecessors: dict[str, str]) -> None:
        super().__init__(lanes)
        self.successors = successors  # internal lane id -> the lane it leads into
        self.predecessors = predecessors  # internal lane id -> the lane that leads into it

    def next_normal_lane(self, lane: Lane) -> Lane | None:
        """The first non-internal lane reached from an internal one."""
        return self._walk(lane, self.successors)

    def previous_normal_lane(self, lane: Lane) -> Lane | None:
        """The non-internal lane an internal one is entered from."""
        return self._walk(lane, self.predecessors)

    def _walk(self, lane: Lane, links: dict[str, str]) -> Lane | None:
        seen = set()
        current: str | None = lane.id
        while current is not None and current not in seen:
            seen.add(current)
            found = self.lanes.get(current)
            if found is not None and not found.internal:
                return found
            current = links.get(current)
        return None


def _shape(text: str) -> tuple[Point, ...]:
    return tuple((float(x), float(y)) for x, y, *_ in (p.split(",") for p in text.split()))


@functools.lru_cache(maxsize=8)
def _read(data: bytes) -> Network:
    lanes: list[Lane] = []
    successors: dict[str, str] = {}
    predecessors: dict[str, str] = {}
    edge_id, internal, ends = "", False, ("", "")
    for event, element in ElementTree.iterparse(io.BytesIO(data), events=("start", "end")):
        if event == "start":
            if element.tag == "edge":
                edge_id, internal = element.get("id", ""), element.get("function") == "internal"
                ends = (element.get("from", ""), element.get("to", ""))
            continue
        if element.tag == "lane":
            allow = element.get("allow", "")
            lanes.append(
                Lane(
                    id=element.get("id", ""),
                    edge=edge_id,
                    index=int(element.get("index", "0")),
                    width=float(element.get("width", "3.2")),
                    length=float(element.get("length", "0")),
                    shape=_shape(element.get("shape", "")),
                    internal=internal,
                    pedestrian_only=allow.split() == ["pedestrian"],
                    ends=ends,
                )
            )
        elif element.tag == "connection":
            source = f"{element.get('from', '')}_{element.get('fromLane')}"
            via = element.get("via")
            if source.startswith(":"):
                successors[source] = via or f"{element.get('to')}_{element.get('toLane')}"
            if via:
                predecessors[via] = source
        elif element.tag in {"edge", "junction", "tlLogic"}:
            element.clear()
    return Network(lanes, successors, predecessors)


def read_network(path: Path) -> Network:
    """The network at `path`, cached by its bytes: every site's scenario folder holds a copy of
    the same map (or of one crop of it), which is read and indexed once."""
    return _read(path.read_bytes())
