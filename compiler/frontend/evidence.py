"""Evidence: the characters of the report each fact was read from, and the check that they are there.

The readers do not read the report as written: participants are renamed (Vehicle #1 -> V1, "the pickup"
-> V2), whitespace is collapsed and the text is cut into sentences. A reader knows where it matched in
the text it read; `Locator` carries such a span back to the report's own characters. It aligns the two
texts word by word (renaming changes a few words, never their order), so a span of the read text maps to
the words of the report it came from, and the quote is always the report's own text.
"""

from __future__ import annotations

import difflib
import re
from dataclasses import replace

from sovarc.compiler.frontend.capitals import sentence_case
from sovarc.compiler.frontend.spelling import spell_out
from sovarc.dsl.explain import check_evidence
from sovarc.dsl.ir import FACT_PATH, Evidence, Reader, Scenario, Unknown

__all__ = ["Alignment", "EvidenceError", "Locator", "check_evidence", "evidence_of_span", "keep_stated", "stated"]

_WORD = re.compile(r"\S+")


class EvidenceError(AssertionError):
    """A reader gave evidence the report does not hold: a defect of the reader, not of the report."""


class Alignment:
    """Each character of a text the readers read, mapped to the report's characters it stands for."""

    def __init__(self, read: str, report: str) -> None:
        self.read = read
        ours = [m.span() for m in _WORD.finditer(read)]
        theirs = [m.span() for m in _WORD.finditer(report)]
        self.first: list[int | None] = [None] * len(read)
        self.last: list[int | None] = [None] * len(read)
        words = [read[s:e] for s, e in ours]
        # (a report in capitals is read in sentence case, letter for letter: see `capitals`)
        recased = sentence_case(report)
        # words compare by their respelling, so a report that writes "carriageway" or "N/B" throughout aligns
        # word for word with the text read, which says "roadway" and "northbound"
        matcher = difflib.SequenceMatcher(None, words, [spell_out(recased[s:e]) for s, e in theirs], autojunk=False)
        for op, i1, i2, j1, j2 in matcher.get_opcodes():
            if op == "equal":
                for (s, e), (t, u) in zip(ours[i1:i2], theirs[j1:j2], strict=True):
                    for c in range(s, e):
                        # (a word respelt stands whole for the report's: "roadway" for "carriageway")
                        same = e - s == u - t
                        self.first[c], self.last[c] = (t + c - s, t + c - s + 1) if same else (t, u)
            elif op == "replace" and "".join(words[i1:i2]) == "".join(report[t:u] for t, u in theirs[j1:j2]):
                # the same characters, split otherwise ("flow. V1" for "flow.V1"): character for character
                ours_chars = [c for s, e in ours[i1:i2] for c in range(s, e)]
                theirs_chars = [c for t, u in theirs[j1:j2] for c in range(t, u)]
                for c, t in zip(ours_chars, theirs_chars, strict=True):
                    self.first[c], self.last[c] = t, t + 1
            elif op == "replace" and i2 - i1 == j2 - j1:  # word for word: "V1" for "V-1"
                for (s, e), (t, u) in zip(ours[i1:i2], theirs[j1:j2], strict=True):
                    for c in range(s, e):
                        self.first[c], self.last[c] = t, u
            elif op == "replace":  # "V1" for "Vehicle #1": the report's words stand for all of ours
                t, u = theirs[j1][0], theirs[j2 - 1][1]
                for s, e in ours[i1:i2]:
                    for c in range(s, e):
                        self.first[c], self.last[c] = t, u
            # "delete": words the readers added (the number given to an unnumbered parked car) map to nothing

    def span(self, start: int, end: int) -> tuple[int, int] | None:
        firsts = [f for f in self.first[max(0, start) : end] if f is not None]
        lasts = [f for f in self.last[max(0, start) : end] if f is not None]
        if firsts:
            return min(firsts), max(lasts)
        # Words the readers added: the number given to an unnumbered road user stands for the words that
        # introduce it, which follow it up to the comma ("V2, a cyclist," for "a cyclist").
        at = next((c for c in range(end, min(len(self.first), end + 4)) if self.first[c] is not None), None)
        if at is None:
            return None
        comma = self.read.find(",", at)
        stop = comma if 0 <= comma - at <= 40 else at + len(self.read[at:].split(" ", 1)[0])
        lasts = [f for f in self.last[at:stop] if f is not None]
        return self.first[at], max(lasts)


class Locator:
    """Evidence for spans of the two texts the rules read: the prepared report (`named`) and its sentences
    joined by one space (`joined`, where clause pieces and sentence offsets count)."""

    def __init__(self, report: str, named: str, sents: list[str]) -> None:
        self.report = report
        self.spaces = {"named": Alignment(named, report), "joined": Alignment(" ".join(sents), report)}
        self.offsets: list[int] = []
        at = 0
        for sentence in sents:
            self.offsets.append(at)
            at += len(sentence) + 1
        self.sents = sents

    def sentence(self, index: int) -> tuple[str, int, int]:
        """A sentence's span in the joined text."""
        return ("joined", self.offsets[index], self.offsets[index] + len(self.sents[index]))

    def evidence(self, fact: str, space: str, start: int, end: int, reader: Reader = Reader.RULES) -> Evidence:
        """Evidence for a span of the `named` or `joined` text, or for sentence number `start` ("sentence")."""
        if space == "sentence":
            space, start, end = self.sentence(start)
        found = self.spaces[space].span(start, end)
        if found is None:
            raise EvidenceError(f"{fact}: the read text {start}..{end} ({space}) stands for no text of the report")
        a, b = found
        return Evidence(fact, reader, a, b, self.report[a:b])


def evidence_of_span(report: str, fact: str, start: int, end: int, reader: Reader) -> Evidence:
    """Evidence for characters `start`..`end` of the report itself, trimmed of surrounding white space."""
    text = report[start:end]
    start += len(text) - len(text.lstrip())
    end -= len(text) - len(text.rstrip())
    return Evidence(fact, reader, start, end, report[start:end])


def stated(scenario: Scenario, fact: str) -> bool:
    """Whether the scenario states the fact a path names (known, and for actions[n], that action exists)."""
    m = FACT_PATH.fullmatch(fact)
    if m is None:
        return False
    nodes = {"environment": scenario.environment, "road": scenario.road, "crash": scenario.crash}
    node = nodes.get(m["head"]) or scenario.participant(m["head"])
    value = getattr(node, m["field"], None) if node is not None else None
    if value is None or isinstance(value, Unknown):
        return False
    if m["index"] is not None:
        return isinstance(value, tuple) and 1 <= int(m["index"]) <= len(value)
    return True


def keep_stated(scenario: Scenario) -> Scenario:
    """The scenario without evidence for facts it no longer states (a reading later dropped or unknown)."""
    p = scenario.provenance
    if p is None or all(stated(scenario, e.fact) for e in p.evidence):
        return scenario
    kept = tuple(e for e in p.evidence if stated(scenario, e.fact))
    return replace(scenario, provenance=replace(p, evidence=kept))
