"""Extraction quality and cost on the labelled NMVCCS reports: the issue's figures in one run.

    python benchmarks/bench_extraction.py [--llm embedded|none|openai:MODEL] [--answers DIR]
        [--fold K] [--unlabelled DIR] [--limit N] [--json FILE]

Prints the per-attribute table (the paper's Table 3 form), the median and
total seconds per report, the model's tokens per report (read and generated:
figures that do not depend on the machine's load), and the peak memory of
sovarc and its model worker. By default the answer cache is a fresh temporary
folder, so every answer is computed (cold cache of answers; the model file
itself stays cached). Give `--answers DIR` to reuse a cache and measure a
rerun instead.

Held-out protocol: the prompts and worked examples were written against the
90 shared reports, so they are split into 3 folds by a hash of the report's
path (`fold_of`). Fold 0 is the one read while tuning prompts and examples;
`--fold 1` is the held-out fold the README's figures come from; fold 2 is kept
unread. `--unlabelled DIR` times reports that have no ground truth (speed only).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import resource
import statistics
import tempfile
import time
from pathlib import Path
from typing import Any

from sovarc.compiler.evaluation.extraction import Report
from sovarc.compiler.frontend import FrontEnd, default_llm
from sovarc.compiler.frontend.truth import import_truth_file
from sovarc.dsl import read_source

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "nmvccs"
FOLDS = 3
TUNING_FOLD = 0


def folds(reports: list[str]) -> dict[str, int]:
    """Each report's fold, by its path under reports/ ("crossing/3.txt"): the reports in the order of their
    paths' SHA-256, dealt round to the folds, so the folds are even (30, 30, 30) and do not follow the
    categories or the numbering."""
    ranked = sorted(reports, key=lambda r: hashlib.sha256(r.encode("utf-8")).hexdigest())
    return {r: i % FOLDS for i, r in enumerate(ranked)}


class TokenCounter:
    """Wraps the model provider to add up llama.cpp's own counts over every request of one report."""

    def __init__(self, inner: Any) -> None:
        self.inner = inner
        self.name, self.model = inner.name, inner.model
        self.reset()

    def reset(self) -> None:
        self.calls = 0
        self.prompt = 0  # tokens in the prompts, cached prefix included
        self.read = 0  # prompt tokens the model actually processed
        self.generated = 0

    def complete_json(self, system: str, user: str, schema: dict[str, Any], *, max_tokens: int) -> str:
        text = self.inner.complete_json(system, user, schema, max_tokens=max_tokens)
        response = getattr(self.inner, "last_response", None) or {}
        timings, usage = response.get("timings", {}), response.get("usage", {})
        self.calls += 1
        self.prompt += int(usage.get("prompt_tokens", 0))
        self.read += int(timings.get("prompt_n", 0))
        self.generated += int(timings.get("predicted_n", 0))
        return text

    def close(self) -> None:
        self.inner.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--llm", default=default_llm())
    parser.add_argument("--model", type=Path, default=None)
    parser.add_argument("--llm-base-url", default=None)
    parser.add_argument("--data", type=Path, default=DATA)
    parser.add_argument("--answers", type=Path, default=None, help="answer cache folder (default: a fresh one)")
    parser.add_argument("--limit", type=int, default=None, help="only the first N reports (a quick look)")
    parser.add_argument("--fold", type=int, default=None, choices=range(FOLDS), help="only this fold of the 90")
    parser.add_argument("--unlabelled", type=Path, default=None, help="time these *.txt reports (no scoring)")
    parser.add_argument("--timeout", type=float, default=None, help="seconds the model may take per answer")
    parser.add_argument("--json", type=Path, default=None, help="write per-report figures here")
    args = parser.parse_args()

    if args.unlabelled is not None:
        cases = [(p, None) for p in sorted(args.unlabelled.glob("*.txt"), key=lambda p: (len(p.stem), p.stem))]
    else:
        truths = sorted((args.data / "truth").glob("*/*.json"))
        fold = folds([f"{t.parent.name}/{t.stem}.txt" for t in truths])
        cases = [
            (args.data / "reports" / t.parent.name / f"{t.stem}.txt", t)
            for t in truths
            if args.fold is None or fold[f"{t.parent.name}/{t.stem}.txt"] == args.fold
        ]
    cases = cases[: args.limit]

    with tempfile.TemporaryDirectory(prefix="sovarc-answers-") as fresh:
        front_end = FrontEnd(args.llm, args.model, args.llm_base_url, cache_dir=args.answers or Path(fresh))
        counter = None
        if args.llm != "none":
            cached = front_end.provider()
            if args.timeout is not None:  # a first run on a loaded machine reads the long prefix slowly
                cached.inner.timeout_s = args.timeout
            counter = TokenCounter(cached.inner)
            cached.inner = counter
        report, rows = Report(), []
        for text, truth_file in cases:
            if counter is not None:
                counter.reset()
            start, cpu = time.perf_counter(), time.process_time()
            got = front_end.extract(read_source(text, "crash report")).scenario
            row = {"report": str(text), "seconds": time.perf_counter() - start, "cpu": time.process_time() - cpu}
            if counter is not None:
                row |= {"calls": counter.calls, "prompt": counter.prompt, "read": counter.read}
                row |= {"generated": counter.generated}
            rows.append(row)
            print(json.dumps(row), flush=True)  # as it goes: a long run cut short still has its figures
            if truth_file is not None:
                report.add(truth_file.parent.name + "/" + truth_file.stem, got, import_truth_file(truth_file).scenario)
        front_end.close()  # ends the model worker, so its peak memory is counted below

    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    worker = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    where = f"fold {args.fold} of {FOLDS}" if args.fold is not None else "all"
    if report.cases:
        print(f"extraction on {len(report.cases)} reports ({where}), --llm {args.llm}\n")
        print(report.table())
    seconds = [r["seconds"] for r in rows]
    print(
        f"\nseconds per report ({len(rows)}): median {statistics.median(seconds):.1f}, max {max(seconds):.1f}, "
        f"first {seconds[0]:.1f} (includes the model load and the prompt prefix), total {sum(seconds):.0f}"
    )
    if counter is not None:
        for key in ("calls", "prompt", "read", "generated"):
            values = [r[key] for r in rows]
            print(f"{key:>10} per report: median {statistics.median(values):.0f}, max {max(values)}")
    print(f"peak memory: sovarc {own:.0f} MB, model worker {worker:.0f} MB")
    if args.json is not None:
        args.json.write_text(json.dumps({"rows": rows, "scores": report.to_json()}, indent=1) + "\n")


if __name__ == "__main__":
    main()
