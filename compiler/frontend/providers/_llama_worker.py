"""The child process that hosts llama.cpp for `EmbeddedProvider`: `python -m` this module.

llama.cpp logs from its own threads straight to file descriptors 1 and 2, and
a stuck generation cannot be interrupted from Python. Running it in a child
whose fds 1 and 2 point at a log file keeps the terminal clean, and lets the
parent enforce a real timeout by killing the child.

Protocol, one JSON object per line: the config arrives on stdin; the child
answers {"ready": load_seconds} or {"error": message} on the protocol pipe
(the original stdout), then one {"ok": response} or {"error": message} per
request line. EOF on stdin ends it.

Prompt prefix states: a request may carry `_prefix_file`, a file name in the
config's `slot_dir`. The first time a process sees it, a saved state is
restored into the slot (llama.cpp then reuses the common prefix, the long
system prompt, instead of processing it again); after the answer, the state
is saved if no file exists yet. Both go through the server's own loopback
`/slots` endpoint, and a failure there only costs time.
"""

from __future__ import annotations

import contextlib
import json
import os
import secrets
import sys
import time
import urllib.error
import urllib.request
from typing import IO, Any


def _private_channel(log_file: str) -> IO[str]:
    """Move the protocol off fd 1, then point fds 1 and 2 at the log file for llama.cpp."""
    channel = os.fdopen(os.dup(1), "w", encoding="utf-8")
    fd = os.open(log_file, os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o644)
    os.dup2(fd, 1)
    os.dup2(fd, 2)
    os.close(fd)
    return channel


def _load(config: dict[str, Any]) -> Any:
    import xllamacpp  # only the child loads the native library

    params = xllamacpp.CommonParams()
    params.model.path = config["model_path"]
    params.n_ctx = config["ctx"]
    params.n_parallel = 1  # one slot: requests are serial, and the whole context goes to it
    params.cpuparams.n_threads = config["threads"]
    params.cpuparams_batch.n_threads = config["threads"]
    # No busy-waiting between llama.cpp's threads: on a shared 2-core machine a spinning thread waits for a
    # descheduled one, and generation fell from ~12 to under 1 token/s under load.
    params.cpuparams.poll = 0
    params.cpuparams_batch.poll = 0
    params.sampling.temp = 0.0
    params.sampling.seed = config["seed"]
    params.api_keys = [config["api_key"]]
    if config.get("slot_dir"):
        params.slot_save_path = config["slot_dir"].rstrip("/") + "/"
        params.endpoint_slots = True
    return xllamacpp.Server(params)


def _slot_action(server: Any, key: str, action: str, filename: str) -> None:
    request = urllib.request.Request(
        f"{server.listening_address}/slots/0?action={action}",
        data=json.dumps({"filename": filename}).encode(),
        headers={"Authorization": f"Bearer {key}", "Content-Type": "application/json"},
    )
    with contextlib.suppress(OSError, urllib.error.URLError):
        urllib.request.urlopen(request, timeout=60).read()


def _answer(server: Any, config: dict[str, Any], request: dict[str, Any], seen: set[str]) -> dict[str, Any]:
    prefix = request.pop("_prefix_file", None)
    slot_dir = config.get("slot_dir")
    if not (prefix and slot_dir):
        return server.handle_chat_completions(request)
    saved = os.path.exists(os.path.join(slot_dir, prefix))
    if saved and prefix not in seen:
        _slot_action(server, config["api_key"], "restore", prefix)
    response = server.handle_chat_completions(request)
    if not saved:
        os.makedirs(slot_dir, exist_ok=True)
        _slot_action(server, config["api_key"], "save", prefix)
    seen.add(prefix)
    return response


def _send(channel: IO[str], message: dict[str, Any]) -> None:
    channel.write(json.dumps(message) + "\n")
    channel.flush()


def main() -> None:
    config = json.loads(sys.stdin.readline())
    config["api_key"] = secrets.token_hex(16)  # the server also listens on a loopback port: keep others out
    channel = _private_channel(config["log_file"])
    started = time.perf_counter()
    try:
        server = _load(config)
    except ImportError:
        _send(channel, {"error": "the xllamacpp package is not installed; run: pip install xllamacpp"})
        return
    except Exception as exc:  # anything here means no model: report it, never a traceback
        _send(channel, {"error": f"{type(exc).__name__}: {exc}"})
        return
    _send(channel, {"ready": time.perf_counter() - started})
    seen: set[str] = set()
    for line in sys.stdin:
        try:
            _send(channel, {"ok": _answer(server, config, json.loads(line), seen)})
        except Exception as exc:
            _send(channel, {"error": f"{type(exc).__name__}: {exc}"})


if __name__ == "__main__":
    main()
