"""Property tests over generated IR: text and JSON round trips, schema validity."""

from __future__ import annotations

import jsonschema
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from sovarc.dsl import from_json, json_schema, parse, to_json, to_text
from sovarc.dsl.ir import (
    UNKNOWN,
    Action,
    ActionKind,
    Crash,
    CrashType,
    Environment,
    Evidence,
    Heading,
    Lighting,
    Participant,
    Provenance,
    Reader,
    Road,
    RoadKind,
    Role,
    Scenario,
    Side,
    Speed,
    SpeedUnit,
    VehicleKind,
    Weather,
)

names = st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,8}", fullmatch=True).filter(
    lambda s: (
        s
        not in {
            "unknown",
            "scenario",
            "vehicle",
            "pedestrian",
            "lane",
            "lanes",
            "speed",
            "type",
            "kind",
            "road",
            "crash",
            "report",
            "model",
            "actions",
            "heading",
            "striker",
            "victim",
            "weather",
            "lighting",
            "environment",
            "provenance",
            "frontend",
            "assumed",
            "sha256",
            "speed_limit",
            "evidence",
        }
    )
)


def maybe(strategy):
    return st.one_of(st.just(UNKNOWN), strategy)


numbers = st.one_of(st.integers(0, 300), st.floats(0, 300, allow_nan=False).map(lambda f: round(f, 3)))
speeds = st.builds(Speed, numbers, st.sampled_from(SpeedUnit))
texts = st.text(st.characters(blacklist_categories=("Cs", "Cc")), max_size=20)
actions = st.builds(
    Action,
    st.sampled_from(ActionKind),
    st.one_of(st.none(), st.integers(1, 9), st.sampled_from(Side)),
)
participants = st.builds(
    Participant,
    names,
    st.sampled_from(Role),
    maybe(st.sampled_from(Heading)),
    maybe(st.integers(1, 9)),
    maybe(speeds),
    maybe(st.lists(actions, max_size=5).map(tuple)),
    maybe(st.sampled_from(VehicleKind)),
)
paths = st.tuples(names, names).map(".".join)
fact_paths = st.one_of(
    paths,
    st.sampled_from(["environment.weather", "road.lanes", "crash.type"]),
    st.tuples(names, st.integers(1, 9)).map(lambda t: f"{t[0]}.actions[{t[1]}]"),
)
evidence = st.builds(
    lambda fact, reader, start, quote: Evidence(fact, reader, start, start + len(quote), quote),
    fact_paths,
    st.sampled_from(Reader),
    st.integers(0, 5000),
    st.text(st.characters(blacklist_categories=("Cs",)), min_size=1, max_size=30),
)
provenances = st.one_of(
    st.none(),
    st.builds(
        Provenance,
        maybe(texts),
        maybe(texts),
        maybe(texts),
        maybe(texts),
        st.lists(paths, max_size=3).map(tuple),
        st.lists(evidence, max_size=4).map(tuple),
    ),
)
scenarios = st.builds(
    Scenario,
    names,
    provenances,
    st.builds(
        Environment,
        maybe(st.lists(st.sampled_from(Weather), min_size=1).map(tuple)),
        maybe(st.lists(st.sampled_from(Lighting), min_size=1).map(tuple)),
    ),
    st.builds(Road, maybe(st.sampled_from(RoadKind)), maybe(st.integers(1, 12)), maybe(speeds)),
    st.lists(participants, max_size=4).map(tuple),
    st.builds(Crash, maybe(st.sampled_from(CrashType)), maybe(names), maybe(names)),
)

SETTINGS = settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@SETTINGS
@given(scenarios)
def test_parse_of_print_is_identity(ir: Scenario) -> None:
    text = to_text(ir)
    assert parse(text) == ir
    assert to_text(parse(text)) == text


@SETTINGS
@given(scenarios)
def test_json_round_trip_and_schema(ir: Scenario) -> None:
    data = to_json(ir)
    jsonschema.validate(data, json_schema())
    assert from_json(data) == ir


def test_equality_ignores_spans_and_comments() -> None:
    text = "scenario a {\n  vehicle V1 {  # hi\n    actions {\n      stop\n    }\n  }\n}\n"
    assert parse(text, "one.sov") == parse("\n\n" + text.replace("  # hi", ""), "two.sov")
