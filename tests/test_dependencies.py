"""The dependency rule, read from the source (no imports run):

- targets/ sees only the IR, the plan, the geometry kernel, the vehicle model, the crash definitions
  (and the file helper every writer uses), never lowering, synthesis, map search or the pipeline;
- compiler/ reaches a target only through the registry (and the verdict and contract types);
- imports are at module level, except a heavy dependency that must load lazily (LAZY), which the
  module says why it defers.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.conftest import ROOT

TARGETS_MAY_IMPORT = (
    "sovarc.dsl",
    "sovarc.targets",
    "sovarc.compiler.plan",
    "sovarc.compiler.geometry",
    "sovarc.compiler.vehicles",
    "sovarc.compiler.crashes",
    "sovarc.compiler.fsutil",
)
COMPILER_MAY_IMPORT_FROM_TARGETS = ("sovarc.targets.registry", "sovarc.targets.contract", "sovarc.targets.verdict")
# The one exception: `sovarc eval tests` measures the FMU target's own ego tests (its ego interface,
# runner and oracle's failure classes), which the target contract does not carry.
EVALUATES_A_TARGET = {"compiler/evaluation/tests.py": ("sovarc.targets.fmu",)}
# Loaded where they are used: each is slow to import or optional, and most runs never need it.
LAZY = (
    "matplotlib",  # only commands that draw
    "libsumo",  # a native SUMO in-process: only the SUMO replay and the FMU harness
    "sumo",  # the eclipse-sumo wheel, only to find its binaries
    "sumolib",  # only when a map is read
    "xllamacpp",  # the embedded model, only in its worker process
    "openai",  # the optional OpenAI-compatible front end
    "fmpy",  # only when an FMU is run
    "pythonfmu",  # only when the reference FMU is built
    "qc_openscenario",  # ASAM's checker, only in the OpenSCENARIO oracle
    "qc_baselib",
    "ray",  # the optional cluster executor
    "toppra",  # imports scipy's interpolation and pyplot (1.5 s): only synthesis, in the process that plans
)


def _modules(folder: str) -> list[Path]:
    return sorted((ROOT / folder).rglob("*.py"))


def _imports(path: Path, package: str | None = None) -> Iterator[tuple[str, int, bool]]:
    """(module imported, line, at module level) for every import of the file, relative ones resolved."""
    tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
    package = package or _package(path)
    functions = [n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef | ast.AsyncFunctionDef)]
    nested = {id(node) for fn in functions for node in ast.walk(fn)}
    type_only = [n for n in ast.walk(tree) if isinstance(n, ast.If) and "TYPE_CHECKING" in ast.dump(n.test)]
    guarded = {id(node) for block in type_only for node in ast.walk(block)}
    for node in ast.walk(tree):
        if id(node) in guarded:
            continue
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield alias.name, node.lineno, id(node) not in nested
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join([*parts, base] if base else parts)
            yield base, node.lineno, id(node) not in nested


def _package(path: Path) -> str:
    relative = path.relative_to(ROOT).with_suffix("")
    parts = ["sovarc", *relative.parts]
    return ".".join(parts[:-1])  # a module's package, and an __init__'s own package


def _under(module: str, prefixes: tuple[str, ...]) -> bool:
    return any(module == p or module.startswith(p + ".") for p in prefixes)


@pytest.mark.parametrize("path", _modules("targets"), ids=lambda p: str(p.relative_to(ROOT)))
def test_targets_import_only_the_ir_plan_kernel_vehicles_and_crashes(path: Path) -> None:
    wrong = [f"{path.name}:{line} imports {m}" for m, line, _ in _imports(path)
             if m.startswith("sovarc.") and not _under(m, TARGETS_MAY_IMPORT)]  # fmt: skip
    assert wrong == []


@pytest.mark.parametrize("path", _modules("compiler"), ids=lambda p: str(p.relative_to(ROOT)))
def test_the_compiler_reaches_targets_only_through_the_registry(path: Path) -> None:
    allowed = COMPILER_MAY_IMPORT_FROM_TARGETS + EVALUATES_A_TARGET.get(path.relative_to(ROOT).as_posix(), ())
    wrong = [f"{path.name}:{line} imports {m}" for m, line, _ in _imports(path)
             if _under(m, ("sovarc.targets",)) and not _under(m, allowed)]  # fmt: skip
    assert wrong == []


@pytest.mark.parametrize(
    "path", [*_modules("compiler"), *_modules("targets"), *_modules("dsl")], ids=lambda p: str(p.relative_to(ROOT))
)
def test_imports_are_at_module_level_except_lazy_heavy_ones(path: Path) -> None:
    hidden = [f"{path.name}:{line} imports {m} inside a function" for m, line, top in _imports(path)
              if not top and not _under(m, LAZY)]  # fmt: skip
    assert hidden == []


def test_the_rule_sees_a_violation(tmp_path: Path) -> None:
    """The checks read what they should: a nested import and a forbidden one are both found."""
    module = tmp_path / "probe.py"
    module.write_text("from ..lower import lower\n\ndef f():\n    import json\n", encoding="utf-8")
    found = list(_imports(module, "sovarc.compiler.synth"))
    assert ("sovarc.compiler.lower", 1, True) in found and ("json", 4, False) in found
