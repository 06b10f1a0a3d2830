"""The compact-JSON grammar the embedded model is held to: exactly the answer form's spelling, no whitespace."""

from __future__ import annotations

import re

from sovarc.compiler.frontend import prompting
from sovarc.compiler.frontend.providers.grammar import compact_json_grammar


def test_the_answer_form_becomes_a_grammar_of_its_compact_spelling() -> None:
    grammar = compact_json_grammar(prompting.answer_schema(["V1", "P1"], [2, 4]))
    assert grammar is not None
    rules = dict(line.split(" ::= ", 1) for line in grammar.splitlines())
    root = rules["root"]
    assert root.startswith('"{" "\\"V1\\"" ":" ') and root.endswith(' "}"')
    # a participant: one to six words or cited numbers; the crash: exactly type, striker, victim, number
    assert any(re.fullmatch(r'"\[" r\d+ \(",\" r\d+\)\{1,5\} "\]"', body) for body in rules.values())
    assert any(re.fullmatch(r'"\[" r\d+ "," r\d+ "," r\d+ "," r\d+ "\]"', body) for body in rules.values())
    assert '"\\"walk\\""' in grammar and '("2" | "4")' in grammar
    assert " " not in "".join(re.findall(r'"(?:[^"\\]|\\.)*"', grammar)).replace('\\"', "")  # no space literal


def test_a_schema_outside_the_answer_form_falls_back_to_llama_cpps_own_conversion() -> None:
    assert compact_json_grammar({"type": "object"}) is None
    assert compact_json_grammar({"type": "string"}) is None
    assert compact_json_grammar({"type": "array", "items": {"enum": [1]}}) is None  # unbounded
