"""Where independent tasks run: a process pool on this machine, or a Ray cluster, behind one interface.

    executor = make_executor("local", jobs=2)        # or make_executor("ray", jobs=2, address="auto")
    for index, result in executor.run(fn, items):    # in the order tasks finish; index into items
        ...
    executor.close()

Neither schedules anything itself: the process pool is the standard library's, Ray's is Ray's. The
function and its items must be picklable (a module-level function and plain data), since both
send them to other processes. `jobs=1` runs in this process, one task after another: no pool, the
same results, and tracebacks where a debugger can reach them.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from multiprocessing import get_context
from typing import Any, Protocol

from sovarc.dsl.errors import SovarcError
from tqdm import tqdm

EXECUTORS = ("local", "ray")
RAY_HINT = "pip install 'sovarc[ray]'"


class ExecutorError(SovarcError):
    stage = "batch"


class Executor(Protocol):
    name: str
    jobs: int

    def run(self, fn: Callable[[Any], Any], items: Sequence[Any]) -> Iterator[tuple[int, Any]]:
        """Yield (index, fn(items[index])) as tasks finish. A task's exception is re-raised here:
        functions that must never stop a batch catch their own errors and return them."""
        ...

    def close(self) -> None: ...


def default_jobs() -> int:
    """Every core this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


class LocalExecutor:
    """A process pool of `jobs` workers on this machine (spawned, so no state leaks from the parent)."""

    name = "local"

    def __init__(self, jobs: int) -> None:
        self.jobs = max(1, jobs)
        self._pool: ProcessPoolExecutor | None = None

    def run(self, fn: Callable[[Any], Any], items: Sequence[Any]) -> Iterator[tuple[int, Any]]:
        if self.jobs == 1 or len(items) <= 1:
            for index, item in enumerate(items):
                yield index, fn(item)
            return
        if self._pool is None:
            self._pool = ProcessPoolExecutor(max_workers=self.jobs, mp_context=get_context("spawn"))
        # Submit a bounded window so a huge batch does not pickle every task up front.
        window = 4 * self.jobs
        pending: dict[Future[Any], int] = {}
        next_index = 0
        while next_index < len(items) or pending:
            while next_index < len(items) and len(pending) < window:
                pending[self._pool.submit(fn, items[next_index])] = next_index
                next_index += 1
            done, _ = wait(pending, return_when=FIRST_COMPLETED)
            for future in sorted(done, key=pending.__getitem__):
                yield pending.pop(future), future.result()

    def close(self) -> None:
        if self._pool is not None:
            self._pool.shutdown(cancel_futures=True)
            self._pool = None


class RayExecutor:
    """The same tasks on a Ray cluster: `address` is a running cluster's ('auto', 'ray://host:10001'),
    or None for a local cluster of `jobs` CPUs started for this run."""

    name = "ray"

    def __init__(self, jobs: int, address: str | None) -> None:
        try:
            import ray  # optional: the 'ray' extra
        except ImportError:
            raise ExecutorError(f"--executor ray needs Ray, which is not installed ({RAY_HINT})") from None
        self._ray = ray
        self.jobs = max(1, jobs)
        self._started = not ray.is_initialized()
        if self._started:
            options: dict[str, Any] = {"include_dashboard": False, "log_to_driver": False}
            if address:
                ray.init(address=address, **options)
            else:
                ray.init(num_cpus=self.jobs, **options)

    def run(self, fn: Callable[[Any], Any], items: Sequence[Any]) -> Iterator[tuple[int, Any]]:
        ray = self._ray
        remote = ray.remote(num_cpus=1, max_retries=0)(fn)
        pending = {remote.remote(item): index for index, item in enumerate(items)}
        while pending:
            done, _ = ray.wait(list(pending), num_returns=1)
            for ref in done:
                yield pending.pop(ref), ray.get(ref)

    def close(self) -> None:
        if self._started and self._ray.is_initialized():
            self._ray.shutdown()


def run_all(executor: Executor, fn: Callable[[Any], Any], items: Sequence[Any], label: str) -> list[Any]:
    """Every item's result, in the items' order however the executor scheduled them, with a progress bar."""
    done: list[Any] = [None] * len(items)
    with tqdm(total=len(items), desc=label, unit="task", disable=None) as bar:
        for index, result in executor.run(fn, items):
            done[index] = result
            bar.update(1)
    return done


def make_executor(name: str, jobs: int | None = None, address: str | None = None) -> Executor:
    """The executor `--executor NAME -j JOBS [--address A]` asks for."""
    jobs = jobs or default_jobs()
    if name == "local":
        if address:
            raise ExecutorError("--address goes with --executor ray")
        return LocalExecutor(jobs)
    if name == "ray":
        return RayExecutor(jobs, address)
    raise ExecutorError(f"no executor named '{name}'; executors: {', '.join(EXECUTORS)}")
