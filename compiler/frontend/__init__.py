"""Front ends: everything that turns something else (a report, ground truth) into scenario IR."""

from __future__ import annotations

from pathlib import Path

from sovarc.dsl import Scenario
from sovarc.dsl.errors import SovarcError
from sovarc.dsl.span import Source

LLM_CHOICES = ("none",)  # the embedded model and OpenAI-compatible endpoints join here


class FrontEndError(SovarcError):
    stage = "extract"


def scenario_name(path: str) -> str:
    """A scenario name from a report's file name: letters, digits and '_' only."""
    stem = "".join(c if c.isalnum() else "_" for c in Path(path).stem) or "report"
    return stem if stem[0].isalpha() else f"report_{stem}"


def extract_report(source: Source, llm: str = "none") -> Scenario:
    """The scenario a crash report states, read by the chosen front end."""
    if llm == "none":
        from sovarc.compiler.frontend.rules import extract

        return extract(source.text, scenario_name(source.name), source.name)
    raise FrontEndError(f"front end '--llm {llm}' is not built yet; available: {', '.join(LLM_CHOICES)}")
