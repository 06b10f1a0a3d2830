"""The offline default provider: a local GGUF model run by llama.cpp through the `xllamacpp` wheel.

The schema is enforced by llama.cpp's grammar sampler, as a GBNF grammar of
its compact JSON spelling (`grammar`) or else through llama.cpp's own schema
conversion (response_format json_schema), so every answer parses; sampling is greedy with a fixed seed so
an answer is reproducible. The model runs in a child process (see
`_llama_worker`) that is started on the first request, so a run served
entirely from the answer cache never loads the model.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import select
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

from sovarc.compiler.frontend.providers.base import ProviderError
from sovarc.compiler.frontend.providers.grammar import compact_json_grammar
from sovarc.compiler.frontend.providers.model_file import MODEL_FILE_NAME, MODEL_SHA256, ensure_model_file
from sovarc.compiler.fsutil import user_cache

DEFAULT_SEED = 1234
LOAD_TIMEOUT_S = 300.0
WORKER_MODULE = "sovarc.compiler.frontend.providers._llama_worker"


def default_log_file() -> Path:
    return user_cache("llama.log")


class EmbeddedProvider:
    """Qwen2.5-Coder-1.5B-Instruct (or a user's GGUF) on local CPU threads; no network."""

    name = "embedded"

    def __init__(
        self,
        model_path: Path | None = None,
        *,
        threads: int | None = None,
        ctx: int = 8192,
        seed: int = DEFAULT_SEED,
        timeout_s: float = 120.0,
        log_file: Path | None = None,
        prefix_dir: Path | None = None,
    ) -> None:
        # A user-given GGUF (`--model`) is used as is; only the bundled model is hash-checked.
        self._user_model = Path(model_path) if model_path is not None else None
        if self._user_model is not None:
            size = _check_gguf(self._user_model)
            self.model = f"{self._user_model.name}@size:{size}"
        else:
            self.model = f"{MODEL_FILE_NAME}@sha256:{MODEL_SHA256[:12]}"
        # SOVARC_LLM_THREADS: on a machine shared with other work one thread can be faster, since llama.cpp's
        # threads meet at a barrier per layer and wait there for each other to be scheduled.
        self.threads = threads or int(os.environ.get("SOVARC_LLM_THREADS", "2"))
        self.ctx = ctx
        self.seed = seed
        self.timeout_s = timeout_s
        self.log_file = log_file or default_log_file()
        self.prefix_dir = prefix_dir or default_log_file().parent / "prefixes"
        self.load_seconds: float | None = None
        self.last_response: dict[str, Any] | None = None  # usage and timings of the last answer, for benchmarks
        self._process: subprocess.Popen[bytes] | None = None
        self._buffer = b""

    # --- the Provider interface -------------------------------------------------------------
    def complete_json(self, system: str, user: str, schema: dict[str, Any], *, max_tokens: int) -> str:
        request: dict[str, Any] = {
            "messages": [{"role": "system", "content": system}, {"role": "user", "content": user}],
            "max_tokens": max_tokens,
            "temperature": 0.0,
            "seed": self.seed,
            "_prefix_file": self._prefix_file(system),
        }
        grammar = compact_json_grammar(schema)  # compact JSON: no whitespace tokens to generate
        if grammar is not None:
            request["grammar"] = grammar
        else:
            request["response_format"] = {"type": "json_schema", "json_schema": {"name": "answer", "schema": schema}}
        response = self._call(request)
        self.last_response = response
        return _content_of(response, max_tokens)

    # --- lifetime ------------------------------------------------------------------------------
    def load(self) -> None:
        """Start the worker and load the model now rather than on the first request."""
        if self._process is not None:
            return
        model_path = self._user_model or ensure_model_file()
        self.log_file.parent.mkdir(parents=True, exist_ok=True)
        config = {"model_path": str(model_path), "log_file": str(self.log_file)}
        config |= {"threads": self.threads, "ctx": self.ctx, "seed": self.seed, "slot_dir": str(self.prefix_dir)}
        with self.log_file.open("ab") as log:  # the child's stderr before it redirects, e.g. an import error
            self._process = subprocess.Popen(
                [sys.executable, "-m", WORKER_MODULE], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=log
            )
        self._buffer = b""
        reply = self._exchange(config, LOAD_TIMEOUT_S, "loading the model")
        if "ready" not in reply:
            self.close()
            detail = reply.get("error")
            raise ProviderError(f"cannot load model {model_path}: {detail} (llama.cpp log: {self.log_file})")
        self.load_seconds = reply["ready"]

    def close(self) -> None:
        process, self._process = self._process, None
        if process is None:
            return
        with contextlib.suppress(OSError):  # the worker may already be gone
            assert process.stdin is not None
            process.stdin.close()  # EOF asks the worker to exit
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
        assert process.stdout is not None
        process.stdout.close()

    def __enter__(self) -> EmbeddedProvider:
        return self

    def __exit__(self, *_exc: object) -> None:
        self.close()

    def __del__(self) -> None:
        if getattr(self, "_process", None) is not None:  # __init__ may have failed before setting it
            self.close()

    # --- internals -----------------------------------------------------------------------------
    def _prefix_file(self, system: str) -> str:
        """The saved-state file of this model and system prompt: later processes skip processing it again."""
        material = json.dumps([self.model, self.ctx, system]).encode("utf-8")
        return f"{hashlib.sha256(material).hexdigest()[:32]}.bin"

    def _call(self, request: dict[str, Any]) -> dict[str, Any]:
        self.load()
        reply = self._exchange(request, self._time_allowed(request), "answering")
        if "ok" not in reply:
            raise ProviderError(f"the embedded model failed: {reply.get('error')} (llama.cpp log: {self.log_file})")
        return reply["ok"]

    def _time_allowed(self, request: dict[str, Any]) -> float:
        """The timeout, plus time to read the prompt at a slow 10 tokens/s (about 4 characters a token):
        the first request of a process may have to process the whole system prompt."""
        characters = sum(len(m["content"]) for m in request["messages"])
        return self.timeout_s + characters / 4 / 10

    def _exchange(self, message: dict[str, Any], timeout_s: float, doing: str) -> dict[str, Any]:
        """Send one line to the worker and read one line back within `timeout_s`."""
        process = self._process
        assert process is not None and process.stdin is not None and process.stdout is not None
        died = ProviderError(f"the embedded model's process died while {doing}; see {self.log_file}")
        try:
            process.stdin.write(json.dumps(message).encode() + b"\n")
            process.stdin.flush()
        except OSError:
            self.close()
            raise died from None
        deadline = time.monotonic() + timeout_s
        fd = process.stdout.fileno()
        while b"\n" not in self._buffer:
            remaining = deadline - time.monotonic()
            if remaining <= 0 or not select.select([fd], [], [], remaining)[0]:
                self._kill()  # the only way to stop llama.cpp mid-generation is to end its process
                raise ProviderError(f"the embedded model timed out after {timeout_s:.0f} s while {doing}")
            chunk = os.read(fd, 1 << 20)
            if not chunk:
                self.close()
                raise died
            self._buffer += chunk
        line, self._buffer = self._buffer.split(b"\n", 1)
        return json.loads(line)

    def _kill(self) -> None:
        if self._process is not None:
            self._process.kill()
        self.close()


def _check_gguf(path: Path) -> int:
    try:
        with path.open("rb") as handle:
            magic = handle.read(4)
        size = path.stat().st_size
    except OSError as exc:
        raise ProviderError(f"cannot read model file {path}: {exc.strerror or exc}") from exc
    if magic != b"GGUF":
        raise ProviderError(f"{path} is not a GGUF model file")
    return size


def _content_of(response: dict[str, Any], max_tokens: int) -> str:
    """The answer's JSON text, or a ProviderError saying why there is none."""
    if "error" in response or not response.get("choices"):
        detail = response.get("error", response)
        raise ProviderError(f"the embedded model returned an error: {json.dumps(detail)[:500]}")
    choice = response["choices"][0]
    content = (choice.get("message") or {}).get("content") or ""
    if choice.get("finish_reason") == "length":
        raise ProviderError(f"the model's answer was cut off at {max_tokens} tokens")
    try:
        json.loads(content)
    except ValueError:
        raise ProviderError(f"the model's answer is not JSON: {content[:200]!r}") from None
    return content
