"""Cam profiles: the transfer function y = f(x) of a cam technology object, and its interpolation.

A cam is defined by interpolation points (x, y) and segments (polynomial of degree <= 6 plus a sine
term over [xmin, xmax]); interpolation closes the gaps between them and yields a :class:`CamCurve`, a
piecewise function that is evaluated every servo cycle (S7-1500T V5 §3.2, §5.1, §6.2.5.7, §9.2.1, §A.2;
the curve itself is in :mod:`.cam_curve`).

Rules of the definition (§6.2.5.7, catalog §4.2.4):

* of several points with the same leading value the one entered last (highest index) counts;
* of overlapping segments the one entered later is used completely; an earlier one is used again
  after the later one's end;
* where a segment and points cover the same range, the segment wins (points inside a segment, and
  within the join tolerance of its ends, are ignored);
* a gap of less than 1.0E-4 between two segments is closed by joining them, a larger one by a
  transition interpolated like any other gap.

Segment polynomials are evaluated at the absolute leading value x:
``y = a0 + a1 x + ... + a6 x^6 + sineAmplitude * sin(sinePeriod * x + sinePhase)`` (docs/decisions.md).

Interpolation modes (``InterpolationSettings.InterpolationMode``):
0 linear: straight lines through the points.
1 cubic spline: C2 spline through the points, C1 into the segments; it may overshoot the points.
2 Bézier spline: a clamped cubic B-spline whose control points are the points; it runs along the
  points without passing through them, through the segments, and never leaves the value range of the
  points and segment end values it joins.
Boundary conditions (``InterpolationSettings.BoundaryConditions``): 0 none; 1 equal first derivative at
the start and the end of the cam (spline: also equal second derivative), for cyclic use.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from .cam_curve import _DEG, CamCurve

MAX_POINTS = 1000
MAX_SEGMENTS = 50
JOIN_GAP = 1.0e-4                 # §6.2.5.7: segment gaps below this are joined, not interpolated
TAG_LIMIT = 1.0e12                # §A.2.2, §A.2.4: value range of Point[] and Segment[] elements
LINEAR, CUBIC_SPLINE, BEZIER = 0, 1, 2
_BEZIER_SUBPIECES = 8             # cubic Hermite pieces per B-spline span (exact values and slopes)


class CamDefinitionError(ValueError):
    """The points and segments of a cam cannot be interpolated; ``reason`` names the problem."""

    def __init__(self, reason: str, message: str):
        super().__init__(message)
        self.reason = reason


@dataclass(frozen=True, slots=True)
class SegmentDef:
    """One segment of a cam TO (``Segment[n]``): polynomial a0..a6 plus a sine term over [xmin, xmax]."""

    xmin: float
    xmax: float
    a: tuple[float, float, float, float, float, float, float] = (0.0,) * 7
    sine_amplitude: float = 0.0
    sine_period: float = 0.0        # b1 in sin(b1 x + b2), rad per unit of x
    sine_phase: float = 0.0         # b2 [rad]

    def value(self, x: float) -> float:
        y = 0.0
        for c in reversed(self.a):
            y = y * x + c
        return y + self.sine_amplitude * math.sin(self.sine_period * x + self.sine_phase)

    def slope(self, x: float) -> float:
        y = 0.0
        for i in range(6, 0, -1):
            y = y * x + i * self.a[i]
        return y + self.sine_amplitude * self.sine_period * math.cos(self.sine_period * x + self.sine_phase)

    def local(self, x0: float) -> np.ndarray:
        """Polynomial coefficients (ascending) in the local variable dx = x - x0 (Taylor shift)."""
        a = np.asarray(self.a, dtype=float)
        out = np.zeros(_DEG)
        for k in range(_DEG):
            s = 0.0
            for i in range(k, _DEG):
                s += a[i] * math.comb(i, k) * x0 ** (i - k)
            out[k] = s
        return out


# ------------------------------------------------------------------------------------------------------
# interpolation
@dataclass(slots=True)
class _Fixed:
    """A range covered by a segment (possibly a truncated part of it)."""

    xa: float
    xb: float
    seg: SegmentDef


def _cover(segments: Sequence[SegmentDef]) -> list[_Fixed]:
    """Ranges covered by segments, later segments taking precedence (§6.2.5.7)."""
    cover: list[_Fixed] = []
    for seg in segments:
        new: list[_Fixed] = []
        for f in cover:
            if f.xb <= seg.xmin or f.xa >= seg.xmax:
                new.append(f)
                continue
            if f.xa < seg.xmin:
                new.append(_Fixed(f.xa, seg.xmin, f.seg))
            if f.xb > seg.xmax:
                new.append(_Fixed(seg.xmax, f.xb, f.seg))
        new.append(_Fixed(seg.xmin, seg.xmax, seg))
        cover = sorted(new, key=lambda f: f.xa)
    # join gaps below the tolerance: the later range starts where the earlier one ends
    for prev, nxt in zip(cover, cover[1:]):
        if 0.0 < nxt.xa - prev.xb < JOIN_GAP:
            nxt.xa = prev.xb
    return [f for f in cover if f.xb > f.xa]


def _clean_points(points: Sequence[tuple[float, float]], cover: list[_Fixed]) -> list[tuple[float, float]]:
    """Unique leading values (the last entered counts), none inside or at the edge of a segment."""
    last: dict[float, float] = {}
    for x, y in points:
        last[float(x)] = float(y)
    out = []
    for x in sorted(last):
        if any(f.xa - JOIN_GAP < x < f.xb + JOIN_GAP for f in cover):
            continue
        out.append((x, last[x]))
    return out


@dataclass(slots=True)
class _Gap:
    nodes: list[tuple[float, float]]
    slope_left: float | None          # None: free end at the cam boundary
    slope_right: float | None
    cam_left: bool                    # the gap starts at the cam start
    cam_right: bool


def _pieces_linear(g: _Gap) -> tuple[list[float], list[np.ndarray]]:
    bp, cs = [], []
    for (x0, y0), (x1, y1) in zip(g.nodes, g.nodes[1:]):
        c = np.zeros(_DEG)
        c[0], c[1] = y0, (y1 - y0) / (x1 - x0)
        bp.append(x0)
        cs.append(c)
    return bp, cs


def _hermite(x0: float, x1: float, y0: float, y1: float, d0: float, d1: float) -> np.ndarray:
    h = x1 - x0
    m = (y1 - y0) / h
    c = np.zeros(_DEG)
    c[0], c[1] = y0, d0
    c[2] = (3.0 * m - 2.0 * d0 - d1) / h
    c[3] = (d0 + d1 - 2.0 * m) / (h * h)
    return c


def _spline(g: _Gap, bc_left, bc_right, periodic_trend: bool = False):
    from scipy.interpolate import CubicSpline

    x = np.array([p[0] for p in g.nodes])
    y = np.array([p[1] for p in g.nodes])
    if periodic_trend:
        m = (y[-1] - y[0]) / (x[-1] - x[0])
        if len(x) == 2:
            spline = None
        else:
            yd = y - m * (x - x[0])
            yd[-1] = yd[0]            # equal by construction; rounding must not fail scipy's periodic check
            spline = CubicSpline(x, yd, bc_type="periodic")
        return spline, m
    return CubicSpline(x, y, bc_type=(bc_left, bc_right)), 0.0


def _pieces_spline(g: _Gap, periodic_trend: bool = False) -> tuple[list[float], list[np.ndarray]]:
    bc_l = (2, 0.0) if g.slope_left is None else (1, g.slope_left)
    bc_r = (2, 0.0) if g.slope_right is None else (1, g.slope_right)
    spline, m = _spline(g, bc_l, bc_r, periodic_trend)
    x = [p[0] for p in g.nodes]
    if spline is None:                              # two nodes, periodic trend: the straight line
        return _pieces_linear(g)
    bp, cs = [], []
    for k in range(len(x) - 1):
        c = np.zeros(_DEG)
        c[:4] = spline.c[::-1, k]                   # scipy: highest power first
        c[0] += m * (x[k] - x[0])                   # the trend taken out for the periodic spline, back in
        c[1] += m
        bp.append(x[k])
        cs.append(c)
    return bp, cs


def _spline_end_slopes(g: _Gap) -> tuple[float, float]:
    """End slopes of the spline of ``g`` with its current boundary conditions."""
    bc_l = (2, 0.0) if g.slope_left is None else (1, g.slope_left)
    bc_r = (2, 0.0) if g.slope_right is None else (1, g.slope_right)
    spline, _ = _spline(g, bc_l, bc_r)
    d = spline.derivative()
    return float(d(g.nodes[0][0])), float(d(g.nodes[-1][0]))


def _bezier_handle(node: tuple[float, float], towards: tuple[float, float], slope: float,
                   lo: float, hi: float) -> tuple[float, float]:
    """Control point on the tangent ``slope`` through ``node``: a third of the way to ``towards``, or
    nearer where that would leave the value range (the tangent itself is kept: C1 with segments and
    the boundary condition come first; a handle shorter than a tenth of that may leave the range)."""
    (x0, y0), (x1, _) = node, towards
    h = (x1 - x0) / 3.0
    y = y0 + slope * h
    if (y > hi or y < lo) and slope:
        fit = ((hi if y > hi else lo) - y0) / slope
        h = math.copysign(max(abs(fit), abs(h) / 10.0), h)
    return x0 + h, y0 + slope * h


def _bezier_slope_range(g: "_Gap", lo: float, hi: float, right: bool) -> tuple[float, float]:
    """Slopes at one end of ``g`` whose full-length Bézier handle stays within [lo, hi]."""
    (x0, y0), (x1, _) = (g.nodes[-1], g.nodes[-2]) if right else (g.nodes[0], g.nodes[1])
    h = (x1 - x0) / 3.0
    a, b = (lo - y0) / h, (hi - y0) / h
    return (min(a, b), max(a, b))


def _pieces_bezier(g: _Gap, lo: float, hi: float) -> tuple[list[float], list[np.ndarray]]:
    """Clamped cubic B-spline with the nodes as control points, as cubic Hermite pieces in x."""
    from scipy.interpolate import BSpline

    ctrl = list(g.nodes)
    # end tangents: along the adjoining segment (or the boundary-condition slope); a control point on
    # the tangent, a third of the way to the next node or nearer so that it stays within the value range
    if g.slope_left is not None and len(ctrl) >= 2:
        ctrl.insert(1, _bezier_handle(ctrl[0], ctrl[1], g.slope_left, lo, hi))
    if g.slope_right is not None and len(ctrl) >= 2:
        ctrl.insert(len(ctrl) - 1, _bezier_handle(ctrl[-1], ctrl[-2], g.slope_right, lo, hi))
    n = len(ctrl)
    if n == 2:
        return _pieces_linear(_Gap(ctrl, None, None, False, False))
    k = min(3, n - 1)
    inner = np.linspace(0.0, 1.0, n - k + 1)
    knots = np.concatenate([np.zeros(k), inner, np.ones(k)])
    px = np.array([p[0] for p in ctrl])
    py = np.array([p[1] for p in ctrl])
    bx, by = BSpline(knots, px, k), BSpline(knots, py, k)
    dbx, dby = bx.derivative(), by.derivative()
    u = np.unique(np.concatenate([np.linspace(a, b, _BEZIER_SUBPIECES + 1) for a, b in zip(inner[:-1], inner[1:])]))
    xs, ys = bx(u), by(u)
    slopes = dby(u) / dbx(u)
    xs[0], ys[0], xs[-1], ys[-1] = ctrl[0][0], ctrl[0][1], ctrl[-1][0], ctrl[-1][1]
    _keep_in_range(xs, ys, slopes, lo, hi, fixed=(g.slope_left is not None, g.slope_right is not None))
    bp, cs = [], []
    for i in range(len(u) - 1):
        bp.append(float(xs[i]))
        cs.append(_hermite(xs[i], xs[i + 1], ys[i], ys[i + 1], slopes[i], slopes[i + 1]))
    return bp, cs


def _hermite_range(y0: float, y1: float, m0: float, m1: float) -> tuple[float, float]:
    """Smallest and largest value of the cubic Hermite piece with end values y0, y1 and end slopes m0, m1
    (already multiplied by the piece's length), over the piece."""
    a, b, c = 3.0 * (m0 + m1 + 2.0 * (y0 - y1)), 2.0 * (3.0 * (y1 - y0) - 2.0 * m0 - m1), m0   # h'(t)
    ts = [0.0, 1.0]
    if abs(a) > 1e-300:
        disc = b * b - 4.0 * a * c
        if disc >= 0.0:
            r = math.sqrt(disc)
            ts += [t for t in ((-b - r) / (2.0 * a), (-b + r) / (2.0 * a)) if 0.0 < t < 1.0]
    elif abs(b) > 1e-300 and 0.0 < -c / b < 1.0:
        ts.append(-c / b)
    vals = [y0 + t * (m0 + t * ((3.0 * (y1 - y0) - 2.0 * m0 - m1) + t * (m0 + m1 + 2.0 * (y0 - y1))))
            for t in ts]
    return min(vals), max(vals)


def _keep_in_range(xs: np.ndarray, ys: np.ndarray, slopes: np.ndarray, lo: float, hi: float,
                   fixed: tuple[bool, bool] = (False, False)) -> None:
    """Limit the sample slopes of a Bézier gap where a Hermite piece between two samples would leave the cam's
    value range [lo, hi] although the curve itself does not (a sample near the edge of the range next to a
    steep one: the Hermite cubic dips past the edge, found by hypothesis as -3.7e-7 on a range of 1).  Such a
    piece gets the Fritsch-Carlson limits (slopes along the chord, at most three times it), which keep it
    between its end values; the slopes are shared with the neighbours, so C1 holds.  An end slope that joins
    a segment or meets the boundary condition (``fixed``) is kept."""
    tol = 1e-12 * max(1.0, abs(lo), abs(hi))
    keep = {0} if fixed[0] else set()
    if fixed[1]:
        keep.add(len(xs) - 1)
    for _ in range(4):                       # a limited slope changes the neighbour piece: recheck
        changed = False
        for i in range(len(xs) - 1):
            h = xs[i + 1] - xs[i]
            if not h > 0.0:
                continue
            y0, y1 = ys[i], ys[i + 1]
            low, high = _hermite_range(y0, y1, slopes[i] * h, slopes[i + 1] * h)
            if low >= lo - tol and high <= hi + tol:
                continue
            d = (y1 - y0) / h
            before = (slopes[i], slopes[i + 1])
            free = [j for j in (i, i + 1) if j not in keep]
            for j in free:
                if slopes[j] * d <= 0.0:
                    slopes[j] = 0.0
            if d != 0.0 and free:
                a, b = slopes[i] / d, slopes[i + 1] / d
                norm = math.hypot(a, b)
                if norm > 3.0:
                    for j in free:
                        slopes[j] *= 3.0 / norm
            changed = changed or before != (slopes[i], slopes[i + 1])
        if not changed:
            return


def _bezier_boundary_slope(first: "_Gap", last: "_Gap", lo: float, hi: float) -> float:
    """The common end slope of a Bézier cam with BoundaryConditions = 1: the mean of the chords at
    the two ends, moved into the slopes whose handles keep the value range (that interval always
    holds 0, so both conditions can be met)."""
    (x0, y0), (x1, y1) = first.nodes[0], first.nodes[1]
    (xa, ya), (xb, yb) = last.nodes[-2], last.nodes[-1]
    s = 0.5 * ((y1 - y0) / (x1 - x0) + (yb - ya) / (xb - xa))
    a1, b1 = _bezier_slope_range(first, lo, hi, right=False)
    a2, b2 = _bezier_slope_range(last, lo, hi, right=True)
    return min(max(s, max(a1, a2)), min(b1, b2))


def interpolate(points: Sequence[tuple[float, float]], segments: Sequence[SegmentDef],
                mode: int = LINEAR, boundary: int = 0) -> CamCurve:
    """Close the gaps between points and segments (MC_InterpolateCam, §5.1, §9.2.1).

    ``points`` and ``segments`` are the valid ones in the order they were entered (index order).
    Raises CamDefinitionError for definitions that cannot be interpolated - never anything else: a
    numerical failure (an ill-conditioned spline, values beyond the float range) is one too.
    """
    try:
        with np.errstate(all="ignore"):
            curve = _interpolate(points, segments, mode, boundary)
    except CamDefinitionError:
        raise
    except (ValueError, ArithmeticError, np.linalg.LinAlgError) as exc:
        raise CamDefinitionError("numeric", f"the cam cannot be interpolated: {exc}") from exc
    if not (np.isfinite(curve.c).all() and np.isfinite(curve.bp).all()
            and np.isfinite(curve._d2).all() and np.isfinite(curve.sin_phase).all()):
        raise CamDefinitionError("numeric", "the interpolated cam exceeds the number range (points too close "
                                            "together for their values)")
    return curve


def _interpolate(points: Sequence[tuple[float, float]], segments: Sequence[SegmentDef],
                 mode: int, boundary: int) -> CamCurve:
    if mode not in (LINEAR, CUBIC_SPLINE, BEZIER):
        raise CamDefinitionError("mode", f"InterpolationMode {mode!r}: 0 linear, 1 cubic spline, 2 Bézier spline")
    if boundary not in (0, 1):
        raise CamDefinitionError("boundary", f"BoundaryConditions {boundary!r}: 0 or 1")
    for i, (x, y) in enumerate(points):
        if not (math.isfinite(x) and math.isfinite(y)):
            raise CamDefinitionError("point", f"point {i + 1}: ({x!r}, {y!r}) is not a finite number pair")
        if abs(x) > TAG_LIMIT or abs(y) > TAG_LIMIT:
            raise CamDefinitionError("point", f"point {i + 1}: ({x!r}, {y!r}) outside -1.0E12 to 1.0E12")
    for i, s in enumerate(segments):
        values = (s.xmin, s.xmax, *s.a, s.sine_amplitude, s.sine_period, s.sine_phase)
        if not all(math.isfinite(v) for v in values):
            raise CamDefinitionError("segment", f"segment {i + 1}: values must be finite numbers")
        if any(abs(v) > TAG_LIMIT for v in values):
            raise CamDefinitionError("segment", f"segment {i + 1}: values outside -1.0E12 to 1.0E12")
        if not s.xmax > s.xmin:
            raise CamDefinitionError("segment", f"segment {i + 1}: xmax ({s.xmax!r}) must be greater than "
                                                f"xmin ({s.xmin!r})")
    cover = _cover(segments)
    pts = _clean_points(points, cover)
    if not cover and len(pts) < 2:
        raise CamDefinitionError("empty", "a cam needs at least two valid points or one valid segment")
    start = min([f.xa for f in cover] + [p[0] for p in pts])
    end = max([f.xb for f in cover] + [p[0] for p in pts])

    # the gaps between the segments (and the cam ends), each with its nodes and end slopes
    gaps: list[tuple[int, _Gap]] = []            # (position in the piece order, gap)
    order: list[object] = []
    edges = [start] + [v for f in cover for v in (f.xa, f.xb)] + [end]
    for i in range(len(cover) + 1):
        xl, xr = edges[2 * i], edges[2 * i + 1]
        left = cover[i - 1] if i > 0 else None
        right = cover[i] if i < len(cover) else None
        # points were already kept clear of the segments: a gap at a cam end takes its edge point
        inside = [p for p in pts if (xl <= p[0] if left is None else xl < p[0])
                  and (p[0] <= xr if right is None else p[0] < xr)]
        nodes = []
        if left is not None:
            nodes.append((left.xb, left.seg.value(left.xb)))
        nodes.extend(inside)
        if right is not None:
            nodes.append((right.xa, right.seg.value(right.xa)))
        if len(nodes) >= 2 and nodes[-1][0] > nodes[0][0]:
            gap = _Gap(nodes, left.seg.slope(left.xb) if left else None,
                       right.seg.slope(right.xa) if right else None, left is None, right is None)
            gaps.append((len(order), gap))
            order.append(gap)
        if right is not None:
            order.append(right)

    ys_all = [p[1] for p in pts] + [f.seg.value(v) for f in cover for v in (f.xa, f.xb)]
    lo, hi = min(ys_all), max(ys_all)

    # cyclic boundary condition: equal slope (and for splines curvature) at the start and the end
    trend_periodic = False
    if boundary == 1 and mode != LINEAR:
        first = gaps[0][1] if gaps and gaps[0][1].cam_left else None
        last = gaps[-1][1] if gaps and gaps[-1][1].cam_right else None
        if first is not None and first is last and first.slope_left is None and first.slope_right is None:
            if mode == CUBIC_SPLINE:
                trend_periodic = True
            else:
                s = _bezier_boundary_slope(first, first, lo, hi)
                first.slope_left = first.slope_right = s
        else:
            s_start = cover[0].seg.slope(cover[0].xa) if first is None and cover else None
            s_end = cover[-1].seg.slope(cover[-1].xb) if last is None and cover else None
            if first is not None and last is not None:
                if mode == CUBIC_SPLINE:
                    s = 0.5 * (_spline_end_slopes(first)[0] + _spline_end_slopes(last)[1])
                else:
                    s = _bezier_boundary_slope(first, last, lo, hi)
                first.slope_left = last.slope_right = s
            elif first is not None and s_end is not None:
                first.slope_left = s_end
            elif last is not None and s_start is not None:
                last.slope_right = s_start

    bp: list[float] = []
    coef: list[np.ndarray] = []
    sine: list[tuple[float, float, float]] = []
    for item in order:
        if isinstance(item, _Gap):
            if mode == LINEAR:
                b, c = _pieces_linear(item)
            elif mode == CUBIC_SPLINE:
                b, c = _pieces_spline(item, trend_periodic)
            else:
                b, c = _pieces_bezier(item, lo, hi)
            bp.extend(b)
            coef.extend(c)
            sine.extend([(0.0, 0.0, 0.0)] * len(b))
        else:
            f: _Fixed = item  # type: ignore[assignment]
            bp.append(f.xa)
            coef.append(f.seg.local(f.xa))
            s = f.seg
            sine.append((s.sine_amplitude, s.sine_period, s.sine_period * f.xa + s.sine_phase))
    bp.append(end)
    return CamCurve(np.array(bp), np.array(coef), np.array(sine))
