"""The interpolated cam: a piecewise function y = f(x), evaluated and inverted every servo cycle.

:class:`CamCurve` is what :func:`plcmotion.kernel.cam.interpolate` builds from the points and segments of a
cam technology object (S7-1500T V5 §5.1, §9.2.1): per piece a local polynomial of degree <= 6 plus a sine
term.  Following axes evaluate it and its derivatives at the leading value, and solve it for the leading
value of a following value (MC_GetCamLeadingValue, S7-1500T V5 §9.2.2).
"""
from __future__ import annotations

import math

import numpy as np

_DEG = 7                          # coefficients per piece (degree 6)


class CamCurve:
    """An interpolated cam: breakpoints ``bp`` and per piece a local polynomial and a sine term.

    Piece k covers [bp[k], bp[k+1]] and gives
    ``y = sum(c[k, i] dx^i) + sin_amp[k] * sin(sin_freq[k] * dx + sin_phase[k])`` with dx = x - bp[k].
    Immutable once built; evaluation is vectorised.
    """

    __slots__ = ("bp", "c", "sin_amp", "sin_freq", "sin_phase", "_d1", "_d2", "_d3", "start", "end",
                 "has_sine")

    def __init__(self, bp: np.ndarray, c: np.ndarray, sine: np.ndarray | None = None):
        self.bp = np.ascontiguousarray(bp, dtype=float)
        self.c = np.ascontiguousarray(c, dtype=float)
        n = len(self.c)
        sine = np.zeros((n, 3)) if sine is None else np.asarray(sine, dtype=float)
        self.sin_amp = np.ascontiguousarray(sine[:, 0])
        self.sin_freq = np.ascontiguousarray(sine[:, 1])
        self.sin_phase = np.ascontiguousarray(sine[:, 2])
        self.has_sine = bool(np.any(self.sin_amp != 0.0))
        powers = np.arange(1, _DEG)
        self._d1 = self.c[:, 1:] * powers
        self._d2 = self._d1[:, 1:] * powers[:-1]
        self._d3 = self._d2[:, 1:] * powers[:-2]
        self.start = float(self.bp[0])
        self.end = float(self.bp[-1])

    @property
    def pieces(self) -> int:
        return len(self.c)

    @property
    def length(self) -> float:
        return self.end - self.start

    def piece_index(self, x: np.ndarray) -> np.ndarray:
        k = np.searchsorted(self.bp, x, side="right") - 1
        return np.clip(k, 0, len(self.c) - 1)

    @staticmethod
    def _horner(coef: np.ndarray, dx: np.ndarray) -> np.ndarray:
        y = coef[..., -1]
        for i in range(coef.shape[-1] - 2, -1, -1):
            y = y * dx + coef[..., i]
        return y

    def evaluate(self, x, order: int = 2) -> tuple[np.ndarray, ...]:
        """(f, f', f''[, f''']) at ``x`` (clamped to the definition range)."""
        x = np.clip(np.asarray(x, dtype=float), self.start, self.end)
        k = self.piece_index(x)
        dx = x - self.bp[k]
        out = [self._horner(self.c[k], dx), self._horner(self._d1[k], dx), self._horner(self._d2[k], dx)]
        if order >= 3:
            out.append(self._horner(self._d3[k], dx))
        if self.has_sine:
            amp, w = self.sin_amp[k], self.sin_freq[k]
            arg = w * dx + self.sin_phase[k]
            s, co = np.sin(arg), np.cos(arg)
            out[0] = out[0] + amp * s
            out[1] = out[1] + amp * w * co
            out[2] = out[2] - amp * w * w * s
            if order >= 3:
                out[3] = out[3] - amp * w ** 3 * co
        return tuple(out[: order + 1])

    def value(self, x):
        return self.evaluate(x, 0)[0]

    def value_range(self, samples_per_piece: int = 64) -> tuple[float, float]:
        """Minimum and maximum of the following value (sampled; exact at the breakpoints)."""
        xs = np.concatenate([np.linspace(a, b, samples_per_piece) for a, b in zip(self.bp[:-1], self.bp[1:])])
        ys = self.value(xs)
        return float(ys.min()), float(ys.max())

    # --- inverse: x for a given y ------------------------------------------------------------------
    def solve(self, y: float, approach: float) -> float | None:
        """The leading value x with f(x) = y closest to ``approach``; None when f never takes y."""
        best: float | None = None
        for x in self.solutions(y):
            if best is None or abs(x - approach) < abs(best - approach):
                best = x
        plateau = self._plateau(y, approach)
        if plateau is not None and (best is None or abs(plateau - approach) < abs(best - approach)):
            best = plateau
        return best

    def _plateau(self, y: float, approach: float) -> float | None:
        """Nearest point to ``approach`` on a constant piece whose value is y."""
        const = np.all(self.c[:, 1:] == 0.0, axis=1) & (self.sin_amp == 0.0)
        tol = 1e-12 * max(1.0, abs(y))
        hits = np.flatnonzero(const & (np.abs(self.c[:, 0] - y) <= tol))
        best = None
        for k in hits:
            x = min(max(approach, self.bp[k]), self.bp[k + 1])
            if best is None or abs(x - approach) < abs(best - approach):
                best = float(x)
        return best

    def solutions(self, y: float) -> list[float]:
        """All isolated solutions of f(x) = y in the definition range (sign changes and touch points)."""
        n_s = 32
        if self.has_sine:
            h = np.diff(self.bp)
            n_s = int(min(4096, max(32, np.max(np.abs(self.sin_freq) * h) / 0.25)))
        t = np.linspace(0.0, 1.0, n_s + 1)
        h = np.diff(self.bp)
        xs = self.bp[:-1, None] + h[:, None] * t[None, :]           # (pieces, n_s + 1)
        g = self.value(xs.ravel()).reshape(xs.shape) - y
        found: list[float] = []
        # exact zeros at sample points
        tol = 1e-12 * max(1.0, abs(y), float(np.max(np.abs(self.c[:, 0]))))
        zero = np.abs(g) <= tol
        lo_x = xs[:, :-1][np.sign(g[:, :-1]) * np.sign(g[:, 1:]) < 0]
        hi_x = xs[:, 1:][np.sign(g[:, :-1]) * np.sign(g[:, 1:]) < 0]
        if lo_x.size:
            found.extend(self._bisect(lo_x, hi_x, y).tolist())
        found.extend(xs[zero].tolist())
        # touch points: local minima of |g| between samples that do not change sign
        a = np.abs(g)
        mid = (a[:, 1:-1] < a[:, :-2]) & (a[:, 1:-1] < a[:, 2:]) & ~zero[:, 1:-1]
        for i, j in zip(*np.nonzero(mid)):
            x = self._refine_touch(float(xs[i, j]), float(xs[i, j + 2]), y)
            if x is not None:
                found.append(x)
        found.sort()
        out: list[float] = []
        for x in found:
            if not out or abs(x - out[-1]) > 1e-9 * max(1.0, abs(x)):
                out.append(x)
        return out

    def _bisect(self, lo: np.ndarray, hi: np.ndarray, y: float) -> np.ndarray:
        glo = self.value(lo) - y
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            gm = self.value(mid) - y
            left = np.sign(gm) == np.sign(glo)
            lo = np.where(left, mid, lo)
            glo = np.where(left, gm, glo)
            hi = np.where(left, hi, mid)
        return 0.5 * (lo + hi)

    def _refine_touch(self, a: float, b: float, y: float) -> float | None:
        """Golden-section minimum of |f - y| on [a, b]; a solution if it reaches (numerically) zero."""
        gr = (math.sqrt(5.0) - 1.0) / 2.0
        c, d = b - gr * (b - a), a + gr * (b - a)
        for _ in range(100):
            if abs(float(self.value(c)) - y) < abs(float(self.value(d)) - y):
                b = d
            else:
                a = c
            c, d = b - gr * (b - a), a + gr * (b - a)
        x = 0.5 * (a + b)
        scale = max(1.0, abs(y)) * 1e-9
        return x if abs(float(self.value(x)) - y) <= scale else None
