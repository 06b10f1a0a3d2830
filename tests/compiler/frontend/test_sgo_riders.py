"""One road user said by two of its kind's names (issue 18, sgo7), on sentences written for these tests: "a
pickup truck" is later "the pickup", and a motorcycle is "the motorcyclist" who rides it."""

from __future__ import annotations

from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.names import label_parties
from sovarc.dsl.ir import ActionKind, CrashType, Scenario
from sovarc.dsl.span import Source


def read(text: str) -> Scenario:
    return FrontEnd("none").extract(Source("sgo.txt", text)).scenario


def test_the_pickup_is_the_pickup_truck() -> None:
    named, _ = label_parties(
        "A Waymo Autonomous Vehicle was in a collision involving a pickup truck. The Waymo AV stopped, yielding to "
        "the oncoming pickup truck, and the driver side of the pickup made contact with the front of the Waymo AV."
    )
    assert "V3" not in named and "the driver side of V2 made contact" in named


def test_the_motorcyclist_rides_the_motorcycle() -> None:
    s = read(
        "A Waymo Autonomous Vehicle was in a collision involving a motorcycle on Pine Street. The Waymo AV was "
        "stopped in traffic in the left lane. A motorcyclist then approached from behind the stopped Waymo AV. As "
        "the motorcyclist passed, the motorcycle made contact with the rear passenger side corner of the Waymo AV."
    )
    assert [p.id for p in s.participants] == ["V1", "V2"]
    assert (s.crash.striker, s.crash.victim, s.crash.type) == ("V2", "V1", CrashType.REAR_END)
    # what the motorcyclist did is the motorcycle's, not the stopped automated vehicle's
    v1 = s.participants[0]
    assert isinstance(v1.actions, tuple) and v1.actions[-1].kind is ActionKind.STOP
