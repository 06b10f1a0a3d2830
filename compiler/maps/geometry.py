"""Fitting a site's arms to a compass cross (site search). The plane geometry itself (angles,
shapes, polylines) is the kernel's: compiler/geometry.

Compass degrees: 0 = north (+y), 90 = east (+x), clockwise, in [0, 360).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

from sovarc.compiler.geometry.angles import angle_diff, circular_mean


@dataclass(frozen=True)
class Frame:
    """A compass cross laid over a site: arm i sits in `slots[i]` (0..3), whose ideal
    heading is `orientation + 90 * slot`; `error` is the worst arm's distance from it."""

    orientation: float  # in [-45, 45)
    slots: tuple[int, ...]
    error: float


def fit_frame(headings: Sequence[float]) -> Frame:
    """The cross (up to four arms, each in its own slot, clockwise order kept) that fits best.

    Keeping the clockwise order means left stays left and right stays right; the best fit is
    the one with the least squared angular error, ties broken by enumeration order.
    """
    count = len(headings)
    if not 1 <= count <= 4:
        raise ValueError(f"a compass cross has 1 to 4 arms, not {count}")
    order = sorted(range(count), key=lambda i: (headings[i], i))
    best: tuple[float, Frame] | None = None
    for chosen in itertools.combinations(range(4), count):
        for shift in range(count):
            slots = [0] * count
            for rank, arm in enumerate(order):
                slots[arm] = chosen[(rank + shift) % count]
            offsets = [headings[i] - 90.0 * slots[i] for i in range(count)]
            centre = circular_mean(offsets)
            errors = [abs(angle_diff(o, centre)) for o in offsets]
            score = sum(e * e for e in errors)
            if best is None or score < best[0] - 1e-9:
                best = (score, _normalized(centre, slots, max(errors)))
    assert best is not None
    return best[1]


def _normalized(orientation: float, slots: list[int], error: float) -> Frame:
    # Pick the multiple of 90 that brings the orientation into [-45, 45) and renumber the slots.
    turns = math.floor((orientation + 45.0) / 90.0)
    orientation -= 90.0 * turns
    return Frame(round(orientation, 6), tuple((s + turns) % 4 for s in slots), round(error, 6))
