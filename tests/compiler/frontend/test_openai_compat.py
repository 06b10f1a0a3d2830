"""The OpenAI-compatible provider against a real local server: llama.cpp's own HTTP server, started from
xllamacpp with the embedded model (no mocks). Slow: it loads the model."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Iterator

import jsonschema
import pytest
from sovarc.compiler.frontend import prompting
from sovarc.compiler.frontend.hybrid import AnswerError, parse_answer
from sovarc.compiler.frontend.layers import motion_layer
from sovarc.compiler.frontend.providers import ProviderError
from sovarc.compiler.frontend.providers.openai_compat import OpenAIProvider

KEY = "sk-local-test-key"
SERVE = """
import sys, xllamacpp
from sovarc.compiler.frontend.providers.model_file import ensure_model_file
p = xllamacpp.CommonParams()
p.model.path = str(ensure_model_file())
p.n_ctx = 2048
p.n_parallel = 1
p.cpuparams.n_threads = 2
p.cpuparams_batch.n_threads = 2
p.api_keys = [sys.argv[1]]
server = xllamacpp.Server(p)
print(server.listening_address, flush=True)
sys.stdin.read()  # serve until the test closes our stdin
"""
SYSTEM = (
    "Answer with the facts of the crash report as JSON. Actions are what each vehicle did before the impact; "
    "crossing a double yellow line is retrograde. The striker is the vehicle whose front hits."
)
NARRATIVE = (
    "On a two-lane road, V1 was northbound. V2 was southbound and crossed the double yellow line to pass "
    "a truck. The front of V2 struck the front of V1."
)
SHOWN = motion_layer(NARRATIVE)
REPORT = prompting.user_prompt(SHOWN, ["V1", "V2"])


@pytest.fixture(scope="module")
def server_url() -> Iterator[str]:
    process = subprocess.Popen(
        [sys.executable, "-c", SERVE, KEY],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
    )
    assert process.stdout is not None and process.stdin is not None
    address = process.stdout.readline().strip()
    assert address.startswith("http://127.0.0.1:"), "the llama.cpp server did not start"
    yield f"{address}/v1"
    process.stdin.close()
    process.wait(timeout=60)


@pytest.mark.slow
def test_a_real_local_server_answers_in_the_compact_form(server_url: str) -> None:
    provider = OpenAIProvider("qwen2.5-coder-1.5b", base_url=server_url, api_key=KEY, timeout_s=300)
    assert provider.model == f"qwen2.5-coder-1.5b@{server_url}"
    ids = ["V1", "V2"]
    answer = provider.complete_json(
        SYSTEM, REPORT, prompting.answer_schema(ids, SHOWN.numbers()), max_tokens=prompting.answer_budget(ids)
    )
    # The server enforces the schema (words and cited numbers, the crash tuple); the order of words before
    # numbers is the grammar's, which only the embedded model gets: here a wrong order is a listed problem the
    # repair round sends back, never a crash.
    jsonschema.Draft7Validator(prompting.answer_schema(ids, SHOWN.numbers())).validate(json.loads(answer))
    try:
        parsed = parse_answer(answer, ids, SHOWN)
    except AnswerError as exc:
        assert exc.problems and all(p.split(":")[0] in [*ids, "crash"] for p in exc.problems), exc.problems
    else:
        assert set(parsed.actions) == {"V1", "V2"}
    provider.close()


@pytest.mark.slow
def test_a_wrong_key_is_a_clear_error(server_url: str) -> None:
    provider = OpenAIProvider("qwen2.5-coder-1.5b", base_url=server_url, api_key="sk-wrong", retries=0)
    with pytest.raises(ProviderError, match="refused the API key"):
        provider.complete_json(SYSTEM, REPORT, {"type": "object"}, max_tokens=8)
