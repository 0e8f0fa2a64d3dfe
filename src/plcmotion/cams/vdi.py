"""Normalized motion laws after VDI 2143 for cam transitions (S7-1500T V5 §6.2.5.15).

A motion law is a normalized transfer function s(z) on z in [0, 1] with s(0) = 0 and s(1) = 1.  It is
stored as :class:`Piece` objects, each ``sum(c_k z^k) + amp * sin(omega * z + phase)`` — the same form
as a cam TO segment, so a law maps onto segments exactly (no fitting), except the double-harmonic law,
which has two sine terms and is approximated by points like in the cam editor (§6.2.5.7).

Characteristic values (:class:`Characteristics`) are the maxima of the normalized derivatives:
Cv = max|s'|, Ca = max s'' (acceleration), Ca* = max -s'' (deceleration), Cj = max|s'''|,
Cmdyn = max|s' s''|.  A jump of s' or s'' inside the law, or against the boundary state of its motion
task (R dwell: v = a = 0, G constant velocity: a = 0, U reverse: v = 0, B motion: none), makes the next
higher value infinite, as in the VDI tables (e.g. Cj = inf for the quadratic parabola).

Motion laws implemented (normalized, dwell-in-dwell unless noted):

* ``line``: s = z (task G-G).
* ``quadratic_parabola``: two constant-acceleration halves; any boundary velocity (C1).
* ``simple_sine``: s = (1 - cos(pi z)) / 2; with equal boundary velocity c: c z + (1-c)(1-cos(pi z))/2.
* ``inclined_sine`` (cycloid): s = z - sin(2 pi z) / (2 pi); with equal boundary velocity c
  (G-G): z - (1 - c) sin(2 pi z) / (2 pi).
* ``polynomial`` (3-4-5, degree 5) and ``polynomial7`` (4-5-6-7, degree 7); boundary-value polynomials
  of any motion task via :func:`boundary_polynomial`.
* ``modified_trapezoid``: acceleration in eighths: sine rise, constant, sine change of sign, constant,
  sine fall (5 pieces).
* ``modified_sine``: acceleration sine quarter (1/8), sine of period 3/2 (6/8), sine quarter (3 pieces).
* ``harmonic_combination`` (task R-U, mirrored U-R): half a cycloid (acceleration half sine) on
  [0, lambda], then a quarter cosine of the velocity into the reversal; lambda = 2 - sqrt(2) makes the
  jerk continuous at the joint, other lambdas match a given end acceleration.
* ``sine_line`` (sine-line combination): half cycloid, straight line, half cycloid (R-R, lambda = 1/4
  acceleration fraction by default); R-G and G-R: half cycloid into the line.
* ``double_harmonic`` (task R-U): (1 - cos(pi z))/2 - (1 - cos(2 pi z))/8, approximated by points.

The VDI 2143 text itself was not available; the harmonic combination and sine-line combination follow
the construction described above (documented choices), the other laws are the standard ones.
"""
from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numpy.polynomial import Polynomial
from numpy.polynomial import polynomial as P

PI = math.pi
TAU = 2.0 * math.pi
INF = math.inf


class UnsupportedTransitionError(ValueError):
    """A motion law cannot meet the boundary conditions of the requested motion task/continuity."""


@dataclass(frozen=True)
class Piece:
    """``sum(c[k] t^k) + amp sin(omega t + phase)`` on [t0, t1] (``amp2``: a second sine term, used
    only by the double-harmonic law, which is therefore never written as a segment)."""

    t0: float
    t1: float
    c: tuple[float, ...]
    amp: float = 0.0
    omega: float = 0.0
    phase: float = 0.0
    amp2: float = 0.0
    omega2: float = 0.0
    phase2: float = 0.0

    @property
    def degree(self) -> int:
        c = np.trim_zeros(np.asarray(self.c, float), "b")
        return max(len(c) - 1, 0)

    def derivatives(self, t, order: int = 3) -> list[np.ndarray]:
        """[f, f', ..., f^(order)] at ``t`` (no clamping)."""
        t = np.asarray(t, dtype=float)
        c = np.asarray(self.c, dtype=float)
        out = []
        for k in range(order + 1):
            p = P.polyval(t, c) if c.size else np.zeros_like(t)
            for amp, om, ph in ((self.amp, self.omega, self.phase), (self.amp2, self.omega2, self.phase2)):
                if amp:
                    p = p + amp * om ** k * np.sin(om * t + ph + k * PI / 2)
            out.append(p)
            c = P.polyder(c) if c.size > 1 else np.zeros(0)
        return out

    def scaled(self, factor: float, offset: float = 0.0) -> Piece:
        """``offset + factor * f``."""
        c = [factor * v for v in self.c] or [0.0]
        c[0] += offset
        return replace(self, c=tuple(c), amp=factor * self.amp, amp2=factor * self.amp2)

    def mirrored(self) -> Piece:
        """``1 - f(1 - t)``: the law run backwards (R-U becomes U-R)."""
        q = Polynomial(self.c)(Polynomial([1.0, -1.0])) if self.c else Polynomial([0.0])
        c = [-float(v) for v in q.coef]
        c[0] += 1.0
        # -A sin(w (1 - t) + p) = A sin(w t - (w + p))
        return Piece(1.0 - self.t1, 1.0 - self.t0, tuple(c), self.amp, self.omega, -(self.omega + self.phase),
                     self.amp2, self.omega2, -(self.omega2 + self.phase2))


@dataclass(frozen=True)
class Characteristics:
    """Characteristic values of a normalized law (maxima of |s'|, s'', -s'', |s'''|, |s' s''|)."""

    cv: float
    ca: float
    ca_star: float
    cj: float
    cmdyn: float

    def as_dict(self) -> dict[str, float]:
        return {"Cv": self.cv, "Ca": self.ca, "Ca*": self.ca_star, "Cj": self.cj, "Cmdyn": self.cmdyn}


@dataclass(frozen=True)
class MotionLaw:
    """A normalized motion law: ``pieces`` cover [0, 1]; ``task`` is its VDI motion task (e.g. "RR")."""

    name: str
    pieces: tuple[Piece, ...]
    task: str = "RR"
    continuity: int = 2             # derivative order continuous at the ends for its task
    points: int = 0                 # > 0: approximated by this many points instead of segments
    lam: float | None = None

    def evaluate(self, z, order: int = 3) -> tuple[np.ndarray, ...]:
        """(s, s', s'', s''') at ``z`` (clamped to [0, 1])."""
        z = np.clip(np.atleast_1d(np.asarray(z, dtype=float)), 0.0, 1.0)
        edges = np.array([p.t0 for p in self.pieces[1:]])
        k = np.searchsorted(edges, z, side="right")
        out = [np.empty_like(z) for _ in range(order + 1)]
        for i, piece in enumerate(self.pieces):
            m = k == i
            if m.any():
                for o, d in zip(out, piece.derivatives(z[m], order)):
                    o[m] = d
        return tuple(out)

    def s(self, z):
        return self.evaluate(z, 0)[0]

    def v(self, z):
        return self.evaluate(z, 1)[1]

    def a(self, z):
        return self.evaluate(z, 2)[2]

    def j(self, z):
        return self.evaluate(z, 3)[3]

    def boundary(self, side: int) -> tuple[float, ...]:
        """(s, s', s'', s''') at z = 0 (side 0) or z = 1 (side 1), from the piece on that side."""
        piece = self.pieces[0] if side == 0 else self.pieces[-1]
        return tuple(float(d) for d in piece.derivatives(float(side), 3))

    def characteristics(self) -> Characteristics:
        ctx = []
        for side, code in ((0, self.task[0]), (1, self.task[1])):
            _, v, a, _ = self.boundary(side)
            ctx.append((v if code in "GB" else 0.0, a if code in "UB" else 0.0))
        return characteristic_values(self.pieces, ctx[0], ctx[1])


# ------------------------------------------------------------------------------------------------------
# characteristic values
def _refined_max(f, lo: float, hi: float, n: int = 513) -> float:
    from scipy.optimize import minimize_scalar

    t = np.linspace(lo, hi, n)
    y = f(t)
    i = int(np.argmax(y))
    a, b = t[max(i - 1, 0)], t[min(i + 1, n - 1)]
    best = float(y[i])
    if b > a:
        r = minimize_scalar(lambda u: -float(f(np.array([u]))[0]), bounds=(a, b), method="bounded",
                            options={"xatol": 1e-13})
        best = max(best, -float(r.fun))
    return best


def _jump(x: float, y: float) -> bool:
    return abs(x - y) > 1e-7 * max(1.0, abs(x), abs(y))


def characteristic_values(pieces: Sequence[Piece], start: tuple[float, float] | None = (0.0, 0.0),
                          end: tuple[float, float] | None = (0.0, 0.0)) -> Characteristics:
    """Cv, Ca, Ca*, Cj, Cmdyn of normalized ``pieces``; ``start``/``end`` are the (v, a) of the
    neighbours (None: no neighbour); jumps against them or between pieces give infinite values."""
    cv = ca = cas = cj = cm = 0.0
    for p in pieces:
        def d(t, p=p):
            return p.derivatives(t, 3)
        cv = max(cv, _refined_max(lambda t: np.abs(d(t)[1]), p.t0, p.t1))
        ca = max(ca, _refined_max(lambda t: d(t)[2], p.t0, p.t1))
        cas = max(cas, _refined_max(lambda t: -d(t)[2], p.t0, p.t1))
        cj = max(cj, _refined_max(lambda t: np.abs(d(t)[3]), p.t0, p.t1))
        cm = max(cm, _refined_max(lambda t: np.abs(d(t)[1] * d(t)[2]), p.t0, p.t1))
    joins: list[tuple[Sequence[Any], Sequence[Any]]] = []
    if start is not None:
        joins.append(((0.0, *start), pieces[0].derivatives(pieces[0].t0, 2)))
    joins += [(left.derivatives(left.t1, 2), right.derivatives(right.t0, 2))
              for left, right in itertools.pairwise(pieces)]
    if end is not None:
        joins.append((pieces[-1].derivatives(pieces[-1].t1, 2), (0.0, *end)))
    for left, right in joins:
        if _jump(float(left[1]), float(right[1])):
            ca = cas = cj = INF
        if _jump(float(left[2]), float(right[2])):
            cj = INF
    return Characteristics(cv, ca, cas, cj, cm)


# ------------------------------------------------------------------------------------------------------
# building blocks
def _poly_piece(t0: float, t1: float, coef) -> Piece:
    return Piece(t0, t1, tuple(float(v) for v in coef))


def _from_accel(t0: float, t1: float, s0: float, v0: float, acc_poly=(), amp: float = 0.0,
                omega: float = 0.0, phase: float = 0.0) -> Piece:
    """The piece with acceleration ``poly + amp sin(omega t + phase)`` and s(t0) = s0, s'(t0) = v0."""
    q = P.polyint(np.asarray(acc_poly, float), 2) if len(acc_poly) else np.zeros(3)
    q = np.concatenate([q, np.zeros(max(0, 3 - len(q)))])
    samp = -amp / omega ** 2 if amp else 0.0
    base = Piece(t0, t1, tuple(q), samp, omega if amp else 0.0, phase if amp else 0.0)
    s, v = base.derivatives(t0, 1)
    q[1] += v0 - float(v)
    q[0] += s0 - float(s) - (v0 - float(v)) * t0
    return replace(base, c=tuple(q))


def _chain(specs, scale_to_one: bool = True) -> tuple[Piece, ...]:
    """Pieces from acceleration specs [(t0, t1, acc_poly, amp, omega, phase)], continuous s and s'."""
    out, s0, v0 = [], 0.0, 0.0
    for t0, t1, acc, amp, om, ph in specs:
        p = _from_accel(t0, t1, s0, v0, acc, amp, om, ph)
        out.append(p)
        s0, v0 = (float(x) for x in p.derivatives(t1, 1))
    if scale_to_one:
        out = [p.scaled(1.0 / s0) for p in out]
    return tuple(out)


# ------------------------------------------------------------------------------------------------------
# the laws
def line() -> MotionLaw:
    return MotionLaw("line", (_poly_piece(0, 1, (0.0, 1.0)),), "GG", 2)


def quadratic_parabola(lam: float = 0.5, v0: float = 0.0, v1: float = 0.0) -> MotionLaw:
    """Constant acceleration a1 on [0, lam], a2 on [lam, 1], meeting the velocities v0 and v1 (C1)."""
    if not 0.0 < lam < 1.0:
        raise ValueError(f"quadratic parabola: lambda must be in (0, 1), got {lam}")
    m = np.array([[lam, 1 - lam], [lam * lam / 2 + lam * (1 - lam), (1 - lam) ** 2 / 2]])
    a1, a2 = np.linalg.solve(m, np.array([v1 - v0, 1.0 - v0]))
    first = _from_accel(0.0, lam, 0.0, v0, (a1,))
    s_l, v_l = (float(x) for x in first.derivatives(lam, 1))
    second = _from_accel(lam, 1.0, s_l, v_l, (a2,))
    return MotionLaw("quadratic_parabola", (first, second), _task(v0, 0, v1, 0), 1, lam=lam)


def simple_sine(c: float = 0.0) -> MotionLaw:
    """(1 - cos(pi z)) / 2, plus c (z - that) for an equal boundary velocity c."""
    d = 1.0 - c
    piece = Piece(0.0, 1.0, (d / 2, c), -d / 2, PI, PI / 2)
    return MotionLaw("simple_sine", (piece,), "RR" if c == 0 else "GG", 1)


def inclined_sine(c: float = 0.0) -> MotionLaw:
    """Cycloid z - sin(2 pi z) / (2 pi); with boundary velocity c the sine part is scaled by 1 - c."""
    piece = Piece(0.0, 1.0, (0.0, 1.0), -(1.0 - c) / TAU, TAU, 0.0)
    return MotionLaw("inclined_sine", (piece,), "RR" if c == 0 else "GG", 2)


def boundary_polynomial(start: Sequence[float | None], end: Sequence[float | None]) -> np.ndarray:
    """Coefficients (ascending, t in [0, 1]) of the lowest-degree polynomial with the given derivatives
    (index k: k-th derivative, None: free) at t = 0 and t = 1; degree = number of conditions - 1."""
    rows, rhs = [], []
    for t, vals in ((0.0, start), (1.0, end)):
        for k, val in enumerate(vals):
            if val is not None:
                rows.append((t, k))
                rhs.append(float(val))
    n = len(rows)
    m = np.zeros((n, n))
    for r, (t, k) in enumerate(rows):
        for i in range(k, n):
            m[r, i] = math.perm(i, k) * t ** (i - k)
    try:
        return np.linalg.solve(m, np.array(rhs))
    except np.linalg.LinAlgError:
        raise ValueError("the boundary values do not determine a polynomial (singular conditions)") from None


def polynomial(start=(0.0, 0.0, 0.0), end=(1.0, 0.0, 0.0), name: str = "polynomial") -> MotionLaw:
    """Boundary-value polynomial on [0, 1] (derivatives at z = 0 and 1); default 3-4-5 (R-R, C2)."""
    piece = _poly_piece(0.0, 1.0, boundary_polynomial(start, end))
    cont = min(len(start), len(end)) - 1
    d0, d1 = piece.derivatives(0.0, 2), piece.derivatives(1.0, 2)
    return MotionLaw(name, (piece,), _task(float(d0[1]), float(d0[2]), float(d1[1]), float(d1[2])), cont)


def polynomial5() -> MotionLaw:
    return polynomial((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), "polynomial5")


def polynomial7() -> MotionLaw:
    return polynomial((0.0, 0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0), "polynomial7")


def modified_trapezoid() -> MotionLaw:
    w = 4 * PI
    pieces = _chain([(0, 1 / 8, (), 1.0, w, 0.0), (1 / 8, 3 / 8, (1.0,), 0, 0, 0),
                     (3 / 8, 5 / 8, (), 1.0, w, PI / 2 - w * 3 / 8), (5 / 8, 7 / 8, (-1.0,), 0, 0, 0),
                     (7 / 8, 1.0, (), 1.0, w, -PI / 2 - w * 7 / 8)])
    return MotionLaw("modified_trapezoid", pieces, "RR", 2)


def modified_sine() -> MotionLaw:
    w, w2 = 4 * PI, 4 * PI / 3
    pieces = _chain([(0, 1 / 8, (), 1.0, w, 0.0), (1 / 8, 7 / 8, (), 1.0, w2, PI / 2 - w2 / 8),
                     (7 / 8, 1.0, (), 1.0, w, -PI / 2 - w * 7 / 8)])
    return MotionLaw("modified_sine", pieces, "RR", 2)


HARMONIC_LAMBDA = 2.0 - math.sqrt(2.0)     # jerk continuous at the joint


def _harmonic_end_accel(lam: float) -> float:
    return -PI / (2.0 * (1.0 - lam) * (lam / 2.0 + 2.0 * (1.0 - lam) / PI))


def harmonic_combination(lam: float = HARMONIC_LAMBDA, end_accel: float | None = None,
                         mirrored: bool = False) -> MotionLaw:
    """Dwell-in-reverse (R-U): half cycloid on [0, lam], quarter cosine of the velocity to the reversal.

    ``end_accel`` (normalized s''(1) < -pi^2/4) selects lam so that the reversal acceleration matches;
    ``mirrored`` gives the reverse-in-dwell (U-R) law (then ``end_accel`` is s''(0) > pi^2/4)."""
    if end_accel is not None:
        from scipy.optimize import brentq

        target = -end_accel if mirrored else end_accel
        if not target < -PI ** 2 / 4:
            raise UnsupportedTransitionError(
                f"harmonic combination: the reversal acceleration {end_accel:.6g} (normalized) must be beyond "
                f"{'+' if mirrored else '-'}pi^2/4 = {PI ** 2 / 4:.4f} in the direction of the stroke")
        lam = brentq(lambda x: _harmonic_end_accel(x) - target, 1e-9, 1 - 1e-9, xtol=1e-15)
    if not 0.0 < lam < 1.0:
        raise ValueError(f"harmonic combination: lambda must be in (0, 1), got {lam}")
    vm = 1.0 / (lam / 2.0 + 2.0 * (1.0 - lam) / PI)
    w1, w2 = PI / lam, PI / (2.0 * (1.0 - lam))
    pieces = _chain([(0.0, lam, (), vm * PI / (2 * lam), w1, 0.0),
                     (lam, 1.0, (), -vm * w2, w2, -w2 * lam)], scale_to_one=False)
    if mirrored:
        return MotionLaw("harmonic_combination", tuple(p.mirrored() for p in reversed(pieces)), "UR", 2,
                         lam=1.0 - lam)
    return MotionLaw("harmonic_combination", pieces, "RU", 2, lam=lam)


def sine_line(lam: float = 0.25, v_end: float | None = None, mirrored: bool = False) -> MotionLaw:
    """Sine-line combination: half cycloid (acceleration half sine) over lam, straight line, half cycloid.

    With ``v_end`` (normalized line velocity, 1 < v_end <= 2) the dwell-in-constant-velocity (R-G) form:
    half cycloid over lam = 2 - 2/v_end into the line; ``mirrored`` gives G-R."""
    if v_end is not None:
        if not 1.0 < v_end <= 2.0 + 1e-12:
            raise UnsupportedTransitionError(
                f"sine-line combination R-G/G-R needs a normalized line velocity in (1, 2], got {v_end:.6g}")
        lam = min(2.0 - 2.0 / v_end, 1.0)
        vm = v_end
        specs = [(0.0, lam, (), vm * PI / (2 * lam), PI / lam, 0.0)]
        if lam < 1.0:
            specs.append((lam, 1.0, (), 0.0, 0.0, 0.0))
        pieces = _chain(specs, scale_to_one=False)
        if mirrored:
            return MotionLaw("sine_line", tuple(p.mirrored() for p in reversed(pieces)), "GR", 2, lam=lam)
        return MotionLaw("sine_line", pieces, "RG", 2, lam=lam)
    if not 0.0 < lam <= 0.5:
        raise ValueError(f"sine-line combination: lambda (acceleration fraction) must be in (0, 0.5], got {lam}")
    vm = 1.0 / (1.0 - lam)
    amp = vm * PI / (2 * lam)
    specs = [(0.0, lam, (), amp, PI / lam, 0.0)]
    if lam < 0.5:
        specs.append((lam, 1.0 - lam, (), 0.0, 0.0, 0.0))
    specs.append((1.0 - lam, 1.0, (), -amp, PI / lam, -PI * (1.0 - lam) / lam))
    return MotionLaw("sine_line", _chain(specs, scale_to_one=False), "RR", 2, lam=lam)


def double_harmonic(mirrored: bool = False, n_points: int = 32) -> MotionLaw:
    """(1 - cos(pi z))/2 - (1 - cos(2 pi z))/8 (R-U); two sine terms: approximated by points."""
    piece = Piece(0.0, 1.0, (0.375,), -0.5, PI, PI / 2, 0.125, TAU, PI / 2)
    if mirrored:
        return MotionLaw("double_harmonic", (piece.mirrored(),), "UR", 0, points=n_points)
    return MotionLaw("double_harmonic", (piece,), "RU", 0, points=n_points)


def split_septic(piece: Piece, lam: float = 0.5, samples: int = 201) -> tuple[Piece, Piece]:
    """Two degree-6 pieces replacing a degree-7 ``piece`` (a cam segment holds a0..a6 only): split at
    ``lam`` of its range, equal value, velocity, acceleration and jerk at both ends and at the split
    (C3), the two remaining freedoms fitted to the septic by least squares (deviation about 6e-4 of the
    stroke for the 4-5-6-7 law).  The sine term, if any, is kept in both halves."""
    from scipy.linalg import null_space

    if not 0.0 < lam < 1.0:
        raise ValueError(f"split of a 7th-degree polynomial: lambda must be in (0, 1), got {lam}")
    w = piece.t1 - piece.t0
    q = Polynomial(piece.c)(Polynomial([piece.t0, w])).coef      # in u = (t - t0) / w on [0, 1]
    q = np.concatenate([q, np.zeros(max(0, 8 - len(q)))])

    def basis(k: int, u: float) -> list[float]:                 # x = (e4, e5, e6, d4, d5, d6)
        row = [math.perm(p, k) * u ** (p - k) for p in (4, 5, 6)]
        row += [math.perm(p, k) * (u - lam) ** (p - k) if u > lam else 0.0 for p in (4, 5, 6)]
        return row

    head = q[:4]
    target = Polynomial(q)
    cons = np.array([basis(k, 1.0) for k in range(4)])
    rhs = np.array([target.deriv(k)(1.0) - Polynomial(head).deriv(k)(1.0) for k in range(4)])
    x0 = np.linalg.lstsq(cons, rhs, rcond=None)[0]
    null = null_space(cons)
    u = np.linspace(0.0, 1.0, samples)
    b = np.array([basis(0, x) for x in u])
    resid = target(u) - Polynomial(head)(u) - b @ x0
    x = x0 + null @ np.linalg.lstsq(b @ null, resid, rcond=None)[0]
    first = np.concatenate([head, x[:3]])
    second = Polynomial(first) + sum(d * Polynomial([-lam, 1.0]) ** p for d, p in zip(x[3:6], (4, 5, 6)))
    back = Polynomial([-piece.t0 / w, 1.0 / w])                  # u as a function of t
    tk = piece.t0 + lam * w
    c1 = Polynomial(first)(back).coef
    c2 = Polynomial(second.coef)(back).coef
    return (replace(piece, t1=tk, c=tuple(c1)), replace(piece, t0=tk, c=tuple(c2)))


# ------------------------------------------------------------------------------------------------------
# registry and the transition solver
LAWS: dict[str, Callable[..., MotionLaw]] = {
    "line": line, "quadratic_parabola": quadratic_parabola, "simple_sine": simple_sine,
    "inclined_sine": inclined_sine, "polynomial5": polynomial5, "polynomial7": polynomial7,
    "modified_trapezoid": modified_trapezoid, "modified_sine": modified_sine,
    "harmonic_combination": harmonic_combination, "sine_line": sine_line, "double_harmonic": double_harmonic,
}
ALIASES = {"parabola": "quadratic_parabola", "sine": "simple_sine", "cycloid": "inclined_sine",
           "polynomial": "polynomial", "poly5": "polynomial5", "poly345": "polynomial5",
           "poly7": "polynomial7", "poly4567": "polynomial7", "modified_acceleration_trapezoid":
           "modified_trapezoid", "sine_line_combination": "sine_line", "double_harmonic_transition":
           "double_harmonic"}
#: the laws' own continuity (derivative order) when none is requested
DEFAULT_CONTINUITY = {"line": 0, "quadratic_parabola": 1, "simple_sine": 1, "inclined_sine": 2, "polynomial": 2,
                      "polynomial5": 2, "polynomial7": 3, "modified_trapezoid": 2, "modified_sine": 2,
                      "harmonic_combination": 2, "sine_line": 2, "double_harmonic": 0}


def canonical(name: str) -> str:
    key = name.strip().lower().replace("-", "_").replace(" ", "_")
    key = ALIASES.get(key, key)
    if key not in DEFAULT_CONTINUITY:
        raise ValueError(f"unknown VDI motion law {name!r}; laws: {', '.join(sorted(DEFAULT_CONTINUITY))}")
    return key


def law(name: str) -> MotionLaw:
    """The standard (dwell-in-dwell, or its own task) form of a law by name."""
    key = canonical(name)
    return polynomial5() if key == "polynomial" else LAWS[key]()


def _code(v: float, a: float, tol: float = 1e-9) -> str:
    zv, za = abs(v) <= tol, abs(a) <= tol
    return "R" if zv and za else "G" if za else "U" if zv else "B"


def _task(v0: float, a0: float, v1: float, a1: float) -> str:
    return _code(v0, a0) + _code(v1, a1)


def transition_law(name: str, start: Sequence[float] = (0.0, 0.0), end: Sequence[float] = (0.0, 0.0),
                   continuity: tuple[int, int] | None = None, lam: float | None = None,
                   n_points: int = 32) -> MotionLaw:
    """The normalized law ``name`` for a transition whose neighbours have the normalized (v, a[, j])
    ``start`` and ``end``, continuous up to the derivative orders ``continuity`` (default: the law's own).

    Raises UnsupportedTransitionError when the law cannot meet them; 'polynomial' meets any motion task
    (its degree follows from the continuity: C1 cubic, C2 quintic, C3 7th degree)."""
    key = canonical(name)
    k0, k1 = continuity if continuity is not None else (DEFAULT_CONTINUITY[key],) * 2
    st = (*start, 0.0, 0.0, 0.0)[:3]
    en = (*end, 0.0, 0.0, 0.0)[:3]
    (v0, a0), (v1, a1) = st[:2], en[:2]
    task = _task(v0, a0, v1, a1)
    if key in ("polynomial", "polynomial5", "polynomial7"):
        got = polynomial((0.0, *st)[: k0 + 1], (1.0, *en)[: k1 + 1], key)
    elif key == "line":
        got = line()
    elif key == "quadratic_parabola":
        got = quadratic_parabola(lam or 0.5, v0 if k0 >= 1 else 0.0, v1 if k1 >= 1 else 0.0)
    elif key in ("simple_sine", "inclined_sine"):
        got = LAWS[key](v0 if k0 >= 1 else v1 if k1 >= 1 else 0.0)
    elif key == "harmonic_combination":
        mirrored = task == "UR"
        k, acc = (k0, a0) if mirrored else (k1, a1)
        if lam is None and k >= 2 and task in ("RU", "UR"):
            got = harmonic_combination(end_accel=acc, mirrored=mirrored)
        else:
            got = harmonic_combination(HARMONIC_LAMBDA if lam is None else lam, mirrored=mirrored)
    elif key == "sine_line":
        if task[1] == "G" and task[0] != "G" and k1 >= 1:
            got = sine_line(v_end=v1)
        elif task[0] == "G" and task[1] != "G" and k0 >= 1:
            got = sine_line(v_end=v0, mirrored=True)
        else:
            got = sine_line(0.25 if lam is None else lam)
    elif key == "double_harmonic":
        got = double_harmonic(mirrored=task == "UR", n_points=n_points)
    else:
        got = LAWS[key]()
    _verify(got, key, task, st, en, k0, k1)
    return got


_NAMES = {0: "position", 1: "velocity", 2: "acceleration", 3: "jerk"}


def _verify(got: MotionLaw, key: str, task: str, start, end, k0: int, k1: int) -> None:
    if got.points and max(k0, k1) > 0:
        raise UnsupportedTransitionError(f"VDI law {key!r} is approximated by points: position continuity only")
    for side, want, k in ((0, start, k0), (1, end, k1)):
        have = got.boundary(side)
        for order in range(1, k + 1):
            if _jump(want[order - 1], have[order]):
                where = "start" if side == 0 else "end"
                raise UnsupportedTransitionError(
                    f"VDI law {key!r} cannot give {_NAMES[k]} continuity at the {where} of a {task[0]}-{task[1]} "
                    f"transition: its normalized {_NAMES[order]} there is {have[order]:.6g}, the neighbouring "
                    f"element's {want[order - 1]:.6g} (S7-1500T V5 §6.2.5.15: laws are limited to the motion "
                    f"task); 'polynomial' meets any motion task, or lower the continuity")


__all__ = ["DEFAULT_CONTINUITY", "HARMONIC_LAMBDA", "LAWS", "Characteristics", "MotionLaw", "Piece",
           "UnsupportedTransitionError", "boundary_polynomial", "canonical", "characteristic_values",
           "double_harmonic", "harmonic_combination", "inclined_sine", "law", "line", "modified_sine",
           "modified_trapezoid", "polynomial", "polynomial5", "polynomial7", "quadratic_parabola",
           "simple_sine", "sine_line", "split_septic", "transition_law"]
