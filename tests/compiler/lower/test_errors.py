"""Lowering's errors: no fitting site, an impossible crash (an unsat core with spans), a bad map."""

from __future__ import annotations

import contextlib
from pathlib import Path

import pytest
from sovarc.compiler.lower import lower
from sovarc.compiler.maps import load_map, match_sites
from sovarc.dsl import parse
from sovarc.dsl.errors import InputError, LoweringError, Severity, UnsatError

from tests.compiler.lower.staging import town
from tests.conftest import SHARED, requires_shared


def _vehicle(pid: str, heading: str, lane: int, actions: str = "follow_lane") -> str:
    return (
        f"  vehicle {pid} {{\n    heading {heading}\n    lane {lane}\n    speed 30 km/h\n"
        f"    actions {{\n      {actions}\n    }}\n  }}\n"
    )


def _scenario(name: str, kind: str, lanes: int, vehicles: list[str], crash: str) -> str:
    road = f"  road {{\n    kind {kind}\n    lanes {lanes}\n    speed_limit 50 km/h\n  }}\n"
    crash_block = f"  crash {{\n    type {crash}\n    striker V1\n    victim V2\n  }}\n"
    return f"scenario {name} {{\n{road}{''.join(vehicles)}{crash_block}}}\n"


def _line_of(text: str, needle: str, occurrence: int = 0) -> int:
    lines = [k + 1 for k, line in enumerate(text.splitlines()) if needle in line]
    return lines[occurrence]


FIVE_LANES = _scenario(
    "five_lanes", "straight", 10, [_vehicle("V1", "north", 5), _vehicle("V2", "north", 5)], "rear_end"
)


def test_no_site_with_five_lanes_per_direction_says_what_is_needed_and_what_the_map_has() -> None:
    with pytest.raises(LoweringError) as caught:
        match_sites(parse(FIVE_LANES, "five.sov"), town(), n=3)
    diagnostic = caught.value.diagnostics[0]
    assert "no site of town.net.xml fits scenario 'five_lanes'" in diagnostic.message
    assert "a straight road with V1 heading north: 5 lanes" in diagnostic.message
    assert (
        "the map has" in diagnostic.message and "straight roads (at most 4 lanes per direction)" in diagnostic.message
    )
    assert diagnostic.hint is not None and "clamp" in diagnostic.hint
    assert diagnostic.span is not None and diagnostic.span.line == _line_of(FIVE_LANES, "kind straight")


def test_lowering_clamps_five_lanes_to_the_widest_road_and_notes_it() -> None:
    staged = lower(parse(FIVE_LANES, "five.sov"), town(), roads=1)
    assert len(staged) == 1
    site_lanes = staged[0].match.site.lanes
    assert site_lanes < 5
    assert any(f"of the 5 lanes needed; lane numbers above {site_lanes} clamped" in n for n in staged[0].notes)


def test_no_t_junction_takes_traffic_from_four_directions() -> None:
    vehicles = [_vehicle(f"V{k + 1}", h, 1) for k, h in enumerate(("north", "east", "south", "west"))]
    text = _scenario("four_ways", "t_junction", 2, vehicles, "side")
    with pytest.raises(LoweringError) as caught:
        lower(parse(text, "four.sov"), town(), roads=3)
    assert not isinstance(caught.value, UnsatError)
    message = caught.value.diagnostics[0].message
    assert "no site of town.net.xml fits scenario 'four_ways': it needs a T-junction with" in message
    for pid, heading in (("V1", "north"), ("V2", "east"), ("V3", "south"), ("V4", "west")):
        assert f"{pid} heading {heading}" in message
    assert "T-junctions" in message.split("the map has", 1)[1]


SAME_WAY_FRONTAL = _scenario(
    "same_way_head_on", "straight", 2, [_vehicle("V1", "north", 1), _vehicle("V2", "north", 1)], "frontal"
)


def test_a_head_on_between_two_cars_going_the_same_way_is_unsat_with_spans_on_the_facts() -> None:
    with pytest.raises(UnsatError) as caught:
        lower(parse(SAME_WAY_FRONTAL, "same_way.sov"), town(), roads=1)
    head, *notes = caught.value.diagnostics
    assert head.severity is Severity.ERROR and "frontal" in head.message
    assert head.span is not None and head.span.file == "same_way.sov"
    assert head.span.line == _line_of(SAME_WAY_FRONTAL, "type frontal")
    heading_lines = {_line_of(SAME_WAY_FRONTAL, "heading north", k) for k in (0, 1)}
    assert {n.span.line for n in notes if n.span is not None} == heading_lines
    assert all(n.severity is Severity.NOTE for n in notes)
    rendered = caught.value.render()
    assert f"same_way.sov:{head.span.line}:" in rendered


@pytest.mark.parametrize(
    ("name", "content", "expected"),
    [
        ("garbage.net.xml", "this is not xml <", "not an XML file"),
        ("empty.net.xml", "", "map file is empty"),
        ("other.net.xml", "<routes><vehicle id='a'/></routes>", "not a SUMO network: its root element is <routes>"),
        ("broken.net.xml", "<net><edge id='e'><lane id='e_0' shape='x'/></edge></net>", "not a readable SUMO network"),
        ("town.osm", "<osm/>", "unknown map format"),
    ],
)
def test_a_bad_map_file_is_an_input_error_naming_the_file(
    tmp_path: Path, name: str, content: str, expected: str
) -> None:
    path = tmp_path / name
    path.write_text(content, encoding="utf-8")
    with pytest.raises(InputError) as caught:
        load_map(path)
    diagnostic = caught.value.diagnostics[0]
    assert expected in diagnostic.message
    assert diagnostic.span is not None and diagnostic.span.file == str(path)


def test_a_missing_map_file_is_an_input_error(tmp_path: Path) -> None:
    with pytest.raises(InputError, match="map file not found"):
        load_map(tmp_path / "nowhere.net.xml")


@requires_shared
@pytest.mark.slow  # loads the DRT city network (about 2 s)
def test_a_lane_shift_on_a_short_city_arm_is_a_lowering_error_not_a_crash() -> None:
    """Ground truth t/19 on SUMO's DRT city, junction 1677246221: the arm before the junction is shorter
    than a lane shift, `Drive.shift_to` blends from arc length 0 and `Polyline` raises ValueError
    ('a polyline needs two distinct points'). Lowering must fail with a SovarcError (or succeed)."""
    import sumo
    from sovarc.compiler.frontend.truth import import_truth_file
    from sovarc.compiler.lower import lower_on
    from sovarc.compiler.lower.assume import assume
    from sovarc.dsl.errors import SovarcError

    city = load_map(Path(sumo.SUMO_HOME) / "tools" / "game" / "DRT" / "osm.net.xml")
    staged, notes = assume(import_truth_file(SHARED / "data" / "nmvccs" / "truth" / "t" / "19.json").scenario)
    match = next(m for m in match_sites(staged, city, n=3, seed=0, clamp=True) if m.site.id == "junction:1677246221")
    with contextlib.suppress(SovarcError):  # an error that names the problem is fine; a ValueError is not
        lower_on(staged, match, city, notes)
