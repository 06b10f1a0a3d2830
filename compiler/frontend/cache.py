"""Model answers cached on disk, so a rerun is instant and gives byte-identical `.sov`.

The key hashes everything an answer depends on: the provider kind, the
model's identity, the system and user prompts, the schema and the token
budget. Entries are written atomically; an unreadable entry is a miss.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
from pathlib import Path
from typing import Any

from sovarc.compiler.frontend.providers.base import Provider
from sovarc.compiler.fsutil import user_cache, write_atomic

CACHE_VERSION = 1


def default_answer_dir() -> Path:
    return user_cache("answers")


def answer_key(provider: Provider, system: str, user: str, schema: dict[str, Any], max_tokens: int) -> str:
    material = {
        "v": CACHE_VERSION,
        "provider": provider.name,
        "model": provider.model,
        "system": system,
        "user": user,
        "schema": schema,
        "max_tokens": max_tokens,
    }
    return hashlib.sha256(json.dumps(material, sort_keys=True, ensure_ascii=False).encode("utf-8")).hexdigest()


class CachedProvider:
    """A provider whose answers are looked up on disk before the model is asked."""

    def __init__(self, provider: Provider, directory: Path | None = None) -> None:
        self.inner = provider
        self.name = provider.name
        self.model = provider.model
        self.directory = directory or default_answer_dir()
        self.hits = 0
        self.misses = 0

    def path_of(self, key: str) -> Path:
        return self.directory / key[:2] / f"{key}.json"

    def complete_json(self, system: str, user: str, schema: dict[str, Any], *, max_tokens: int) -> str:
        path = self.path_of(answer_key(self.inner, system, user, schema, max_tokens))
        try:
            entry = json.loads(path.read_text(encoding="utf-8"))
            self.hits += 1
            return str(entry["answer"])
        except (OSError, ValueError, KeyError, TypeError):
            pass
        answer = self.inner.complete_json(system, user, schema, max_tokens=max_tokens)
        self.misses += 1
        entry = {"provider": self.name, "model": self.model, "answer": answer}
        with contextlib.suppress(OSError):  # a read-only cache only costs speed; the answer itself is good
            write_atomic(path, json.dumps(entry, ensure_ascii=False) + "\n")
        return answer

    def close(self) -> None:
        close = getattr(self.inner, "close", None)
        if close is not None:
            close()
