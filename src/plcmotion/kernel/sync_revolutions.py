"""Which revolution of a modulo following axis a synchronization aims at (S7-1500T V5 §9.1.2, §9.1.5
SyncDirection, "in effect for axes with activated Modulo setting"; docs/s7_1500/decisions.md row 17).

The synchronous operation function fixes the following axis's position only modulo its length: the
synchronization may end k modulo lengths away.  SyncDirection chooses k - 1: the following axis's net
travel during the synchronization is not negative, 2: not positive, 3: the smallest correction - and,
among the candidates, one with one-way motion is preferred (decided by the caller).

Plain functions of a coupling and the following axis's modulo length (0 for a linear axis): they hold no
state and need no axis.
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

from .sync import GEAR, Coupling


def slave_correction(c: Coupling, e0: float, law_delta: float, length: float, shift_law: bool = False) -> float:
    """Position error to remove during a synchronization over time; on a modulo following axis the
    revolution of the synchronous position follows ``SyncDirection`` (1 positive, 2 negative,
    3 shortest)."""
    k = revolutions(c, e0, law_delta, length)[0]
    if shift_law:
        shift_by(c, k, length)
    return e0 - k * length


def stroke_in_revolutions(c: Coupling, length: float) -> bool:
    """Does one cam cycle move the following axis by a whole, non-zero number of modulo lengths?
    The positions at the cam's end and start are then the same (cross cutter, rotary knife)."""
    curve = c.curve
    if not length or curve is None:
        return False
    stroke = (float(curve.value(curve.end)) - float(curve.value(curve.start))) * c.slave_scaling
    turns = round(stroke / length)
    return turns != 0 and abs(stroke - turns * length) <= 1e-9 * max(1.0, abs(stroke))


def revolutions(c: Coupling, e0: float, law_delta: float, length: float) -> list[int]:
    """Candidate revolutions k (the following axis's synchronous position shifted by k modulo
    lengths), best first: the smallest corrections ``e0 - k * length`` whose net travel of the
    following axis, ``law_delta - (e0 - k * length)``, keeps to ``SyncDirection`` (1 not negative,
    2 not positive, 3 any; decision 17).  Never empty: the allowed k form a half-open range whatever
    the leading value travels during the synchronization (many revolutions of a short modulo axis)."""
    if not length:
        return [0]
    direction = c.job.extra.get("sync_direction", 3)
    best = round(e0 / length)
    tol = 1e-9 * max(1.0, abs(law_delta), abs(e0))
    if direction == 1:          # travel >= 0  <=>  k >= (e0 - law_delta) / length
        lo = math.ceil((e0 - law_delta - tol) / length)
        ks = list(range(max(best - 1, lo), max(best - 1, lo) + 4))
    elif direction == 2:        # travel <= 0  <=>  k <= (e0 - law_delta) / length
        hi = math.floor((e0 - law_delta + tol) / length)
        ks = list(range(min(best + 1, hi) - 3, min(best + 1, hi) + 1))
    else:
        ks = [best - 1, best, best + 1]
    # the smallest correction; of two equally small ones the one travelling with the leading value
    ks.sort(key=lambda k: (abs(e0 - k * length),
                           -(law_delta - (e0 - k * length)) * (1 if law_delta >= 0 else -1)))
    return ks[:3]


def monotonic(c: Coupling, coef, x0: float, length: float, law_delta: float,
              law_at: Callable[..., tuple[float, float, float]]) -> bool:
    """Does the following axis move in one direction only during the blend (sampled)?  ``law_at`` is
    the sync stage's synchronous operation function."""
    sign = 1.0 if c.job.extra.get("sync_direction", 3) == 1 else -1.0
    s = np.linspace(0.0, 1.0, 33)
    e = coef[0] + s * (coef[1] + s * (coef[2] + s * (coef[3] + s * (coef[4] + s * coef[5]))))
    ys = np.array([law_at(c, x0 + si * length, 0.0, 0.0)[0] for si in s]) + e
    step = np.diff(ys) * sign
    return bool(np.all(step >= -1e-9 * max(1.0, float(np.max(np.abs(ys))))))


def shift_by(c: Coupling, k: int, length: float) -> None:
    """Move the synchronous operation function by ``k`` modulo lengths of the following axis."""
    if k:
        shift = k * length
        if c.law == GEAR:
            c.offset += shift
        else:
            c.slave_offset += shift
