"""The stage runner: one explicit ordered tuple of stages, each with a typed input,
a typed output and a printable form.

Later stages (extract, defaults, lower, synthesize, emit, check) are added to
PIPELINE; the runner, `--stop-after` and `--dump-ir-after` need no change.
Between stages that produce a Scenario the verifier runs, so a pass that
breaks the IR is caught where it broke it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from sovarc.dsl import Diagnostic, Scenario, parse_source, to_text, verify_or_raise
from sovarc.dsl.errors import SovarcError
from sovarc.dsl.span import Source


@dataclass(frozen=True)
class Options:
    """Everything a run depends on besides its input; recorded in every artifact."""

    seed: int = 0
    target: str | None = None
    llm: str = "none"  # front end for reports: see sovarc.compiler.frontend.LLM_CHOICES
    model: str | None = None  # --model PATH.gguf for the embedded front end
    llm_base_url: str | None = None  # --llm-base-url for an OpenAI-compatible front end


@dataclass
class RunLog:
    """What a run learnt on the way: warnings, and each stage's output by name."""

    warnings: list[Diagnostic] = field(default_factory=list)
    outputs: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Stage:
    name: str
    summary: str
    consumes: type
    produces: type
    run: Callable[[Any, Options, RunLog], Any]
    render: Callable[[Any], str]


def _read(source: Source, options: Options, log: RunLog) -> Scenario:
    if Path(source.name).suffix.lower() == ".txt":
        from sovarc.compiler.frontend import extract_report

        model = Path(options.model) if options.model else None
        return extract_report(source, options.llm, model_path=model, base_url=options.llm_base_url)
    return parse_source(source)


def _verify(scenario: Scenario, options: Options, log: RunLog) -> Scenario:
    log.warnings += verify_or_raise(scenario)
    return scenario


PIPELINE: tuple[Stage, ...] = (
    Stage("read", "parse a .sov scenario, or extract one from a crash report (.txt)", Source, Scenario, _read, to_text),
    Stage("verify", "check the IR's semantic rules", Scenario, Scenario, _verify, to_text),
)

STAGE_NAMES: tuple[str, ...] = tuple(s.name for s in PIPELINE)


class PipelineError(SovarcError):
    stage = "pipeline"


def entry_stage(path: str) -> str:
    """The stage a file enters the pipeline at, by its kind."""
    suffix = Path(path).suffix.lower()
    if suffix in (".sov", ".txt", ""):
        return "read"
    raise PipelineError(f"{path}: unknown input kind '{suffix}'; expected a crash report (.txt) or a scenario (.sov)")


def run_pipeline(
    value: Any,
    *,
    start: str,
    stop: str | None = None,
    options: Options | None = None,
    after_stage: Callable[[Stage, Any], None] | None = None,
) -> tuple[Any, RunLog]:
    """Run the stages from `start` through `stop` (default: the last) on `value`."""
    options = options or Options()
    names = list(STAGE_NAMES)
    for name in (start, stop):
        if name is not None and name not in names:
            raise PipelineError(f"no stage named '{name}'; stages: {', '.join(names)}")
    first, last = names.index(start), names.index(stop or names[-1])
    if last < first:
        raise PipelineError(f"stage '{stop}' comes before '{start}'")
    log = RunLog()
    for index in range(first, last + 1):
        stage = PIPELINE[index]
        value = stage.run(value, options, log)
        following = PIPELINE[index + 1].name if index + 1 < len(PIPELINE) else None
        if isinstance(value, Scenario) and "verify" not in (stage.name, following):
            log.warnings += verify_or_raise(value)
        log.outputs[stage.name] = value
        if after_stage is not None:
            after_stage(stage, value)
    return value, log
