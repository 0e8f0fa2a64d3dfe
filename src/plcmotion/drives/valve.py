"""The valve characteristic of a hydraulic axis and the row-wise curves the drive groups evaluate.

S7-Technology V4.1 §4.6.4: a valve profile is a cam whose leading value ("Master") is the manipulated
variable in percent of the +-10 V output and whose following value ("Slave") is the velocity the axis reaches
with it.  It is measured on the machine, so it holds the valve's non-linearity: a dead band where a valve
with overlap opens no flow (a flat piece at velocity 0), kinks of a progressive spool, different speeds per
direction.  The controller needs the inverse: which output gives the velocity its position controller
asks for.  :class:`ValveCharacteristic` builds that inverse once, as two piecewise linear branches
(positive and negative velocities) that start at the ends of the dead band, so the output jumps across the
dead band instead of creeping through it - that is the compensation.

Per servo cycle every member of a group has its own curve; :func:`interp_rows` evaluates them for all
members at once on padded tables (no Python per axis).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Iterable, Sequence

import numpy as np

from .spec_errors import DriveSpecError, finite


@dataclass(frozen=True)
class ValveCharacteristic:
    """A valve profile: ``points`` are pairs (output [% of 10 V], velocity [length unit/s]).

    The outputs lie in [-100, 100] and differ from each other; the velocity must not fall where the output
    rises (a monotonic valve), and the profile must contain velocity 0 (an axis that cannot stand still
    cannot be position controlled).  Between the points the curve is linear; a dead band is a flat piece at
    velocity 0, e.g. ``[(-100, -300), (-3, 0), (3, 0), (100, 300)]``.  A profile that has no negative (or
    no positive) velocities, like that of a pump with switching directional valves (§4.6.4), gives the
    output at velocity 0 for every velocity it cannot reach.
    """

    points: tuple[tuple[float, float], ...]

    def __post_init__(self) -> None:
        name = "ValveCharacteristic.points"
        raw = list(self.points) if isinstance(self.points, (list, tuple)) else None
        if raw is None or len(raw) < 2:
            raise DriveSpecError(name, self.points, "give at least two pairs (output %, velocity)")
        pts = []
        for k, pair in enumerate(raw):
            if not isinstance(pair, (list, tuple)) or len(pair) != 2:
                raise DriveSpecError(f"{name}[{k}]", pair, "must be a pair (output %, velocity)")
            u = finite(f"{name}[{k}] output", pair[0])
            if not -100.0 <= u <= 100.0:
                raise DriveSpecError(f"{name}[{k}] output", pair[0], "must lie in [-100, 100] % of 10 V")
            pts.append((u, finite(f"{name}[{k}] velocity", pair[1])))
        pts.sort()
        for (u0, v0), (u1, v1) in zip(pts, pts[1:]):
            if u1 == u0:
                raise DriveSpecError(name, u0, "every output % may appear once")
            if v1 < v0:
                raise DriveSpecError(name, (u1, v1), f"the velocity falls from {v0:g} at {u0:g} % to {v1:g}: "
                                     "a valve characteristic must be monotonic")
        if not pts[0][1] <= 0.0 <= pts[-1][1]:
            raise DriveSpecError(name, (pts[0][1], pts[-1][1]), "the velocities must include 0 "
                                 "(an output at which the axis stands still)")
        object.__setattr__(self, "points", tuple(pts))

    # --- construction ------------------------------------------------------------------------------------
    @classmethod
    def linear(cls, reference_velocity: float) -> "ValveCharacteristic":
        """The straight line +-100 % <-> +-``reference_velocity`` (no valve profile active)."""
        v = finite("HydraulicSpec.reference_velocity", reference_velocity)
        if v <= 0.0:
            raise DriveSpecError("HydraulicSpec.reference_velocity", reference_velocity, "must be > 0")
        return cls(((-100.0, -v), (100.0, v)))

    @classmethod
    def from_curve(cls, curve: Any, samples_per_piece: int = 8) -> "ValveCharacteristic":
        """The profile of an interpolated cam (``kernel.cam_curve.CamCurve``: leading value = output %,
        following value = velocity), sampled at its breakpoints and ``samples_per_piece`` points inside
        each piece (exact for straight pieces)."""
        bp = np.asarray(getattr(curve, "bp", ()), dtype=float)
        if bp.size < 2 or not callable(getattr(curve, "value", None)):
            raise DriveSpecError("ValveCharacteristic curve", curve, "must be an interpolated cam (breakpoints, "
                                 "value(x))")
        inner = [np.linspace(a, b, samples_per_piece + 2)[1:-1] for a, b in zip(bp, bp[1:])]
        xs = np.unique(np.concatenate([bp, *inner]))
        ys = np.asarray(curve.value(xs), dtype=float)
        return cls(tuple(zip(xs.tolist(), ys.tolist())))

    # --- the inverse --------------------------------------------------------------------------------------
    def branches(self) -> tuple[list[tuple[float, float]], list[tuple[float, float]], float]:
        """(positive branch [(velocity, output)], negative branch [(-velocity, output)], output at velocity 0).

        Each branch starts at velocity 0 at its end of the dead band and rises strictly in velocity; where
        the profile is flat at a velocity the branch keeps the output nearest to the dead band."""
        pts = self.points
        za, zb = _zero_set(pts)
        u0 = min(max(0.0, za), zb)
        vmin, vmax = pts[0][1], pts[-1][1]
        pos = [(0.0, zb if vmax > 0.0 else u0)]
        for u, v in pts:
            if u > zb and v > pos[-1][0]:
                pos.append((v, u))
        neg = [(0.0, za if vmin < 0.0 else u0)]
        for u, v in reversed(pts):
            if u < za and -v > neg[-1][0]:
                neg.append((-v, u))
        return pos, neg, u0

    def output(self, velocity: Any) -> Any:
        """The output [%] that asks the valve for ``velocity`` (array or scalar)."""
        pos, neg, u0 = self.branches()
        v = np.asarray(velocity, dtype=float)
        pv, pu = zip(*pos)
        nv, nu = zip(*neg)
        out = np.where(v > 0.0, np.interp(v, pv, pu), np.where(v < 0.0, np.interp(-v, nv, nu), u0))
        return float(out) if out.ndim == 0 else out

    def velocity(self, output: Any) -> Any:
        """The velocity the profile assigns to ``output`` [%] (the cam itself)."""
        u, v = zip(*self.points)
        out = np.interp(np.asarray(output, dtype=float), u, v)
        return float(out) if out.ndim == 0 else out


def _zero_set(pts: Sequence[tuple[float, float]]) -> tuple[float, float]:
    """[za, zb]: the outputs at which the monotonic piecewise linear profile gives velocity 0."""
    za = zb = None
    for (u0, v0), (u1, v1) in zip(pts, pts[1:]):
        if za is None and v1 >= 0.0:            # the first piece that reaches 0
            za = u0 if v0 >= 0.0 else u0 + (u1 - u0) * (-v0) / (v1 - v0)
        if v0 <= 0.0:                           # the last piece that starts at or below 0
            zb = u1 if v1 <= 0.0 else u0 + (u1 - u0) * (-v0) / (v1 - v0)
    assert za is not None and zb is not None          # the constructor checked min <= 0 <= max
    return za, zb


# --- padded tables: one curve per member, evaluated for all members at once ------------------------------
def pad_rows(rows: Iterable[Sequence[tuple[float, float]]]) -> tuple[np.ndarray, np.ndarray]:
    """(X, Y): one row per curve, each curve's points [(x, y)] (x strictly rising) padded to a common
    length by continuing x with the last y, so that :func:`interp_rows` holds the end value."""
    rows = [list(r) for r in rows]
    width = max([2] + [len(r) for r in rows])
    X = np.empty((len(rows), width))
    Y = np.empty((len(rows), width))
    for i, r in enumerate(rows):
        xs = [p[0] for p in r]
        ys = [p[1] for p in r]
        last = xs[-1]
        step = max(1.0, abs(last))
        xs += [last + step * (k + 1) for k in range(width - len(r))]
        ys += [ys[-1]] * (width - len(r))
        X[i], Y[i] = xs, ys
    return X, Y


def interp_rows(X: np.ndarray, Y: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Row i: the piecewise linear curve (X[i], Y[i]) at x[i], held constant beyond its ends."""
    n, width = X.shape
    if n == 0:
        return np.zeros(0)
    k = np.clip((X <= x[:, None]).sum(axis=1) - 1, 0, width - 2)
    r = np.arange(n)
    x0, x1 = X[r, k], X[r, k + 1]
    y0, y1 = Y[r, k], Y[r, k + 1]
    frac = np.clip((x - x0) / (x1 - x0), 0.0, 1.0)
    return y0 + (y1 - y0) * frac


__all__ = ["ValveCharacteristic", "interp_rows", "pad_rows"]
