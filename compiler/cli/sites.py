"""`sovarc sites`: what the compiler sees in a map, the sites it finds per kind, listed and drawn."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from sovarc.compiler.maps import load_map
from sovarc.compiler.maps.sites import DEFAULT_MIN_LENGTH
from sovarc.compiler.maps.survey import draw, missing, survey
from sovarc.compiler.pipeline import default_map
from sovarc.dsl.errors import EXIT_INPUT, EXIT_OK
from sovarc.dsl.ir import RoadKind

KINDS = tuple(k.value for k in RoadKind)


def add_sites_parser(sub: Any, summary: str, formatter: Any) -> None:
    sites = sub.add_parser(
        "sites",
        help=summary,
        formatter_class=formatter,
        description=(
            "List the sites the compiler finds in a map, per road kind: each site's id, where it is, and per\n"
            "arm its heading, its lanes each way and their widths. With --png, draw the map with the sites\n"
            "marked (intersections red, T-junctions blue, straight roads green). Straight stretches shorter than\n"
            "--min-length (a city block between junctions) are listed last, under their own heading, and drawn\n"
            "dashed: the site search tries them only after every other fitting site. A kind the map lacks is said,\n"
            "with how many sites of each kind it has.\n\n"
            "examples:\n"
            "  sovarc sites examples/maps/town.net.xml\n"
            "  sovarc sites ../shared/data/opendrive/carla/Town01.xodr --png town01.png\n"
            "  sovarc sites city.net.xml --kind straight --min-length 120"
        ),
    )
    sites.add_argument("map", nargs="?", help="road network, .net.xml or .xodr (default: the bundled example town)")
    sites.add_argument("--kind", choices=KINDS, help="list only the sites of this kind")
    sites.add_argument("--png", metavar="FILE", help="also draw the map with its sites marked, as a PNG")
    sites.add_argument(
        "--min-length",
        type=float,
        default=DEFAULT_MIN_LENGTH,
        metavar="M",
        help=f"the shortest straight site tried before short ones, in metres (default {DEFAULT_MIN_LENGTH:g})",
    )


def cmd_sites(args: argparse.Namespace) -> int:
    road_map = load_map(args.map or default_map())
    found = survey(road_map, args.kind, min_length=args.min_length)
    print(found.text(), end="")
    if road_map.keeps_left:
        print(
            f"note: traffic keeps left on {road_map.name}: a report's crash is staged here as its mirror image "
            "(its left turns across the oncoming lanes are right turns)",
            file=sys.stderr,
        )
    if args.png:
        draw(road_map, found.sites, args.png, found.short)
        print(f"drawn to {args.png}", file=sys.stderr)
    lacking = missing(road_map, args.kind, min_length=args.min_length) if args.kind else None
    if lacking:
        print(f"sovarc: {lacking}", file=sys.stderr)
        return EXIT_INPUT
    return EXIT_OK
