"""Extraction quality and cost on the labelled NMVCCS reports: the issue's figures in one run.

    python benchmarks/bench_extraction.py [--llm embedded|none|openai:MODEL] [--answers DIR]

Prints the per-attribute table (the paper's Table 3 form), the median and
total seconds per report, and the peak memory of sovarc and its model worker.
By default the answer cache is a fresh temporary folder, so every answer is
computed (cold cache of answers; the model file itself stays cached). Give
`--answers DIR` to reuse a cache and measure a rerun instead.
"""

from __future__ import annotations

import argparse
import resource
import statistics
import tempfile
import time
from pathlib import Path

from sovarc.compiler.evaluation.extraction import Report
from sovarc.compiler.frontend import FrontEnd, default_llm
from sovarc.compiler.frontend.truth import import_truth_file
from sovarc.dsl import read_source

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "nmvccs"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--llm", default=default_llm())
    parser.add_argument("--model", type=Path, default=None)
    parser.add_argument("--llm-base-url", default=None)
    parser.add_argument("--data", type=Path, default=DATA)
    parser.add_argument("--answers", type=Path, default=None, help="answer cache folder (default: a fresh one)")
    parser.add_argument("--limit", type=int, default=None, help="only the first N reports (a quick look)")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory(prefix="sovarc-answers-") as fresh:
        front_end = FrontEnd(args.llm, args.model, args.llm_base_url, cache_dir=args.answers or Path(fresh))
        report, seconds = Report(), []
        for truth_file in sorted((args.data / "truth").glob("*/*.json"))[: args.limit]:
            text = args.data / "reports" / truth_file.parent.name / f"{truth_file.stem}.txt"
            truth = import_truth_file(truth_file).scenario
            start = time.perf_counter()
            got = front_end.extract(read_source(text, "crash report")).scenario
            seconds.append(time.perf_counter() - start)
            report.add(truth.name, got, truth)
        front_end.close()  # ends the model worker, so its peak memory is counted below

    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    worker = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    print(f"extraction on {len(report.cases)} reports, --llm {args.llm}\n")
    print(report.table())
    print(
        f"\nseconds per report: median {statistics.median(seconds):.1f}, max {max(seconds):.1f}, first "
        f"{seconds[0]:.1f} (includes the model load and the prompt prefix), total {sum(seconds):.0f}"
    )
    print(f"peak memory: sovarc {own:.0f} MB, model worker {worker:.0f} MB")


if __name__ == "__main__":
    main()
