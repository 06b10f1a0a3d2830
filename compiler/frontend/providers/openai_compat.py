"""Any OpenAI-compatible chat endpoint: OpenAI itself, vLLM, Ollama, a llama.cpp server.

`--llm openai:MODEL` picks the model, `--llm-base-url` the endpoint (else
OPENAI_BASE_URL, else OpenAI's), and the key comes from OPENAI_API_KEY
(a local server that wants none gets a placeholder). Requests ask for a
json_schema response; servers that ignore it are still safe, because the
front end validates every answer against the schema and repairs or refuses.
"""

from __future__ import annotations

import json
import os
from typing import Any

from sovarc.compiler.frontend.providers.base import ProviderError

DEFAULT_TIMEOUT_S = 120.0
DEFAULT_RETRIES = 2
DEFAULT_SEED = 1234


# An endpoint constrains an answer to its JSON Schema but not to its compact spelling (the embedded model
# also gets a grammar that does): llama.cpp's schema conversion lets a model indent and break lines, about
# twice the tokens of the same answer. The budget leaves room for that, so a cut-off still means garbage.
WHITESPACE_ROOM = 4


class OpenAIProvider:
    name = "openai"

    def __init__(
        self,
        model: str,
        *,
        base_url: str | None = None,
        api_key: str | None = None,
        timeout_s: float = DEFAULT_TIMEOUT_S,
        retries: int = DEFAULT_RETRIES,
    ) -> None:
        try:
            import openai
        except ImportError:
            raise ProviderError("--llm openai:MODEL needs the openai package: pip install 'sovarc[openai]'") from None
        self._openai = openai
        self.base_url = base_url or os.environ.get("OPENAI_BASE_URL") or "https://api.openai.com/v1"
        key = api_key or os.environ.get("OPENAI_API_KEY")
        if not key and "api.openai.com" in self.base_url:
            raise ProviderError("--llm openai:MODEL needs an API key: set OPENAI_API_KEY")
        self.model = f"{model}@{self.base_url}"
        self._model_name = model
        self._client = openai.OpenAI(
            base_url=self.base_url, api_key=key or "sk-no-key", timeout=timeout_s, max_retries=retries
        )

    def complete_json(self, system: str, user: str, schema: dict[str, Any], *, max_tokens: int) -> str:
        openai = self._openai
        try:
            response = self._client.chat.completions.create(
                model=self._model_name,
                messages=[{"role": "system", "content": system}, {"role": "user", "content": user}],
                max_tokens=max_tokens * WHITESPACE_ROOM,
                temperature=0.0,
                seed=DEFAULT_SEED,
                response_format={"type": "json_schema", "json_schema": {"name": "answer", "schema": schema}},
            )
        except openai.APITimeoutError:
            raise ProviderError(f"the endpoint {self.base_url} did not answer in time") from None
        except openai.APIConnectionError:
            raise ProviderError(f"cannot reach the OpenAI-compatible endpoint {self.base_url}") from None
        except openai.AuthenticationError:
            raise ProviderError(f"the endpoint {self.base_url} refused the API key (OPENAI_API_KEY)") from None
        except openai.APIStatusError as exc:
            raise ProviderError(f"the endpoint {self.base_url} answered {exc.status_code}: {_short(exc)}") from None
        if not response.choices:
            raise ProviderError(f"the endpoint {self.base_url} returned no answer")
        choice = response.choices[0]
        content = choice.message.content or ""
        if choice.finish_reason == "length":
            raise ProviderError(f"the model's answer was cut off at {max_tokens * WHITESPACE_ROOM} tokens")
        return content

    def close(self) -> None:
        self._client.close()


def _short(exc: Exception) -> str:
    body = getattr(exc, "body", None)
    text = json.dumps(body) if body is not None else str(exc)
    return text[:300]
