"""The site search's rules on hand-made sites: rotation, stem or bar, lanes, clamping, diversity (no SUMO)."""

from __future__ import annotations

from dataclasses import replace

import pytest
from sovarc.compiler.maps import Arm, Connection, LaneInfo, Site, match_site, pick_diverse, scenario_needs
from sovarc.dsl import parse
from sovarc.dsl.ir import Heading, RoadKind


def lanes(edge: str, count: int, width: float = 3.2) -> tuple[LaneInfo, ...]:
    return tuple(LaneInfo(f"{edge}_{i}", edge, i, i + 1, width, 100.0, 13.9, ((0, 0), (0, 100))) for i in range(count))


def arm(name: str, heading: float, slot: int, n_in: int, n_out: int) -> Arm:
    return Arm(name, heading, slot, lanes(name, n_in), lanes(f"-{name}", n_out), 100.0)


def link(src: str, dst: str, direction: str) -> Connection:
    return Connection(f"{src}_0", f"-{dst}_0", direction, None)


# A T-junction: the bar runs east-west (arms w, e), the stem s comes up from the south.
T_SITE = Site(
    id="junction:t",
    kind=RoadKind.T_JUNCTION,
    centre=(0.0, 0.0),
    orientation=0.0,
    arms=(arm("s", 0.0, 0, 1, 1), arm("w", 90.0, 1, 2, 2), arm("e", 270.0, 3, 2, 2)),
    connections=tuple(
        sorted(
            [
                link("w", "e", "s"),
                link("w", "s", "r"),
                link("e", "w", "s"),
                link("e", "s", "l"),
                link("s", "w", "l"),
                link("s", "e", "r"),
            ],
            key=lambda c: (c.from_lane, c.to_lane),
        )
    ),
    junction="t",
    control="priority",
)


def scenario(*vehicles: tuple[str, str, str], kind: str = "t_junction") -> tuple:
    """Needs of a scenario with one vehicle per (heading, lane, actions)."""
    body = "".join(
        f"  vehicle V{i} {{\n    heading {h}\n    lane {lane}\n    actions {{\n      {acts}\n    }}\n  }}\n"
        for i, (h, lane, acts) in enumerate(vehicles, start=1)
    )
    return scenario_needs(parse(f"scenario s {{\n  road {{\n    kind {kind}\n  }}\n{body}}}\n"))


def test_report_north_is_the_arm_whose_traffic_enters_heading_north() -> None:
    match = match_site(T_SITE, scenario(("north", "1", "turn_left"), ("east", "1", "go_across")))
    assert match is not None and match.rotation == 0
    assert match.placement("V1").arm == "s" and match.placement("V2").arm == "w"
    assert dict(match.arms) == {Heading.NORTH: "s", Heading.EAST: "w", Heading.SOUTH: None, Heading.WEST: "e"}


def test_a_heading_moves_from_the_stem_to_the_bar_when_its_action_needs_it() -> None:
    # going straight across is impossible from the stem, so the compass turns by a quarter
    match = match_site(T_SITE, scenario(("north", "1", "go_across"), ("south", "1", "go_across")))
    assert match is not None and match.rotation == 90
    assert (match.placement("V1").arm, match.placement("V2").arm) == ("w", "e")
    assert match.site_heading(Heading.NORTH) == 90.0


def test_no_rotation_fits_three_roads_going_straight() -> None:
    assert match_site(T_SITE, scenario(("north", "1", "go_across"), ("east", "1", "go_across"))) is None


def test_lanes_must_fit_unless_clamped() -> None:
    needs = scenario(("east", "3", "follow_lane"))
    assert match_site(T_SITE, needs) is None
    match = match_site(T_SITE, needs, clamp=True)
    assert match is not None and not match.exact
    assert match.placement("V1").lane == 2
    assert match.clamped == ("V1: arm w has 2 of the 3 lanes needed; lane numbers above 2 clamped to 2",)


def test_a_turn_into_a_narrow_road_is_clamped_too() -> None:
    needs = scenario(("west", "1", "turn_left(to: 3)"))
    assert match_site(T_SITE, needs) is None
    match = match_site(T_SITE, needs, clamp=True)
    assert match is not None and match.rotation == 0
    (note,) = match.clamped
    assert note == "V1: the road its turn_left enters has 1 of the 3 lanes needed; lane numbers above 1 clamped to 1"


def test_an_exact_rotation_is_preferred_to_a_clamped_one() -> None:
    wide = replace(T_SITE, arms=(arm("s", 0.0, 0, 3, 3), *T_SITE.arms[1:]))
    match = match_site(wide, scenario(("east", "3", "follow_lane")), clamp=True)
    assert match is not None and match.exact and match.placement("V1").arm == "s"


def test_wrong_way_driving_and_u_turns_need_the_opposite_lanes() -> None:
    one_way = replace(T_SITE, arms=(arm("s", 0.0, 0, 1, 0), *T_SITE.arms[1:]))
    for actions in ("retrograde", "u_turn"):
        needs = scenario(("north", "1", actions))
        assert match_site(T_SITE, needs) is not None, actions
        match = match_site(one_way, needs)
        assert match is None or match.placement("V1").arm != "s", actions
    # driving the wrong way after a turn needs the opposite lanes of the road turned into
    no_return = replace(T_SITE, arms=(T_SITE.arms[0], arm("w", 90.0, 1, 0, 2), T_SITE.arms[2]))
    needs = scenario(("north", "1", "turn_left\n      retrograde"))
    assert match_site(T_SITE, needs) is not None
    match = match_site(no_return, needs)
    assert match is None or match.placement("V1").arm != "s"


def test_an_unknown_heading_needs_only_some_arm_wide_enough() -> None:
    match = match_site(T_SITE, scenario(("unknown", "2", "follow_lane")))
    assert match is not None and match.placement("V1").arm is None
    assert match_site(T_SITE, scenario(("unknown", "3", "follow_lane"))) is None


def test_turns_off_a_straight_road_need_no_connection() -> None:
    road = Site("road:a|-a", RoadKind.STRAIGHT, (0.0, 0.0), 0.0, (arm("a", 0.0, 0, 2, 2), arm("-a", 180.0, 2, 2, 2)))
    match = match_site(road, scenario(("south", "1", "turn_left"), ("north", "2", "follow_lane"), kind="straight"))
    assert match is not None and match.rotation == 0
    assert match.placement("V1").arm == "-a"
    assert match_site(road, scenario(("east", "1", "follow_lane"), ("north", "1", "follow_lane"))) is None


def sites_with(widths: list[float]) -> list:
    needs = scenario(("north", "1", "turn_left"))
    out = []
    for i, width in enumerate(widths):
        site = replace(
            T_SITE,
            id=f"junction:t{i}",
            arms=tuple(replace(a, incoming=lanes(a.id, len(a.incoming), width)) for a in T_SITE.arms),
        )
        out.append(match_site(site, needs))
    return out


def test_pick_diverse_is_deterministic_distinct_and_spread() -> None:
    matches = sites_with([3.0, 3.01, 3.02, 3.5, 4.0])
    first = pick_diverse(matches, 3, seed=7)
    assert [m.site.id for m in first] == [m.site.id for m in pick_diverse(list(reversed(matches)), 3, seed=7)]
    assert len({m.site.id for m in first}) == 3
    widths = sorted(round(m.site.mean_width, 2) for m in first)
    assert widths[0] <= 3.11 and widths[-1] >= 3.6  # both ends of the range, not three near-twins
    starts = {pick_diverse(matches, 1, seed=s)[0].site.id for s in range(20)}
    assert len(starts) > 1
    assert len(pick_diverse(matches, 10, seed=0)) == 5


def test_pick_diverse_takes_exact_fits_first() -> None:
    exact = sites_with([3.0])[0]
    clamped = replace(sites_with([4.0])[0], clamped=("V1: clamped",))
    assert [m.exact for m in pick_diverse([clamped, exact], 2, seed=3)] == [True, False]


@pytest.mark.parametrize("n", [0, -1])
def test_n_must_be_positive(n: int) -> None:
    from sovarc.compiler.maps import match_sites

    with pytest.raises(ValueError, match="at least 1"):
        match_sites(parse("scenario s {\n}\n"), None, n=n)  # type: ignore[arg-type]
