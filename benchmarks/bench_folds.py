"""Held-out beside tuned: the rules front end on the development fold, the held-out folds and the unlabelled
`other` reports scored against the crash database's own codes.

    python benchmarks/bench_folds.py [--llm none] [--data DIR] [--failures] [--json FILE]

Sets (see `compiler/evaluation/folds.py` and `coded.py`):
- dev: fold 0 of the 90 labelled reports (30, 10 per kind); rules may be read and tuned on it;
- held: folds 1 and 2 (60); only run, never read while rules change. The rules that predate the split were
  tuned on all 90, so for them these are not unseen;
- other: the 25 unlabelled reports, which no rule was tuned on, scored against coded_variables.csv.
Each labelled set is scored twice: against the SoVAR ground truth (the paper's Table 3 attributes) and
against the coded variables. The last column scores the ground truth itself against the codes on all 90:
how far the two labellings agree, the ceiling of a coded column.

`--failures` prints the dev fold's failures only (the held-out sets' are not to be read while tuning).
"""

from __future__ import annotations

import argparse
import json
import re
from collections import Counter
from pathlib import Path

from maps import SHARED
from sovarc.compiler.evaluation import coded, extraction
from sovarc.compiler.evaluation.folds import split
from sovarc.compiler.frontend import FrontEnd, FrontEndError
from sovarc.compiler.frontend.truth import import_truth_file
from sovarc.dsl import read_source
from sovarc.dsl.ir import Scenario, Unknown

DATA = SHARED / "data" / "nmvccs"  # $SOVARC_SHARED, as every benchmark reads it


def _extract(front_end: FrontEnd, data: Path, names: list[str]) -> dict[str, Scenario | None]:
    out: dict[str, Scenario | None] = {}
    for name in names:
        try:
            out[name] = front_end.extract(read_source(data / "reports" / f"{name}.txt", "crash report")).scenario
        except FrontEndError:
            out[name] = None  # refused: every attribute of the case is wrong
    return out


def _truth(data: Path, name: str) -> Scenario:
    return import_truth_file(data / "truth" / f"{name}.json").scenario


def _against_truth(data: Path, got: dict[str, Scenario | None]) -> extraction.Report:
    report = extraction.Report()
    for name, scenario in got.items():
        truth = _truth(data, name)
        report.add(name, scenario or Scenario(name), truth)
    return report


def _against_codes(codes: dict[str, coded.Coded], got: dict[str, Scenario | None]) -> coded.CodedReport:
    return coded.CodedReport({n: coded.score(s or Scenario(n), codes[n]) for n, s in got.items()})


def _kinds_of_misses(got: dict[str, Scenario | None], truth: dict[str, Scenario]) -> str:
    """Per vehicle whose sequence is wrong: the action kinds it lacks and has in excess, or 'order' when the
    kinds agree, or 'unknown' when one side does not know."""
    tally: Counter[str] = Counter()
    for name, want in truth.items():
        mine = {p.id: p for p in (got[name] or Scenario(name)).participants}
        for p in want.participants:
            have = mine.get(p.id)
            a = None if have is None or isinstance(have.actions, Unknown) else [x.kind.value for x in have.actions]
            b = None if isinstance(p.actions, Unknown) else [x.kind.value for x in p.actions]
            if a == b:
                continue
            if a is None or b is None:
                tally["unknown vs known"] += 1
                continue
            lost, extra = Counter(b) - Counter(a), Counter(a) - Counter(b)
            tally.update(f"missing {k}" for k in lost)
            tally.update(f"extra {k}" for k in extra)
            if not lost and not extra:
                tally["order"] += 1
    return ", ".join(f"{k} {n}" for k, n in tally.most_common()) or "none"


def _coded_misses(report: coded.CodedReport) -> str:
    tally: Counter[str] = Counter()
    for _, why in report.failures("DrivingActions"):
        for part in why.split("; "):
            tally.update(f"needs {n}" for n in re.findall(r"needs ([\w/]+)", part))
            tally.update(
                f"has denied {k}"
                for k in re.findall(r"\b(turn_left|turn_right|u_turn)\b", part.split("≠")[0])
                if "no " in part
            )
    return ", ".join(f"{k} {n}" for k, n in tally.most_common()) or "none"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--llm", default="none")
    parser.add_argument("--data", type=Path, default=DATA)
    parser.add_argument("--failures", action="store_true", help="print the dev fold's failures")
    parser.add_argument("--kinds", action="store_true", help="count the action misses by kind, every set")
    parser.add_argument("--json", type=Path, default=None, help="write the figures here too")
    args = parser.parse_args()

    dev, held = split(args.data / "reports")
    other = sorted(f"other/{p.stem}" for p in (args.data / "reports" / "other").glob("*.txt"))
    codes = coded.load(args.data / "coded_variables.csv")
    front_end = FrontEnd(args.llm)
    got = {"dev": _extract(front_end, args.data, dev), "held": _extract(front_end, args.data, held)}
    got["other"] = _extract(front_end, args.data, other)
    front_end.close()

    truth = {k: _against_truth(args.data, got[k]) for k in ("dev", "held")}
    by_code = {k: _against_codes(codes, got[k]) for k in ("dev", "held", "other")}
    ceiling = _against_codes(codes, {n: _truth(args.data, n) for n in dev + held})

    head = ["attribute", "dev truth", "held truth", "dev coded", "held coded", "other coded", "truth~coded"]
    rows = [head, ["reports", str(len(dev)), str(len(held)), str(len(dev)), str(len(held)), str(len(other)), "90"]]
    figures: dict[str, dict[str, float | None]] = {}
    for attribute in (*extraction.ATTRIBUTES, "mean", *extraction.EXTRA):
        row = [attribute]
        fig: dict[str, float | None] = {}
        for k in ("dev", "held"):
            value = truth[k].mean() if attribute == "mean" else truth[k].accuracy(attribute)
            fig[f"{k} truth"] = round(value, 1)
            row.append(f"{value:.1f}")
        for k, report in (*by_code.items(), ("truth~coded", ceiling)):
            if attribute not in coded.ATTRIBUTES:
                row.append("-")
                continue
            value, n = report.accuracy(attribute)
            fig[f"{k} coded" if k != "truth~coded" else k] = round(value, 1)
            row.append(f"{value:.1f} ({n})")
        figures[attribute] = fig
        rows.append(row)
    widths = [max(len(r[i]) for r in rows) for i in range(len(head))]
    print(f"--llm {args.llm}; coded columns give (cases scored)\n")
    print("\n".join("  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows))

    if args.failures:
        print("\ndev fold against the ground truth:")
        for name, attribute, why in truth["dev"].failures():
            print(f"  {name:12} {attribute:18} {why}")
        print("\ndev fold against the coded variables:")
        for attribute in coded.ATTRIBUTES:
            for name, why in by_code["dev"].failures(attribute):
                print(f"  {name:12} {attribute:18} {why}")
    if args.kinds:
        print("\nwhat the DrivingActions misses are, by kind (counts only: held-out reports are not shown)")
        for k in ("dev", "held"):
            print(f"  {k} truth: {_kinds_of_misses(got[k], {n: _truth(args.data, n) for n in got[k]})}")
        for k in ("dev", "held", "other"):
            print(f"  {k} coded: {_coded_misses(by_code[k])}")
        agreed = {n for n, c in ceiling.cases.items() if (r := c.get("DrivingActions")) is not None and r[0]}
        for k in ("dev", "held"):
            both = coded.CodedReport({n: c for n, c in by_code[k].cases.items() if n in agreed})
            value, n = both.accuracy("DrivingActions")
            print(f"  {k} coded, where the ground truth meets the codes: {value:.1f} ({n}); {_coded_misses(both)}")
    if args.json:
        args.json.write_text(json.dumps(figures, indent=1) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
