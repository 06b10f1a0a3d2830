"""The pipeline: one explicit ordered tuple of stages, each with a typed input, a typed output and
a printable form, so `--stop-after` and `--dump-ir-after` work for every stage alike.

    read    Source     -> Scenario   parse a .sov, or extract one from a crash report (.txt)
    verify  Scenario   -> Scenario   the IR's semantic rules
    assume  Scenario   -> Assumed    unknown facts filled with noted choices; headings checked
    sites   Assumed    -> Sites      the map's candidate sites for the scenario, in the search's order
    stage   SiteJob    -> SiteResult the lowering-and-synthesis search on one site (staging.py)
    emit    SiteResult -> SiteResult the plan's files (plan.txt, .json, .png) and each target's files
    check   SiteResult -> SiteResult each target's oracle on what it emitted; verdict-<target>.json

The last three run once per site, inside the wrapper that fills several sites (`fill`: --roads N,
spare sites in place of failed ones; slots.py); their printable form is that of every slot.
Between stages that produce a Scenario the verifier runs, so a pass that breaks the IR is caught
where it broke it.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from sovarc.compiler.emit import check_target, emit_target, target_options, write_plan_files
from sovarc.compiler.frontend import extract_report
from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.lower.assume import assume
from sovarc.compiler.lower.consistency import check_headings
from sovarc.compiler.maps import RoadMap, SiteMatch, load_map, match_sites, planning_map
from sovarc.compiler.maps.lefthand import mirror_plan
from sovarc.compiler.plan_text import render_plan
from sovarc.compiler.slots import SiteResult, default_spare, fill_slots, folder_name, summary
from sovarc.compiler.staging import stage_on_site
from sovarc.dsl import Diagnostic, Scenario, parse_source, to_text, verify_or_raise
from sovarc.dsl.errors import LoweringError, SovarcError
from sovarc.dsl.span import Source

DEFAULT_MAP = Path(__file__).resolve().parents[1] / "examples" / "maps" / "town.net.xml"


@dataclass(frozen=True)
class Options:
    """Everything a run depends on besides its input."""

    seed: int = 0
    llm: str = "none"  # front end for reports: see sovarc.compiler.frontend.LLM_CHOICES
    model: str | None = None  # --model PATH.gguf for the embedded front end
    llm_base_url: str | None = None  # --llm-base-url for an OpenAI-compatible front end
    map: str | Path | RoadMap | None = None  # a path, or a map already loaded (a batch loads it once); None: the town
    roads: int = 1  # sites to stage on
    spare: int | None = None  # extra sites tried in place of failed ones; None: default_spare(roads)
    targets: tuple[str, ...] = ()  # checked by the check stage
    out_dir: Path | None = None  # emit and check write one folder per site here; None: nothing is written
    # the targets' own options (--ego, --osc-version, ...) by flag destination, as the registry declares them
    target_values: dict[str, Any] = field(default_factory=dict)


@dataclass
class RunLog:
    """What a run learnt on the way: warnings, and each stage's output by name."""

    warnings: list[Diagnostic] = field(default_factory=list)
    outputs: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Assumed:
    """The scenario with its unknown facts filled in, and a note saying how for each."""

    scenario: Scenario
    notes: tuple[str, ...]


@dataclass(frozen=True)
class Sites:
    """The candidate sites of the map for the scenario: the first `roads` take the slots, the rest are spares."""

    assumed: Assumed
    road_map: RoadMap
    candidates: tuple[SiteMatch, ...]
    roads: int
    mirror: RoadMap | None = None  # where traffic keeps left, the map's mirror image the candidates are on

    @property
    def planning(self) -> RoadMap:
        """The map the candidates are on and lowering plans on: `road_map`, or its mirror image."""
        return self.mirror or self.road_map


@dataclass(frozen=True)
class SiteJob:
    """One candidate site to stage the scenario on."""

    sites: Sites
    match: SiteMatch


@dataclass(frozen=True)
class Slots:
    """The per-site stages' results, one per slot, in the order of their first candidates."""

    sites: Sites
    results: list[SiteResult]
    targets: tuple[str, ...]


@dataclass(frozen=True)
class Stage:
    name: str
    summary: str
    consumes: type
    produces: type
    run: Callable[[Any, Options, RunLog], Any]
    render: Callable[[Any], str]  # the printable form of its output (per site: of the Slots)
    per_site: bool = False  # runs once per site, inside the site-filling wrapper (`fill`)
    unfilled: Callable[[SiteResult, Options], None] | None = None  # what it does for a slot no site filled


def _read(source: Source, options: Options, log: RunLog) -> Scenario:
    if Path(source.name).suffix.lower() == ".txt":
        model = Path(options.model) if options.model else None
        return extract_report(source, options.llm, model_path=model, base_url=options.llm_base_url)
    return parse_source(source)


def _verify(scenario: Scenario, options: Options, log: RunLog) -> Scenario:
    log.warnings += verify_or_raise(scenario)
    return scenario


def _assume(scenario: Scenario, options: Options, log: RunLog) -> Assumed:
    staged, notes = assume(scenario)
    check_headings(staged)
    return Assumed(staged, tuple(notes))


def _render_assumed(assumed: Assumed) -> str:
    notes = "".join("# assumed: " + " ".join(note.splitlines()) + "\n" for note in assumed.notes)
    return notes + to_text(assumed.scenario)


def default_map() -> Path:
    if not DEFAULT_MAP.is_file():
        raise SovarcError("no bundled example map in this installation; give a map with -m MAP (.net.xml or .xodr)")
    return DEFAULT_MAP


def _sites(assumed: Assumed, options: Options, log: RunLog) -> Sites:
    road_map = options.map if isinstance(options.map, RoadMap) else load_map(options.map or default_map())
    spare = default_spare(options.roads) if options.spare is None else options.spare
    planning = planning_map(road_map)
    found = match_sites(assumed.scenario, planning, n=options.roads + spare, seed=options.seed, clamp=True)
    return Sites(assumed, road_map, tuple(found), options.roads, planning if planning.mirrored else None)


def _render_sites(sites: Sites) -> str:
    lines = [f"# {len(sites.candidates)} candidate site(s) on {sites.road_map.name}, in the search's order"]
    for index, match in enumerate(sites.candidates):
        role = "slot" if index < sites.roads else "spare"
        lines.append(f"{match.site.id}  {match.site.kind.value}  rotation {match.rotation}  {role}")
    return "\n".join(lines) + "\n"


def _stage(job: SiteJob, options: Options, log: RunLog) -> SiteResult:
    """The staging search on one site; a failure is kept as the result's error."""
    assumed, match = job.sites.assumed, job.match
    result = SiteResult(match.site.id, road_map=job.sites.road_map)
    planning = job.sites.planning
    try:
        plan = stage_on_site(assumed.scenario, list(assumed.notes), planning, match, seed=options.seed)
        result.plan = mirror_plan(plan) if planning.mirrored else plan
    except SovarcError as exc:
        result.error = exc
    except Exception as exc:  # a defect met on this site's geometry: said, and the next site is tried
        defect = f"{type(exc).__name__}: {exc}"
        message = f"on {match.site.id}, sovarc failed on this site's geometry ({defect}); please report it"
        result.error = LoweringError(message)
    return result


def _render_plans(slots: Slots) -> str:
    out = []
    for r in slots.results:
        out.append(f"// ----- plan on {r.site} -----\n")
        if r.plan is not None:
            out.append(render_plan(r.plan))
    return "".join(out)


def _emit(result: SiteResult, options: Options, log: RunLog) -> SiteResult:
    """The plan's files, then each target's, in the site's folder."""
    if options.out_dir is not None and result.plan is not None and result.road_map is not None:
        result.folder = options.out_dir / folder_name(result.site)
        write_plan_files(result.plan, result.road_map, result.folder)
        for target in options.targets:
            chosen = target_options(target, seed=options.seed, **options.target_values)
            result.emitted[target] = emit_target(target, result.plan, result.folder, chosen)
    return result


def _emit_unfilled(result: SiteResult, options: Options) -> None:
    """A slot no site could fill: its folder holds the error."""
    if options.out_dir is not None:
        result.folder = options.out_dir / folder_name(result.site)
        write_atomic(result.folder / "error.txt", result.error.render() + "\n" if result.error else "")


def _render_sites_table(slots: Slots) -> str:
    """One row per slot: its site and impact time (the table `sovarc lower` prints)."""
    return summary(slots.results, ()) + _fewer(slots)


def _fewer(slots: Slots) -> str:
    """Said when the map has fewer sites the scenario fits than were asked for: no site of its shape."""
    found, asked = len(slots.results), slots.sites.roads
    if found >= asked:
        return ""
    name = slots.sites.road_map.name
    return (
        f"note: {name} has {found} site{'s' if found != 1 else ''} this scenario fits, {asked} asked: "
        "it has no other site of the shape the scenario needs\n"
    )


def _check(result: SiteResult, options: Options, log: RunLog) -> SiteResult:
    """Each target's oracle on what it emitted; its verdicts written beside its folder."""
    if result.folder is not None:
        for target, emitted in result.emitted.items():
            result.verdicts[target] = check_target(emitted, result.folder)
    return result


def _render_summary(slots: Slots) -> str:
    """One row per slot: its site, impact time and each target's verdict."""
    return summary(slots.results, slots.targets) + _fewer(slots)


PIPELINE: tuple[Stage, ...] = (
    Stage("read", "parse a .sov scenario, or extract one from a crash report (.txt)", Source, Scenario, _read, to_text),
    Stage("verify", "check the IR's semantic rules", Scenario, Scenario, _verify, to_text),
    Stage("assume", "fill unknown facts with noted choices; check headings", Scenario, Assumed, _assume,
          _render_assumed),
    Stage("sites", "find the map's candidate sites for the scenario", Assumed, Sites, _sites, _render_sites),
    Stage("stage", "per site: lower, synthesize and verify stagings; keep the first plan that passes",
          SiteJob, SiteResult, _stage, _render_plans, per_site=True),
    Stage("emit", "per site: write plan.txt, plan.json and plan.png, and each target's files",
          SiteResult, SiteResult, _emit, _render_sites_table, per_site=True, unfilled=_emit_unfilled),
    Stage("check", "per site: each target's oracle, its verdicts written",
          SiteResult, SiteResult, _check, _render_summary, per_site=True),
)  # fmt: skip

STAGE_NAMES: tuple[str, ...] = tuple(s.name for s in PIPELINE)


def stage_named(name: str) -> Stage:
    return PIPELINE[STAGE_NAMES.index(name)]


class PipelineError(SovarcError):
    stage = "pipeline"


def entry_stage(path: str) -> str:
    """The stage a file enters the pipeline at, by its kind."""
    suffix = Path(path).suffix.lower()
    if suffix in (".sov", ".txt", ""):
        return "read"
    raise PipelineError(f"{path}: unknown input kind '{suffix}'; expected a crash report (.txt) or a scenario (.sov)")


def fill(sites: Sites, stages: Sequence[Stage], options: Options, log: RunLog) -> Slots:
    """The site-filling wrapper: the per-site `stages` on the candidates, in order, until `roads`
    slots hold a plan or the candidates run out (slots.fill_slots)."""

    def attempt(match: SiteMatch) -> SiteResult:
        result: Any = SiteJob(sites, match)
        for stage in stages:
            result = stage.run(result, options, log)
            if result.plan is None:
                break  # no plan on this site: it may give way to the next candidate
        return result

    results = fill_slots(sites.candidates, sites.roads, attempt)
    for stage in stages:
        if stage.unfilled is not None:
            for result in results:
                if result.plan is None:
                    stage.unfilled(result, options)
    return Slots(sites, results, options.targets)


def run_pipeline(
    value: Any,
    *,
    start: str,
    stop: str | None = None,
    options: Options | None = None,
    after_stage: Callable[[Stage, Any], None] | None = None,
) -> tuple[Any, RunLog]:
    """Run the stages from `start` through `stop` (default: the last) on `value`. The per-site
    stages run inside `fill`, and each one's output is the Slots they produced."""
    options = options or Options()
    names = list(STAGE_NAMES)
    for name in (start, stop):
        if name is not None and name not in names:
            raise PipelineError(f"no stage named '{name}'; stages: {', '.join(names)}")
    first, last = names.index(start), names.index(stop or names[-1])
    if last < first:
        raise PipelineError(f"stage '{stop}' comes before '{start}'")
    chosen = PIPELINE[first : last + 1]
    log = RunLog()
    for stage in (s for s in chosen if not s.per_site):
        index = names.index(stage.name)
        value = stage.run(value, options, log)
        following = PIPELINE[index + 1].name if index + 1 < len(PIPELINE) else None
        if isinstance(value, Scenario) and "verify" not in (stage.name, following):
            log.warnings += verify_or_raise(value)
        log.outputs[stage.name] = value
        if after_stage is not None:
            after_stage(stage, value)
    per_site = [s for s in chosen if s.per_site]
    if per_site:
        if not isinstance(value, Sites):
            raise PipelineError(f"stage '{per_site[0].name}' runs on the sites the 'sites' stage found")
        value = fill(value, per_site, options, log)
        for stage in per_site:
            log.outputs[stage.name] = value
            if after_stage is not None:
                after_stage(stage, value)
    return value, log


def stage_sites(scenario: Scenario, options: Options) -> list[SiteResult]:
    """The scenario staged on `options.roads` sites (assume, sites, stage): the evaluations' way in."""
    slots, _ = run_pipeline(scenario, start="assume", stop="stage", options=options)
    return slots.results
