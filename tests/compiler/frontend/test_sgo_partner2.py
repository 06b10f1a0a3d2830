"""The crash partner in fleet narratives, read from how such filings are written, each on sentences written for
these tests: an update's note before the narrative, a shuttle named by its model or fleet number, a second road
user of the partner's kind said with "a" after "the"."""

from __future__ import annotations

from sovarc.compiler.frontend import FrontEnd
from sovarc.compiler.frontend.sentences import narrative_start, sentences
from sovarc.dsl.ir import Action, ActionKind, Scenario, Side, Unknown
from sovarc.dsl.span import Source


def read(text: str) -> Scenario:
    return FrontEnd("none").extract(Source("sgo.txt", text)).scenario


def actions(s: Scenario, pid: str) -> list[Action]:
    p = next(p for p in s.participants if p.id == pid)
    return [] if isinstance(p.actions, Unknown) else list(p.actions)


NOTE = (
    "This is an update to report 12345-678-1, first submitted in May. Since then the operator learned of an "
    "injury to the cyclist involved in contact with the Waymo AV.\n"
)
DAY = (
    "On June [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle (Waymo AV) was in a collision involving a van. "
    "The Waymo AV was stopped at a red light on [XXX]. A van traveling behind the Waymo AV changed lanes to the left "
    "and made contact with the rear of the Waymo AV. The Waymo AV then rolled forward and made contact with a "
    "cyclist.\n"
)


def test_an_update_note_is_not_the_narrative() -> None:
    """The note names the crash's parties as already known; the crash is the narrative's first impact."""
    s = read(NOTE + DAY)
    assert s.crash.striker == "V2" and s.crash.victim == "V1"
    assert next(p for p in s.participants if p.id == "V2").kind.value == "van"
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE, Side.LEFT)


def test_the_narrative_starts_at_its_date_after_a_note() -> None:
    sents = sentences(NOTE + DAY)
    assert sents[narrative_start(sents)].startswith("On June [XXX], 2024")
    # no note: the narrative is the whole text
    assert narrative_start(sentences(DAY)) == 0
    # a note with no dated opening after it: only the sentences about the report
    undated = "Other than a corrected time, the content of this report is unchanged. The AV was stopped at a light."
    assert narrative_start(sentences(undated)) == 1


def test_a_note_that_says_the_report_is_unchanged() -> None:
    note = (
        "Other than noting that the vehicle that struck the Waymo AV had swerved, the content of this report is "
        "unchanged from the initial report.\n"
    )
    s = read(note + DAY)
    assert next(p for p in s.participants if p.id == "V2").kind.value == "van"
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE, Side.LEFT)


def kind_of(s: Scenario, pid: str) -> str:
    p = next(p for p in s.participants if p.id == pid)
    return str(p.kind.value) if not isinstance(p.kind, Unknown) else "unknown"


def test_a_version_number_is_no_label() -> None:
    """ "(V1.0)" after a shuttle's model is its version: the report still numbers nobody, so the rule does."""
    s = read(
        "A Harbor Mobility electric Tern shuttle (V2.1), running an autonomy kit, was driving in autonomous mode "
        "along a campus road. A pickup truck backed out of a driveway and struck the left side of the Tern."
    )
    assert {p.id for p in s.participants} == {"V1", "V2"}
    assert kind_of(s, "V2") == "pickup"
    assert actions(s, "V2")[-1].kind is ActionKind.REVERSE
    assert s.crash.striker == "V2" and s.crash.victim == "V1"


def test_a_shuttle_said_again_as_the_shuttle() -> None:
    s = read(
        "A Pelican Transit shuttle operated by Acme was driving on [XXX] under autonomous control. The shuttle "
        "slowed behind a parked van. The shuttle then steered left, striking a parked sedan on the other side of "
        "[XXX]."
    )
    assert s.crash.striker == "V1"
    assert kind_of(s, "V2") == "car"
    assert actions(s, "V2")[-1].kind is ActionKind.PARKED


def test_the_shuttle_is_not_another_shuttle() -> None:
    """A report that brings in a second shuttle leaves "the shuttle" unresolved: it may be either."""
    s = read(
        "A Pelican Transit shuttle operated by Acme was driving on [XXX] under autonomous control. A second "
        "shuttle was parked at the stop. The shuttle then struck a parked sedan."
    )
    assert "V2" not in {p.id for p in s.participants} or kind_of(s, "V2") != "car"


def test_a_shuttle_named_by_its_fleet_number() -> None:
    s = read(
        "An autonomous shuttle (Q207) was stopped at the transit stop on [XXX] while riders boarded. A city bus "
        "pulled in behind Q207 and then changed lanes to the left. Q207 began moving again, and the bus moved back "
        "into the transit lane and struck the left front side of Q207."
    )
    assert s.crash.striker == "V2" and s.crash.victim == "V1"
    assert kind_of(s, "V2") == "bus"
    assert "Q207" not in " ".join(p.id for p in s.participants)


def test_nearly_stopped_at_the_impact_is_still_moving() -> None:
    s = read(
        "An Acme Autonomous Vehicle (Acme AV) was traveling north on [XXX]. A sedan pulled out of a parking space "
        "ahead of the Acme AV, and although the Acme AV was nearly stopped, its front struck the left side of the "
        "sedan."
    )
    assert actions(s, "V1")[-1].kind is ActionKind.FOLLOW_LANE
    assert s.crash.striker == "V1"


def test_back_into_a_lane_it_had_left_is_a_lane_change() -> None:
    """The side is the one the impact shows (see test_sgo_partner): it met V1's left, so it moved right."""
    s = read(
        "An Acme Autonomous Vehicle (Acme AV) was traveling north in the bus lane of [XXX]. A delivery van "
        "behind the Acme AV left the bus lane for the general travel lane, then re-entered the bus lane and made "
        "contact with the left side of the Acme AV."
    )
    assert s.crash.striker == "V2"
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE, Side.RIGHT)


def test_back_onto_the_travel_lane_is_still_onto_the_road() -> None:
    s = read(
        "An Acme Autonomous Vehicle (Acme AV) was traveling north on [XXX]. A sedan stopped on the shoulder "
        "re-entered the travel lane and made contact with the rear of the Acme AV."
    )
    assert actions(s, "V2")[-1].kind is ActionKind.DRIVE_INTO


def test_beginning_to_pull_out_after_a_stop_is_moving_off() -> None:
    s = read(
        "An Acme Autonomous Vehicle (Acme AV) stopped behind a delivery truck on [XXX]. The Acme AV then went "
        "around the truck. A sedan stopped at the curb began to pull out and made contact with the rear of the "
        "Acme AV."
    )
    assert [a.kind for a in actions(s, "V2")][-2:] == [ActionKind.STOP, ActionKind.FOLLOW_LANE]


def test_pulling_out_of_a_place_or_over_is_no_moving_off() -> None:
    s = read(
        "An Acme Autonomous Vehicle (Acme AV) was traveling north on [XXX]. A sedan began to pull out of a "
        "parking space and made contact with the right side of the Acme AV."
    )
    assert actions(s, "V2")[-1].kind is ActionKind.DRIVE_INTO


def test_from_behind_toward_the_side_of_another_is_a_move_to_that_side() -> None:
    s = read(
        "An Acme Autonomous Vehicle (Acme AV) was stopped at a red light on [XXX]. The sedan directly behind the "
        "Acme AV moved toward the left side of the Acme AV and made contact with its rear bumper."
    )
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE, Side.LEFT)


def test_toward_the_rear_of_another_is_no_sideways_move() -> None:
    s = read(
        "An Acme Autonomous Vehicle (Acme AV) was stopped at a red light on [XXX]. A sedan traveling behind the "
        "Acme AV accelerated toward the rear of the Acme AV and made contact with its rear bumper."
    )
    assert all(a.kind is not ActionKind.CHANGE_LANE for a in actions(s, "V2"))


def test_the_truck_is_not_the_automated_truck_beside_another_truck() -> None:
    """With "a semi-truck" brought in, "the truck" may be either: it is not taken for the automated truck."""
    s = read(
        "An Acme truck was driving in autonomous mode in the right lane of [XXX]. A semi-truck in the left lane "
        "changed lanes to the right, and the truck made contact with the left side of the Acme truck."
    )
    assert s.crash.victim == "V1" and s.crash.striker != "V1"


def test_a_lane_named_before_the_verb_is_no_lane_change_noun() -> None:
    """ "in the left lane changed lanes to the right": the side is the one after the verb, not the lane's."""
    s = read(
        "An Acme Autonomous Vehicle (Acme AV) was traveling in the right lane of [XXX]. A sedan in the left lane "
        "changed lanes to the right and made contact with the left side of the Acme AV."
    )
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE, Side.RIGHT)
    s = read(
        "An Acme Autonomous Vehicle (Acme AV) was traveling in the right lane of [XXX]. A sedan made a right lane "
        "change and made contact with the left side of the Acme AV."
    )
    assert actions(s, "V2")[-1] == Action(ActionKind.CHANGE_LANE, Side.RIGHT)


def test_a_narrative_that_quotes_a_report_has_no_note() -> None:
    sents = sentences(
        "According to the police report, the Acme AV was struck by a sedan. On May [XXX], 2024 the Acme AV was "
        "stopped at a light."
    )
    assert narrative_start(sents) == 0


def test_a_bus_route_beside_the_partner_is_no_fleet_number_of_the_automated_vehicle() -> None:
    s = read(
        "An Acme Autonomous Vehicle (Acme AV) was stopped at a red light on [XXX]. A city bus, M15, pulled away "
        "from the stop and made contact with the left side of the Acme AV."
    )
    assert s.crash.striker == "V2" and s.crash.victim == "V1"
