"""Front ends: everything that turns something else (a report, ground truth) into scenario IR.

`--llm` picks how a report is read:
- `embedded`: the offline default, a local GGUF model through llama.cpp (the `model` extra);
- `openai:MODEL`: any OpenAI-compatible endpoint (`--llm-base-url`, key from OPENAI_API_KEY);
- `none`: the deterministic rules alone.
The model front ends are hybrid (see `hybrid`): rules for what text patterns
state exactly, the model for the dynamic layer. All of them end with the
defaults pass, which records every fact it fills in.
"""

from __future__ import annotations

import functools
import hashlib
from dataclasses import dataclass, field, replace
from pathlib import Path

from sovarc.compiler.frontend.cache import CachedProvider
from sovarc.compiler.frontend.choice import (
    LLM_CHOICES,
    MODEL_EXTRA_HINT,
    FrontEndError,
    check_llm,
    default_llm,
    model_extra_installed,
)
from sovarc.compiler.frontend.defaults import apply_defaults
from sovarc.compiler.frontend.evidence import EvidenceError, check_evidence
from sovarc.compiler.frontend.hybrid import model_reading
from sovarc.compiler.frontend.names import partner_refusal
from sovarc.compiler.frontend.providers import make_provider
from sovarc.compiler.frontend.providers.base import Provider
from sovarc.compiler.frontend.refusals import refuse
from sovarc.compiler.frontend.rules import extract
from sovarc.compiler.frontend.text import check_narrative, prepare_report, unrepresented
from sovarc.dsl import Scenario
from sovarc.dsl.ir import Provenance, Unknown
from sovarc.dsl.span import Source

__all__ = [
    "LLM_CHOICES",
    "MODEL_EXTRA_HINT",
    "Extraction",
    "FrontEnd",
    "FrontEndError",
    "check_llm",
    "default_llm",
    "extract_report",
    "model_extra_installed",
    "scenario_name",
]


def scenario_name(path: str) -> str:
    """A scenario name from a report's file name: letters, digits and '_' only."""
    stem = "".join(c if c.isalnum() else "_" for c in Path(path).stem) or "report"
    return stem if stem[0].isalpha() else f"report_{stem}"


@dataclass(frozen=True)
class Extraction:
    scenario: Scenario
    notes: tuple[str, ...] = ()  # cross-check disagreements, repairs, fall-backs: for the user to see


@dataclass
class FrontEnd:
    """One way of reading reports; holds its provider (and so a loaded model) across reports."""

    llm: str = "none"
    model_path: Path | None = None
    base_url: str | None = None
    cache_dir: Path | None = None
    use_cache: bool = True
    _provider: Provider | None = field(default=None, repr=False)

    def provider(self) -> Provider:
        """The model behind this front end, built on first use and cached on disk unless told not to."""
        if self._provider is None:
            inner = make_provider(self.llm, model_path=self.model_path, base_url=self.base_url)
            self._provider = CachedProvider(inner, self.cache_dir) if self.use_cache else inner
        return self._provider

    def use(self, provider: Provider) -> FrontEnd:
        """Read with this provider (a recorded one in tests, say) instead of building one from `llm`."""
        self._provider = provider
        return self

    def extract(self, source: Source) -> Extraction:
        check_narrative(source.text, source.name)
        prepared = prepare_report(source.text)  # the naming, once for the refusals, the rules and the note
        refuse(source.text, source.name, prepared.named)
        if refusal := partner_refusal(prepared.labelled, prepared.note):
            raise FrontEndError(f"{source.name}: {refusal}; nothing to extract")
        rules = extract(source.text, scenario_name(source.name), source.name, prepared)
        notes = unrepresented(source.text)
        if prepared.note:
            notes = [prepared.note, *notes]
        if not rules.participants:
            raise FrontEndError(
                f"{source.name}: the report names no vehicle or pedestrian (looked for V1, Vehicle #1, "
                "vehicle one, labels like '(Vehicle 1)', an automated vehicle such as 'the Waymo AV' with the road "
                "user it struck, pedestrian, ...); nothing to extract"
            )
        scenario = rules
        if self.llm != "none":
            provider = self.provider()
            scenario, found = model_reading(rules, source.text, provider)
            notes += found
            evidence = scenario.provenance.evidence if scenario.provenance else ()
            provenance = replace(_provenance(source, self.llm, provider.model), evidence=evidence)
            scenario = replace(scenario, provenance=provenance)
        scenario = apply_defaults(scenario)
        if problems := check_evidence(source.text, scenario.provenance.evidence if scenario.provenance else ()):
            raise EvidenceError(f"{source.name}: evidence not in the report: " + "; ".join(problems))
        return Extraction(scenario, tuple(notes))

    def close(self) -> None:
        close = getattr(self._provider, "close", None)
        if close is not None:
            close()
        self._provider = None


def _provenance(source: Source, llm: str, model: str) -> Provenance:
    digest = hashlib.sha256(source.text.encode("utf-8")).hexdigest()
    frontend = llm.split(":", 1)[0]
    return Provenance(source.name, digest, frontend, model or Unknown.UNKNOWN)


# functools.cache, not `cache`: in this package that name is the answer-cache submodule
@functools.cache
def _shared(llm: str, model_path: Path | None, base_url: str | None) -> FrontEnd:
    return FrontEnd(llm, model_path, base_url)


def extract_report(
    source: Source, llm: str = "none", *, model_path: Path | None = None, base_url: str | None = None
) -> Scenario:
    """The scenario a crash report states, read by the chosen front end (kept loaded for the next report)."""
    return _shared(llm, model_path, base_url).extract(source).scenario
