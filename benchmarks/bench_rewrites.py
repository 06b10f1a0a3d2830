"""Metamorphic benchmark: the rules front end on meaning-preserving rewrites of the labelled NMVCCS reports.

    python benchmarks/bench_rewrites.py [--llm none] [--data DIR] [--only NAME ...] [--failures] [--json FILE]

Each rewrite (`compiler/evaluation/rewrites.py`) says the same facts in other words a report writer uses ("V1"
as "Vehicle #1", "45 mph" as "45 miles per hour", "traveling northbound" as "heading north", one sentence as
two). The right extraction of a rewritten report is the original's. Per rewrite it prints, on the development
fold 0 beside the held-out folds 1-2 (`compiler/evaluation/folds.py`):
- applied: how many reports the rewrite changed the text of;
- changed: how many reports' extraction (the IR without its provenance, whose spans move with the text) is not
  the original's, a refusal counting as a change (a speed said in another unit is the same speed);
- the mean of the 10 attributes, DrivingActions, CrashType and Striker against the ground truth.
The first row, `original`, is the reports as they are.

`--failures` prints fold 0's changed reports only, as the diff of the IR (held-out reports are measured, never
read while the front end changes).
"""

from __future__ import annotations

import argparse
import difflib
import json
import re
from dataclasses import replace
from pathlib import Path

from maps import SHARED
from sovarc.compiler.evaluation import extraction
from sovarc.compiler.evaluation.folds import split
from sovarc.compiler.evaluation.rewrites import REWRITES
from sovarc.compiler.frontend import FrontEnd, FrontEndError
from sovarc.compiler.frontend.truth import import_truth_file
from sovarc.dsl import to_text
from sovarc.dsl.ir import Scenario
from sovarc.dsl.span import Source

DATA = SHARED / "data" / "nmvccs"  # $SOVARC_SHARED, as every benchmark reads it
COLUMNS = ("mean", "DrivingActions", "CrashType", "Striker")


def _read(front_end: FrontEnd, name: str, text: str) -> tuple[Scenario | None, str]:
    """The scenario (None when refused) and its IR text without provenance, for comparing two readings."""
    try:
        scenario = front_end.extract(Source(f"{name.replace('/', '_')}.txt", text)).scenario
    except FrontEndError as e:
        return None, f"refused: {e}\n"
    except Exception as e:  # an internal error on a rewritten report is a finding, not a reason to stop
        return None, f"internal error: {type(e).__name__}: {e}\n"
    return scenario, to_text(replace(scenario, provenance=None))


_SPEED = re.compile(r"\b(\d+(?:\.\d+)?) (km/h|mph|m/s)\b")
_MPS = {"km/h": 1 / 3.6, "mph": 0.44704, "m/s": 1.0}


def _same(a: str, b: str) -> bool:
    """Two readings' IR texts alike, a speed in one unit equal to the same speed in another (within 0.5 m/s, as
    the scorer compares them): "48 km/h" is the sign "30 mph" names."""
    if _SPEED.sub("SPEED", a) != _SPEED.sub("SPEED", b):
        return False
    speeds = [[float(n) * _MPS[u] for n, u in _SPEED.findall(x)] for x in (a, b)]
    return all(abs(x - y) < 0.5 for x, y in zip(*speeds, strict=True))


def _score(got: dict[str, Scenario | None], truth: dict[str, Scenario]) -> dict[str, float]:
    report = extraction.Report()
    for name, scenario in got.items():
        report.add(name, scenario or Scenario(truth[name].name), truth[name])
    return {c: report.mean() if c == "mean" else report.accuracy(c) for c in COLUMNS}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--llm", default="none")
    parser.add_argument("--data", type=Path, default=DATA)
    parser.add_argument("--only", nargs="*", default=None, metavar="NAME", help="these rewrites only")
    parser.add_argument("--failures", action="store_true", help="print fold 0's changed reports (IR diff)")
    parser.add_argument("--json", type=Path, default=None, help="write the figures here too")
    args = parser.parse_args()

    dev, held = split(args.data / "reports")
    sets = {"dev": dev, "held": held}
    texts = {n: (args.data / "reports" / f"{n}.txt").read_text(encoding="utf-8") for n in dev + held}
    truth = {n: import_truth_file(args.data / "truth" / f"{n}.json").scenario for n in dev + held}
    front_end = FrontEnd(args.llm)
    original = {n: _read(front_end, n, texts[n]) for n in dev + held}

    names = args.only if args.only is not None else list(REWRITES)
    rows: list[list[str]] = []
    figures: dict[str, dict[str, object]] = {}
    failures: list[str] = []

    def row(label: str, got: dict[str, Scenario | None], applied: dict[str, int], changed: dict[str, int]) -> None:
        fig: dict[str, object] = {}
        cells = [label]
        for k in ("dev", "held"):
            fig[f"{k} applied"], fig[f"{k} changed"] = applied[k], changed[k]
        cells.append(f"{applied['dev']}/{applied['held']}")
        cells.append(f"{changed['dev']}/{changed['held']}")
        for k in ("dev", "held"):
            scores = _score({n: got[n] for n in sets[k]}, truth)
            fig.update({f"{k} {c}": round(v, 1) for c, v in scores.items()})
        for c in COLUMNS:
            cells.append(f"{fig[f'dev {c}']:.1f} | {fig[f'held {c}']:.1f}")
        rows.append(cells)
        figures[label] = fig

    zero = {"dev": 0, "held": 0}
    row("original", {n: s for n, (s, _) in original.items()}, zero, zero)
    for rewrite in names:
        got: dict[str, Scenario | None] = {}
        applied, changed = dict(zero), dict(zero)
        for k, members in sets.items():
            for n in members:
                text = REWRITES[rewrite](texts[n])
                if text == texts[n]:
                    got[n] = original[n][0]
                    continue
                applied[k] += 1
                got[n], ir = _read(front_end, n, text)
                if not _same(ir, original[n][1]):
                    changed[k] += 1
                    if k == "dev":
                        diff = difflib.unified_diff(
                            original[n][1].splitlines(), ir.splitlines(), "original", rewrite, n=0, lineterm=""
                        )
                        failures.append(f"== {rewrite} {n}\n" + "\n".join(list(diff)[2:]))
        row(rewrite, got, applied, changed)
    front_end.close()

    head = ["rewrite", "applied", "changed", *(f"{c} dev | held" for c in COLUMNS)]
    table = [head, *rows]
    widths = [max(len(r[i]) for r in table) for i in range(len(head))]
    print(f"--llm {args.llm}; fold 0 (development, {len(dev)} reports) | folds 1-2 (held out, {len(held)})")
    print("applied, changed: reports, dev/held\n")
    print("\n".join("  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in table))
    if args.failures:
        print("\nfold 0's changed extractions (IR diff, original -> rewritten):")
        print("\n".join(failures) or "none")
    if args.json:
        args.json.write_text(json.dumps(figures, indent=1) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
