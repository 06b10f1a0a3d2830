"""The SUMO oracle's lane look-ups."""

from __future__ import annotations

from sovarc.targets.sumo.network import read_network

from tests.targets.sumo.plans import TOWN


def test_locate_prefers_the_participants_own_junction_lane() -> None:
    network = read_network(TOWN)
    # inside x_oak, where the northbound straight lane crosses the eastbound lane 2
    point = (401.7, -5.9)
    own = network.locate(*point, 0.0, frozenset({":x_oak_12_0"}))
    assert own.lane.id == ":x_oak_12_0"
    assert network.locate(*point, 90.0, frozenset({":x_oak_16_1"})).lane.id == ":x_oak_16_1"
    assert network.locate(4.5, -150.0, 0.0, frozenset()).lane.id == "main1_1"  # a car
    assert network.locate(7.0, -150.0, 0.0, frozenset()).lane.id == "main1_1"  # never on the sidewalk
    assert network.locate(7.0, -150.0, 0.0, frozenset(), pedestrian=True).lane.id == "main1_0"
