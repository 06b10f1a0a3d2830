"""The target contract: what a back end is to the compiler, and how every target's verdicts are written.

A new target is one subpackage and one registry line: a subpackage that exports one object
satisfying `Target`, and its line in `targets/registry.py` (or `registry.register(obj)` at run time).
The compiler reaches targets only through the registry, and runs each the same way:

    target = registry.get("sumo")
    options = target.Options()                          # or options_from(target, values from the CLI)
    artifacts = target.emit(plan, folder / target.name, options)
    verdicts = target.check(plan, artifacts, options)   # one per test: one, or one per ego for the FMU
    write_verdicts(folder, target, verdicts)            # folder/verdict-<name>.json

A target reads the plan and the files its network names (`plan.network`: the SUMO network, and the
OpenDRIVE file when `needs_opendrive` asks the compiler to provide it); it never loads maps or runs
netconvert.

Options are a frozen dataclass per target (its `Options`, all fields with defaults). A field whose
metadata names a `flag` (see `option`) is offered on the command line; `shared` marks a flag the
command line has anyway (--seed), which the target only reads.
"""

from __future__ import annotations

import builtins
import dataclasses
import json
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar, Protocol, runtime_checkable

from sovarc.compiler.fsutil import write_atomic
from sovarc.compiler.plan import Plan
from sovarc.targets.verdict import Verdict


@dataclass(frozen=True)
class Artifacts:
    """What a target's emit wrote: its folder and the files, the main one first."""

    folder: Path
    files: tuple[Path, ...] = ()

    @property
    def main(self) -> Path:
        return self.files[0]


@runtime_checkable
class Target(Protocol):
    name: str  # 'sumo': the -t choice, the output folder and verdict-<name>.json
    Options: ClassVar[type[Any]]  # a frozen dataclass of the options it accepts, each with a default
    needs_opendrive: bool  # the compiler fills plan.network.opendrive before emit
    one_verdict: bool  # check gives exactly one verdict (written as one object), else a list (one per test)

    def emit(self, plan: Plan, folder: Path, options: Any) -> Artifacts:
        """Write the target's files for `plan` into `folder` (created if needed)."""
        ...

    def check(self, plan: Plan, artifacts: Artifacts, options: Any) -> list[Verdict]:
        """Judge what emit wrote; one verdict per test the target runs."""
        ...


@dataclass(frozen=True)
class Flag:
    """A target option as the command line offers it."""

    target: str
    field: str  # the option's name in the target's Options
    flag: str  # '--osc-version'
    help: str
    choices: tuple[str, ...] | None
    default: Any
    shared: bool  # the command line defines this flag itself (e.g. --seed); the target only reads it
    type: Callable[[str], Any]  # what makes the value from the command line's text

    @property
    def dest(self) -> str:
        """The argparse destination of the flag: '--osc-version' -> 'osc_version'."""
        return self.flag.lstrip("-").replace("-", "_")


def option(
    default: Any,
    flag: str,
    help: str,
    choices: Sequence[str] | None = None,
    *,
    shared: bool = False,
    type: Callable[[str], Any] | None = None,
) -> Any:
    """A field of a target's Options offered on the command line as `flag`; its text is made a value
    by `type` (default: int or float when the default is one, else the text itself)."""
    if type is None:
        type = builtins.type(default) if isinstance(default, int | float) and not isinstance(default, bool) else str
    meta = {"flag": flag, "help": help, "choices": tuple(choices) if choices else None, "shared": shared, "type": type}
    return dataclasses.field(default=default, metadata=meta)


def flags(target: Target) -> list[Flag]:
    """The command-line flags of a target's options, in their declared order."""
    found = []
    for f in dataclasses.fields(target.Options):
        if "flag" in f.metadata:
            m = f.metadata
            found.append(
                Flag(target.name, f.name, m["flag"], m["help"], m["choices"], f.default, m["shared"], m["type"])
            )
    return found


def options_from(target: Target, values: Mapping[str, Any]) -> Any:
    """The target's Options from command-line values (by flag destination); None or absent: the default."""
    given = {f.field: values[f.dest] for f in flags(target) if values.get(f.dest) is not None}
    return target.Options(**given)


def verdict_file(folder: Path, target: Target) -> Path:
    return folder / f"verdict-{target.name}.json"


def write_verdicts(folder: Path, target: Target, verdicts: Sequence[Verdict]) -> Path:
    """Write a target's verdicts as `folder/verdict-<name>.json`, the same way for every target:
    the verdict object for a one-verdict target, else a list of them."""
    if target.one_verdict:
        if len(verdicts) != 1:
            raise ValueError(f"target {target.name} gave {len(verdicts)} verdicts, expected one")
        text = verdicts[0].dumps()
    else:
        text = json.dumps([v.to_json() for v in verdicts], indent=2, ensure_ascii=False) + "\n"
    path = verdict_file(folder, target)
    write_atomic(path, text)
    return path
