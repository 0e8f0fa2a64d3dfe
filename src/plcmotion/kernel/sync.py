"""Leading value couplings, evaluated for all following axes together every servo cycle.

Each coupled following axis gets its setpoint from the synchronous operation function (gear ratio or cam)
of its effective leading value, plus a synchronization offset while it synchronizes
(S7-1500T V5 §3, §4, §5):

    x   = leading value (setpoint of the leading axis, or an external value) + additive value + phase shift
    FV  = law(x) + blend(x) + own(t) + superimposed(t)

* ``law``: gear ``ratio * x + offset`` or cam ``SlaveScaling * f((x - MasterOffset) / MasterScaling)
  + SlaveOffset`` (cyclic, appending or once);
* ``blend``: synchronization over a leading value distance, a quintic in s = (x - x0) / L that takes
  the following axis from where it was at the start to the law with matching position, velocity and
  acceleration at s = 1 (the manual fixes start and end of this phase, not its shape; catalog §11.2);
* ``own``: the axis's own profile, which while coupled is a time-based offset (synchronization with
  dynamic parameters, planned once with ruckig) or zero.

Following axes are processed in levels: a following axis whose leading axis is itself coupled comes
after it in the same servo cycle (master -> slave -> slave).  Python code per axis runs only for events:
a waiting job's start position is crossed, a synchronization ends, a cam end is reached.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable, Protocol

import numpy as np

from .cam import CamCurve
from .sync_limits import SwLimitWatch


GEAR, CAM = 0, 1
#: an effective leading value whose |position| + |velocity| + |acceleration| exceeds this (or is not a
#: number) is invalid: positions are LREALs of -1.0E12 .. 1.0E12, plus additive value and phase shift
LV_LIMIT = 1.0e14
_CYCLE_LIMIT = 2.0 ** 52            # cam cycles beyond this cannot be counted exactly
ONCE, CYCLIC, APPENDING = 0, 1, 2          # MC_CamIn.ApplicationMode


class CouplingCycle(ValueError):
    """The couplings would form a cycle (a leading axis following its own leading value)."""


def quintic(e0: float, d0: float, dd0: float) -> np.ndarray:
    """Coefficients (ascending in s) of e(s) with e(0)=e0, e'(0)=d0, e''(0)=dd0, e(1)=e'(1)=e''(1)=0."""
    c0, c1, c2 = e0, d0, dd0 / 2.0
    # remaining c3, c4, c5 from the three end conditions
    r0 = -(c0 + c1 + c2)
    r1 = -(c1 + 2 * c2)
    r2 = -(2 * c2)
    c3 = 10 * r0 - 4 * r1 + 0.5 * r2
    c4 = -15 * r0 + 7 * r1 - r2
    c5 = 6 * r0 - 3 * r1 + 0.5 * r2
    return np.array([c0, c1, c2, c3, c4, c5])


@dataclass(eq=False)
class Coupling:
    """One following axis coupled (or waiting to couple) to one leading value source."""

    follower: Any                      # the following axis (its ``follower`` component runs the job)
    source: Any                        # leading value source TO
    job: Any                           # the GearIn / GearInPos / CamIn job
    mode: str = "setpoint"             # setpoint | actual | delayed
    law: int = GEAR
    ratio: float = 1.0
    offset: float = 0.0
    cam: Any = None                    # CamTO
    curve: CamCurve | None = None
    master_offset: float = 0.0
    master_scaling: float = 1.0
    slave_offset: float = 0.0
    slave_scaling: float = 1.0
    app_mode: int = CYCLIC
    waiting: bool = False              # job waits for its start condition (law not applied)
    poll: bool = False                 # waiting condition is checked in Python every cycle
    trigger: float = 0.0               # waiting: leading value at which synchronization starts
    direction: float = 1.0             # direction of leading value travel the trigger expects
    blend: np.ndarray | None = None    # LV synchronization: quintic coefficients
    blend_x0: float = 0.0
    blend_len: float = 1.0             # signed leading value distance of the blend
    simulated: bool = False            # MC_SynchronizedMotionSimulation: law not applied
    phase: Any = None                  # Profile of the phase shift (leading value units) or None
    phase_seg: int = 0
    slot: int = -1                     # index in the compiled arrays
    level: int = 1
    # last effective leading value (StatusSynchronizedMotion.EffectiveLeadingValue)
    lv: tuple[float, float, float] = (0.0, 0.0, 0.0)
    cam_cycle: int = 0
    # successive cam cycles are joined by the cam's stroke: ApplicationMode 2, and cyclic camming of a
    # modulo following axis whose stroke is whole modulo lengths (the same positions, without a step)
    joins_cycles: bool = False
    extra: dict = field(default_factory=dict)

    @property
    def applied(self) -> bool:
        return not self.waiting and not self.simulated


class _CamTable:
    """All cam curves in use, concatenated so that one searchsorted finds every follower's piece."""

    def __init__(self, curves: list[CamCurve]):
        self.curves = curves
        keys, c, d1, d2, sine, bp = [], [], [], [], [], []
        self.first = np.zeros(len(curves), dtype=np.int64)
        self.last = np.zeros(len(curves), dtype=np.int64)
        self.start = np.array([cv.start for cv in curves], dtype=float)
        self.length = np.array([cv.length for cv in curves], dtype=float)
        self.f_start = np.array([float(cv.value(cv.start)) for cv in curves], dtype=float)
        self.f_end = np.array([float(cv.value(cv.end)) for cv in curves], dtype=float)
        n = 0
        for k, cv in enumerate(curves):
            self.first[k] = n
            keys.append(k + (cv.bp[:-1] - cv.start) / cv.length)
            bp.append(cv.bp[:-1])
            c.append(cv.c)
            d1.append(cv._d1)
            d2.append(cv._d2)
            sine.append(np.column_stack([cv.sin_amp, cv.sin_freq, cv.sin_phase]))
            n += cv.pieces
            self.last[k] = n - 1
        self.keys = np.concatenate(keys) if keys else np.zeros(0)
        self.bp = np.concatenate(bp) if bp else np.zeros(0)
        self.c = np.concatenate(c) if c else np.zeros((0, 7))
        self.d1 = np.concatenate(d1) if d1 else np.zeros((0, 6))
        self.d2 = np.concatenate(d2) if d2 else np.zeros((0, 5))
        sine_all = np.concatenate(sine) if sine else np.zeros((0, 3))
        self.has_sine = bool(np.any(sine_all[:, 0] != 0.0))
        self.s_amp, self.s_w, self.s_ph = sine_all[:, 0], sine_all[:, 1], sine_all[:, 2]

    def evaluate(self, cid: np.ndarray, u: np.ndarray, start: np.ndarray, inv_length: np.ndarray,
                 first: np.ndarray, last: np.ndarray):
        """f, f', f'' of the curves ``cid`` at cam coordinates ``u`` (inside the definition ranges);
        ``start``, ``inv_length``, ``first``, ``last`` are the per-follower values of the curves."""
        key = cid + np.minimum(np.maximum((u - start) * inv_length, 0.0), 1.0 - 1e-15)
        k = np.searchsorted(self.keys, key, side="right") - 1
        k = np.minimum(np.maximum(k, first), last)
        dx = u - self.bp[k]
        f = _horner(self.c[k], dx)
        f1 = _horner(self.d1[k], dx)
        f2 = _horner(self.d2[k], dx)
        if self.has_sine:
            amp, w = self.s_amp[k], self.s_w[k]
            arg = w * dx + self.s_ph[k]
            s, co = np.sin(arg), np.cos(arg)
            f = f + amp * s
            f1 = f1 + amp * w * co
            f2 = f2 - amp * w * w * s
        return f, f1, f2


def _carried(prev: np.ndarray, bad: np.ndarray, p: np.ndarray, v: np.ndarray, a: np.ndarray, dt: float):
    """``p, v, a`` with the rows ``bad`` replaced by last cycle's values ``prev`` carried forward by dt."""
    pp, pv, pa = prev[0], prev[1], prev[2]
    return (np.where(bad, pp + dt * (pv + 0.5 * dt * pa), p), np.where(bad, pv + dt * pa, v),
            np.where(bad, pa, a))


def _horner(coef: np.ndarray, dx: np.ndarray) -> np.ndarray:
    y = coef[:, -1].copy()
    for i in range(coef.shape[1] - 2, -1, -1):
        y *= dx
        y += coef[:, i]
    return y


class _Level:
    """Compiled arrays of the couplings of one level."""

    def __init__(self, couplings: list[Coupling], table: _CamTable | None, curve_ids: dict[int, int]):
        self.couplings = couplings
        n = len(couplings)
        self.fidx = np.array([c.follower.index for c in couplings], dtype=np.int64)
        # setpoints of axes come from the bank; everything else (actual, delayed, proxy values) from a slot
        self.use_ext = np.array(["ext_slot" in c.extra for c in couplings], dtype=bool)
        self.src_axis = np.array([0 if "ext_slot" in c.extra else c.source.index for c in couplings], dtype=np.int64)
        self.src_ext = np.array([c.extra.get("ext_slot", 0) for c in couplings], dtype=np.int64)
        self.any_ext = bool(self.use_ext.any())
        self.add = np.zeros((3, n))
        self.any_add = False
        self.ph = np.zeros((5, n))            # phase segment: t, p, v, a, j
        self.any_phase = False
        self.apply = np.array([c.applied for c in couplings], dtype=bool)
        self.gear = np.array([c.law == GEAR for c in couplings], dtype=bool)
        self.ratio = np.array([c.ratio for c in couplings])
        self.offset = np.array([c.offset for c in couplings])
        self.cam = np.flatnonzero([c.law == CAM for c in couplings])
        self.table = table
        self.cid = np.array([curve_ids.get(id(c.curve), 0) for c in couplings], dtype=np.int64)[self.cam]
        cams = [couplings[i] for i in self.cam]
        self.moff = np.array([c.master_offset for c in cams])
        self.mscale = np.array([c.master_scaling for c in cams])
        self.soff = np.array([c.slave_offset for c in cams])
        self.sscale = np.array([c.slave_scaling for c in cams])
        self.app_mode = np.array([c.app_mode for c in cams], dtype=np.int64)
        self.cam_once = self.app_mode == ONCE
        self.all_cyclic = not bool(self.cam_once.any())
        self.appending = np.array([c.joins_cycles for c in cams], dtype=bool)
        self.any_append = bool(self.appending.any())
        self.inv_mscale = 1.0 / self.mscale if len(cams) else self.mscale
        if table is not None and len(cams):
            self.cstart = table.start[self.cid]
            self.clength = table.length[self.cid]
            self.inv_clength = 1.0 / self.clength
            self.cend = self.cstart + self.clength
            self.cstroke = table.f_end[self.cid] - table.f_start[self.cid]
            self.cfirst = table.first[self.cid]
            self.clast = table.last[self.cid]
        self.prev_cycle = np.array([c.cam_cycle for c in cams], dtype=np.int64)
        self.prev_inside = np.array([c.extra.get("inside", True) for c in cams], dtype=bool)
        self.blend_idx = np.flatnonzero([c.blend is not None for c in couplings])
        bl = [couplings[i] for i in self.blend_idx]
        self.bx0 = np.array([c.blend_x0 for c in bl])
        self.blen = np.array([c.blend_len for c in bl])
        self.bcoef = np.array([c.blend for c in bl]).reshape(len(bl), 6)
        self.wait_idx = np.flatnonzero([c.waiting and not c.poll for c in couplings])
        wl = [couplings[i] for i in self.wait_idx]
        self.wtrig = np.array([c.trigger for c in wl])
        self.wdir = np.array([c.direction for c in wl])
        self.wprev = np.array([c.extra.get("wprev", np.nan) for c in wl])
        self.poll = [c for c in couplings if c.waiting and c.poll]
        # effective leading value and synchronous operation function of the last cycle: what an invalid
        # leading value is replaced with (carried forward) until its follower has been stopped
        self.xe = np.array([c.lv for c in couplings], dtype=float).reshape(n, 3).T.copy()
        y0 = np.array([c.extra.get("y", (0.0, 0.0, 0.0)) for c in couplings], dtype=float).reshape(n, 3).T
        self.y_last = (y0[0].copy(), y0[1].copy(), y0[2].copy())
        for i, c in enumerate(couplings):
            c.slot = i
            self.set_additive(c)
            self.set_phase(c)

    def set_additive(self, c: Coupling) -> None:
        add = c.follower.follower.lv_additive
        self.add[:, c.slot] = add if add is not None else (0.0, 0.0, 0.0)
        self.any_add = bool(self.add.any())

    def set_phase(self, c: Coupling) -> None:
        prof = c.phase
        if prof is None:
            self.ph[:, c.slot] = 0.0
        else:
            seg = prof.segments[c.phase_seg]
            self.ph[:, c.slot] = (seg.t, seg.p, seg.v, seg.a, seg.j)
            self.any_phase = True


class SyncHost(Protocol):
    """What the sync stage uses of its controller."""

    bank: Any                          # the array bank of all axes (setpoints sp_p, sp_v, sp_a)
    servo_cycle: float


class SyncStage:
    """All leading value couplings of a controller."""

    def __init__(self, ctl: SyncHost):
        self.ctl = ctl
        self.couplings: list[Coupling] = []
        self.levels: list[_Level] = []
        self._dirty = False
        self._ext: list[Callable[[float], tuple[float, float, float]]] = []
        self.ext = np.zeros((3, 0))
        self._post: list[Callable[[float], None]] = []     # after the couplings (delayed values, outputs)
        self._once: list[Callable[[float], None]] = []     # one-shot work after this cycle's couplings
        self.sw_limits = SwLimitWatch()                     # SW limit switches of coupled axes
        self.active = False

    def _update_active(self) -> None:
        #: anything to do in the servo cycle (read every cycle: kept as a plain attribute)
        self.active = bool(self.couplings) or bool(self._ext) or bool(self._post) or bool(self._once)

    # --- external leading values (actual values, delayed values, proxies) -------------------------------
    def register_ext(self, provider: Callable[[float], tuple[float, float, float]]) -> int:
        """A value provider evaluated every servo cycle before the couplings; returns its slot."""
        self._ext.append(provider)
        self.ext = np.zeros((3, len(self._ext)))
        self._update_active()
        return len(self._ext) - 1

    def after_couplings(self, fn: Callable[[float], None]) -> None:
        """Run ``fn(t)`` once, after the couplings of the present (or next) servo cycle, when the
        setpoints of all coupled axes are complete: e.g. stopping followers from where they are."""
        self._once.append(fn)
        self.active = True

    def stop_followers_of(self, source: Any, alarm: Any) -> None:
        """The leading value of ``source`` became invalid: every follower coupled to it (not simulated)
        gets ``alarm`` once this servo cycle's setpoints are complete, so that it brakes from where it is."""
        def stop(t: float) -> None:
            for c in list(self.couplings):
                if c.source is source and not c.simulated:
                    c.follower.raise_alarm(alarm)
        self.after_couplings(stop)

    def register_post(self, fn: Callable[[float], None]) -> None:
        if fn not in self._post:
            self._post.append(fn)
        self._update_active()

    # --- coupling management ----------------------------------------------------------------------------
    def add(self, coupling: Coupling) -> None:
        self.couplings.append(coupling)
        try:
            self._levels_of(self.couplings)
        except CouplingCycle:
            self.couplings.remove(coupling)
            raise
        self._dirty = True
        self._update_active()

    def remove(self, coupling: Coupling) -> None:
        if coupling in self.couplings:
            self.couplings.remove(coupling)
            self._dirty = True
            self._update_active()

    def changed(self) -> None:
        """Coupling data changed (law, blend, waiting state): recompile before the next evaluation."""
        self._dirty = True

    def would_cycle(self, follower: Any, source: Any, mode: str) -> bool:
        """Would coupling ``follower`` to ``source`` close a cycle of couplings?"""
        seen = set()
        node = source
        while node is not None and id(node) not in seen:
            if node is follower:
                return True
            seen.add(id(node))
            c = next((c for c in self.couplings if c.follower is node), None)
            node = c.source if c is not None else None
        return False

    def _levels_of(self, couplings: list[Coupling]) -> dict[int, int]:
        by_follower = {id(c.follower): c for c in couplings}
        levels: dict[int, int] = {}

        def level(c: Coupling, stack: tuple = ()) -> int:
            key = id(c)
            if key in levels:
                return levels[key]
            if key in stack:
                raise CouplingCycle(f"{c.follower.name} would follow its own leading value")
            lvl = 1
            if "ext_slot" not in c.extra:
                up = by_follower.get(id(c.source))
                if up is not None:
                    lvl = level(up, stack + (key,)) + 1
            levels[key] = lvl
            return lvl

        for c in couplings:
            c.level = level(c)
        return levels

    def _save_state(self) -> None:
        """Keep the per-cycle memory of the compiled arrays in the couplings before recompiling."""
        for lv in self.levels:
            for k, i in enumerate(lv.wait_idx):
                lv.couplings[i].extra["wprev"] = float(lv.wprev[k])
            for k, i in enumerate(lv.cam):
                c = lv.couplings[i]
                c.cam_cycle = int(lv.prev_cycle[k])
                c.extra["inside"] = bool(lv.prev_inside[k])
            y, yv, ya = lv.y_last
            for c in lv.couplings:
                c.lv = (float(lv.xe[0, c.slot]), float(lv.xe[1, c.slot]), float(lv.xe[2, c.slot]))
                c.extra["y"] = (float(y[c.slot]), float(yv[c.slot]), float(ya[c.slot]))

    def effective_lv(self, c: Coupling) -> tuple[float, float, float]:
        """Effective leading value of the last servo cycle (StatusSynchronizedMotion.EffectiveLeadingValue)."""
        lv = self.level_of(c)
        if lv is None:
            return c.lv
        return float(lv.xe[0, c.slot]), float(lv.xe[1, c.slot]), float(lv.xe[2, c.slot])

    def _compile(self) -> None:
        self._save_state()
        self._dirty = False
        self._levels_of(self.couplings)
        curves: list[CamCurve] = []
        ids: dict[int, int] = {}
        for c in self.couplings:
            if c.law == CAM and c.curve is not None and id(c.curve) not in ids:
                ids[id(c.curve)] = len(curves)
                curves.append(c.curve)
        table = _CamTable(curves) if curves else None
        depth = max((c.level for c in self.couplings), default=0)
        self.levels = []
        for lvl in range(1, depth + 1):
            group = [c for c in self.couplings if c.level == lvl]
            group.sort(key=lambda c: c.follower.index)
            if group:
                self.levels.append(_Level(group, table, ids))

    def level_of(self, coupling: Coupling) -> _Level | None:
        if self._dirty:
            return None
        for lv in self.levels:
            if coupling.slot < len(lv.couplings) and lv.couplings[coupling.slot] is coupling:
                return lv
        return None

    # --- the servo cycle --------------------------------------------------------------------------------
    def run(self, t: float) -> None:
        if self._ext:
            for k, provider in enumerate(self._ext):
                self.ext[:, k] = provider(t)
        if self._dirty:
            self._compile()
        b = self.ctl.bank
        for lv in self.levels:
            self._run_level(lv, b, t)
            if self._dirty:                   # an event changed the couplings: rebuild, go on
                self._compile()
        if self._once:
            work, self._once = self._once, []
            for fn in work:
                fn(t)
            self._update_active()
            if self._dirty:
                self._compile()
        for axis, side in self.sw_limits.check(b, self.ctl.servo_cycle):
            try:
                axis.follower.sw_limit_in_reach(side, t)
            except Exception as exc:   # isolate a defect to its axis
                axis._internal_error(exc)
        for fn in self._post:
            fn(t)

    def _run_level(self, lv: _Level, b: Any, t: float) -> None:
        x = b.sp_p[lv.src_axis]
        xv = b.sp_v[lv.src_axis]
        xa = b.sp_a[lv.src_axis]
        if lv.any_ext:
            e = self.ext
            x = np.where(lv.use_ext, e[0, lv.src_ext], x)
            xv = np.where(lv.use_ext, e[1, lv.src_ext], xv)
            xa = np.where(lv.use_ext, e[2, lv.src_ext], xa)
        if lv.any_add:
            x = x + lv.add[0]
            xv = xv + lv.add[1]
            xa = xa + lv.add[2]
        if lv.any_phase:
            ph = lv.ph
            tau = t - ph[0]
            x = x + (ph[1] + tau * (ph[2] + tau * (0.5 * ph[3] + tau * ph[4] / 6.0)))
            xv = xv + (ph[2] + tau * (ph[3] + 0.5 * tau * ph[4]))
            xa = xa + (ph[3] + tau * ph[4])
        dt = self.ctl.servo_cycle
        ok = np.abs(x) + np.abs(xv) + np.abs(xa) <= LV_LIMIT           # not NaN, inf or absurd
        bad = None
        if not ok.all():
            bad = ~ok
            x, xv, xa = _carried(lv.xe, bad, x, xv, xa, dt)
        lv.xe[0], lv.xe[1], lv.xe[2] = x, xv, xa
        y = lv.ratio * x + lv.offset
        yv = lv.ratio * xv
        ya = lv.ratio * xa
        events: list[tuple[str, Coupling, Any]] = []
        if lv.cam.size:
            ci = lv.cam
            u = (x[ci] - lv.moff) * lv.inv_mscale
            uv = xv[ci] * lv.inv_mscale
            ua = xa[ci] * lv.inv_mscale
            start, length = lv.cstart, lv.clength
            r = (u - start) * lv.inv_clength
            countable = np.abs(r) < _CYCLE_LIMIT
            if not countable.all():
                if bad is None:
                    bad = np.zeros(len(x), dtype=bool)
                bad[ci[~countable]] = True
                r = np.where(countable, r, 0.0)
            cyc = np.floor(r).astype(np.int64)
            # a leading value standing on a cam end is still inside; moving away past it, it has left
            inside = (((u > start) | ((u == start) & (uv >= 0.0)))
                      & ((u < lv.cend) | ((u == lv.cend) & (uv <= 0.0))))
            if lv.all_cyclic:
                uw = start + (r - cyc) * length
            else:
                cyclic = ~lv.cam_once
                uw = np.where(cyclic, start + (r - cyc) * length, np.minimum(np.maximum(u, start), lv.cend))
            f, f1, f2 = lv.table.evaluate(lv.cid, uw, start, lv.inv_clength, lv.cfirst, lv.clast)
            if not lv.all_cyclic:
                moving = cyclic | inside
                f1 = np.where(moving, f1, 0.0)
                f2 = np.where(moving, f2, 0.0)
            if lv.any_append:
                f = f + np.where(lv.appending, cyc * lv.cstroke, 0.0)
            y[ci] = lv.sscale * f + lv.soff
            yv[ci] = lv.sscale * f1 * uv
            ya[ci] = lv.sscale * (f2 * uv * uv + f1 * ua)
            if lv.all_cyclic:
                changed = cyc != lv.prev_cycle
                if changed.any():
                    for k in np.flatnonzero(changed):
                        events.append(("cam_wrap", lv.couplings[ci[k]], int(cyc[k])))
            else:
                wrapped = cyclic & (cyc != lv.prev_cycle)
                left = lv.cam_once & lv.prev_inside & ~inside
                if wrapped.any() or left.any():
                    for k in np.flatnonzero(wrapped | left):
                        events.append(("cam_end" if left[k] else "cam_wrap", lv.couplings[ci[k]], int(cyc[k])))
            lv.prev_cycle = cyc
            lv.prev_inside = inside
        if lv.blend_idx.size:
            bi = lv.blend_idx
            s_raw = (x[bi] - lv.bx0) / lv.blen
            s = np.clip(s_raw, 0.0, 1.0)
            c = lv.bcoef
            e = c[:, 0] + s * (c[:, 1] + s * (c[:, 2] + s * (c[:, 3] + s * (c[:, 4] + s * c[:, 5]))))
            d1 = c[:, 1] + s * (2 * c[:, 2] + s * (3 * c[:, 3] + s * (4 * c[:, 4] + s * 5 * c[:, 5])))
            d2 = 2 * c[:, 2] + s * (6 * c[:, 3] + s * (12 * c[:, 4] + s * 20 * c[:, 5]))
            live = (s_raw > 0.0) & (s_raw < 1.0)
            inv = 1.0 / lv.blen
            sv = xv[bi] * inv
            y[bi] += e
            yv[bi] += np.where(live, d1 * sv, 0.0)
            ya[bi] += np.where(live, d2 * sv * sv + d1 * xa[bi] * inv, 0.0)
            done = s_raw >= 1.0
            if done.any():
                for k in np.flatnonzero(done):
                    events.append(("blend_end", lv.couplings[bi[k]], None))
        finite = np.isfinite(y + yv + ya)
        if not finite.all():
            bad = ~finite if bad is None else bad | ~finite
        any_bad = bad is not None
        if any_bad:
            y, yv, ya = _carried(np.array(lv.y_last), bad, y, yv, ya, dt)
            if not np.isfinite(y + yv + ya).all():        # nothing finite to carry forward: stand
                y, yv, ya = (np.nan_to_num(v, nan=0.0, posinf=0.0, neginf=0.0) for v in (y, yv, ya))
        lv.y_last = (y, yv, ya)
        ap = lv.apply
        f_idx = lv.fidx[ap]
        b.sp_p[f_idx] += y[ap]
        b.sp_v[f_idx] += yv[ap]
        b.sp_a[f_idx] += ya[ap]
        if lv.wait_idx.size:
            wi = lv.wait_idx
            s_now = (x[wi] - lv.wtrig) * lv.wdir
            crossed = (s_now >= 0.0) & (lv.wprev <= 0.0)
            lv.wprev = s_now
            if crossed.any():
                for k in np.flatnonzero(crossed):
                    events.append(("trigger", lv.couplings[wi[k]], None))
        for c in lv.poll:
            events.append(("poll", c, None))
        if any_bad:
            # the follower is stopped instead of following a leading value that is not a number
            failed = {id(lv.couplings[k]) for k in np.flatnonzero(bad)}
            events = [e for e in events if id(e[1]) not in failed]
            events.extend(("lv_invalid", lv.couplings[k], None) for k in np.flatnonzero(bad))
        for kind, c, arg in events:
            role = c.follower.follower          # the Follower component of the following axis
            try:
                role.sync_event(kind, c, arg, t)
            except Exception as exc:   # isolate a defect to its job and axis
                try:
                    role.failure(c, exc)
                except Exception as exc2:
                    c.follower._internal_error(exc2)

    # --- values for Python code -------------------------------------------------------------------------
    def law_at(self, c: Coupling, x: float, xv: float, xa: float) -> tuple[float, float, float]:
        """The synchronous operation function (without blend) for one coupling at one leading value."""
        if c.law == GEAR:
            return c.ratio * x + c.offset, c.ratio * xv, c.ratio * xa
        curve = c.curve
        assert curve is not None
        u = (x - c.master_offset) / c.master_scaling
        uv, ua = xv / c.master_scaling, xa / c.master_scaling
        length = curve.length
        append = 0.0
        if c.app_mode != ONCE:
            r = (u - curve.start) / length
            cyc = math.floor(r)
            u = curve.start + (r - cyc) * length
            if c.joins_cycles:
                append = cyc * (float(curve.value(curve.end)) - float(curve.value(curve.start)))
            inside = True
        else:
            # the same rule as the vectorised stage: on a cam end the value is inside unless it moves out
            inside = (u > curve.start or (u == curve.start and uv >= 0.0)) and \
                     (u < curve.end or (u == curve.end and uv <= 0.0))
            u = min(max(u, curve.start), curve.end)
        f, f1, f2 = (float(v[0]) for v in curve.evaluate(np.array([u])))
        if not inside:
            f1 = f2 = 0.0
        return (c.slave_scaling * (f + append) + c.slave_offset, c.slave_scaling * f1 * uv,
                c.slave_scaling * (f2 * uv * uv + f1 * ua))
