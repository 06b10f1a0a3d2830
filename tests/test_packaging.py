"""A normal (non-editable) install: one `sovarc` namespace, grammar shipped as package data."""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

from tests.conftest import EXAMPLES, ROOT


@pytest.mark.slow
def test_wheel_installs_one_namespace_and_runs(tmp_path: Path) -> None:
    built = subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(tmp_path / "dist"), str(ROOT)],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert built.returncode == 0, built.stderr
    (wheel,) = (tmp_path / "dist").glob("sovarc-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    top = {n.split("/")[0] for n in names if not n.startswith("sovarc-")}
    assert top == {"sovarc"}, top
    assert "sovarc/grammar/sov.lark" in names
    # Every source module of the mapped folders is in the wheel (a package missing from
    # pyproject's list would install fine in editable mode and break a normal install).
    for folder in ("compiler", "dsl", "targets"):
        for module in (ROOT / folder).rglob("*.py"):
            assert f"sovarc/{module.relative_to(ROOT).as_posix()}" in names, module

    site = tmp_path / "site"
    subprocess.run(
        [sys.executable, "-m", "pip", "install", "-q", "--no-deps", "--target", str(site), str(wheel)],
        check=True,
        timeout=300,
    )
    example = EXAMPLES / "scenarios" / "straight_rear_end_stopped_traffic.sov"
    # Run from an empty folder so that nothing resolves to the source tree.
    run = subprocess.run(
        [
            sys.executable,
            "-c",
            "import sys, sovarc.dsl as d; sys.path.insert(0, '');"
            "from sovarc.compiler.cli import main; print(d.__file__); sys.exit(main(['check', sys.argv[1]]))",
            str(example),
        ],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=120,
        env={"PYTHONPATH": str(site), "PATH": "/usr/bin:/bin"},
    )
    assert run.returncode == 0, run.stderr
    assert run.stdout.startswith(str(site))
