"""The IR's weather and lighting as an OpenSCENARIO Environment.

What the format cannot say (street lights; wind before 1.1; rain and snow at once) comes back
as a warning naming the IR span; what the format requires but the report does not state
(a date; clouds when only the light is known, in 1.0) comes back as a note.
"""

from __future__ import annotations

from dataclasses import dataclass

from lxml import etree
from sovarc.dsl.errors import Diagnostic, Severity
from sovarc.dsl.ir import Environment, Lighting, Unknown, Weather
from sovarc.targets.openscenario.versions import Dialect
from sovarc.targets.openscenario.xml import el, num

# The report gives no date; a fixed one keeps output reproducible. Only the time of day is read.
DATE = "2000-06-21"
NIGHT_TIME = "23:00:00"
DUSK_TIME = "20:30:00"
NOON_TIME = "12:00:00"


@dataclass(frozen=True)
class Sky:
    time: str
    sun_elevation: float  # rad above the horizon
    sun_azimuth: float  # rad, clockwise from north
    illuminance: float  # lx


DAY = Sky(NOON_TIME, 1.2, 3.1416, 100000.0)
DUSK = Sky(DUSK_TIME, 0.05, 5.0, 400.0)
NIGHT = Sky(NIGHT_TIME, -0.4, 5.8, 0.0)


def _sky(lighting: tuple[Lighting, ...] | Unknown) -> Sky | None:
    if isinstance(lighting, Unknown):
        return None
    day, dark = Lighting.DAYLIGHT in lighting, Lighting.DARK in lighting or Lighting.STREET_LIGHTS in lighting
    if day and dark:
        return DUSK
    return DAY if day else NIGHT


def environment_element(env: Environment, dialect: Dialect) -> tuple[etree._Element | None, list[Diagnostic]]:
    """The <Environment> for the IR environment, or None when weather and lighting are both unknown."""
    weather, lighting = env.weather, env.lighting
    notes: list[Diagnostic] = []
    where_w, where_l = env.meta.where("weather"), env.meta.where("lighting")
    if isinstance(weather, Unknown) and isinstance(lighting, Unknown):
        notes.append(Diagnostic("weather and lighting unknown: no EnvironmentAction, the player's defaults apply",
                                env.meta.span, Severity.NOTE))  # fmt: skip
        return None, notes
    sky = _sky(lighting)
    if sky is not None:
        notes.append(Diagnostic(f"the report gives no date: TimeOfDay uses {DATE}, time from the lighting",
                                where_l, Severity.NOTE))  # fmt: skip
        if not isinstance(lighting, Unknown) and Lighting.STREET_LIGHTS in lighting:
            notes.append(Diagnostic("lighting street_lights: OpenSCENARIO has no road lighting; "
                                    "written as night (or dusk with daylight)", where_l, Severity.WARNING))  # fmt: skip
    elif not dialect.optional_environment:
        sky = DAY
        notes.append(Diagnostic("lighting unknown: OpenSCENARIO 1.0 requires a time of day; noon written",
                                where_l, Severity.NOTE))  # fmt: skip
    stated = frozenset(() if isinstance(weather, Unknown) else weather)
    if isinstance(weather, Unknown) and not dialect.optional_environment:
        notes.append(Diagnostic("weather unknown: OpenSCENARIO 1.0 requires a weather; clear and dry written",
                                where_w, Severity.NOTE))  # fmt: skip
    if Weather.RAINY in stated and Weather.SNOWY in stated:
        notes.append(Diagnostic("weather rainy and snowy: OpenSCENARIO has one precipitation type; rain written",
                                where_w, Severity.WARNING))  # fmt: skip
    if Weather.WINDY in stated and not dialect.wind:
        notes.append(Diagnostic(f"weather windy: OpenSCENARIO {dialect.version} has no wind (1.1 and later have)",
                                where_w, Severity.WARNING))  # fmt: skip
    write_weather = not isinstance(weather, Unknown) or not dialect.optional_environment
    node = el(
        "Environment",
        {"name": "sovarc_environment"},
        _time_of_day(sky) if sky is not None else None,
        _weather(stated, sky, dialect) if write_weather or sky is not None else None,
        _road_condition(stated, dialect) if write_weather else None,
    )
    return node, notes


def _time_of_day(sky: Sky) -> etree._Element:
    return el("TimeOfDay", {"animation": False, "dateTime": f"{DATE}T{sky.time}"})


def _cloud(stated: frozenset[Weather]) -> tuple[str, str] | None:
    """(cloudState, fractionalCloudCover) the weather words imply, or None when they say nothing of clouds."""
    if Weather.RAINY in stated or Weather.SNOWY in stated:
        return "overcast", "eightOktas"
    if Weather.CLOUDY in stated:
        return "cloudy", "sixOktas"
    if Weather.CLEAR in stated or Weather.SUNNY in stated:
        return "free", "zeroOktas"
    return None


def _weather(stated: frozenset[Weather], sky: Sky | None, dialect: Dialect) -> etree._Element:
    attrs: dict[str, str] = {}
    cloud = _cloud(stated)
    if cloud is None and not dialect.optional_environment:
        cloud = ("free", "zeroOktas")
    if cloud is not None:
        attrs["fractionalCloudCover" if dialect.cloud_cover else "cloudState"] = cloud[1 if dialect.cloud_cover else 0]
    children: list[etree._Element | None] = []
    if sky is not None or not dialect.optional_environment:
        sky = sky or DAY
        overcast = cloud is not None and cloud[0] == "overcast"
        light = sky.illuminance * (0.1 if overcast else 1.0)
        sun = {"azimuth": num(sky.sun_azimuth, 4), "elevation": num(sky.sun_elevation, 4)}
        sun["illuminance" if dialect.sun_illuminance else "intensity"] = num(light)
        children.append(el("Sun", sun))
    if Weather.FOGGY in stated:
        children.append(el("Fog", {"visualRange": num(100.0)}))
    elif not dialect.optional_environment:
        children.append(el("Fog", {"visualRange": num(100000.0)}))
    precipitation = _precipitation(stated, dialect)
    if precipitation is not None:
        children.append(precipitation)
    if Weather.WINDY in stated and dialect.wind:
        children.append(el("Wind", {"direction": 0, "speed": num(12.0)}))
    return el("Weather", attrs, *children)


def _precipitation(stated: frozenset[Weather], dialect: Dialect) -> etree._Element | None:
    if Weather.RAINY in stated:
        kind, mm_per_h = "rain", 5.0
    elif Weather.SNOWY in stated:
        kind, mm_per_h = "snow", 2.0
    elif stated or not dialect.optional_environment:
        kind, mm_per_h = "dry", 0.0
    else:
        return None
    if dialect.precipitation_intensity:
        return el("Precipitation", {"precipitationType": kind, "precipitationIntensity": num(mm_per_h)})
    return el("Precipitation", {"intensity": num(min(1.0, mm_per_h / 5.0)), "precipitationType": kind})


def _road_condition(stated: frozenset[Weather], dialect: Dialect) -> etree._Element:
    if Weather.SNOWY in stated:
        friction, wetness = 0.4, "moist"
    elif Weather.RAINY in stated:
        friction, wetness = 0.7, "wetWithPuddles"
    else:
        friction, wetness = 1.0, "dry"
    attrs = {"frictionScaleFactor": num(friction)}
    if dialect.wetness:
        attrs["wetness"] = wetness
    return el("RoadCondition", attrs)
