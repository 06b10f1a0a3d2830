"""Finding and running SUMO's netconvert, the one external program the map layer needs."""

from __future__ import annotations

import functools
import os
import shutil
import subprocess
from collections.abc import Sequence
from pathlib import Path

from sovarc.dsl.errors import Diagnostic, InputError, SovarcError
from sovarc.dsl.span import Span

TIMEOUT_S = 300


class ToolError(SovarcError):
    """A program the map layer needs is missing or broken (not the user's input)."""

    stage = "map"


@functools.cache
def netconvert_path() -> str:
    """The netconvert binary: $SUMO_HOME/bin first, then PATH, then the eclipse-sumo wheel."""
    candidates: list[str] = []
    if home := os.environ.get("SUMO_HOME"):
        candidates.append(str(Path(home) / "bin" / "netconvert"))
    if found := shutil.which("netconvert"):
        candidates.append(found)
    try:
        import sumo  # the eclipse-sumo wheel ships the binaries

        candidates.append(str(Path(sumo.SUMO_HOME) / "bin" / "netconvert"))
    except ImportError:
        pass
    for path in candidates:
        if Path(path).is_file() and os.access(path, os.X_OK):
            return path
    raise ToolError("netconvert not found: install SUMO (`pip install eclipse-sumo`) or set SUMO_HOME")


@functools.cache
def netconvert_version() -> str:
    """Its name and version as it prints them, e.g. 'Eclipse SUMO netconvert 1.28.0'."""
    done = subprocess.run([netconvert_path(), "--version"], capture_output=True, text=True, timeout=60)
    first = done.stdout.splitlines()[0].strip() if done.stdout else ""
    if done.returncode != 0 or not first:
        raise ToolError(f"{netconvert_path()} --version failed: {done.stderr.strip() or done.returncode}")
    return first.replace(" Version ", " ")


def run_netconvert(args: Sequence[str], source: str | os.PathLike[str]) -> None:
    """Run netconvert; a failure is the input's fault, so it is an InputError naming `source`."""
    try:
        done = subprocess.run([netconvert_path(), *args], capture_output=True, text=True, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        raise _input_error(source, f"netconvert did not finish within {TIMEOUT_S} s") from None
    if done.returncode != 0:
        errors = [line for line in done.stderr.splitlines() if line.startswith("Error")]
        reason = errors[0] if errors else (done.stderr.strip().splitlines() or ["no message"])[-1]
        raise _input_error(source, f"netconvert failed: {reason}")


def convert_opendrive(xodr: str | os.PathLike[str], out: str | os.PathLike[str], *, lefthand: bool = False) -> None:
    """Convert an OpenDRIVE file to a SUMO network, keeping its coordinates (no offset); `lefthand` for
    a map whose traffic keeps left (its roads' `rule="LHT"`)."""
    args = ["--opendrive-files", str(xodr), "--offset.disable-normalization", "true", "-o", str(out)]
    args += ["--lefthand", "true"] if lefthand else []
    run_netconvert([*args, "--xml-validation", "never", "--no-warnings", "true"], xodr)


def _input_error(source: str | os.PathLike[str], message: str) -> InputError:
    return InputError(Diagnostic(message, Span.whole_file(str(source))))
