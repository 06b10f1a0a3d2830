"""The map layer: load a road network, find its candidate sites, and match a scenario onto them.

road_map = load_map("town.net.xml")              # or an OpenDRIVE .xodr, through netconvert
network = with_opendrive(road_map.network)   # the map in both formats, as plans carry it
sites = find_sites(road_map, RoadKind.T_JUNCTION)
last = short_sites(road_map)                     # straight stretches of a city block, tried last
matches = match_sites(scenario, road_map, n=3, seed=0)
"""

from sovarc.compiler.maps.load import RoadMap, load_map, planning_map
from sovarc.compiler.maps.needs import Need, scenario_needs
from sovarc.compiler.maps.netconvert import ToolError, convert_opendrive
from sovarc.compiler.maps.networks import network_of, with_opendrive
from sovarc.compiler.maps.search import (
    Placement,
    SiteMatch,
    has_shape,
    match_site,
    match_sites,
    pick_diverse,
    site_rotations,
)
from sovarc.compiler.maps.sites import Arm, Connection, LaneInfo, Site, find_sites, short_sites

__all__ = [
    "Arm",
    "Connection",
    "LaneInfo",
    "Need",
    "Placement",
    "RoadMap",
    "Site",
    "SiteMatch",
    "ToolError",
    "convert_opendrive",
    "find_sites",
    "has_shape",
    "load_map",
    "match_site",
    "match_sites",
    "network_of",
    "pick_diverse",
    "planning_map",
    "scenario_needs",
    "short_sites",
    "site_rotations",
    "with_opendrive",
]
