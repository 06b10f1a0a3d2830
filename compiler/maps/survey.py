"""What the compiler sees in a map, shown to its user: the sites per kind, listed and drawn.

report = survey(road_map)                 # every site, per kind
print(report.text())                      # one line per site: arms, lanes, widths; short straight ones last
draw(road_map, report.sites, "map.png", report.short)   # the map with its sites marked
missing(road_map, RoadKind.INTERSECTION)  # why a scenario of that kind finds no site, or None
"""

from __future__ import annotations

import os
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

from sovarc.compiler.maps.load import RoadMap
from sovarc.compiler.maps.roads import is_road
from sovarc.compiler.maps.sites import DEFAULT_MIN_LENGTH, Arm, Site, find_sites, merges, short_sites
from sovarc.dsl.ir import RoadKind

KIND_NAMES: dict[RoadKind, tuple[str, str]] = {
    RoadKind.INTERSECTION: ("an intersection (a 4-way junction)", "intersections"),
    RoadKind.T_JUNCTION: ("a T-junction", "T-junctions"),
    RoadKind.STRAIGHT: ("a straight road", "straight roads"),
}
COLOURS = {RoadKind.INTERSECTION: "tab:red", RoadKind.T_JUNCTION: "tab:blue", RoadKind.STRAIGHT: "tab:green"}


@dataclass(frozen=True)
class Survey:
    """The sites found on one map (of one kind, or of every kind), and how many of each kind it has."""

    map_name: str
    sites: tuple[Site, ...]
    counts: dict[RoadKind, int]  # every kind, whatever was asked
    short: tuple[Site, ...] = ()  # the straight sites of last resort (`short_sites`), when straight roads are asked
    min_length: float = DEFAULT_MIN_LENGTH

    def text(self) -> str:
        lines = [f"{self.map_name}: {have(self.counts)}"]
        for kind in RoadKind:
            chosen = [s for s in self.sites if s.kind is kind]
            if not chosen:
                continue
            lines.append(f"{KIND_NAMES[kind][1]} ({len(chosen)}):")
            lines += ["  " + describe(site) for site in chosen]
        if self.short:
            lines.append(f"{SHORT_NAME.format(self.min_length)} ({len(self.short)}):")
            lines += ["  " + describe(site) for site in self.short]
        return "\n".join(lines) + "\n"


# the heading the short straight sites are listed under, after every other site, as the search tries them
SHORT_NAME = "straight roads shorter than {:g} m, tried last"


def survey(road_map: RoadMap, kind: RoadKind | str | None = None, *, min_length: float = DEFAULT_MIN_LENGTH) -> Survey:
    every = find_sites(road_map, min_length=min_length)
    wanted = RoadKind(kind) if kind is not None else None
    counts = Counter(s.kind for s in every)
    return Survey(
        road_map.name,
        tuple(s for s in every if wanted is None or s.kind is wanted),
        {k: counts[k] for k in RoadKind},
        tuple(short_sites(road_map, wanted, min_length=min_length)),
        min_length,
    )


def have(counts: dict[RoadKind, int]) -> str:
    """'3 intersections, 12 T-junctions, 11 straight roads'."""
    return ", ".join(f"{counts.get(k, 0)} {KIND_NAMES[k][1]}" for k in RoadKind)


def missing(road_map: RoadMap, kind: RoadKind | str, *, min_length: float = DEFAULT_MIN_LENGTH) -> str | None:
    """The message for a map with no site of `kind`; None when it has one."""
    wanted = RoadKind(kind)
    found = survey(road_map, min_length=min_length)
    if found.counts[wanted]:
        return None
    message = f"{road_map.name} has no {KIND_NAMES[wanted][0].split(' ', 1)[1]}: it has {have(found.counts)}"
    if wanted is RoadKind.STRAIGHT and found.short:
        message += f"; {len(found.short)} {SHORT_NAME.format(min_length)}"
    return message + ramps(road_map, wanted)


def ramps(road_map: RoadMap, kind: RoadKind) -> str:
    """For a miss of a junction kind: the merges and diverges of one-way roads the map has instead."""
    count = merges(road_map) if kind is not RoadKind.STRAIGHT else 0
    if not count:
        return ""
    places = "place" if count == 1 else "places"
    return f"; {count} {places} where one-way roads only merge or diverge (ramps) are no junction of crossing traffic"


def describe(site: Site) -> str:
    """One line: the site, where it is, and per arm its heading, lanes each way and their widths."""
    x, y = site.centre
    arms = "; ".join(_arm(arm) for arm in site.arms)
    control = f" {site.control}" if site.control else ""
    median = f", open median {site.median:.1f} m" if site.median else ""
    return f"{site.id} at ({x:.0f}, {y:.0f}){control}, {site.min_length:.0f} m{median}: {arms}"


def _arm(arm: Arm) -> str:
    def widths(lanes: tuple) -> str:
        return "/".join(f"{lane.width:.1f}" for lane in lanes) or "-"

    return (
        f"{round(arm.heading) % 360}° {len(arm.incoming)} in ({widths(arm.incoming)} m)"
        f" + {len(arm.outgoing)} out ({widths(arm.outgoing)} m)"
    )


def draw(
    road_map: RoadMap,
    sites: tuple[Site, ...] | list[Site],
    path: str | os.PathLike[str],
    short: tuple[Site, ...] | list[Site] = (),
) -> Path:
    """The map's car lanes in grey and every site marked in its kind's colour, as a PNG at `path`; the
    short straight sites (`short_sites`), if given, dashed."""
    # matplotlib is heavy and only this picture needs it: imported here, not when the compiler loads.
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(12, 12))
    for edge in road_map.net.getEdges():
        if is_road(edge):
            for lane in edge.getLanes():
                xs, ys = zip(*(p[:2] for p in lane.getShape()), strict=True)
                axes.plot(xs, ys, color="0.75", linewidth=0.6)
    for site in sites:
        colour = COLOURS[site.kind]
        for arm in site.arms:
            for lane in arm.incoming + arm.outgoing:
                xs, ys = zip(*lane.shape, strict=True)
                axes.plot(xs, ys, color=colour, linewidth=1.4, alpha=0.8)
    for site in short:
        for arm in site.arms:
            for lane in arm.incoming + arm.outgoing:
                xs, ys = zip(*lane.shape, strict=True)
                axes.plot(xs, ys, color=COLOURS[RoadKind.STRAIGHT], linewidth=1.0, alpha=0.8, linestyle="--")
        if site.kind is not RoadKind.STRAIGHT:
            axes.plot(*site.centre, "o", color=colour, markersize=6)
        axes.annotate(site.id.split(":", 1)[1][:18], site.centre, fontsize=5, color=colour)
    counts = Counter(s.kind for s in sites)
    axes.set_title(f"{road_map.name}: " + have({k: counts[k] for k in RoadKind}))
    for kind, colour in COLOURS.items():
        axes.plot([], [], color=colour, label=KIND_NAMES[kind][1])
    if short:
        axes.plot([], [], color=COLOURS[RoadKind.STRAIGHT], linestyle="--", label="shorter straight roads, tried last")
    axes.legend(loc="upper right")
    axes.set_aspect("equal")
    out = Path(path)
    figure.savefig(out, dpi=110)
    plt.close(figure)
    return out
