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
