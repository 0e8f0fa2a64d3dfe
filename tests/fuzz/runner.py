"""Runs one episode against the product and checks the invariants (see ``tests/fuzz/__init__.py``).

The harness is PLC-like: before each application cycle the episode's operations of that cycle change
instance inputs or write tags, then every instruction instance is called once (fixed order, as a cyclic
OB calls its FBs), then ``Controller.step()`` runs the servo cycles of the period.  Calls are made by the
harness, not from a registered program, so that an exception escaping an instruction is seen with its
traceback instead of as a STOP.
"""
from __future__ import annotations

import math
import numbers
import time
import traceback
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

import plcmotion.s7_1200 as S12
import plcmotion.s7_1500 as S15
import plcmotion.s7_1500.errors as S15_ERRORS
import plcmotion.s7t as S7T
from plcmotion.s7t.fb_errors import fb_codes
from plcmotion import Controller
from plcmotion.kernel.tag_views import TagAccessError
from plcmotion.s7_1200 import variables

from .gen import Episode, Op
from .oracle_s7t import S7TOracle
from .sources import FuzzLeadingSource
from .values import Ref, TagRefSpec, VarSpec, lit

FINITE_FIELDS = ("sp_p", "sp_v", "sp_a", "act_p", "act_v", "cmd_v", "fe")
STUCK_SECONDS = 2.5            # Busy at standstill longer than this (virtual time) is "stuck"
# instructions whose Busy at standstill of all their axes cannot be a legitimate wait
STUCK_CHECKED = {"MC_MoveAbsolute", "MC_MoveRelative", "MC_Halt", "MC_Reset", "MC_MoveSuperimposed",
                 "MC_PhasingRelative", "MC_PhasingAbsolute", "MC_InterpolateCam", "MC_GetCamLeadingValue",
                 "MC_GetCamFollowingValue", "MC_ChangeDynamic", "MC_WriteParam",
                 # S7-Technology V4.1 (the manual's spelling of FB 413)
                 "MC_MoveSuperImposed", "MC_MoveAdditive"}
S7T_DIALECT = "S7-Technology"
#: ErrorIDs outside an FB's table that docs/s7t/decisions.md decides: MC_SetCharacteristic refused during a
#: restart or at a deactivated object, 8045 (D65, D75)
S7T_DECIDED = frozenset({("MC_SetCharacteristic", 0x8045)})
#: the float members of an axis technology DB (S7-Technology V4.1 §7.1, §7.2): finite after every cycle
S7T_DB_REALS = ("CommandVelocity", "CommandAcceleration", "ActualVelocity", "ActualAcceleration", "SpeedOverride",
                "AccelerationOverride", "ActualPosition", "CommandPosition", "TargetPosition", "Distance",
                "DecelerationDistance", "FollowingError")
#: S7-Technology tags of the bounds (§9.4): maximum velocity, acceleration (= deceleration, the state-dependent
#: model of §4.5.7.4), emergency ramp and jerk
_S7T_V = ("TypeOfAxis.MaxVelocity.maximum",)
_S7T_A = ("TypeOfAxis.MaxAcceleration.maximum", "TypeOfAxis.EmergencyRampGenerator.maxDeceleration")
_S7T_J = ("TypeOfAxis.MaxJerk.maximum",)
# outputs that show a job progressing although its axes stand still
PROGRESS_OUTPUTS = ("CoveredPhaseShift", "AbsolutePhaseShift")
REL_TOL = 1e-3                 # relative tolerance of the dynamic limits
ABS_TOL = 1e-6


@dataclass
class Failure:
    kind: str                  # exception, stop, internal, nonfinite, velocity, acceleration, jerk, swlimit,
    #                            exclusive, stuck, setup
    where: str                 # instruction instance / axis
    cycle: int
    message: str
    detail: str = ""
    key: tuple = ()            # what makes two failures "the same" (deduplication)

    def signature(self) -> str:
        return "|".join(map(str, (self.kind,) + self.key))


def _resolve(v: Any, objs: dict[str, Any]) -> Any:
    if isinstance(v, Ref):
        return objs[v.name]
    if isinstance(v, TagRefSpec):
        return objs[v.name].ref(v.path)
    if isinstance(v, VarSpec):
        return getattr(variables, v.kind)(v.value)
    if isinstance(v, bytearray):
        return bytearray(v)            # an ANY area the FB fills: every run of the episode starts with its own
    return v


def _where_in_src(exc: BaseException) -> str:
    """The innermost frame in plcmotion's sources: file:function (stable across edits of line numbers)."""
    tb = traceback.extract_tb(exc.__traceback__)
    for fr in reversed(tb):
        if "plcmotion" in fr.filename:
            return f"{fr.filename.rsplit('plcmotion/', 1)[-1]}:{fr.name}"
    return f"{tb[-1].filename.rsplit('/', 1)[-1]}:{tb[-1].name}" if tb else "?"


def _num(x: Any) -> float | None:
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        return None
    try:
        f = float(x)
    except OverflowError:
        return None
    return f if math.isfinite(f) else None


class _AxisWatch:
    """Running bounds of one axis: the largest dynamics the manual lets its setpoint have."""

    def __init__(self, axis: Any, is1500: bool, s7t: bool = False):
        self.axis = axis
        self.is1500 = is1500
        self.s7t = s7t
        self.vlim = 0.0
        self.alim = 0.0
        self.jlim = 0.0
        self.jerk_free = False     # a jerk of 0 (no jerk limitation) was in force at some time
        self.grace = False         # after synchronous operation: braking from the synchronous velocity
        self.inside: tuple | None = None   # SW limits: (min, max, v_ref) while inside
        self.stop_acc = math.inf
        self.last_p: float | None = None
        self.sp_in = False         # S7-Technology: the setpoint was inside the SW limits at the last check

    def _tags(self, paths: tuple[str, ...]) -> list[float]:
        out = []
        ax = self.axis
        for p in paths:
            for src in (getattr(ax, "cfg", {}), getattr(ax, "ueff", {})):
                x = _num(src.get(p))
                if x is not None:
                    out.append(x)
        return out

    def update_bounds(self) -> None:
        if self.s7t:
            v, a, j, stop = self._tags(_S7T_V), self._tags(_S7T_A), self._tags(_S7T_J), self._tags(_S7T_A)
        elif self.is1500:
            v = self._tags(("DynamicLimits.MaxVelocity",))
            a = self._tags(("DynamicLimits.MaxAcceleration", "DynamicLimits.MaxDeceleration",
                            "DynamicDefaults.EmergencyDeceleration"))
            j = self._tags(("DynamicLimits.MaxJerk",))
            stop = self._tags(("DynamicLimits.MaxDeceleration", "DynamicDefaults.EmergencyDeceleration"))
        else:
            v = self._tags(("DynamicLimits.MaxVelocity",))
            a = self._tags(("DynamicDefaults.Acceleration", "DynamicDefaults.Deceleration",
                            "DynamicDefaults.EmergencyDeceleration"))
            j = self._tags(("DynamicDefaults.Jerk",))
            stop = self._tags(("DynamicDefaults.Deceleration", "DynamicDefaults.EmergencyDeceleration"))
        self.vlim = max([self.vlim] + [x for x in v if x > 0])
        self.alim = max([self.alim] + [x for x in a if x > 0])
        self.jlim = max([self.jlim] + [x for x in j if x > 0])
        if any(x == 0 for x in j):
            self.jerk_free = True
        pos = [x for x in stop if x > 0]
        self.stop_acc = min(pos) if pos else math.inf

    def coupled(self) -> bool:
        """In synchronous operation or with a superimposed part: the manual's single-axis limits do not
        bound the total setpoint (a following axis follows its leading value)."""
        if not self.is1500:
            return False
        f = self.axis.__dict__.get("follower")  # plain attribute reads: the tag __getattr__ is slow for misses
        return bool(f is not None and (f.coupling is not None or f.waiting is not None or f.sim_job is not None
                                       or f.lv_additive_job is not None or f.phasing_job is not None)
                    or self.axis.superimposed_active)


class Run:
    """One episode, executed cycle by cycle."""

    def __init__(self, ep: Episode, *, log: Callable[[str], None] | None = None, ignore: tuple[str, ...] = ()):
        self.ep = ep
        self.ignore = ignore           # signature prefixes of known failures to look past (triage)
        self.log = log
        self.failure: Failure | None = None
        self.calls = 0
        self.cycle = 0
        self.objs: dict[str, Any] = {}
        self.fbs: dict[str, Any] = {}
        self.fb_cls: dict[str, str] = {}
        self._busy_still: dict[str, int] = {}
        self._progress: dict[str, tuple] = {}
        self._prev_exec: dict[str, bool] = {}
        self._job_axes: dict[str, list] = {}
        self.stopped = False
        self._prev_out: dict[str, dict] = {}
        self.ctl: Controller | None = None
        self.oracle: S7TOracle | None = None
        try:
            self._build()
        except Exception as exc:
            self._fail("setup", "setup", f"{type(exc).__name__}: {exc}", traceback.format_exc(),
                       (type(exc).__name__, _where_in_src(exc)))

    # --- set-up ----------------------------------------------------------------------------------------
    def _build(self) -> None:
        ep = self.ep
        ctl = self.ctl = Controller(**ep.ctl)
        self.is1500 = ep.family() != "S7-1200"
        self.s7t = ep.dialect == S7T_DIALECT
        for px in ep.proxies:
            src = FuzzLeadingSource(px["velocity"], px["glitch"], px["gap"], px["seed"])
            self.objs[px["name"]] = ctl.add_leading_axis_proxy(px["name"], {}, source_link=src)
        for a in ep.axes:
            if a["kind"] == "sync":
                self.objs[a["name"]] = ctl.add_synchronous_axis(a["name"], a["params"], leading_values=a["leading"])
            else:
                self.objs[a["name"]] = ctl.add_positioning_axis(a["name"], a["params"])
        for c in ep.cams:
            if self.s7t:             # a cam disk as valve profile (S7-Technology V4.1 §4.6.4)
                self.objs[c["name"]] = S7T.add_cam_disk(ctl, c["name"], c["points"], db_number=c["db"])
                continue
            self.objs[c["name"]] = ctl.add_cam(c["name"], c["points"], interpolation_mode=c["interpolation"],
                                               boundary_conditions=c["boundary"])
        for t in ep.tables:
            self.objs[t["name"]] = ctl.add_command_table(t["name"], t["commands"])
        mod = S7T if self.s7t else S15 if self.is1500 else S12
        for f in ep.fbs:
            fb = getattr(mod, f["cls"])()
            for k, v in f["init"].items():
                setattr(fb, k, _resolve(v, self.objs))
            self.fbs[f["name"]] = fb
            self.fb_cls[f["name"]] = f["cls"]
        self.axes = [self.objs[a["name"]] for a in ep.axes]
        if self.s7t:                 # the technology DB's REAL members (§7.1, §7.2)
            self.getters = [[(f"db.{m}", (lambda db=ax.db, m=m: getattr(db, m))) for m in S7T_DB_REALS
                             if m in ax.db.__dict__] for ax in self.axes]
        else:
            self.getters = [[(tag, ax.tag_getter(tag)) for tag in ("Position", "Velocity", "ActualPosition",
                                                                   "ActualVelocity")] for ax in self.axes]
        self.watch = [_AxisWatch(ax, self.is1500, self.s7t) for ax in self.axes]
        self.oracle = S7TOracle(self) if self.s7t else None
        # S7-Technology: an Axis input may be the number of the technology DB (also as INT below 0, §6.9.3)
        self._by_db = {n: ax for ax in self.axes if self.s7t for n in (ax.db_number, ax.db_number - 65536)}
        self.index = np.array([ax.index for ax in self.axes], dtype=int)
        n = len(self.axes)
        self._peak_v = np.zeros(n)
        self._peak_a = np.zeros(n)
        # Acceleration built without a jerk limit: the setpoint acceleration stepped (a jerk-free ramp was in
        # force: the emergency-stop ramp of MC_Stop Mode 0 and of error reactions, S7-1500T sync V5 §6.1.5.2 /
        # §6.1.5.3, S7-1200 V6 error reaction "without any jerk limit"; or Jerk 0 = no jerk limitation,
        # §6.1.5.2).  Taking such an acceleration back cannot be bound by the configured jerk (the jerk never
        # applied to building it), so the jerk check is out of scope until the acceleration is zero again.
        self._prev_a = np.zeros(n)
        self._prev_j = np.zeros(n)
        self._prev_t = -math.inf                     # time of the previous servo sample
        self._free_acc = np.zeros(n, dtype=bool)     # outstanding jerk-free acceleration
        # Settling (docs/decisions.md row 66): where a re-plan starts with an acceleration the configured jerk
        # cannot take back before the velocity passes its bound, the first segment of the new plan takes it
        # back with the smallest sufficient jerk, above the configured one.  Such a segment starts at the
        # re-plan, opposes the acceleration and ends when it is zero; its jerk is out of the jerk check's scope
        # (the velocity check still holds).  The segment is recognised by its start time.
        self._jlim = np.zeros(n)                     # largest configured jerk per axis (from the watches)
        self._settle_t = np.full(n, -np.inf)         # start time of the settling segment in force
        self._peak_j = np.zeros(n)                   # peak |jerk| of the samples outside settling segments
        self._nonfinite: str | None = None
        # the bank holds exactly the episode's axes in order: no gather needed
        self._whole_bank = ctl.bank.n == n and list(self.index) == list(range(n))
        ctl.on_post_servo(self._servo_hook)
        # instructions that change dynamics tags: the bounds are re-read when one of them is Done
        self._tag_writers = [self.fbs[f["name"]] for f in ep.fbs if f["cls"] in ("MC_ChangeDynamic", "MC_WriteParam")]
        self._ops = {}
        for op in ep.ops:
            self._ops.setdefault(op.cycle, []).append(op)

    def _servo_hook(self, t: float) -> None:
        """Every servo cycle: peaks of the setpoint dynamics and finiteness of the bank (never raises)."""
        b = self.ctl.bank
        try:
            if self._nonfinite is None:
                # fast path: a NaN/inf anywhere makes the sum non-finite (a finite overflow is re-checked)
                total = 0.0
                for name in FINITE_FIELDS:
                    total += getattr(b, name).sum()
                if not math.isfinite(total):
                    idx = self.index
                    for name in FINITE_FIELDS:
                        arr = getattr(b, name)[idx]
                        if not np.isfinite(arr).all():
                            k = int(np.flatnonzero(~np.isfinite(arr))[0])
                            self._nonfinite = f"bank.{name} of {self.axes[k].name} = {arr[k]!r} at t = {t:.4f} s"
                            break
            if self._whole_bank:
                np.maximum(self._peak_v, np.abs(b.sp_v), out=self._peak_v)
                np.maximum(self._peak_a, np.abs(b.sp_a), out=self._peak_a)
            else:
                idx = self.index
                np.maximum(self._peak_v, np.abs(b.sp_v[idx]), out=self._peak_v)
                np.maximum(self._peak_a, np.abs(b.sp_a[idx]), out=self._peak_a)
            a = b.sp_a if self._whole_bank else b.sp_a[self.index]
            j = b.sp_j if self._whole_bank else b.sp_j[self.index]
            if self._whole_bank:
                seg_t, seg_a, seg_j = b.seg_t, b.seg_a, b.seg_j
            else:
                idx = self.index
                seg_t, seg_a, seg_j = b.seg_t[idx], b.seg_a[idx], b.seg_j[idx]
            # a segment that began since the previous sample: a plan made at this sample (an event) or in the
            # application cycle before it (an instruction plans from the last sample's time)
            fresh = seg_t > self._prev_t - 1e-12
            jl = self._jlim * (1 + REL_TOL) + ABS_TOL
            starts = fresh & (np.abs(seg_j) > jl) & (seg_j * seg_a < 0)
            if starts.any():
                self._settle_t = np.where(starts, seg_t, self._settle_t)
            settling = (seg_t == self._settle_t) & (a * seg_a >= 0) & (j == seg_j)
            # a change of acceleration larger than the jerks in force can explain is a step; over the interval
            # before a fresh plan the old plan's jerk was in force, not the new one's
            j_in_force = np.where(fresh, np.maximum(np.abs(self._prev_j), self._jlim),
                                  np.maximum(np.abs(j), np.abs(self._prev_j)))
            slack = j_in_force * self.ctl.servo_cycle * (1 + REL_TOL) + ABS_TOL * (1 + np.abs(a))
            stepped = np.abs(a - self._prev_a) > slack
            self._free_acc = (self._free_acc | stepped) & (np.abs(a) > ABS_TOL)
            # the jerk of a sample counts unless a settling segment, a step or a jerk-free acceleration explains it
            exempt = settling | stepped | self._free_acc
            jabs = np.abs(j)
            if exempt.any():
                jabs = np.where(exempt, 0.0, jabs)
            np.maximum(self._peak_j, jabs, out=self._peak_j)
            self._prev_a[:] = a
            self._prev_j[:] = j
            self._prev_t = t
        except Exception as exc:  # pragma: no cover - a defect of the fuzzer itself
            self._nonfinite = f"fuzzer hook failed: {exc!r}"

    # --- running ---------------------------------------------------------------------------------------
    def _fail(self, kind: str, where: str, message: str, detail: str = "", key: tuple = ()) -> None:
        if self.failure is None:
            f = Failure(kind, where, self.cycle, message, detail, key)
            if self.ignore and f.signature().startswith(self.ignore):
                return
            self.failure = f
            if self.log:
                self.log(f"  !! FAILURE {kind} at {where}: {message}")

    def run(self, *, stop_at_failure: bool = True) -> Failure | None:
        if self.failure is not None:
            return self.failure
        ep = self.ep
        for c in range(ep.cycles):
            self.cycle = c
            self.step(self._ops.get(c, ()))
            if (self.failure is not None and stop_at_failure) or self.stopped:
                return self.failure
        # bounded drain: an instruction Busy at standstill gets STUCK_SECONDS to finish
        limit = int(STUCK_SECONDS / self.ctl.app_cycle) + 1
        extra = 0
        while (self.failure is None and not self.stopped and any(0 < n for n in self._busy_still.values())
               and extra < limit):
            self.cycle += 1
            extra += 1
            self.step(())
        return self.failure

    def step(self, ops) -> None:
        ctl = self.ctl
        for op in ops:
            self._apply(op)
        for name, fb in self.fbs.items():
            ex = fb.__dict__.get("Execute")
            if ex is True and not self._prev_exec.get(name):
                if self.oracle is not None:
                    self.oracle.edge(name, self.fb_cls[name], fb)
                # a job works on the axes wired at its start, whatever is wired later
                self._job_axes[name] = [a for a in (self._by_db.get(a, a) if self.s7t and type(a) is int else a
                                                    for a in (fb.__dict__.get(k) for k in ("Axis", "Master", "Slave")))
                                        if a is not None and any(a is x for x in self.axes)]
            self._prev_exec[name] = ex is True
            try:
                fb()
            except Exception as exc:
                self._fail("exception", name, f"{self.fb_cls[name]} raised {type(exc).__name__}: {exc}",
                           traceback.format_exc(), (type(exc).__name__, _where_in_src(exc)))
                continue
            self.calls += 1
            self._check_outputs(name, fb)
        # S7-Technology: MC_WriteParameter, MC_ChangeDataset and restarts change the bounds at any time
        if ops or self.cycle == 0 or self.s7t or any(fb.Done for fb in self._tag_writers):
            for w in self.watch:
                w.update_bounds()
            self._jlim[:] = [w.jlim for w in self.watch]
        coupled_before = [w.coupled() for w in self.watch]
        self._peak_v[:] = 0.0
        self._peak_a[:] = 0.0
        self._peak_j[:] = 0.0
        try:
            ctl.step()
        except BaseException as exc:
            self._fail("exception", "Controller.step", f"step() raised {type(exc).__name__}: {exc}",
                       traceback.format_exc(), ("step", type(exc).__name__, _where_in_src(exc)))
            return
        self._check_cycle(coupled_before)

    def _apply(self, op: Op) -> None:
        if self.log:
            self.log(f"  {op.target}.{op.key} := {lit(op.value)}" if op.kind == "in"
                     else f"  tag {op.target}.{op.key} := {lit(op.value)}")
        if op.kind == "in":
            setattr(self.fbs[op.target], op.key, _resolve(op.value, self.objs))
            return
        obj = self.objs[op.target]
        try:
            obj.set_tag(op.key, op.value)
        except TagAccessError:
            pass                                      # access rule of the tag: a programming error by design
        except TypeError:
            # a value of the wrong data type (None, str, list, bool for REAL) does not compile in a PLC
            if _num(op.value) is not None or (isinstance(op.value, numbers.Real) and not isinstance(op.value, bool)):
                self._fail("exception", f"{op.target}.{op.key}", f"writing {lit(op.value)} raised TypeError",
                           traceback.format_exc(), ("tag", op.key, "TypeError"))
        except Exception as exc:
            self._fail("exception", f"{op.target}.{op.key}", f"writing {lit(op.value)} raised {type(exc).__name__}: {exc}",
                       traceback.format_exc(), ("tag", type(exc).__name__, _where_in_src(exc)))

    # --- invariants ------------------------------------------------------------------------------------
    def _check_outputs(self, name: str, fb: Any) -> None:
        cls = self.fb_cls[name]
        out = fb.__dict__
        outs = type(fb).OUTPUTS
        if self.log:
            now = {k: out[k] for k in outs}
            if now != self._prev_out.get(name):
                shown = " ".join(f"{k}={v if not isinstance(v, int) or isinstance(v, bool) or k not in ('ErrorID', 'ErrorInfo') else f'16#{v:04X}'}"
                                 for k, v in now.items() if v)
                self.log(f"  {name:<28} {cls:<24} {shown or '-'}")
                self._prev_out[name] = now
        if out.get("ErrorID") == 0x8FFF:
            self._fail("internal", name, f"{cls} ErrorID 16#8FFF (internal error), ErrorInfo "
                       f"16#{out.get('ErrorInfo', 0):04X}", "", (cls, "8FFF"))
        if self.s7t:
            self._check_outputs_s7t(name, cls, fb, out, outs)
            for kind, where, message, key in self.oracle.outputs(name, cls, fb, out):
                self._fail(kind, where, message, "", key)
            return
        if self.is1500:
            self._check_errorid_1500(name, cls, out)
        finals = [k for k in ("Done", "CommandAborted", "Error") if k in outs and out[k]]
        if "Done" in outs or "CommandAborted" in outs:
            if len(finals) > 1 or (finals and out.get("Busy")):
                self._fail("exclusive", name, f"{cls} shows {finals + (['Busy'] if out.get('Busy') else [])} "
                           f"at once", "", (cls, tuple(finals)))
            for k in ("InVelocity", "InGear", "InSync"):
                if out.get(k) and (not out.get("Busy") or finals):
                    self._fail("exclusive", name, f"{cls} {k} without Busy or with {finals}", "", (cls, k))
        # bounded Busy: at standstill of every axis it works on, a job of these instructions cannot wait
        if cls in STUCK_CHECKED and out.get("Busy"):
            axes = self._job_axes.get(name, [])
            b = self.ctl.bank
            # exactly frozen setpoints: a job crawling at 1e-300 is slow, not stuck
            still = all(b.sp_v[a.index] == 0.0 and b.sp_a[a.index] == 0.0 and abs(b.act_v[a.index]) < 1e-6
                        and self._basic_velocity(a.index) == 0.0 for a in axes)
            override = all(_num(a.cfg.get("Override.Velocity", 100.0)) not in (None, 0.0) for a in axes)
            # a phase shift goes on while synchronous operation is simulated (S7-1500T V5 §9.1.6.1: the
            # follower's synchronous setpoint is zero then): its progress output moving is not standstill
            progress = tuple(out.get(k) for k in PROGRESS_OUTPUTS if k in out)
            moved = progress != self._progress.get(name, progress)
            self._progress[name] = progress
            if still and override and not moved:
                n = self._busy_still.get(name, 0) + 1
                self._busy_still[name] = n
                if n * self.ctl.app_cycle > STUCK_SECONDS:
                    self._fail("stuck", name, f"{cls} Busy for {STUCK_SECONDS} s with its axes at standstill",
                               "", (cls,))
                return
        self._busy_still.pop(name, None)

    def _check_errorid_1500(self, name: str, cls: str, out: dict) -> None:
        """S7-1500: ErrorID is 0 or a code of the CPU's list this instruction can give
        (``plcmotion.s7_1500.errors.INSTRUCTION_CODES``), Error never with 0."""
        eid = out.get("ErrorID", 0)
        codes = S15_ERRORS.INSTRUCTION_CODES.get(cls)
        if codes is not None and eid != 0 and eid not in codes:
            self._fail("errorid", name, f"{cls} ErrorID {eid!r} is not in its list", "",
                       (cls, eid if isinstance(eid, int) else type(eid).__name__))
        if out.get("Error") and not eid:
            self._fail("errorid", name, f"{cls} Error with ErrorID 0", "", (cls, "error-no-id"))

    def _check_outputs_s7t(self, name: str, cls: str, fb: Any, out: dict, outs: dict) -> None:
        """S7-Technology V4.1 §5.8: at most one of Done / CommandAborted / Error (MC_MoveVelocity: InVelocity
        in place of Done once the command is complete), none of them with Busy except InVelocity (reached,
        still running); ErrorID only from the FB's table of §6 (fb_errors.fb_codes), 0 without Error/a
        warning; internal errors (16#8001) are defects."""
        eid = out.get("ErrorID", 0)
        if eid == 0x8001 or fb.__dict__.get("_internal_fault") is not None:
            self._fail("internal", name, f"{cls} ErrorID 16#{eid:04X} (internal error): "
                       f"{getattr(fb.__dict__.get('_internal_fault'), 'message', '')}", "", (cls, "8001"))
        if not isinstance(eid, int) or eid not in fb_codes(cls) and (cls, eid) not in S7T_DECIDED:
            self._fail("errorid", name, f"{cls} ErrorID {eid!r} is not in its table of §6", "",
                       (cls, eid if isinstance(eid, int) else type(eid).__name__))
        if out.get("Error") and not (isinstance(eid, int) and eid >= 0x8000):
            self._fail("errorid", name, f"{cls} Error with ErrorID 16#{eid:04X}", "", (cls, "error-no-id"))
        if "Done" in outs or "CommandAborted" in outs:
            finals = [k for k in ("Done", "CommandAborted", "Error") if k in outs and out[k]]
            if cls == "MC_MoveVelocity" and out.get("InVelocity") and not out.get("Busy"):
                finals.append("InVelocity")          # complete (Velocity 0 reached or ended): its Done
            if len(finals) > 1 or (finals and out.get("Busy")):
                self._fail("exclusive", name, f"{cls} shows {finals + (['Busy'] if out.get('Busy') else [])} "
                           f"at once", "", (cls, tuple(finals)))
        if cls in STUCK_CHECKED and out.get("Busy"):
            axes = self._job_axes.get(name, [])
            b = self.ctl.bank
            still = all(b.sp_v[a.index] == 0.0 and b.sp_a[a.index] == 0.0 and abs(b.act_v[a.index]) < 1e-6
                        and self._basic_velocity(a.index) == 0.0 for a in axes)
            override = all(_num(a.cfg.get("override.velocity", 100.0)) not in (None, 0.0) for a in axes)
            if axes and still and override:
                n = self._busy_still.get(name, 0) + 1
                self._busy_still[name] = n
                if n * self.ctl.app_cycle > STUCK_SECONDS:
                    self._fail("stuck", name, f"{cls} Busy for {STUCK_SECONDS} s with its axes at standstill",
                               "", (cls,))
                return
        self._busy_still.pop(name, None)

    def _basic_velocity(self, i: int) -> float:
        """Velocity of the basic motion alone: a superimposed motion (S7-1500 MC_MoveSuperimposed) can cancel
        it exactly, so that the axis stands while both jobs progress (fuzz seed 516188)."""
        b = self.ctl.bank
        tau = self.ctl._bank_time - b.seg_t[i]
        return float(b.seg_v[i] + tau * (b.seg_a[i] + 0.5 * tau * b.seg_j[i]))

    def _check_cycle(self, coupled_before: list[bool]) -> None:
        ctl = self.ctl
        if ctl.mode != "RUN":
            reason = (ctl.stop_reason or "").splitlines()
            head = reason[0] if reason else "?"
            where = "?"
            for line in reversed(reason):
                if "plcmotion/" in line and line.strip().startswith("File"):
                    where = line.split("plcmotion/", 1)[-1].split('"')[0] + ":" + line.rsplit(" in ", 1)[-1]
                    break
            self._fail("stop", "Controller", f"controller went to STOP: {head}", ctl.stop_reason or "",
                       (head.split(" at t =")[0].split(":")[0][:60], where))
            self.stopped = True        # nothing after a STOP is meaningful (also when the STOP is ignored)
            return
        if self._nonfinite is not None:
            self._fail("nonfinite", "bank", self._nonfinite, "", (self._nonfinite.split(" of ")[0],
                                                                   self.ep.dialect))
        for k, (ax, w) in enumerate(zip(self.axes, self.watch)):
            if ax.last_internal_error is not None:
                first = ax.last_internal_error.strip().splitlines()[-1]
                self._fail("internal", ax.name, f"internal error (16#8FFF) on {ax.name}: {first}",
                           ax.last_internal_error, (first.split(":")[0], _tb_where(ax.last_internal_error)))
            for tag, get in self.getters[k]:
                x = get()
                if not math.isfinite(x):
                    self._fail("nonfinite", ax.name, f"{ax.name}.{tag} = {x!r}", "", (tag, self.ep.dialect))
            self._check_dynamics(k, ax, w, coupled_before[k])
            self._check_sw_limits(k, ax, w)
        if self.oracle is not None:
            for kind, where, message, key in self.oracle.cycle():
                self._fail(kind, where, message, "", key)

    def _check_dynamics(self, k: int, ax: Any, w: _AxisWatch, coupled_before: bool) -> None:
        if coupled_before or w.coupled():
            w.grace = True
            return
        if ax.state not in ("enabled", "disabling") or self.ctl.bank.follow_act[ax.index]:
            return
        v, a, j = self._peak_v[k], self._peak_a[k], self._peak_j[k]
        vlim = w.vlim * (1 + REL_TOL) + ABS_TOL
        if w.grace:
            # after synchronous operation or a superimposed motion the overriding job takes the total motion
            # back to the configured limits (S7-1500T V5 §4.4.1 "transitioned (smoothed)"): velocity and
            # acceleration are out of scope until both are within them again (fuzz seed 547578)
            b = self.ctl.bank
            if (abs(b.sp_v[ax.index]) <= vlim
                    and abs(b.sp_a[ax.index]) <= w.alim * (1 + REL_TOL) + ABS_TOL):
                w.grace = False
            return
        if self.s7t:
            kind = f"technology {ax.technology}" + (" virtual" if ax.virtual else "")
        else:
            kind = f"actor {ax.cfg.get('Actor.Type')}" + (" virtual" if ax.cfg.get("VirtualAxis.Mode") else "") \
                + (" simulated" if ax.cfg.get("Simulation.Mode") else "")
        if v > vlim:
            self._fail("velocity", ax.name, f"|setpoint velocity| {v:.6g} > MaxVelocity {w.vlim:.6g} "
                       f"({v / w.vlim:.3g} x), {kind}", "", (self.ep.family(), kind.split()[1]))
        elif ax.state == "disabling":
            pass                       # S7-1200 StopMode 1 (immediate stop) has no deceleration bound
        elif a > w.alim * (1 + REL_TOL) + ABS_TOL:
            self._fail("acceleration", ax.name, f"|setpoint acceleration| {a:.6g} > largest configured "
                       f"{w.alim:.6g} ({a / w.alim:.3g} x), {kind}", "", (self.ep.family(), kind.split()[1]))
        elif not w.jerk_free and w.jlim > 0 and j > w.jlim * (1 + REL_TOL) + ABS_TOL:
            self._fail("jerk", ax.name, f"|setpoint jerk| {j:.6g} > largest configured {w.jlim:.6g}, {kind}",
                       "", (self.ep.family(), kind.split()[1]))

    def _check_sw_limits(self, k: int, ax: Any, w: _AxisWatch) -> None:
        try:
            on = ax.sw_limits_effective()
        except Exception:
            on = False
        if not on or w.coupled():
            w.inside = w.last_p = None
            w.sp_in = False
            return
        if self.s7t:
            lo, hi = _num(ax.eff.get("swlimit.minusposition")), _num(ax.eff.get("swlimit.plusposition"))
        else:
            lo = _num(ax.eff.get("PositionLimits_SW.MinPosition"))
            hi = _num(ax.eff.get("PositionLimits_SW.MaxPosition"))
        if lo is None or hi is None or lo >= hi:
            w.inside = None
            return
        b = self.ctl.bank
        i = ax.index
        p, act = b.sp_p[i], b.act_p[i]
        v = abs(b.sp_v[i])
        jump = w.last_p is not None and abs(p - w.last_p) > self._peak_v[k] * self.ctl.app_cycle * 1.01 + 1e-6
        w.last_p = p
        sp_was_in, w.sp_in = w.sp_in, lo <= p <= hi
        if lo <= p <= hi and lo <= act <= hi:
            w.inside = (lo, hi, v, abs(b.fe[i]))
            return
        if w.inside is None or w.inside[:2] != (lo, hi) or jump:
            w.inside = None            # limits changed, or the coordinate was set (homing): not a motion
            return
        if self.s7t and sp_was_in and ax.state == "enabled" and not b.follow_act[i] \
                and max(lo - p, p - hi) > 1e-9 * (1.0 + abs(lo) + abs(hi)):
            # S7-Technology V4.1 §4.5.7.3: a motion travels up to the software limit switch, not beyond it.  Not
            # MC_Power's stop programs (disabling): TimeStop brakes in its time, the braking-distance rule
            # above bounds them (fuzz seed 202479)
            self._fail("swlimit", ax.name, f"setpoint {p:.9g} beyond the SW limit [{lo:g}, {hi:g}] "
                       f"(S7-Technology: up to the switch)", "", (self.ep.family(), "setpoint"))
        _, _, v_in, fe_in = w.inside
        app = self.ctl.app_cycle
        v_ref = v_in + w.alim * app    # not capped at MaxVelocity: a superimposed part may add to it
        a_stop = w.stop_acc if math.isfinite(w.stop_acc) else w.alim
        t_j = (a_stop / w.jlim) if w.jlim > 0 and not w.jerk_free else 0.0
        off_ramp = _num(ax.cfg.get("Plant.OffRampTime")) or 0.1
        allowed = 1.1 * (v_ref ** 2 / (2 * a_stop) + v_ref * (2 * app + t_j + off_ramp) + fe_in) + 1e-3 * (1 + v_ref)
        excess = max(lo - p, p - hi, lo - act, act - hi)
        if excess > allowed:
            self._fail("swlimit", ax.name, f"{excess:.6g} beyond the SW limit [{lo:g}, {hi:g}] (braking distance "
                       f"allows {allowed:.6g})", "", (self.ep.family(),))


def _tb_where(text: str) -> str:
    for line in reversed(text.splitlines()):
        s = line.strip()
        if s.startswith("File") and "plcmotion/" in s:
            return s.split("plcmotion/", 1)[-1].split('"')[0] + ":" + s.rsplit(" in ", 1)[-1]
    return "?"


def run_episode(ep: Episode, log: Callable[[str], None] | None = None) -> tuple[Failure | None, int, int]:
    """(failure or None, instruction calls, application cycles)."""
    r = Run(ep, log=log)
    f = r.run()
    return f, r.calls, r.cycle + 1
