"""Evidence in the IR: its text form, the verifier's checks, diff leaving it out, and explain refusing a
report that is not the one the scenario was read from."""

from __future__ import annotations

import hashlib
from dataclasses import replace

import pytest
from sovarc.dsl import InputError, diff, parse, to_text, verify
from sovarc.dsl.explain import check_evidence, explain
from sovarc.dsl.ir import Evidence, Reader
from sovarc.dsl.span import Source

from tests.conftest import EXAMPLES

REPORT = "It was raining. V1 was traveling north and turned left. V2 struck V1."
SHA = hashlib.sha256(REPORT.encode()).hexdigest()

TEXT = f"""\
scenario t {{
  provenance {{
    report "r.txt"
    sha256 "{SHA}"
    frontend rules
    model unknown
    evidence {{
      environment.weather rules 7..14 "raining"
      V1.heading rules 19..38 "was traveling north"
      V1.actions[2] rules 43..54 "turned left"
      crash.striker model 56..69 "V2 struck V1."
    }}
  }}
  environment {{
    weather rainy
    lighting unknown
  }}
  road {{
    kind unknown
    lanes unknown
    speed_limit unknown
  }}
  vehicle V1 {{
    heading north
    lane unknown
    speed unknown
    actions {{
      follow_lane
      turn_left
    }}
  }}
  vehicle V2 {{
    heading unknown
    lane unknown
    speed unknown
    actions unknown
  }}
  crash {{
    type unknown
    striker V2
    victim V1
  }}
}}
"""


def test_evidence_reads_and_prints_back_unchanged() -> None:
    s = parse(TEXT)
    assert to_text(s) == TEXT
    assert s.provenance is not None
    assert s.provenance.evidence_for("V1.actions[2]") == (
        Evidence("V1.actions[2]", Reader.RULES, 43, 54, "turned left"),
    )
    assert check_evidence(REPORT, s.provenance.evidence) == []
    assert [d.message for d in verify(s) if d.severity == "error"] == []


def test_evidence_prints_in_the_order_of_the_facts() -> None:
    shuffled = TEXT.replace('      environment.weather rules 7..14 "raining"\n', "").replace(
        "      crash.striker", '      environment.weather rules 7..14 "raining"\n      crash.striker'
    )
    assert shuffled != TEXT and to_text(parse(shuffled)) == TEXT


def test_files_without_evidence_print_unchanged() -> None:
    for path in sorted(EXAMPLES.rglob("*.sov")):
        text = path.read_text(encoding="utf-8")
        assert to_text(parse(text, str(path))) == text, path


@pytest.mark.parametrize(
    ("line", "message"),
    [
        ('V3.heading rules 0..2 "It"', "evidence for 'V3.heading' names no fact of this scenario"),
        ('V1.colour rules 0..2 "It"', "evidence for 'V1.colour' names no fact of this scenario"),
        ('V1.actions[3] rules 0..2 "It"', "evidence for 'V1.actions[3]' names no action of V1"),
        ('V1.heading rules 0..5 "It"', "evidence for 'V1.heading' spans 5 characters but quotes 2"),
    ],
)
def test_verifier_checks_what_evidence_names(line: str, message: str) -> None:
    s = parse(TEXT.replace('      crash.striker model 56..69 "V2 struck V1."', "      " + line))
    assert message in [d.message for d in verify(s)]


def test_a_span_that_ends_before_it_starts_is_a_parse_error() -> None:
    with pytest.raises(Exception, match="ends before it starts"):
        parse(TEXT.replace("7..14", "14..7"))


def test_diff_leaves_evidence_out_unless_asked() -> None:
    a = parse(TEXT)
    b = parse(TEXT.replace('V1.actions[2] rules 43..54 "turned left"', 'V1.actions[2] model 39..54 "and turned left"'))
    assert diff(a, b) == []
    changes = diff(a, b, evidence=True)
    assert [c.path for c in changes] == ["evidence.V1.actions[2]"]
    assert changes[0].message == (
        'evidence of V1.actions[2]: rules 43..54 "turned left" → model 39..54 "and turned left"'
    )


def test_check_evidence_names_each_span_the_report_does_not_hold() -> None:
    good = Evidence("V1.heading", Reader.RULES, 19, 38, "was traveling north")
    assert check_evidence(REPORT, [good]) == []
    assert check_evidence(REPORT, [replace(good, quote="was traveling south")]) == [
        "V1.heading: the report has 'was traveling north' at 19..38, not 'was traveling south'"
    ]
    assert check_evidence(REPORT, [replace(good, start=60, end=90)]) == [
        f"V1.heading: span 60..90 is not inside the report ({len(REPORT)} characters)"
    ]


def test_explain_refuses_another_report() -> None:
    s = parse(TEXT, "t.sov")
    with pytest.raises(InputError, match="is not the report this scenario was read from"):
        explain(s, Source("r.txt", REPORT.replace("north", "south")))
    unhashed = replace(
        s, provenance=replace(s.provenance, sha256=parse(TEXT.replace(f'"{SHA}"', "unknown")).provenance.sha256)
    )
    with pytest.raises(InputError, match=r"evidence does not match r\.txt"):
        explain(unhashed, Source("r.txt", REPORT.replace("north", "south")))


def test_explain_says_why_each_fact_has_no_evidence() -> None:
    shown = explain(parse(TEXT), Source("r.txt", REPORT))
    assert "  lighting unknown: not stated\n" in shown
    assert "  actions[1] follow_lane: no evidence\n" in shown
    assert "  actions[2] turn_left: rules, line 1:44\n" in shown
    assert "     1 | It was raining. V1 was traveling north and turned left. V2 struck V1.\n" in shown
    assert "       |                                            ^~~~~~~~~~~\n" in shown
