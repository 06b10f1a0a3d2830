"""A progress bar for long batches, drawn on standard error only when it is a terminal."""

from __future__ import annotations

import sys
from collections.abc import Iterable, Iterator
from typing import TextIO, TypeVar

T = TypeVar("T")


def progress(items: Iterable[T], total: int, label: str = "", stream: TextIO | None = None) -> Iterator[T]:
    """Yield `items`, redrawing `label [#####.....] 12/90` after each one."""
    out = stream or sys.stderr
    live = out.isatty() and total > 1
    for done, item in enumerate(items, 1):
        yield item
        if live:
            filled = int(30 * done / total)
            out.write(f"\r{label} [{'#' * filled}{'.' * (30 - filled)}] {done}/{total}")
            out.flush()
    if live:
        out.write("\n")
