"""Participants named any way: how often the rules front end (`--llm none`) reads a report's road users.

    python benchmarks/bench_names.py [--sgo CSV] [--nmvccs DIR]

SGO pool: rows of NHTSA's SGO ADS incident file whose crash partner is a road user the IR holds (a vehicle
class or a pedestrian: "Crash With" of Passenger Car, SUV, Pickup Truck, Heavy Truck, Van, Bus, Motorcycle,
First Responder Vehicle, Non-Motorist: Pedestrian), so the crash has two parties, and whose narrative is not
confidential ("Narrative - CBI?" not Y, no "[REDACTED", at least 100 characters). One row per Report ID (the
highest Report Version). The pool is split by the parity of the first byte of sha256(Report ID): even is the
development half (rules may be tuned on it), odd is held out (never read while tuning).

Per half: the share extracted (not refused, no internal error) and the share whose participant count is 2;
and how many refused narratives say no impact at all (GM's duplicate filings of Cruise reports are
boilerplate whose crash description is cut off: refusing them is right).
Then the NMVCCS figures `sovarc eval extraction --llm none` prints on the 90 labelled reports (mean, actions).
"""

from __future__ import annotations

import argparse
import re
from pathlib import Path

from sovarc.compiler.evaluation.extraction import Report
from sovarc.compiler.evaluation.sgo import held_out, read_pool
from sovarc.compiler.frontend import FrontEnd, FrontEndError
from sovarc.compiler.frontend.truth import import_truth_file
from sovarc.dsl import read_source
from sovarc.dsl.span import Source

DATA = Path(__file__).resolve().parents[2] / "shared" / "data"


def sgo_pool(path: Path) -> dict[str, dict[str, str]]:
    """Two-party rows with a readable narrative, the latest version per Report ID (see evaluation.sgo)."""
    return read_pool(path)


_IMPACT = re.compile(r"\b(?:struck|strik\w+|impact\w*|contact\w*|collid\w+|hit|rear[- ]end\w*)\b", re.I)


def read_half(front_end: FrontEnd, rows: list[dict[str, str]]) -> tuple[int, int, int, list[str], int]:
    extracted = two = silent = 0
    errors: list[str] = []
    for row in rows:
        source = Source(f"sgo_{row['Report ID']}.txt", row["Narrative"])
        try:
            got = front_end.extract(source).scenario
        except FrontEndError:
            silent += not _IMPACT.search(row["Narrative"])
            continue
        except Exception as e:  # an internal error is a failure to report, not to hide
            errors.append(f"{row['Report ID']}: {type(e).__name__}: {e}")
            continue
        extracted += 1
        two += len(got.participants) == 2
    return extracted, two, len(rows), errors, silent


def nmvccs(front_end: FrontEnd, data: Path) -> Report:
    report = Report()
    for truth_file in sorted((data / "truth").glob("*/*.json")):
        text = data / "reports" / truth_file.parent.name / f"{truth_file.stem}.txt"
        truth = import_truth_file(truth_file).scenario
        report.add(truth.name, front_end.extract(read_source(text, "crash report")).scenario, truth)
    return report


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sgo", type=Path, default=DATA / "sgo" / "sgo_ads_incidents_dev.csv")
    parser.add_argument("--nmvccs", type=Path, default=DATA / "nmvccs")
    args = parser.parse_args()

    front_end = FrontEnd("none")
    pool = sgo_pool(args.sgo)
    halves = {
        "development": [r for i, r in sorted(pool.items()) if not held_out(i)],
        "held-out": [r for i, r in sorted(pool.items()) if held_out(i)],
    }
    print(f"SGO two-party narratives, rules front end (--llm none): {len(pool)} reports\n")
    print(f"{'':24}{'development':>14}{'held-out':>14}")
    figures = {name: read_half(front_end, rows) for name, rows in halves.items()}
    print(f"{'reports':24}" + "".join(f"{f[2]:>14}" for f in figures.values()))
    print(f"{'extracted %':24}" + "".join(f"{100 * f[0] / max(f[2], 1):>14.1f}" for f in figures.values()))
    print(f"{'two participants %':24}" + "".join(f"{100 * f[1] / max(f[2], 1):>14.1f}" for f in figures.values()))
    print(f"{'refused, no impact said':24}" + "".join(f"{f[4]:>14}" for f in figures.values()))
    for name, f in figures.items():
        for error in f[3]:
            print(f"internal error ({name}): {error}")

    report = nmvccs(front_end, args.nmvccs)
    print(f"\nNMVCCS labelled reports ({len(report.cases)}), --llm none")
    print(f"mean of 10 {report.mean():.1f}, DrivingActions {report.accuracy('DrivingActions'):.1f}")


if __name__ == "__main__":
    main()
