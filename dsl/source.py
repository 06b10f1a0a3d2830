"""Reading input files, with one clear line for each way a file can be unusable."""

from __future__ import annotations

import os
from pathlib import Path

from sovarc.dsl.errors import Diagnostic, InputError
from sovarc.dsl.span import Source, Span


def read_source(path: str | os.PathLike[str], what: str = "file") -> Source:
    """Read a UTF-8 text file, refusing directories, binary, non-UTF-8 and empty files."""
    name = os.fspath(path)
    p = Path(name)

    def fail(reason: str) -> InputError:
        return InputError(Diagnostic(reason, Span.whole_file(name)))

    if p.is_dir():
        raise fail(f"is a directory, expected a {what}")
    try:
        data = p.read_bytes()
    except FileNotFoundError:
        raise fail("no such file") from None
    except PermissionError:
        raise fail("permission denied") from None
    except OSError as exc:
        raise fail(f"cannot be read ({exc.strerror or exc})") from None
    if b"\x00" in data[:8192]:
        raise fail(f"is a binary file, expected a {what}")
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        raise fail(f"is not valid UTF-8 (byte 0x{data[exc.start]:02x} on line {line})") from None
    if not text.strip():
        raise fail("is empty")
    return Source(name, text)
