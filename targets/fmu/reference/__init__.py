"""The reference ego FMU: built from `sovarc_ego.py` with pythonfmu on first use, then cached.

The cache key is the source's hash and pythonfmu's version, so editing the driver rebuilds it. The
cache lives in the user's cache folder ($XDG_CACHE_HOME/sovarc/fmu, else ~/.cache/sovarc/fmu);
binaries are never written into the source tree.
"""

from __future__ import annotations

import hashlib
import os
import subprocess
import sys
import tempfile
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

from sovarc.dsl.errors import OracleError

SOURCE = Path(__file__).with_name("sovarc_ego.py")
MODEL = "SovarcEgo"


def default_cache_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "sovarc" / "fmu"


def reference_fmu(cache_dir: Path | None = None) -> Path:
    """The path of the reference ego FMU, building it first if this source has not been built yet."""
    try:
        tool = version("pythonfmu")
    except PackageNotFoundError:
        raise OracleError("building the reference ego FMU needs pythonfmu: `pip install pythonfmu`") from None
    key = hashlib.sha256(SOURCE.read_bytes() + tool.encode()).hexdigest()[:16]
    folder = cache_dir or default_cache_dir()
    target = folder / f"{MODEL}-{key}.fmu"
    if target.exists():
        return target
    folder.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="sovarc-fmu-") as tmp:
        # pythonfmu imports the script to describe it: do that in a child, not in this process.
        done = subprocess.run(
            [sys.executable, "-m", "pythonfmu", "build", "-f", str(SOURCE), "-d", tmp, "--no-external-tool"],
            capture_output=True,
            text=True,
            timeout=300,
            cwd=tmp,
        )
        built = Path(tmp) / f"{MODEL}.fmu"
        if done.returncode != 0 or not built.exists():
            raise OracleError(f"pythonfmu could not build the reference ego FMU:\n{done.stderr.strip()}")
        partial = folder / f".{target.name}.{os.getpid()}"
        partial.write_bytes(built.read_bytes())
        partial.replace(target)  # atomic: a concurrent build leaves one whole file
    return target
