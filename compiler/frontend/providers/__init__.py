"""LLM providers behind one small interface; the front end never imports a vendor library directly."""

from sovarc.compiler.frontend.providers.base import Provider, ProviderError

__all__ = ["Provider", "ProviderError"]
