"""A front end as an executor task sees it: named by plain data, made once per worker process.

The evaluations that read reports (`eval extraction`, NMVCCS or SGO) send each report to an executor
as a task. A task carries the front end's name and settings, not the front end (a model worker is a
process, which does not travel); each worker makes it on its first task and keeps it for the rest, so
the embedded model loads once per worker, and closes it when the worker exits.
"""

from __future__ import annotations

import atexit
import functools
from dataclasses import dataclass

from sovarc.compiler.frontend import FrontEnd


@dataclass(frozen=True)
class FrontEndSpec:
    llm: str
    model: str | None = None
    base_url: str | None = None


@functools.cache
def front_end(spec: FrontEndSpec) -> FrontEnd:
    """This process's front end for `spec`, made on first use."""
    made = FrontEnd(spec.llm, spec.model, spec.base_url)
    atexit.register(made.close)
    return made
