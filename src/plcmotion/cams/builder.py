"""Offline cam builder: cam elements in leading-value order -> points and segments for a cam TO.

Elements follow the cam editor (S7-1500T V5 §6.2.5.9–§6.2.5.15): point, point group, line, sine
(inclined sine), polynomial (coefficients or boundary values, optional trigonometric part), inverse
sine (approximated by points) and transitions between elements, either left to the TO's system
interpolation or written as VDI 2143 motion-law segments (:mod:`plcmotion.cams.vdi`).

:meth:`CamBuilder.build` returns a :class:`CamDefinition`: the ``Point[]``/``Segment[]`` contents and
interpolation settings a cam TO takes, with statistics (§6.2.5.7).  Segments are evaluated at the
absolute leading value x (``y = sum a_i x^i + A sin(b1 x + b2)``, see :mod:`plcmotion.kernel.cam`);
element math is done in local coordinates and converted once, and the converted coefficients are checked
against the LREAL tag range of the TO (±1.0E12) and for rounding error.

Conventions: phases are in rad, periods in leading-value units; a point's optional derivatives (default
0, i.e. a dwell) are used only by VDI transitions (§6.2.5.9); a point-based neighbour of a VDI transition
gives up its boundary point to the transition (statistics table of §6.2.5.7).
"""
from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np
from numpy.polynomial import Polynomial

from ..kernel.cam import (BEZIER, CUBIC_SPLINE, JOIN_GAP, LINEAR, MAX_POINTS, MAX_SEGMENTS, CamCurve, SegmentDef,
                          interpolate)
from . import vdi
from .vdi import Characteristics, Piece

COEFFICIENT_LIMIT = 1.0e12          # LREAL range of the Segment[] tags of the cam TO (§A.2.4)
SEGMENT_FIELDS = ("xmin", "xmax", "a0", "a1", "a2", "a3", "a4", "a5", "a6", "sineAmplitude", "sinePeriod",
                  "sinePhase")
CONTINUITY = {"position": 0, "velocity": 1, "acceleration": 2, "jerk": 3}
_EPS = np.finfo(float).eps


class CamCapacityError(ValueError):
    """The cam would need more than 1000 points or 50 segments (§6.2.5.7); names the element."""

    def __init__(self, message: str, element: str, resource: str, needed: int, limit: int):
        super().__init__(message)
        self.element, self.resource, self.needed, self.limit = element, resource, needed, limit


class CamCoefficientError(ValueError):
    """A segment coefficient exceeds the ±1.0E12 range of the TO tags (or is not finite)."""


# ------------------------------------------------------------------------------------------------------
@dataclass
class _Seg:
    """A segment to be: y(x) = piece((x - xref) / scale) on [xa, xb]."""

    xa: float
    xb: float
    piece: Piece
    xref: float = 0.0
    scale: float = 1.0

    def state(self, x: float) -> tuple[float, float, float, float]:
        d = self.piece.derivatives((x - self.xref) / self.scale, 3)
        return tuple(float(v) / self.scale ** k for k, v in enumerate(d))  # type: ignore[return-value]

    def to_segment(self, label: str) -> tuple[SegmentDef, float]:
        """The TO segment and an estimate of its rounding error at absolute x."""
        p = self.piece
        poly = Polynomial(p.c or (0.0,))(Polynomial([-self.xref / self.scale, 1.0 / self.scale]))
        a = [float(v) for v in poly.coef] + [0.0] * 7
        if any(v != 0.0 for v in a[7:]):
            raise AssertionError(f"{label}: segment of degree > 6")
        b1 = p.omega / self.scale if p.amp else 0.0
        b2 = math.remainder(p.phase - p.omega * self.xref / self.scale, 2 * math.pi) if p.amp else 0.0
        values = (*a[:7], p.amp, b1, b2)
        bad = [f"{n}={v:.6g}" for n, v in zip(SEGMENT_FIELDS[2:], values)
               if not math.isfinite(v) or abs(v) > COEFFICIENT_LIMIT]
        if bad:
            raise CamCoefficientError(
                f"{label} [{self.xa:g}, {self.xb:g}]: {', '.join(bad)} outside ±1.0E12 (LREAL range of the "
                f"Segment tags, S7-1500T V5 §A.2.4); the polynomial in absolute x is ill-conditioned this far "
                f"from x = 0 - shift the cam's leading range towards 0 or widen the element")
        xm = max(abs(self.xa), abs(self.xb))
        err = _EPS * sum(abs(c) * xm ** i for i, c in enumerate(a[:7]))
        return SegmentDef(self.xa, self.xb, tuple(a[:7]), p.amp, b1, b2), err  # type: ignore[arg-type]


@dataclass
class _Element:
    kind: str
    index: int
    x0: float
    x1: float
    points: list[tuple[float, float]] = field(default_factory=list)
    segs: list[_Seg] = field(default_factory=list)
    state_fn: Callable[[int], tuple[float, ...]] | None = None

    @property
    def label(self) -> str:
        return f"{self.kind} #{self.index}"

    def state(self, side: int) -> tuple[float, ...]:
        if self.state_fn is not None:
            return self.state_fn(side)
        return self.segs[0].state(self.x0) if side == 0 else self.segs[-1].state(self.x1)


@dataclass
class _Transition:
    index: int
    method: str
    law: str | None
    continuity: tuple[int, int] | None
    lam: float | None
    n_points: int

    @property
    def label(self) -> str:
        return f"transition #{self.index}"


@dataclass(eq=False)
class TransitionInfo:
    """A VDI transition as built: law, VDI motion task (e.g. "RG"), continuity orders at its ends and
    (computed on first access) the characteristic values of the realized transition, normalized by its
    stroke, with jumps against the neighbours counted (None when the transition has no stroke)."""

    label: str
    law: str
    task: str
    continuity: tuple[int, int]
    x0: float
    x1: float
    segments: int
    points: int
    lam: float | None = None
    normalized: tuple[Piece, ...] = field(default=(), repr=False)
    context: tuple = field(default=(None, None), repr=False)

    @cached_property
    def characteristics(self) -> Characteristics | None:
        if not self.normalized:
            return None
        return vdi.characteristic_values(self.normalized, *self.context)


def _continuity(value) -> tuple[int, int] | None:
    if value is None:
        return None
    if isinstance(value, (tuple, list)):
        a, b = (_continuity(v)[0] for v in value)  # type: ignore[index]
        return a, b
    k = CONTINUITY.get(value, value) if isinstance(value, str) else value
    if isinstance(k, bool) or k not in (0, 1, 2, 3):
        raise ValueError(f"continuity {value!r}: one of {', '.join(CONTINUITY)} or 0..3, or a (start, end) pair")
    return int(k), int(k)


def _num(name: str, v: Any) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)) or not math.isfinite(v):
        raise ValueError(f"{name} must be a finite number, got {v!r}")
    return float(v)


def _code(v: float, a: float, tol: float) -> str:
    zv, za = abs(v) <= tol, abs(a) <= tol
    return "R" if zv and za else "G" if za else "U" if zv else "B"


# ------------------------------------------------------------------------------------------------------
class CamBuilder:
    """Assemble a cam from elements in leading-value order; every element method returns the builder.

    ``interpolation_mode`` 0 linear, 1 cubic spline, 2 Bézier and ``boundary_conditions`` 0/1 are the
    system interpolation of the cam TO (InterpolationSettings, §6.2.5.4) that closes gaps and system
    transitions.
    """

    def __init__(self, interpolation_mode: int = CUBIC_SPLINE, boundary_conditions: int = 0):
        if interpolation_mode not in (LINEAR, CUBIC_SPLINE, BEZIER):
            raise ValueError(f"interpolation_mode {interpolation_mode!r}: 0 linear, 1 cubic spline, 2 Bézier")
        if boundary_conditions not in (0, 1):
            raise ValueError(f"boundary_conditions {boundary_conditions!r}: 0 or 1")
        self.interpolation_mode = interpolation_mode
        self.boundary_conditions = boundary_conditions
        self._items: list[_Element | _Transition] = []

    # --- elements ----------------------------------------------------------------------------------------
    def _add(self, e: _Element) -> CamBuilder:
        prev = next((it for it in reversed(self._items) if isinstance(it, _Element)), None)
        if prev is not None:
            tol = 1e-12 * max(1.0, abs(prev.x1))
            if e.x0 < prev.x1 - tol:
                raise ValueError(f"{e.label} starts at x={e.x0:g}, before the end of {prev.label} (x={prev.x1:g}): "
                                 f"add elements in leading-value order without overlap (S7-1500T V5 §6.2.5.7)")
            if abs(e.x0 - prev.x1) <= tol and e.points and prev.points and e.points[0][0] <= prev.points[-1][0] + tol:
                raise ValueError(f"{e.label} and {prev.label} both have a point at x={e.x0:g}: two points with the "
                                 f"same leading value (only the last would count, §6.2.5.7)")
        self._items.append(e)
        return self

    def _new(self, kind: str, x0: float, x1: float, zero_width: bool = False) -> _Element:
        x0, x1 = _num(f"{kind} start", x0), _num(f"{kind} end", x1)
        n = len(self._items) + 1
        if not (x1 > x0 or (zero_width and x1 == x0)):
            raise ValueError(f"{kind} #{n}: the end ({x1:g}) must be greater than the start ({x0:g})")
        return _Element(kind, n, x0, x1)

    def point(self, x: float, y: float, *, v: float | None = None, a: float | None = None,
              j: float | None = None) -> CamBuilder:
        """A point (§6.2.5.9); v/a/j (default 0) are used only by adjacent VDI transitions."""
        e = self._new("point", x, x, zero_width=True)
        y = _num("point y", y)
        d = tuple(0.0 if val is None else _num(n, val) for n, val in (("v", v), ("a", a), ("j", j)))
        e.points = [(e.x0, y)]
        e.state_fn = lambda side: (y, *d)
        return self._add(e)

    def point_group(self, points: Iterable[Sequence[float]], relative: bool | str = False,
                    x_range: Sequence[float] | None = None, y_range: Sequence[float] | None = None) -> CamBuilder:
        """Points interpolated together (§6.2.5.10).  ``relative`` True (or "x"/"y") maps 0..1 coordinates
        into ``x_range`` = (start, end) and ``y_range`` = (minimum, maximum following value)."""
        rel_x = relative is True or relative in ("x", "both")
        rel_y = relative is True or relative in ("y", "both")
        if relative not in (True, False, "x", "y", "both"):
            raise ValueError(f"relative must be True/False, 'x', 'y' or 'both', got {relative!r}")
        pts = [(_num("point group x", p[0]), _num("point group y", p[1])) for p in points]
        if len(pts) < 2:
            raise ValueError("a point group needs at least two points (a single point is a point, §6.2.5.10)")
        for rel, rng, axis in ((rel_x, x_range, 0), (rel_y, y_range, 1)):
            if rel:
                if rng is None or len(rng) != 2 or not rng[1] > rng[0]:
                    raise ValueError(f"relative {'leading' if axis == 0 else 'following'} values need "
                                     f"{'x_range' if axis == 0 else 'y_range'} = (low, high) with high > low")
                if any(not -1e-12 <= p[axis] <= 1 + 1e-12 for p in pts):
                    raise ValueError(f"relative coordinates must be within 0..1, got {[p[axis] for p in pts]}")
                lo, hi = float(rng[0]), float(rng[1])
                pts = [(lo + p[0] * (hi - lo), p[1]) if axis == 0 else (p[0], lo + p[1] * (hi - lo)) for p in pts]
        pts.sort()
        if any(b[0] <= a[0] for a, b in itertools.pairwise(pts)):
            raise ValueError("point group: two points with the same leading value")
        if x_range is not None and not rel_x and (pts[0][0] < x_range[0] or pts[-1][0] > x_range[1]):
            raise ValueError(f"point group: points outside x_range {tuple(x_range)}")
        e = self._new("point_group", pts[0][0], pts[-1][0])
        e.points = pts
        e.state_fn = _spline_state(pts)
        return self._add(e)

    def line(self, x0: float, x1: float, y0: float | None = None, y1: float | None = None,
             slope: float | None = None) -> CamBuilder:
        """A straight line (§6.2.5.11) from two of: y0 (start), y1 (end), slope."""
        e = self._new("line", x0, x1)
        if sum(v is not None for v in (y0, y1, slope)) != 2:
            raise ValueError(f"{e.label}: give exactly two of y0, y1, slope (§6.2.5.11)")
        if slope is None:
            slope = (_num("y1", y1) - _num("y0", y0)) / (e.x1 - e.x0)
        elif y0 is None:
            y0 = _num("y1", y1) - _num("slope", slope) * (e.x1 - e.x0)
        e.segs = [_Seg(e.x0, e.x1, Piece(0.0, e.x1 - e.x0, (_num("y0", y0), _num("slope", slope))), e.x0)]
        return self._add(e)

    def sine(self, x0: float, x1: float, amplitude: float, offset: float | None = None, *,
             phase0: float | None = None, phase1: float | None = None, period: float | None = None,
             frequency: float | None = None, inclined: bool = False, offset0: float | None = None,
             offset1: float | None = None, inclination: float | None = None) -> CamBuilder:
        """``offset + amplitude sin(phase)`` (§6.2.5.12), the phase [rad] running linearly over the element,
        defined by phase0 + phase1, phase0 + period/frequency, or period/frequency + phase1 (period in
        leading-value units, frequency = 1/period).  ``inclined``: the offset runs linearly, from two of
        offset0, offset1, inclination."""
        e = self._new("sine", x0, x1)
        w = e.x1 - e.x0
        if period is not None and frequency is not None:
            raise ValueError(f"{e.label}: give period or frequency, not both")
        if frequency is not None:
            if not _num("frequency", frequency) > 0:
                raise ValueError(f"{e.label}: frequency must be > 0")
            period = 1.0 / frequency
        if period is not None:
            if not _num("period", period) > 0:
                raise ValueError(f"{e.label}: period must be > 0")
            b1 = 2 * math.pi / period
            if phase0 is not None and phase1 is not None:
                raise ValueError(f"{e.label}: give two of phase0, phase1, period/frequency (§6.2.5.12)")
            p0 = _num("phase0", phase0) if phase0 is not None else (
                _num("phase1", phase1) - b1 * w if phase1 is not None else 0.0)
        else:
            if phase0 is None or phase1 is None:
                raise ValueError(f"{e.label}: give two of phase0, phase1, period/frequency (§6.2.5.12)")
            p0 = _num("phase0", phase0)
            b1 = (_num("phase1", phase1) - p0) / w
        if inclined:
            if offset is not None or sum(v is not None for v in (offset0, offset1, inclination)) != 2:
                raise ValueError(f"{e.label}: an inclined sine takes two of offset0, offset1, inclination")
            if inclination is None:
                inclination = (_num("offset1", offset1) - _num("offset0", offset0)) / w
            elif offset0 is None:
                offset0 = _num("offset1", offset1) - _num("inclination", inclination) * w
            off0, incl = _num("offset0", offset0), _num("inclination", inclination)
        else:
            if any(v is not None for v in (offset0, offset1, inclination)):
                raise ValueError(f"{e.label}: offset0/offset1/inclination need inclined=True")
            off0, incl = (0.0 if offset is None else _num("offset", offset)), 0.0
        amp = _num("amplitude", amplitude)
        e.segs = [_Seg(e.x0, e.x1, Piece(0.0, w, (off0, incl), amp, b1, p0), e.x0)]
        return self._add(e)

    def polynomial(self, x0: float, x1: float, coefficients: Sequence[float] | None = None, *,
                   y0: float | None = None, y1: float | None = None, v0: float | None = None,
                   v1: float | None = None, a0: float | None = None, a1: float | None = None,
                   j0: float | None = None, j1: float | None = None,
                   trig: tuple[float, float, float] | None = None, split: float = 0.5) -> CamBuilder:
        """A polynomial (§6.2.5.13) from ``coefficients`` a0..a6 in the element's own x (u = x - x0), or
        from boundary values y0, y1 and optional derivatives v/a/j at both ends (degree = number of
        values - 1).  ``trig`` = (amplitude, b1, b2) adds amplitude sin(b1 u + b2).  A 7th-degree
        polynomial (all eight values) uses 2 segments: degree-6 halves split at ``split``, continuous
        up to the jerk (see :func:`plcmotion.cams.vdi.split_septic`)."""
        e = self._new("polynomial", x0, x1)
        w = e.x1 - e.x0
        amp, b1, b2 = (0.0, 0.0, 0.0) if trig is None else (_num("trig", t) for t in trig)
        bounds = (y0, y1, v0, v1, a0, a1, j0, j1)
        if coefficients is not None:
            if any(v is not None for v in bounds):
                raise ValueError(f"{e.label}: give coefficients or boundary values, not both")
            c = [_num("coefficient", v) for v in coefficients]
            if not 1 <= len(c) <= 7:
                raise ValueError(f"{e.label}: coefficients a0..a6 (at most 7, §6.2.5.13), got {len(c)}")
            e.segs = [_Seg(e.x0, e.x1, Piece(0.0, w, tuple(c), amp, b1, b2), e.x0)]
            return self._add(e)
        if y0 is None or y1 is None:
            raise ValueError(f"{e.label}: boundary values need y0 and y1 (or give coefficients)")
        trig_piece = Piece(0.0, 1.0, (), amp, b1 * w, b2)
        tl, tr = trig_piece.derivatives(0.0, 3), trig_piece.derivatives(1.0, 3)
        start = [None if v is None else _num("boundary value", v) * w ** k - float(tl[k])
                 for k, v in enumerate((y0, v0, a0, j0))]
        end = [None if v is None else _num("boundary value", v) * w ** k - float(tr[k])
               for k, v in enumerate((y1, v1, a1, j1))]
        try:
            coef = vdi.boundary_polynomial(start, end)
        except ValueError as exc:
            raise ValueError(f"{e.label}: {exc}") from None
        piece = Piece(0.0, 1.0, tuple(coef), amp, b1 * w, b2)
        pieces = [piece] if len(coef) <= 7 else list(vdi.split_septic(piece, split))
        e.segs = [_Seg(e.x0 + w * p.t0, e.x0 + w * p.t1, p, e.x0, w) for p in pieces]
        return self._add(e)

    def inverse_sine(self, x0: float, x1: float, y_min: float, y_max: float, mirrored: bool = False,
                     t_start: float = -1.0, t_end: float = 1.0, n_points: int = 32) -> CamBuilder:
        """arcsin over [t_start, t_end] within [-1, 1], scaled to y_min..y_max (falling when ``mirrored``),
        approximated by ``n_points`` points equally spaced in x (§6.2.5.14)."""
        e = self._new("inverse_sine", x0, x1)
        ts, te, lo, hi = (_num(n, v) for n, v in (("t_start", t_start), ("t_end", t_end), ("y_min", y_min),
                                                  ("y_max", y_max)))
        if not -1.0 <= ts < te <= 1.0:
            raise ValueError(f"{e.label}: need -1 <= t_start < t_end <= 1, got {ts}, {te}")
        if not hi > lo:
            raise ValueError(f"{e.label}: y_max must be greater than y_min")
        if isinstance(n_points, bool) or not isinstance(n_points, int) or n_points < 2:
            raise ValueError(f"{e.label}: n_points must be an integer >= 2, got {n_points!r}")
        sign = -1.0 if mirrored else 1.0
        g0, g1 = sorted((sign * math.asin(ts), sign * math.asin(te)))
        k = (hi - lo) / (g1 - g0)
        dt = (te - ts) / (e.x1 - e.x0)

        def f(x: float) -> float:
            t = min(max(ts + (x - e.x0) * dt, -1.0), 1.0)
            return lo + k * (sign * math.asin(t) - g0)

        def state(side: int) -> tuple[float, ...]:
            t = ts if side == 0 else te
            q = 1.0 - t * t
            if q <= 0.0:
                return (f(e.x1 if side else e.x0), math.inf, math.inf, math.inf)
            d = (1 / math.sqrt(q), t / q ** 1.5, (1 + 2 * t * t) / q ** 2.5)
            return (f(e.x1 if side else e.x0), *(sign * k * v * dt ** (i + 1) for i, v in enumerate(d)))

        xs = np.linspace(e.x0, e.x1, n_points)
        e.points = [(float(x), f(float(x))) for x in xs]
        e.state_fn = state
        return self._add(e)

    def transition(self, method: str = "system", law: str | None = None, *, continuity=None,
                   lam: float | None = None, n_points: int = 32) -> CamBuilder:
        """A transition between the previous and the next element (§6.2.5.15).  "system": nothing is
        written, the TO's interpolation closes the gap.  "vdi": ``law`` (see :mod:`plcmotion.cams.vdi`,
        default "polynomial") is written as segments from the exact end state of the previous element to
        the start state of the next.  ``continuity``: "position"/"velocity"/"acceleration"/"jerk" or
        0..3, or a (start, end) pair; default: the law's own.  ``lam``: the law's lambda (switch point)."""
        if method not in ("system", "vdi"):
            raise ValueError(f"transition method {method!r}: 'system' or 'vdi' (§6.2.5.15)")
        if method == "system" and law is not None:
            raise ValueError("a system transition takes no law; use method='vdi'")
        tr = _Transition(len(self._items) + 1, method, vdi.canonical(law or "polynomial") if method == "vdi" else None,
                         _continuity(continuity), lam, n_points)
        if not self._items or isinstance(self._items[-1], _Transition):
            raise ValueError(f"{tr.label}: a transition follows an element (and precedes the next one)")
        self._items.append(tr)
        return self

    # --- build -------------------------------------------------------------------------------------------
    def build(self) -> CamDefinition:
        """Points, segments and settings for the cam TO; raises CamCapacityError/CamCoefficientError."""
        items = self._items
        if not any(isinstance(it, _Element) for it in items):
            raise ValueError("the cam has no elements")
        if isinstance(items[-1], _Transition):
            raise ValueError(f"{items[-1].label}: a transition needs an element after it")
        absorbed: set[tuple[int, int]] = set()
        made: dict[int, tuple[list[_Seg], list[tuple[float, float]], TransitionInfo]] = {}
        for i, it in enumerate(items):
            if isinstance(it, _Transition) and it.method == "vdi":
                left, right = items[i - 1], items[i + 1]
                made[i] = _vdi(it, left, right)    # type: ignore[arg-type]
                absorbed.update({(i - 1, 1), (i + 1, 0)})
        points: list[tuple[float, float]] = []
        segments: list[SegmentDef] = []
        rows: list[dict] = []
        infos: list[TransitionInfo] = []
        warnings: list[str] = []
        prev: _Element | None = None
        for i, it in enumerate(items):
            if isinstance(it, _Transition):
                if i not in made:
                    rows.append({"element": it.label, "kind": "transition", "method": "system", "points": 0,
                                 "segments": 0})
                    continue
                segs, pts, info = made[i]
                label, kind = it.label, "transition"
                infos.append(info)
            else:
                segs, pts, label, kind = it.segs, list(it.points), it.label, it.kind
                if pts and (i, 0) in absorbed and pts[0][0] == it.x0:
                    pts = pts[1:]
                if pts and (i, 1) in absorbed and pts[-1][0] == it.x1:
                    pts = pts[:-1]
                if prev is not None and not isinstance(items[i - 1], _Transition) and it.x0 == prev.x1:
                    ya, yb = prev.state(1)[0], it.state(0)[0]
                    if abs(ya - yb) > 1e-9 * max(1.0, abs(ya), abs(yb)):
                        warnings.append(f"{prev.label} ends at y={ya:.9g}, {it.label} starts at y={yb:.9g}: "
                                        f"a step at x={it.x0:g}")
                prev = it
            for what, have, add, limit in (("points", len(points), len(pts), MAX_POINTS),
                                           ("segments", len(segments), len(segs), MAX_SEGMENTS)):
                if have + add > limit:
                    raise CamCapacityError(
                        f"{label} needs {add} {what}; with the elements before it the cam would use "
                        f"{have + add} of at most {limit} {what} (S7-1500T V5 §6.2.5.7)",
                        label, what, have + add, limit)
            for s in segs:
                seg, err = s.to_segment(label)
                scale = max(1.0, abs(s.state(s.xa)[0]), abs(s.state(s.xb)[0]))
                if err > 1e-6 * scale:
                    warnings.append(f"{label}: segment [{s.xa:g}, {s.xb:g}] may lose about {err:.2g} to rounding "
                                    f"when evaluated at the absolute leading value")
                segments.append(seg)
            points.extend(pts)
            rows.append({"element": label, "kind": kind, "points": len(pts), "segments": len(segs)})
        return CamDefinition(points, segments, self.interpolation_mode, self.boundary_conditions, rows, infos,
                             warnings)


def _spline_state(pts: list[tuple[float, float]]) -> Callable[[int], tuple[float, ...]]:
    """End states of a point group: natural cubic spline through its points (a line for two points)."""
    if len(pts) == 2:
        (xa, ya), (xb, yb) = pts
        m = (yb - ya) / (xb - xa)
        return lambda side: (yb if side else ya, m, 0.0, 0.0)
    from scipy.interpolate import CubicSpline

    sp = CubicSpline([p[0] for p in pts], [p[1] for p in pts], bc_type="natural")
    return lambda side: tuple(float(sp(pts[-1 if side else 0][0], k)) for k in range(4))


def _vdi(tr: _Transition, left: _Element, right: _Element) -> tuple[list[_Seg], list, TransitionInfo]:
    """Segments (or points) of a VDI transition from the end state of ``left`` to the start of ``right``."""
    xa, xb = left.x1, right.x0
    h = xb - xa
    if not h > JOIN_GAP:
        raise ValueError(f"{tr.label}: a VDI transition needs a gap between {left.label} (ends at x={xa:g}) and "
                         f"{right.label} (starts at x={xb:g}) of more than {JOIN_GAP:g}")
    sa, sb = left.state(1), right.state(0)
    for el, st in ((left, sa), (right, sb)):
        if not all(math.isfinite(v) for v in st):
            raise ValueError(f"{tr.label}: {el.label} has an infinite slope at its end; restrict its definition "
                             f"range or use a system transition")
    ya, yb = sa[0], sb[0]
    stroke = yb - ya
    key = tr.law or "polynomial"
    ta = [v * h ** k for k, v in enumerate(sa)]         # derivatives with respect to t = (x - xa) / h
    tb = [v * h ** k for k, v in enumerate(sb)]
    tiny = 1e-12 * max(1.0, abs(ya), abs(yb))
    big = abs(stroke) > tiny
    norm = stroke if big else max(1.0, abs(ya), abs(yb))
    na, nb = [v / norm for v in ta[1:]], [v / norm for v in tb[1:]]
    task = _code(na[0], na[1], 1e-9) + _code(nb[0], nb[1], 1e-9)
    poly = key.startswith("polynomial")
    k0, k1 = tr.continuity or (vdi.DEFAULT_CONTINUITY[key],) * 2
    pts: list[tuple[float, float]] = []
    lam = tr.lam
    if poly:
        c = vdi.boundary_polynomial(ta[: k0 + 1], tb[: k1 + 1])
        piece = Piece(0.0, 1.0, tuple(c))
        pieces = [piece] if len(c) <= 7 else list(vdi.split_septic(piece, 0.5 if lam is None else lam))
    else:
        if not big and task != "RR":
            raise ValueError(f"{tr.label}: law {key!r} needs a stroke for a {task[0]}-{task[1]} transition, but both "
                             f"ends are at y={ya:.9g}; use 'polynomial'")
        try:
            law = vdi.transition_law(key, na if big else (0.0, 0.0), nb if big else (0.0, 0.0), (k0, k1), lam,
                                     tr.n_points)
        except vdi.UnsupportedTransitionError as exc:
            raise vdi.UnsupportedTransitionError(f"{tr.label} between {left.label} and {right.label}: {exc}") from None
        lam = law.lam
        pieces = [p.scaled(stroke, ya) for p in law.pieces]
        if law.points:
            z = np.linspace(0.0, 1.0, law.points)
            pts = [(xa + h * float(zi), ya + stroke * float(si)) for zi, si in zip(z, law.s(z))]
    segs = [] if pts else [_Seg(xa + h * p.t0, xa + h * p.t1, p, xa, h) for p in pieces]
    if segs:
        segs[-1].xb = xb
    normalized = tuple(p.scaled(1.0 / stroke, -ya / stroke) for p in pieces) if big else ()
    info = TransitionInfo(tr.label, key, task, (k0, k1), xa, xb, len(segs), len(pts), lam, normalized,
                          (tuple(na[:2]), tuple(nb[:2])))
    return segs, pts, info


# ------------------------------------------------------------------------------------------------------
@dataclass
class CamDefinition:
    """What a cam TO takes: valid points and segments (in TO order) and the interpolation settings."""

    points: list[tuple[float, float]]
    segments: list[SegmentDef]
    interpolation_mode: int = CUBIC_SPLINE
    boundary_conditions: int = 0
    elements: list[dict] = field(default_factory=list)        # per element: points/segments used
    transitions: list[TransitionInfo] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)

    def statistics(self) -> dict:
        """Points and segments used, in total and per element (profile statistics, §6.2.5.7)."""
        return {"points": len(self.points), "segments": len(self.segments), "max_points": MAX_POINTS,
                "max_segments": MAX_SEGMENTS, "elements": [dict(r) for r in self.elements]}

    def curve(self) -> CamCurve:
        """The cam as the TO interpolates it (MC_InterpolateCam, §5.1)."""
        return interpolate(self.points, self.segments, self.interpolation_mode, self.boundary_conditions)

    def segment_dicts(self) -> list[dict[str, float]]:
        return [dict(zip(SEGMENT_FIELDS, (s.xmin, s.xmax, *s.a, s.sine_amplitude, s.sine_period, s.sine_phase)))
                for s in self.segments]

    def apply(self, cam) -> Any:
        """Write points, segments and InterpolationSettings into a cam TO (then MC_InterpolateCam)."""
        cam.set_points(self.points)
        cam.set_segments(self.segment_dicts())
        cam.InterpolationSettings.InterpolationMode = self.interpolation_mode
        cam.InterpolationSettings.BoundaryConditions = self.boundary_conditions
        return cam

    def to_dict(self) -> dict:
        """JSON-ready description (project files); infinite characteristic values become None."""
        def ch(c: Characteristics | None):
            return None if c is None else {k: (v if math.isfinite(v) else None) for k, v in c.as_dict().items()}
        return {"format": "plcmotion-cam/1", "interpolationMode": self.interpolation_mode,
                "boundaryConditions": self.boundary_conditions,
                "points": [[x, y] for x, y in self.points], "segments": self.segment_dicts(),
                "statistics": self.statistics(),
                "transitions": [{"element": t.label, "law": t.law, "task": t.task, "continuity": list(t.continuity),
                                 "x0": t.x0, "x1": t.x1, "lambda": t.lam, "characteristics": ch(t.characteristics)}
                                for t in self.transitions],
                "warnings": list(self.warnings)}

    @classmethod
    def from_dict(cls, data: dict) -> CamDefinition:
        """Points, segments and settings from :meth:`to_dict` output (statistics recomputed)."""
        pts = [(float(x), float(y)) for x, y in data.get("points", [])]
        segs = []
        for i, d in enumerate(data.get("segments", [])):
            unknown = set(d) - set(SEGMENT_FIELDS)
            if unknown:
                raise ValueError(f"segment {i + 1}: unknown fields {sorted(unknown)}")
            v = [float(d.get(f, 0.0)) for f in SEGMENT_FIELDS]
            segs.append(SegmentDef(v[0], v[1], tuple(v[2:9]), v[9], v[10], v[11]))  # type: ignore[arg-type]
        return cls(pts, segs, int(data.get("interpolationMode", CUBIC_SPLINE)), int(data.get("boundaryConditions", 0)))


__all__ = ["COEFFICIENT_LIMIT", "CONTINUITY", "SEGMENT_FIELDS", "CamBuilder", "CamCapacityError",
           "CamCoefficientError", "CamDefinition", "TransitionInfo"]
