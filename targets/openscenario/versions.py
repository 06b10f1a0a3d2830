"""The OpenSCENARIO XML versions the target writes, and what differs between them.

The emitter asks a `Dialect` yes/no questions instead of comparing version strings, so each
difference between versions is named once, here.
"""

from __future__ import annotations

from dataclasses import dataclass

DEFAULT_VERSION = "1.3"


@dataclass(frozen=True)
class Dialect:
    version: str  # '1.0' .. '1.3'
    rev_minor: int
    schema_folder: str  # under schemas/openscenario/
    trajectory_ref: bool  # FollowTrajectoryAction wraps the trajectory in TrajectoryRef (1.1+)
    optional_environment: bool  # Environment, Weather children and cloudState may be left out (1.1+)
    wind: bool  # Weather has Wind (1.1+)
    precipitation_intensity: bool  # Precipitation.precipitationIntensity in mm/h (1.1+), not intensity 0..1
    sun_illuminance: bool  # Sun.illuminance (1.2+), not intensity
    cloud_cover: bool  # Weather.fractionalCloudCover in oktas (1.2+), not cloudState
    wetness: bool  # RoadCondition.wetness (1.2+)
    greater_or_equal: bool  # Rule greaterOrEqual (1.1+)
    priority: str  # Event priority that replaces running events: overwrite (1.0, 1.1), override (1.2+)


DIALECTS: dict[str, Dialect] = {
    d.version: d
    for d in (
        Dialect("1.0", 0, "1.0.0", False, False, False, False, False, False, False, False, "overwrite"),
        Dialect("1.1", 1, "1.1.1", True, True, True, True, False, False, False, True, "overwrite"),
        Dialect("1.2", 2, "1.2.0", True, True, True, True, True, True, True, True, "override"),
        Dialect("1.3", 3, "1.3.0", True, True, True, True, True, True, True, True, "override"),
    )
}

VERSIONS: tuple[str, ...] = tuple(DIALECTS)


def dialect(version: str) -> Dialect:
    """The dialect of '1.0'..'1.3' (also accepted: '1.1.1' and the like); ValueError for others."""
    key = ".".join(version.strip().split(".")[:2])
    if key not in DIALECTS:
        raise ValueError(f"OpenSCENARIO version {version!r} is not supported; choose one of {', '.join(VERSIONS)}")
    return DIALECTS[key]


def dialect_of_revision(rev_major: int, rev_minor: int) -> Dialect | None:
    """The dialect a file's FileHeader names, or None when it is not one the target knows."""
    return DIALECTS.get(f"{rev_major}.{rev_minor}") if rev_major == 1 else None
