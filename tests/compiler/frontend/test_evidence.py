"""Every fact the front end reads carries evidence: the report's own characters, checked to be there."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from sovarc.compiler.frontend import FrontEnd, FrontEndError
from sovarc.compiler.frontend.evidence import Alignment, EvidenceError, Locator, stated
from sovarc.compiler.frontend.hybrid import attach_evidence, shown_span
from sovarc.compiler.frontend.rules import _WEATHER
from sovarc.compiler.frontend.text import prepare, sentences
from sovarc.dsl.explain import _facts, check_evidence
from sovarc.dsl.ir import Evidence, Reader, Scenario
from sovarc.dsl.span import Source

from tests.compiler.cli.test_cli import sovarc
from tests.compiler.frontend.test_hybrid import _front_end
from tests.conftest import EXAMPLES, ROOT, SHARED, Golden, requires_shared

EXAMPLE = EXAMPLES / "reports" / "evidence_left_turn_signal.txt"
LABELLED = ("crossing", "straight", "t")  # the 90 reports with ground truth


def _read(text: str, name: str = "r.txt") -> Scenario:
    return FrontEnd("none").extract(Source(name, text)).scenario


def _unexplained(s: Scenario) -> list[str]:
    """Facts the report states that carry no evidence and were not assumed. A straight road is the rules'
    reading when no junction is named; a pedestrian crosses unless the report says otherwise."""
    p = s.provenance
    assert p is not None
    have = {e.fact for e in p.evidence}
    return [
        f"{path} {shown}"
        for _, rows in _facts(s)
        for path, shown, unknown in rows
        if not unknown and path not in have and path not in p.assumed
        if (path, shown) != ("road.kind", "straight") and not (path.startswith("P") and shown == "cross")
    ]


def test_renamed_participants_quote_the_reports_own_words() -> None:
    text = "Vehicle #1, a 2015 Subaru Outback, was\nnorthbound. The front of the pickup struck Vehicle #1.\n"
    text = "Vehicle #2, a 2019 Ram 1500 pickup, was southbound. " + text
    named = prepare(text)
    assert "V1" in named and "the pickup" not in named
    locate = Locator(text, named, sentences(named))
    at = named.index("V2 struck V1")  # the reader's own words ...
    e = locate.evidence("crash.type", "named", at, at + len("V2 struck V1"))
    assert e.quote == "the pickup struck Vehicle #1."  # ... are the report's: "the pickup" stands for V2
    joined = " ".join(sentences(named))
    e = locate.evidence("V1.heading", "joined", joined.index("was northbound"), joined.index("was northbound") + 14)
    assert e.quote == "was\nnorthbound" and text[e.start : e.end] == e.quote


def test_every_stated_fact_of_our_example_has_checked_evidence() -> None:
    text = EXAMPLE.read_text(encoding="utf-8")
    s = _read(text)
    assert s.provenance is not None and check_evidence(text, s.provenance.evidence) == []
    assert _unexplained(s) == []
    quotes = {e.fact: e.quote for e in s.provenance.evidence}
    assert quotes["V1.actions[2]"] == "proceeded to make a left turn at the intersection on a green signal."
    assert quotes["V1.heading"] == "was traveling northbound in the left lane"
    assert quotes["crash.striker"].startswith("The front of the pickup struck")
    assert all(e.reader is Reader.RULES for e in s.provenance.evidence)


def test_a_span_the_report_does_not_hold_is_an_internal_error(monkeypatch: pytest.MonkeyPatch) -> None:
    real = Locator.evidence

    def off_by_one(self: Locator, *args: object) -> Evidence:
        e = real(self, *args)  # type: ignore[arg-type]
        return Evidence(e.fact, e.reader, e.start + 1, e.end + 1, e.quote)

    monkeypatch.setattr(Locator, "evidence", off_by_one)
    with pytest.raises(EvidenceError, match="evidence not in the report"):
        _read(EXAMPLE.read_text(encoding="utf-8"))
    assert not issubclass(EvidenceError, FrontEndError)  # never mistaken for a problem of the report


def test_the_models_facts_carry_the_sentences_its_answer_cited() -> None:
    text = "At the intersection V1 was westbound and turned left. V2 was eastbound. V1 and V2 collided. Both stopped."
    front_end, _ = _front_end('{"V1":["follow","left",1],"V2":["follow",2],"crash":["side","V2","V1",3]}')
    s = front_end.extract(Source("r.txt", text)).scenario
    assert s.provenance is not None
    model = [e for e in s.provenance.evidence if e.reader is Reader.MODEL]
    assert {e.fact for e in model} == {"crash.type", "crash.striker", "crash.victim"}
    assert {e.quote for e in model} == {"V1 and V2 collided."}  # the sentence the answer cited for the crash
    assert check_evidence(text, s.provenance.evidence) == []
    start, end = shown_span(text)
    assert text[start:end] == text[: text.index(" Both")]  # what the model was shown: up to the first impact
    replaced = attach_evidence(s, "crash.type", 0, 3, text, Reader.RULES)
    assert replaced.provenance is not None
    assert [e.quote for e in replaced.provenance.evidence_for("crash.type")] == ["At"]


@requires_shared
@pytest.mark.parametrize("where", LABELLED)
def test_every_evidence_span_of_the_shared_reports_checks(where: str) -> None:
    """The 90 labelled NMVCCS reports: every span is the report's text, every stated fact has one, and the
    words say what was read (a heading's quote names the heading, or the vehicle it follows)."""
    for path in sorted((SHARED / "data" / "nmvccs" / "reports" / where).glob("*.txt"), key=lambda p: int(p.stem)):
        text = path.read_text(encoding="utf-8")
        s = _read(text, str(path))  # raises EvidenceError on a span the report does not hold
        assert s.provenance is not None
        assert check_evidence(text, s.provenance.evidence) == [], path
        assert all(stated(s, e.fact) for e in s.provenance.evidence), path
        assert _unexplained(s) == [], path
        for e in s.provenance.evidence:
            field = e.fact.split(".", 1)[1]
            if field == "heading":
                heading = str(s.participant(e.fact.split(".")[0]).heading)  # type: ignore[union-attr]
                same_way = re.search(r"behind|ahead|following|same direction|in back of", e.quote, re.I)
                assert heading in e.quote.lower() or same_way, (path, e)
            elif field == "weather":
                assert any(re.search(pattern, e.quote.lower()) for _, pattern in _WEATHER), (path, e)
            elif field in ("speed", "speed_limit"):
                value = getattr(s.participant(e.fact.split(".")[0]) or s.road, field).value
                assert re.search(rf"\b{value}\s*-?\s*(?:k|mph)", e.quote, re.I), (path, e)


def test_explain_golden(tmp_path: Path, golden: Golden) -> None:
    report = str(EXAMPLE.relative_to(ROOT))
    written = sovarc("extract", report, "--llm", "none", "-o", str(tmp_path), cwd=ROOT)
    assert written.returncode == 0, written.stderr
    scenario = tmp_path / "evidence_left_turn_signal.sov"
    shown = sovarc("explain", str(scenario), "--report", report, cwd=ROOT)
    assert shown.returncode == 0, shown.stderr
    golden.check(ROOT / "tests/compiler/frontend/fixtures/explain/evidence_left_turn_signal.txt", shown.stdout)
    # the report the provenance names is found without --report, from the checkout
    assert sovarc("explain", str(scenario), cwd=ROOT).stdout == shown.stdout


def test_explain_refuses_a_changed_report(tmp_path: Path) -> None:
    sovarc("extract", str(EXAMPLE), "--llm", "none", "-o", str(tmp_path))
    changed = tmp_path / "changed.txt"
    changed.write_text(EXAMPLE.read_text(encoding="utf-8").replace("raining", "snowing"), encoding="utf-8")
    refused = sovarc("explain", str(tmp_path / "evidence_left_turn_signal.sov"), "--report", str(changed))
    assert refused.returncode == 1 and refused.stdout == ""
    assert "is not the report this scenario was read from" in refused.stderr
    shown = sovarc("explain", "--help")
    assert "assumed" in shown.stdout and "not stated" in shown.stdout and "examples:" in shown.stdout


def test_a_number_the_readers_gave_stands_for_the_words_that_introduce_it() -> None:
    """ "V2, a cyclist," is read where the report says "a cyclist": evidence at the added "V2" is those words,
    not an internal error."""
    report = "The AV was in a collision involving a cyclist on Elm Street. The cyclist rode on."
    read = "V1 was in a collision involving V2, a cyclist, on Elm Street. V2 rode on."
    at = read.index("V2")
    found = Alignment(read, report).span(at, at + 2)
    assert found is not None and report[found[0] : found[1]] == "a cyclist"
