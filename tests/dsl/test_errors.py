"""Golden rendered diagnostics: file:line:col, the line, a caret, the message."""

from __future__ import annotations

from pathlib import Path

import pytest
from sovarc.dsl import SovarcError, parse, verify
from sovarc.dsl.span import Source

from tests.conftest import Golden

ERRORS = Path(__file__).parent / "fixtures" / "errors"


def render_all(path: Path) -> str:
    source = Source(path.name, path.read_text(encoding="utf-8"))
    sources = {source.name: source}
    try:
        scenario = parse(source.text, source.name)
    except SovarcError as exc:
        return exc.render(sources) + "\n"
    return "\n".join(d.render(sources) for d in verify(scenario)) + "\n"


@pytest.mark.parametrize("path", sorted(ERRORS.glob("*.sov")), ids=lambda p: p.stem)
def test_rendered_error_matches_golden(path: Path, golden: Golden) -> None:
    rendered = render_all(path)
    assert "error" in rendered
    golden.check(path.with_suffix(".err"), rendered)


def test_every_error_points_at_a_line_and_column() -> None:
    for path in ERRORS.glob("*.sov"):
        first = render_all(path).splitlines()[0]
        assert first.startswith(f"{path.name}:"), first
        line, col = first.split(":")[1:3]
        assert int(line) >= 1 and int(col) >= 1
