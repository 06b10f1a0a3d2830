"""The provider interface every LLM back end implements, and its one error type."""

from __future__ import annotations

from typing import Any, Protocol, runtime_checkable

from sovarc.dsl.errors import SovarcError


class ProviderError(SovarcError):
    """The model could not answer: missing or corrupt model file, unreachable endpoint, garbage, timeout."""

    stage = "extract"


@runtime_checkable
class Provider(Protocol):
    """A model that answers a chat prompt with JSON constrained to a schema."""

    name: str  # the provider kind, e.g. "embedded" or "openai"; part of the answer-cache key
    model: str  # the model's identity within that provider; also part of the cache key

    def complete_json(self, system: str, user: str, schema: dict[str, Any], *, max_tokens: int) -> str:
        """Return the raw JSON text the model produced; raise ProviderError when there is none."""
        ...
