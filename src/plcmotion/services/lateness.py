"""Statistics of the lateness of the paced servo cycles: a bounded numpy ring plus exact run totals.

p50/p99 are nearest-rank percentiles (the smallest recorded value with at least p % of the samples at or
below it) over the last ``window`` cycles, so memory stays bounded over hours; the maximum and the counts
cover the whole run."""
from __future__ import annotations

import math

import numpy as np

#: cycles the percentiles look back over (65 s at a 1 ms servo cycle)
DEFAULT_WINDOW = 1 << 16


class LatenessStats:
    """Lateness samples [ns] of the servo cycles."""

    def __init__(self, window: int = DEFAULT_WINDOW):
        if window < 1:
            raise ValueError(f"window must be >= 1 cycle, got {window!r}")
        self._ring = np.zeros(window, dtype=np.int64)
        self._next = 0
        #: cycles recorded since the start
        self.count = 0
        #: the largest lateness of the run [ns]
        self.max_ns = 0

    def add(self, lateness_ns: int) -> None:
        self._ring[self._next] = lateness_ns
        self._next = (self._next + 1) % len(self._ring)
        self.count += 1
        if lateness_ns > self.max_ns:
            self.max_ns = lateness_ns

    def samples(self) -> np.ndarray:
        """The samples in the window (oldest first)."""
        n = min(self.count, len(self._ring))
        if n < len(self._ring):
            return self._ring[:n].copy()
        return np.concatenate((self._ring[self._next:], self._ring[:self._next]))

    def percentile_ns(self, p: float) -> int:
        """Nearest-rank percentile ``p`` (0 < p <= 100) of the window [ns]; 0 before the first sample."""
        n = min(self.count, len(self._ring))
        if n == 0:
            return 0
        rank = max(1, math.ceil(p / 100.0 * n))
        return int(np.partition(self._ring[:n], rank - 1)[rank - 1])
