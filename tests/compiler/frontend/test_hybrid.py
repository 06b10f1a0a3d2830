"""Hybrid extraction on recorded model answers: merging and cross-checks, the repair loop, defaults, the cache.

`fixtures/answers/<report>.json` are the embedded model's real answers to our
own example reports (recorded with `sovarc extract`, see fixtures/README.md);
`fixtures/hybrid/<report>.sov` are the scenarios they give, as golden files.
Broken answers below are written by hand to stand for a model gone wrong.
"""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest
from sovarc.compiler.frontend import FrontEnd, FrontEndError
from sovarc.compiler.frontend.cache import CachedProvider
from sovarc.compiler.frontend.defaults import apply_defaults
from sovarc.compiler.frontend.hybrid import AnswerError, merge, parse_answer
from sovarc.compiler.frontend.layers import cue, motion_layer, states_action
from sovarc.compiler.frontend.providers import ProviderError
from sovarc.compiler.frontend.rules import extract
from sovarc.dsl import read_source, to_text, verify
from sovarc.dsl.ir import (
    UNKNOWN,
    Action,
    ActionKind,
    Crash,
    CrashType,
    Heading,
    Participant,
    Road,
    Role,
    Scenario,
    Side,
)
from sovarc.dsl.span import Source

from tests.conftest import EXAMPLES, Golden

FIXTURES = Path(__file__).parent / "fixtures"
RECORDED = sorted((FIXTURES / "answers").glob("*.json"))
LEFT_TURN = EXAMPLES / "reports" / "left_turn_oncoming_pickup.txt"
# The left-turn report shows sentences 5 (V1 turning left), 6 (V2 going straight), 7 and 8 (the impact).
GOOD = '{"V1":["follow","left",5],"V2":["follow",6],"crash":["side","V2","V1",8]}'
LEFT_TURN_SHOWN = motion_layer(LEFT_TURN.read_text())


class Recorded:
    """A provider that plays back recorded answers in order and keeps the prompts it was given."""

    name = "recorded"
    model = "recorded-answers"

    def __init__(self, *answers: str) -> None:
        self.answers = list(answers)
        self.prompts: list[str] = []

    def complete_json(self, system: str, user: str, schema: dict[str, Any], *, max_tokens: int) -> str:
        self.prompts.append(user)
        if not self.answers:
            raise ProviderError("no recorded answer left")
        return self.answers.pop(0)


def _front_end(*answers: str) -> tuple[FrontEnd, Recorded]:
    recorded = Recorded(*answers)
    return FrontEnd("embedded", use_cache=False).use(recorded), recorded


@pytest.mark.parametrize("answer", RECORDED, ids=lambda p: p.stem)
def test_recorded_answers_give_the_golden_scenarios(answer: Path, golden: Golden) -> None:
    report = EXAMPLES / "reports" / f"{answer.stem}.txt"
    front_end, _ = _front_end(*json.loads(answer.read_text())["answers"])
    got = front_end.extract(read_source(str(report.relative_to(EXAMPLES.parent)), "crash report"))
    assert [d for d in verify(got.scenario) if d.severity == "error"] == []
    golden.check(FIXTURES / "hybrid" / f"{answer.stem}.sov", to_text(got.scenario))


def test_there_are_recorded_answers_for_every_example_report() -> None:
    assert {p.stem for p in RECORDED} == {p.stem for p in (EXAMPLES / "reports").glob("*.txt")}


def test_a_garbage_answer_is_repaired_with_the_problem_named() -> None:
    front_end, recorded = _front_end("V1 turned left, I think.", GOOD)
    got = front_end.extract(read_source(str(LEFT_TURN), "crash report"))
    assert "the answer is not JSON" in recorded.prompts[1] and "V1 turned left, I think." in recorded.prompts[1]
    assert "the model's answer was repaired in 1 round(s)" in got.notes
    assert [a.kind for a in got.scenario.participant("V1").known_actions] == ["follow_lane", "turn_left"]


def test_verifier_errors_go_back_to_the_model() -> None:
    good = '{"V1":["follow","left",1],"V2":["follow",2],"crash":["side","V2","V1",3]}'
    self_strike = good.replace('"V2","V1",3', '"V2","V2",3')
    front_end, recorded = _front_end(self_strike, good)
    unstated = "At the intersection V1 was westbound and turned left. V2 was eastbound. V1 and V2 collided."
    got = front_end.extract(Source("r.txt", unstated))
    assert "'V2' cannot strike itself" in recorded.prompts[1]
    assert got.scenario.crash == Crash(CrashType.SIDE, "V2", "V1")


def test_the_repair_loop_is_bounded_and_then_the_rules_reading_stands() -> None:
    front_end, recorded = _front_end("{", "{", "{", GOOD)
    got = front_end.extract(read_source(str(LEFT_TURN), "crash report"))
    assert len(recorded.prompts) == 3 and recorded.answers == [GOOD]
    assert any("no usable answer after 2 repair round(s)" in note for note in got.notes)
    rules = apply_defaults(extract(LEFT_TURN.read_text(), "left_turn_oncoming_pickup", str(LEFT_TURN)))
    assert got.scenario.participants == rules.participants


def test_schema_violations_are_named_by_path() -> None:
    flying = json.loads(GOOD)
    flying["V1"] = ["fly", 5]
    flying["crash"] = ["side", "V2", "V1", 3]  # sentence 3 is not among those shown
    with pytest.raises(AnswerError) as caught:
        parse_answer(json.dumps(flying), ["V1", "V2"], LEFT_TURN_SHOWN)
    assert any(p.startswith("V1/0: 'fly' is not valid") for p in caught.value.problems), caught.value.problems
    assert any(p.startswith("crash/3: 3 is not one of [5, 6, 7, 8]") for p in caught.value.problems)
    numbers_first = GOOD.replace('["follow","left",5]', '[5,"follow","left"]')
    with pytest.raises(AnswerError, match="V1: the actions first, then the numbers"):
        parse_answer(numbers_first, ["V1", "V2"], LEFT_TURN_SHOWN)


def test_the_answer_carries_its_evidence_as_sentence_numbers_and_report_spans() -> None:
    answer = parse_answer(GOOD, ["V1", "V2"], LEFT_TURN_SHOWN)
    assert answer.evidence == {
        "V1.actions": (5,),
        "V2.actions": (6,),
        "crash.type": (8,),
        "crash.striker": (8,),
        "crash.victim": (8,),
    }
    text = LEFT_TURN.read_text()
    ((start, end),) = answer.spans["crash.striker"]
    assert text[start:end] == "The front of V2 struck the right side of V1 within the intersection."


def _two(v1: tuple[Action, ...], v2: tuple[Action, ...], crash: Crash | None = None) -> Scenario:
    return Scenario(
        "s",
        road=Road(lanes=4),
        participants=(
            Participant("V1", Role.VEHICLE, Heading.NORTH, 1, actions=v1),
            Participant("V2", Role.VEHICLE, actions=v2),
        ),
        crash=crash or Crash(),
    )


FOLLOW = (Action(ActionKind.FOLLOW_LANE),)


def test_cross_checks_settle_each_disagreement_by_its_evidence() -> None:
    rules = _two(FOLLOW, FOLLOW, Crash(CrashType.REAR_END, "V1", "V2"))
    merged, notes = merge(rules, parse_answer(GOOD, ["V1", "V2"], LEFT_TURN_SHOWN), LEFT_TURN_SHOWN)
    # a crash the report states outright is the rules'
    assert merged.crash == Crash(CrashType.REAR_END, "V1", "V2")
    assert "crash: the report states rear_end, the model read side" in notes
    assert "crash: the report states V1 struck, the model read V2" in notes
    # headings and lanes stay the rules'
    assert merged.participant("V1").heading == Heading.NORTH and merged.participant("V1").lane == 1
    # the model's turn is stated as done in the sentence it cites ("was turning left"): it stands
    assert [a.kind for a in merged.participant("V1").known_actions] == ["follow_lane", "turn_left"]
    assert "V1 actions: the model's turn_left is stated in sentence 5; added to the rules'" in notes
    assert [a.kind for a in merged.participant("V2").known_actions] == ["follow_lane"]
    unstated, _ = merge(
        replace(rules, crash=Crash()), parse_answer(GOOD, ["V1", "V2"], LEFT_TURN_SHOWN), LEFT_TURN_SHOWN
    )
    assert unstated.crash == Crash(CrashType.SIDE, "V2", "V1")


def test_a_fact_whose_sentence_does_not_state_it_is_rejected() -> None:
    rules = _two(FOLLOW, FOLLOW)
    # V2's turn cites sentence 5, which is about V1; the crash cites sentence 6, which describes no impact
    wrong = '{"V1":["follow",5],"V2":["follow","right",5],"crash":["side","V2","V1",6]}'
    merged, notes = merge(rules, parse_answer(wrong, ["V1", "V2"], LEFT_TURN_SHOWN), LEFT_TURN_SHOWN)
    assert merged.participant("V2").known_actions == FOLLOW
    assert "V2 actions: the model's turn_right cites sentence(s) 5, which do not state it of V2; rejected" in notes
    assert merged.crash == Crash()
    assert (
        "crash: the model's side by V2 into V1 cites sentence(s) 6, which do not describe that impact; rejected"
        in notes
    )


def test_an_intention_is_no_evidence_and_a_turn_said_as_done_is() -> None:
    shown = motion_layer(
        "V2 was northbound, intending to turn left at the intersection. V1 was southbound. "
        "V2 then began its left turn. The front of V1 struck the right side of V2."
    )
    rules = _two(FOLLOW, FOLLOW)  # as if the rules had dropped the turn as intended only
    intended = '{"V1":["follow",2],"V2":["follow","left",1],"crash":["side","V1","V2",4]}'
    merged, notes = merge(rules, parse_answer(intended, ["V1", "V2"], shown), shown)
    assert merged.participant("V2").known_actions == FOLLOW
    done = intended.replace('"left",1]', '"left",1,3]')
    merged, notes = merge(rules, parse_answer(done, ["V1", "V2"], shown), shown)
    assert [a.kind for a in merged.participant("V2").known_actions] == ["follow_lane", "turn_left"]
    assert "V2 actions: the model's turn_left is stated in sentence 3; added to the rules'" in notes
    # a turn to the other side than the rules read leaves the rules' reading
    right = _two(FOLLOW, (*FOLLOW, Action(ActionKind.TURN_RIGHT)))
    merged, notes = merge(right, parse_answer(done, ["V1", "V2"], shown), shown)
    assert [a.kind for a in merged.participant("V2").known_actions] == ["follow_lane", "turn_right"]
    assert "V2 actions: the model read turn_left, the rules turn_right; kept the rules" in notes


def test_defaults_are_recorded_as_assumed() -> None:
    actions = parse_answer(GOOD, ["V1", "V2"], LEFT_TURN_SHOWN).actions
    s = Scenario(
        "s",
        road=Road(lanes=2),
        participants=(
            Participant("V1", Role.VEHICLE, actions=actions["V1"]),
            Participant("V2", Role.VEHICLE, lane=1, actions=actions["V2"]),
        ),
        crash=Crash(CrashType.SIDE, "V2"),
    )
    filled = apply_defaults(s)
    assert filled.participant("V1").lane == 1 and filled.crash.victim == "V1"
    assert filled.provenance is not None and filled.provenance.assumed == ("V1.lane", "crash.victim")
    assert apply_defaults(replace_lanes(s, UNKNOWN)).participant("V1").lane == UNKNOWN


def replace_lanes(s: Scenario, lanes: object) -> Scenario:
    return replace(s, road=replace(s.road, lanes=lanes))


def test_answers_are_cached_and_a_rerun_is_byte_identical(tmp_path: Path) -> None:
    recorded = Recorded(GOOD)
    cached = CachedProvider(recorded, tmp_path)
    first = FrontEnd("embedded").use(cached).extract(read_source(str(LEFT_TURN), "crash report"))
    again = FrontEnd("embedded").use(CachedProvider(Recorded(), tmp_path))  # no answers: it must not be asked
    second = again.extract(read_source(str(LEFT_TURN), "crash report"))
    assert to_text(first.scenario) == to_text(second.scenario)
    assert (cached.misses, len(list(tmp_path.rglob("*.json")))) == (1, 1)
    another = Recorded()
    another.model = "another-model"  # a different model is a different key: it is asked, and has no answer
    with pytest.raises(ProviderError, match="no recorded answer left"):
        FrontEnd("embedded").use(CachedProvider(another, tmp_path)).extract(read_source(str(LEFT_TURN), "crash report"))


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            "Das Fahrzeug fuhr nach Norden und die Fahrerin bremste zu spät vor der Kreuzung im Regen.",
            "not read as English",
        ),
        ("The weather was clear and the road was dry at the time of the crash on the bridge.", "names no vehicle"),
        ("1234 5678 ---- ####", "no words"),
    ],
)
def test_bad_reports_get_one_clear_error(text: str, message: str) -> None:
    front_end, recorded = _front_end(GOOD)
    with pytest.raises(FrontEndError, match=message):
        front_end.extract(Source("r.txt", text))
    assert recorded.prompts == []  # nothing was asked of the model


def test_an_unreachable_endpoint_is_a_clear_error() -> None:
    from sovarc.compiler.frontend.providers.openai_compat import OpenAIProvider

    provider = OpenAIProvider("any", base_url="http://127.0.0.1:9/v1", timeout_s=5, retries=0)
    with pytest.raises(ProviderError, match=r"cannot reach the OpenAI-compatible endpoint http://127.0.0.1:9/v1"):
        provider.complete_json("s", "u", {"type": "object"}, max_tokens=8)


def test_what_the_ir_cannot_hold_is_named() -> None:
    text = (
        "V1 was northbound on the road. P1, a bicyclist, was riding across. The front of V1 struck P1. "
        "V1 then struck a parked car."
    )
    front_end, _ = _front_end('{"V1":["follow",1],"P1":["cross",2],"crash":["side","V1","P1",3]}')
    notes = front_end.extract(Source("r.txt", text)).notes
    assert "only the first impact is encoded; the report describes 2 impact sentences" in notes


def test_a_rear_end_answer_against_crossing_headings_becomes_a_side_crash() -> None:
    rules = Scenario(
        "s",
        participants=(
            Participant("V1", Role.VEHICLE, Heading.NORTH, actions=(Action(ActionKind.FOLLOW_LANE),)),
            Participant("V2", Role.VEHICLE, Heading.EAST, actions=(Action(ActionKind.FOLLOW_LANE),)),
        ),
    )
    rear = GOOD.replace('["side"', '["rear_end"')
    merged, notes = merge(rules, parse_answer(rear, ["V1", "V2"], LEFT_TURN_SHOWN), LEFT_TURN_SHOWN)
    assert merged.crash.type == CrashType.SIDE
    assert "crash: the model read rear_end, but the headings make it side; kept side" in notes


def test_an_endpoint_that_never_answers_times_out_with_a_clear_error() -> None:
    import socket

    from sovarc.compiler.frontend.providers.openai_compat import OpenAIProvider

    with socket.socket() as silent:  # accepts connections (the kernel's backlog) and never says a word
        silent.bind(("127.0.0.1", 0))
        silent.listen(4)
        url = f"http://127.0.0.1:{silent.getsockname()[1]}/v1"
        provider = OpenAIProvider("any", base_url=url, timeout_s=1, retries=0)
        with pytest.raises(ProviderError, match=f"the endpoint {url} did not answer in time"):
            provider.complete_json("s", "u", {"type": "object"}, max_tokens=8)


def test_a_struck_part_the_report_does_not_name_stays_unknown() -> None:
    rules = Scenario(
        "s",
        participants=(
            Participant("V1", Role.VEHICLE, actions=(Action(ActionKind.FOLLOW_LANE),)),
            Participant("V2", Role.VEHICLE, actions=(Action(ActionKind.DRIVE_INTO),)),
        ),
        crash=Crash(UNKNOWN, "V2", "V1"),  # "V1 was struck by the front of V2": who, but not where
    )
    merged, notes = merge(rules, parse_answer(GOOD, ["V1", "V2"], LEFT_TURN_SHOWN), LEFT_TURN_SHOWN)
    assert merged.crash == Crash(UNKNOWN, "V2", "V1")
    assert "crash: the report names no struck part; the model's side is not kept" in notes
    assert "V2 actions: the model did not read [drive_into]; kept the rules'" in notes


def test_entering_and_leaving_the_road_exclude_each_other() -> None:
    shown = motion_layer("V1 was leaving a parking lot and pulled onto the road. V2 was eastbound. V2 struck V1.")
    rules = _two((Action(ActionKind.DRIVE_INTO),), FOLLOW)
    leave = '{"V1":["leave",1],"V2":["follow",2],"crash":["side","V2","V1",3]}'
    merged, notes = merge(rules, parse_answer(leave, ["V1", "V2"], shown), shown)
    assert [a.kind for a in merged.participant("V1").known_actions] == ["drive_into"]
    assert "V1 actions: the model read drive_off, the rules drive_into; kept the rules" in notes


@pytest.mark.parametrize("kind", list(ActionKind))
def test_every_action_kind_has_cue_words_for_its_evidence(kind: ActionKind) -> None:
    stated = {
        ActionKind.REVERSE: "V2 was backing out of a driveway.",
        ActionKind.PARKED: "V2 was parked at the curb.",
    }
    assert cue(kind.value).pattern
    if kind in stated:
        assert states_action(stated[kind], kind.value)
        assert not states_action("V2 was traveling north in the right lane.", kind.value)


def test_evidence_is_read_in_the_participants_own_piece_of_a_sentence() -> None:
    # a run-on sentence: the stop is V1's, the crossing over V2's; V2 is named in it but did not stop
    shown = motion_layer(
        "V1 was eastbound on a two-lane road. V2 was westbound. "
        "The driver of V1 pulled over and stopped the driver of V2 crossed the center line and struck V1."
    )
    rules = _two(FOLLOW, (*FOLLOW, Action(ActionKind.RETROGRADE)))
    answer = '{"V1":["follow","stop",1,3],"V2":["follow","stop","wrong_way",2,3],"crash":["frontal","V2","V1",3]}'
    merged, notes = merge(rules, parse_answer(answer, ["V1", "V2"], shown), shown)
    assert [a.kind for a in merged.participant("V1").known_actions] == ["follow_lane", "stop"]
    assert [a.kind for a in merged.participant("V2").known_actions] == ["follow_lane", "retrograde"]
    assert "V2 actions: the model's stop cites sentence(s) 2, 3, which do not state it of V2; rejected" in notes


def test_one_move_named_two_ways_keeps_the_rules_name() -> None:
    shown = motion_layer(
        "V1 was northbound in a curve when it went left over the double yellow lines into the southbound lane. "
        "V2 was southbound. V1 struck the front of V2 with its front."
    )
    rules = _two((*FOLLOW, Action(ActionKind.RETROGRADE)), FOLLOW)
    answer = '{"V1":["follow","lane_left",1],"V2":["follow",2],"crash":["frontal","V1","V2",3]}'
    merged, notes = merge(rules, parse_answer(answer, ["V1", "V2"], shown), shown)
    assert [a.kind for a in merged.participant("V1").known_actions] == ["follow_lane", "retrograde"]
    assert "V1 actions: the model read change_lane_left, the rules retrograde; kept the rules" in notes


def test_the_model_gives_the_side_the_rules_left_open() -> None:
    """A lane change the rules read without its side and the model with one is one move: the side is kept."""
    shown = motion_layer("V1 was northbound in the right lane. V2 was northbound. V2 changed lanes and struck V1.")
    rules = _two(FOLLOW, (*FOLLOW, Action(ActionKind.CHANGE_LANE)))
    answer = '{"V1":["follow",1],"V2":["follow","lane_right",2,3],"crash":["side","V2","V1",3]}'
    merged, notes = merge(rules, parse_answer(answer, ["V1", "V2"], shown), shown)
    assert merged.participant("V2").known_actions[-1] == Action(ActionKind.CHANGE_LANE, Side.RIGHT)
    assert "V2 actions: the rules read a change_lane without its side; kept the model's change_lane_right" in notes
    assert not any("did not read" in n for n in notes)
    # a side against a side stays the rules'
    sided = _two(FOLLOW, (*FOLLOW, Action(ActionKind.CHANGE_LANE, Side.LEFT)))
    merged, _ = merge(sided, parse_answer(answer, ["V1", "V2"], shown), shown)
    assert merged.participant("V2").known_actions[-1] == Action(ActionKind.CHANGE_LANE, Side.LEFT)
