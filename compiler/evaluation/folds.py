"""A fixed split of the labelled NMVCCS reports into folds, so that rules are judged on reports they were not
written for.

Within each kind (crossing, straight, t) the reports are ordered by sha256 of their path relative to the
reports folder ("crossing/7.txt") and dealt out in turn, so every fold holds the same number of each kind
and the split never changes with the file system's order. Fold 0 is the development fold: its reports and
failures may be read while rules change. The other folds are held out: they are only run, to measure.

The rules that predate the split were tuned on all 90 reports, so for them the held-out folds are not
unseen; the 25 unlabelled `other` reports scored against the crash database's coded variables
(`coded.py`) are the set no rule was written for.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

FOLDS = 3
DEV = 0
KINDS = ("crossing", "straight", "t")


def _key(name: str) -> str:
    return hashlib.sha256(name.encode("utf-8")).hexdigest()


def fold_of(reports: Path) -> dict[str, int]:
    """ "kind/n" -> its fold, for every labelled report under `reports/<kind>/<n>.txt`."""
    folds: dict[str, int] = {}
    for kind in KINDS:
        names = sorted((f"{kind}/{p.stem}" for p in (reports / kind).glob("*.txt")), key=lambda n: _key(n + ".txt"))
        folds.update({name: i % FOLDS for i, name in enumerate(names)})
    return folds


def split(reports: Path) -> tuple[list[str], list[str]]:
    """(development, held out) report names ("kind/n"), each in name order."""
    folds = fold_of(reports)
    dev = sorted(n for n, f in folds.items() if f == DEV)
    held = sorted(n for n, f in folds.items() if f != DEV)
    return dev, held
