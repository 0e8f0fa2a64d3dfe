"""Software limit switches of following axes in synchronous operation (S7-1500T V5 §4.4.1, §6.1.5.4).

A coupled axis gets its setpoint from the leading value, not from a planned profile, so the limit
cannot be found when the motion is planned.  Each servo cycle the setpoints of the watched axes are
compared, all at once, with the limits less the distance the axis needs to stop with its configured
dynamic limits (one cycle of look-ahead included); the axis is told once the limit comes within reach.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from .profiles import INF


class SwLimitWatch:
    def __init__(self) -> None:
        self._axes: dict[int, tuple[Any, float, float, float, float]] = {}
        self._compile()

    def set(self, axis: Any, lo: float, hi: float, dec: float, jerk: float) -> None:
        self._axes[axis.index] = (axis, lo, hi, dec, jerk)
        self._compile()

    def clear(self, axis: Any) -> None:
        if self._axes.pop(axis.index, None) is not None:
            self._compile()

    def _compile(self) -> None:
        rows = list(self._axes.values())
        self.axes = [r[0] for r in rows]
        self.idx = np.array([r[0].index for r in rows], dtype=np.int64)
        self.lo = np.array([r[1] for r in rows])
        self.hi = np.array([r[2] for r in rows])
        self.dec = np.array([r[3] for r in rows])
        # time the deceleration takes to build up with the jerk limit (0: no jerk limitation)
        self.ramp = np.array([0.0 if r[4] in (0.0, INF) else r[3] / r[4] for r in rows])

    def check(self, bank: Any, dt: float) -> list[tuple[Any, str]]:
        """Axes whose limit comes within their stopping distance, with the side ("min" or "max")."""
        if not self.axes:
            return []
        p = bank.sp_p[self.idx]
        v = bank.sp_v[self.idx]
        speed = np.abs(v)
        reach = speed * (dt + 0.5 * self.ramp) + v * v / (2.0 * self.dec)
        hit_max = (v > 0.0) & (p + reach >= self.hi)
        hit_min = (v < 0.0) & (p - reach <= self.lo)
        if not (hit_max.any() or hit_min.any()):
            return []
        return [(self.axes[k], "max" if hit_max[k] else "min") for k in np.flatnonzero(hit_max | hit_min)]
