"""Synchronous operation jobs of a following axis (S7-1500T V5 §3 - §5, §9.1, §9.3.2).

A following axis has at most one active synchronous operation (GearIn, GearInPos or CamIn, or one that
is simulated) and at most one waiting job (GearInPos/CamIn before its start condition).  The active one
is a :class:`~plcmotion.kernel.sync.Coupling` evaluated by the controller's sync stage.  Synchronization
runs either over time with the job's dynamics (MC_GearIn, SyncProfileReference 0: the offset to the
synchronous operation function is planned once with ruckig) or over a leading value distance
(SyncProfileReference 1, 3, 4: a quintic in the leading value).

Leading values of modulo axes are unwrapped internally; a synchronous position given in modulo
coordinates refers to its next occurrence in the direction the leading value moves when the job starts
(the manual gives the positive direction only, catalog §11.2 item 3; docs/decisions_s7_1500.md).
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from . import faults as F
from . import policy as O
from .family import ACTUAL_VALUE_COUPLING
from .faults import Fault, Reaction
from .jobs import Job, JobKind, JobState
from .leading import setpoint_at
from .motion import limits
from .profiles import INF, Planner, PlanningError, Profile
from .sync import _CYCLE_LIMIT, APPENDING, CAM, GEAR, LV_LIMIT, ONCE, Coupling, CouplingCycle, quintic
from .sync_modifiers import SyncModifiersMixin
from .sync_revolutions import RevolutionsMixin

if TYPE_CHECKING:  # pragma: no cover
    from .axis import PositioningAxis as Axis

_EPS = 1e-12
COUPLING_TYPES = ("setpoint", "actual", "delayed")
SETPOINTS = ("setpoint", "cascade")      # coupling to the setpoint (cascade: ahead at a proxy, §8.1.3)


class LeadingValueInvalid(ValueError):
    """The leading value of a coupling is not a number (or absurdly large): its job cannot go on."""


class SynchronousMixin(RevolutionsMixin, SyncModifiersMixin):
    """Following axis behaviour, mixed into the S7-1500 synchronous axis."""

    def _sync_init(self: "Axis", leading_values) -> None:
        self.coupling: Coupling | None = None
        self.waiting: Coupling | None = None
        self.phasing_job: Job | None = None
        self.lv_additive: tuple[float, float, float] | None = None
        self.lv_additive_job: Job | None = None
        self.sim_job: Job | None = None
        self._leading_values: dict[str, str] = {}
        for item in leading_values or ():
            name, mode = (item, "setpoint") if isinstance(item, str) else tuple(item)
            if mode not in COUPLING_TYPES:
                raise ValueError(f"{self.name}: leading value {name!r}: type of coupling {mode!r} is not one of "
                                 f"{', '.join(COUPLING_TYPES)}")
            self._leading_values[str(name)] = mode

    @property
    def possible_leading_values(self: "Axis") -> dict[str, str]:
        """Configured leading value interconnections: source name -> type of coupling (§6.1.3)."""
        return dict(self._leading_values)

    # --- status -----------------------------------------------------------------------------------------
    @property
    def sync_job(self: "Axis") -> Job | None:
        c = self.coupling
        return c.job if c is not None else None

    @property
    def synchronizing(self: "Axis") -> bool:
        c = self.coupling
        return c is not None and not c.simulated and not c.job.in_sync

    @property
    def synchronous(self: "Axis") -> bool:
        c = self.coupling
        return c is not None and c.job.in_sync

    def function_state(self: "Axis") -> int:
        c = self.coupling
        if c is None:
            return 0
        return {JobKind.GEAR_IN: 1, JobKind.GEAR_IN_POS: 2, JobKind.CAM_IN: 3}[c.job.kind]

    def waiting_function_state(self: "Axis") -> int:
        w = self.waiting
        if w is None or w.job.kind == JobKind.GEAR_IN:
            return 0
        return 2 if w.job.kind == JobKind.GEAR_IN_POS else 3

    def phase_shift(self: "Axis", t: float | None = None) -> float:
        c = self.coupling
        if c is None or c.phase is None:
            return 0.0
        return c.phase.at(self.now if t is None else t)[0]

    def effective_leading_value(self: "Axis") -> tuple[float, float, float]:
        c = self.coupling or self.waiting
        if c is None:
            return 0.0, 0.0, 0.0
        return self.ctl.sync.effective_lv(c)

    # --- leading value ----------------------------------------------------------------------------------
    def _resolve_master(self: "Axis", master: Any) -> tuple[Any, str] | Fault:
        name = getattr(master, "name", None)
        mode = self._leading_values.get(name) if name is not None else None
        if mode is None or self.ctl._lookup(name) is not master:
            self.raise_alarm(F.alarm(F.SYNC_MASTER, str(name), Reaction.NONE,
                                     f"{name} is not configured as a possible leading value of {self.name}"))
            return F.reject(F.SYNC_MASTER, str(name))
        if master is self:
            return F.reject(F.COUPLING_CYCLE, "self")
        if mode == "actual" and not getattr(master, "provides_actual_values", False):
            return F.reject(F.LV_NOT_READY, "no_actual_values")
        if mode == "setpoint" and not getattr(master, "provides_setpoints", False):
            return F.reject(F.LV_NOT_READY, "no_setpoints")
        if mode == "delayed" and not getattr(master, "provides_delayed_values", False):
            return F.reject(F.LV_NOT_READY, "no_delayed_values")      # §3.3.3: not a proxy
        if mode != "setpoint" and ACTUAL_VALUE_COUPLING not in self.ctl.features:
            return F.reject(F.NOT_AVAILABLE, "actual_value_coupling")
        if mode == "setpoint" and getattr(master, "cascade_delay", 0.0) and self.provides_cross_plc():
            # §8.1.3 cascade: the axis that provides the value on runs ahead by the proxy's
            # Parameter.LocalLeadingValueDelayTime, the delay it sends with (docs: decisions #31)
            mode = "cascade"
        return master, mode

    def provides_cross_plc(self: "Axis") -> bool:
        """Configured to provide its leading value to other controllers (§6.1.4)."""
        return self.config.leading_value_output.enabled

    def _lv_now(self: "Axis", source: Any, mode: str, t: float) -> tuple[float, float, float]:
        """Effective leading value (source value plus additive value) at time ``t``."""
        p, v, a = source.lv_value(mode, t)
        add = self.lv_additive
        if add is not None:
            p, v, a = p + add[0], v + add[1], a + add[2]
        if not abs(p) + abs(v) + abs(a) <= LV_LIMIT:
            raise LeadingValueInvalid(f"leading value of {getattr(source, 'name', source)} is ({p!r}, {v!r}, {a!r})")
        return p, v, a

    # --- the current state of the following axis -------------------------------------------------------
    def _coupled_state_at(self: "Axis", t: float) -> tuple[float, float, float]:
        """Setpoint of a coupled axis at ``t``: the last servo cycle's values carried forward."""
        return setpoint_at(self, t)

    def total_state_at(self: "Axis", t: float) -> tuple[float, float, float]:
        """Total setpoint (basic motion, synchronous operation and superimposed motion)."""
        if self.coupling is not None and self.coupling.applied:
            return self._coupled_state_at(t)
        p, v, a = self._state_at(t)
        sp, sv, sa = self.sup_state_at(t)
        return p + sp, v + sv, a + sa

    # --- job entry ---------------------------------------------------------------------------------------
    def sync_submit(self: "Axis", job: Job) -> None:
        """Start MC_GearIn, MC_GearInPos, MC_CamIn or a phasing job.  Whatever goes wrong inside ends
        the job with an error (never an exception out of the instruction, never Busy forever)."""
        try:
            self._sync_submit(job)
        except Exception as exc:
            c = next((c for c in (self.waiting, self.coupling) if c is not None and c.job is job), None)
            self._sync_failure(c if c is not None else Coupling(self, None, job), exc)

    def _sync_failure(self: "Axis", c: Coupling, exc: Exception) -> None:
        """A synchronous job failed in the kernel: it ends with Error - 16#8FFF for an internal error,
        the alarm of an invalid leading value otherwise - and the axis gets the technology alarm."""
        t = self.now
        job = c.job
        if isinstance(exc, LeadingValueInvalid):
            alarm = F.alarm(F.LV_INVALID, str(getattr(c.source, "name", "")), Reaction.STOP, str(exc))
            own = alarm
        else:
            import traceback

            self.last_internal_error = "".join(traceback.format_exception(exc))
            alarm = F.alarm(F.INTERNAL, "", Reaction.REMOVE_ENABLE, f"{type(exc).__name__}: {exc}")
            own = F.reject(F.INTERNAL, "", f"{type(exc).__name__}: {exc}")
        try:
            if c is self.coupling:
                self._end_coupling(c, JobState.ERROR, t, replan=True, fault=own)
            else:
                if c is self.waiting:
                    self.waiting = None
                self.ctl.sync.remove(c)
                self._finish_coupling_job(c, JobState.ERROR, t, own)
        finally:
            job.finish(JobState.ERROR, own)          # whatever happened above, the job has ended
            self.raise_alarm(alarm)

    def _sync_submit(self: "Axis", job: Job) -> None:
        t = self.now
        if not self.ctl.offers_job(job.kind):
            job.finish(JobState.ERROR, F.reject(F.NOT_AVAILABLE, job.kind.value))
            return
        fault = self._sync_check(job)
        if fault is not None:
            job.finish(JobState.ERROR, fault)
            return
        if job.kind == JobKind.PHASING:
            self._start_phasing(job, t)
            return
        resolved = self._resolve_master(job.extra["master"])
        if isinstance(resolved, Fault):
            job.finish(JobState.ERROR, resolved)
            return
        source, mode = resolved
        invalid = source.leading_value_invalid(mode)
        if invalid is not None:
            # the same as a leading value that becomes invalid while coupled: alarm, job ends with Error
            self._sync_failure(Coupling(self, source, job, mode), LeadingValueInvalid(invalid))
            return
        if self.ctl.sync.would_cycle(self, source, mode):
            job.finish(JobState.ERROR, F.reject(F.COUPLING_CYCLE))
            return
        if job.kind == JobKind.CAM_IN:
            fault = self._check_cam(job)
            if fault is not None:
                job.finish(JobState.ERROR, fault)
                return
        c = Coupling(self, source, job, mode)
        if mode != "setpoint" or getattr(source, "index", None) is None:
            c.extra["ext_slot"] = source.lv_slot(mode)
        if job.kind == JobKind.GEAR_IN:
            self._start_gear_in(c, t)
        else:
            self._prepare_positioned(c, t)

    def _sync_check(self: "Axis", job: Job) -> Fault | None:
        if self.ctl.mode != "RUN":
            return F.reject(F.REJECTED, "starting_up")
        if self.state != "enabled":
            return F.reject(F.NOT_ENABLED)
        fault = self._blocking_alarm()
        if fault is not None:
            return fault
        if self.stop_job is not None:
            return F.reject(F.STOP_ACTIVE)
        if self.sim_job is not None and self.sim_job.busy:
            return F.reject(F.SYNC_SIMULATION)
        if job.kind == JobKind.PHASING:
            c = self.coupling
            if c is None or not c.job.in_sync or c.job.kind == JobKind.CAM_IN or c.simulated:
                return F.reject(F.NOT_SYNCHRONOUS, "gearing")
            if job.extra.get("master") is not c.source:
                return F.reject(F.NOT_SYNCHRONOUS, "master")
        return None

    def _check_cam(self: "Axis", job: Job) -> Fault | None:
        cam = job.extra["cam"]
        if cam.curve is None:
            return F.reject(F.CAM_NOT_INTERPOLATED)
        x = job.extra
        span = cam.curve.length * x["master_scaling"]
        if x["spr"] in (0, 1, 2, 3) and not (-1e-9 * max(1.0, abs(span)) <= x["master_sync"] <= span * (1 + 1e-12)):
            return F.reject(F.SYNC_POSITION_RANGE, "", f"MasterSyncPosition {x['master_sync']!r} outside 0 .. {span!r}")
        return None

    # --- MC_GearIn: synchronization over time with the job's dynamics --------------------------------
    def _start_gear_in(self: "Axis", c: Coupling, t: float) -> None:
        self._limit_gear_in_dynamics(c.job)
        c.law = GEAR
        c.ratio = c.job.extra["ratio"]
        if c.mode in SETPOINTS and not c.source.lv_position_controlled():
            # §3.3.5: with setpoint coupling the job waits until the leading axis is position-controlled
            c.waiting = c.poll = True
            self._set_waiting(c, t)
            self._override(O.GEAR_IN, t, c.job)
            return
        self._override(O.GEAR_IN, t, c.job)
        self._activate_gear_in(c, t)

    def _limit_gear_in_dynamics(self: "Axis", job: Job) -> None:
        """§4.4.1: MC_GearIn synchronizes within the configured dynamic limits of the following axis;
        larger job values are limited and shown as a warning (WarningWord.X6, alarms 501-503)."""
        lim = limits(self, None, job=job)
        job.acceleration, job.deceleration, job.jerk = lim.acceleration, lim.deceleration, lim.jerk
        self._note_limits(lim)

    def _activate_gear_in(self: "Axis", c: Coupling, t: float) -> None:
        x, xv, xa = self._lv_now(c.source, c.mode, t)
        p, v, a = self._take_over(t)
        c.offset = p - c.ratio * x
        ev, ea = v - c.ratio * xv, a - c.ratio * xa
        job = c.job
        target = c.ratio * xv
        speeding_up = abs(target) > abs(v)
        up, down = job.acceleration, job.deceleration
        lim_up = up if speeding_up else down
        lim_other = down if speeding_up else up
        if ev <= 0.0:          # the offset velocity must rise
            amax, amin = lim_up, -lim_other
        else:
            amax, amin = lim_other, -lim_up
        try:
            rel = self.motion.planner.free(t, 0.0, ev, ea, target_p=None, vmin=-INF, vmax=INF, amin=amin,
                                           amax=amax, jerk=job.jerk if job.jerk is not None else INF)
        except PlanningError as exc:
            self.raise_alarm(F.alarm(F.INTERNAL, "planning", Reaction.EMERGENCY, str(exc)), job=job)
            return
        self._couple(c, t, rel)

    # --- MC_GearInPos / MC_CamIn: synchronous positions -------------------------------------------------
    def _prepare_positioned(self: "Axis", c: Coupling, t: float) -> None:
        job = c.job
        x = job.extra
        spr = x["spr"]
        lv, lvv, _ = self._lv_now(c.source, c.mode, t)
        modulo = c.source.lv_modulo()
        c.direction = d = self._travel_direction(job, lv, lvv, modulo)
        if job.kind == JobKind.GEAR_IN_POS:
            c.law = GEAR
            c.ratio = x["ratio"]
            sync = x["master_sync"]
        else:
            c.law = CAM
            cam = x["cam"]
            c.cam = cam
            c.curve = cam.curve
            c.master_scaling = x["master_scaling"]
            c.slave_scaling = x["slave_scaling"]
            c.master_offset = x["master_offset"]
            c.slave_offset = x["slave_offset"]
            c.app_mode = x["app_mode"]
            c.joins_cycles = c.app_mode == APPENDING or (c.app_mode != ONCE and self._stroke_in_revolutions(c))
            sync = c.curve.start * c.master_scaling + c.master_offset + x["master_sync"]
        length = x["start_distance"]
        if spr == 2:                                  # CamIn: direct synchronous setting
            self._override(O.SYNC_ACTIVE, t, job)
            self._activate_direct(c, t)
            return
        if spr == 4:                                  # CamIn: subsequent from the current leading value
            if c.app_mode == ONCE:
                # §5.4.3: a cam run once must define the leading values of the synchronization
                u0 = (lv - c.master_offset) / c.master_scaling
                u1 = (lv + d * length - c.master_offset) / c.master_scaling
                tol = 1e-9 * max(1.0, abs(c.curve.length))
                if not all(c.curve.start - tol <= u <= c.curve.end + tol for u in (u0, u1)):
                    job.finish(JobState.ERROR, F.reject(
                        F.SYNC_POSITION_RANGE, "", f"leading value {lv!r} (+ MasterStartDistance) outside the cam"))
                    return
            self._override(O.SYNC_ACTIVE, t, job)
            self._activate_blend(c, t, lv + d * length, sync_offset_ref=None)
            return
        x["sync_raw"] = sync
        c.extra["base_master_offset"] = c.master_offset
        c.extra["direction_guessed"] = abs(lvv) <= 1e-9 and modulo is not None
        if not self._place(c, lv, d):
            job.finish(JobState.ERROR, F.reject(F.START_DISTANCE))
            return
        c.waiting = True
        c.poll = spr == 0 or c.extra["direction_guessed"] or (
            c.mode in SETPOINTS and not c.source.lv_position_controlled())
        if spr == 0:
            c.extra["armed"] = False
        self._set_waiting(c, t)

    def _place(self: "Axis", c: Coupling, lv: float, d: float) -> bool:
        """Unwrapped start and synchronous positions ahead of the leading value in direction ``d``."""
        x = c.job.extra
        spr = x["spr"]
        length = x["start_distance"]
        sync = x["sync_raw"]
        c.direction = d
        if c.law == CAM:
            c.master_offset = c.extra["base_master_offset"]
        start = sync - d * length if spr == 1 else sync
        modulo = c.source.lv_modulo()
        if modulo is not None:
            m_len = modulo[1]
            k = math.ceil(((lv - start) * d) / m_len - 1e-12) if (start - lv) * d < 0 else 0
            shift = d * k * m_len
            sync += shift
            start += shift
            if c.law == CAM:
                c.master_offset += shift
        elif spr == 1 and (sync - lv) * d < length * (1 - 1e-12):
            return False
        x["sync_u"] = sync
        x["start_u"] = start
        if c.law == GEAR:
            c.offset = x["slave_sync"] - c.ratio * sync
        c.trigger = start
        # the start must be crossed (or reached) in direction d; a leading value already past it waits
        c.extra["wprev"] = (lv - start) * d if (lv - start) * d <= 0 else math.nan
        return True

    def _travel_direction(self: "Axis", job: Job, lv: float, lvv: float, modulo) -> float:
        """Direction in which the leading value is expected to travel (catalog §11.2 item 3).

        The direction of a moving leading axis; at standstill the direction towards the synchronous
        position (positive on a modulo axis, where every position lies ahead)."""
        if abs(lvv) > 1e-9:
            return 1.0 if lvv > 0 else -1.0
        x = job.extra
        if job.kind == JobKind.GEAR_IN_POS and modulo is None and x["spr"] in (0, 1, 3):
            gap = x["master_sync"] - lv
            if abs(gap) > 1e-12:
                return 1.0 if gap > 0 else -1.0
        return 1.0

    def _set_waiting(self: "Axis", c: Coupling, t: float) -> None:
        """A new waiting job replaces a waiting one (§9.3.2); the active synchronous operation goes on."""
        old = self.waiting
        if old is not None:
            self._finish_coupling_job(old, JobState.ABORTED, t)
            self.ctl.sync.remove(old)
        if c.job.kind != JobKind.GEAR_IN:
            for name in ("cam",):
                cam = c.job.extra.get(name)
                if cam is not None:
                    cam.acquire(c.job)
        self.waiting = c
        try:
            self.ctl.sync.add(c)
        except CouplingCycle:
            self.waiting = None
            c.job.finish(JobState.ERROR, F.reject(F.COUPLING_CYCLE))

    def _poll(self: "Axis", c: Coupling, t: float) -> None:
        """Waiting condition checked every cycle: a position-controlled leading axis; SPR 0 start time."""
        if c.mode in SETPOINTS and not c.source.lv_position_controlled():
            return
        if c.job.kind == JobKind.GEAR_IN:
            self.waiting = None
            c.waiting = c.poll = False
            self.ctl.sync.remove(c)
            self._activate_gear_in(c, t)
            return
        spr = c.job.extra["spr"]
        x, xv, xa = self._lv_now(c.source, c.mode, t)
        if c.extra.get("direction_guessed"):
            if abs(xv) <= 1e-9:
                return                          # direction still unknown: wait for the leading axis to move
            c.extra["direction_guessed"] = False
            d = 1.0 if xv > 0 else -1.0
            if d != c.direction:
                self._place(c, x, d)
                self.ctl.sync.changed()
        if spr != 0:
            c.poll = False                      # from now on the vectorised trigger watches the start
            self.ctl.sync.changed()
            return
        d = c.direction
        remaining = (c.job.extra["sync_u"] - x) * d
        if remaining < 0.0:
            self._sync_position_passed(c, t, x)
            return
        speed = xv * d
        if speed <= _EPS:
            c.extra["armed"] = remaining > 0.0
            return
        plan = self._plan_dynamic_sync(c, t, x, xv, xa, None)
        if plan is None:
            return
        need = plan.t_end - t
        margin = 2.0 * self.ctl.servo_cycle
        arrival = _arrival_time(remaining, speed, xa * d)
        if arrival > need + margin:
            c.extra["armed"] = True
            return
        if not c.extra.get("armed"):
            return                              # §5.4.1: the start position must be crossed first
        self._activate_dynamic(c, t, arrival)

    def _sync_position_passed(self: "Axis", c: Coupling, t: float, x: float) -> None:
        """SPR 0: the leading value passed the synchronous position before the synchronization could
        start (too close for the job's dynamics).  The job goes on waiting (§5.4.1: the start position
        must be crossed first): a modulo leading value meets the synchronous position again one
        revolution later, a linear one when it comes back."""
        c.extra["armed"] = False
        if c.source.lv_modulo() is not None:
            self._place(c, x, c.direction)
            self.ctl.sync.changed()

    @staticmethod
    def _sync_velocity(job: Job, law_velocity: float) -> float:
        """Velocity bound of a synchronization over time (decision 13): the job's Velocity, but never
        below the synchronous velocity the following axis must reach (§4.3: the limits may be exceeded
        by the leading axis's dynamics; a bound below it would make the synchronization impossible)."""
        v = abs(law_velocity)
        return job.velocity if v < job.velocity else 1.01 * v

    def _plan_dynamic_sync(self: "Axis", c: Coupling, t: float, x: float, xv: float, xa: float,
                           duration: float | None) -> Profile | None:
        """Offset to the synchronous operation function, planned with the job's dynamics (SPR 0)."""
        job = c.job
        p, v, a = self.total_state_at(t)
        y, yv, ya = self.ctl.sync.law_at(c, x, xv, xa)
        e0 = self._slave_correction(c, p - y, self.ctl.sync.law_at(c, job.extra["sync_u"], 0.0, 0.0)[0] - y)
        vmax = self._sync_velocity(job, yv)
        try:
            return self.motion.planner.free(t, e0, v - yv, a - ya, target_p=0.0, vmin=-vmax - yv, vmax=vmax - yv,
                                            amin=-job.deceleration, amax=job.acceleration,
                                            jerk=job.jerk if job.jerk is not None else INF, duration=duration)
        except PlanningError:
            return None

    def _activate_dynamic(self: "Axis", c: Coupling, t: float, duration: float) -> None:
        x, xv, xa = self._lv_now(c.source, c.mode, t)
        self._override(O.SYNC_ACTIVE, t, c.job)
        p, v, a = self._take_over(t)
        y, yv, ya = self.ctl.sync.law_at(c, x, xv, xa)
        delta = self.ctl.sync.law_at(c, c.job.extra["sync_u"], 0.0, 0.0)[0] - y
        e0 = self._slave_correction(c, p - y, delta, shift_law=True)
        job = c.job
        vmax = self._sync_velocity(job, yv)
        try:
            rel = self.motion.planner.free(t, e0, v - yv, a - ya, target_p=0.0, vmin=-vmax - yv, vmax=vmax - yv,
                                           amin=-job.deceleration, amax=job.acceleration,
                                           jerk=job.jerk if job.jerk is not None else INF, duration=duration)
        except PlanningError as exc:
            self.raise_alarm(F.alarm(F.INTERNAL, "planning", Reaction.EMERGENCY, str(exc)), job=job)
            return
        self._leave_waiting(c)
        c.extra["sync_x"] = c.job.extra["sync_u"]
        self._couple(c, t, rel)

    def _activate_direct(self: "Axis", c: Coupling, t: float) -> None:
        """CamIn SyncProfileReference 2: InSync at once at the present positions (§5.4.4)."""
        x, xv, xa = self._lv_now(c.source, c.mode, t)
        job = c.job
        p, v, a = self._take_over(t)
        curve = c.curve
        u_sync = curve.start + job.extra["master_sync"] / c.master_scaling
        c.master_offset = x - curve.start * c.master_scaling - job.extra["master_sync"]
        c.slave_offset = p - float(curve.value(u_sync)) * c.slave_scaling
        if c.app_mode != ONCE:
            c.master_offset = x - u_sync * c.master_scaling
        rel = Planner.hold(t, 0.0)
        job.in_sync = True
        c.extra["inside"] = self._cam_inside(c, x)
        c.extra["sync_x"] = x
        self._couple(c, t, rel)

    def _activate_blend(self: "Axis", c: Coupling, t: float, x_end: float, sync_offset_ref) -> None:
        """Synchronize over the leading value distance up to ``x_end`` (SPR 1, 3, 4)."""
        x, xv, xa = self._lv_now(c.source, c.mode, t)
        p, v, a = self._take_over(t)
        law = self.ctl.sync.law_at
        y, dy, ddy = law(c, x, 1.0, 0.0)                       # law and its derivatives in x
        law_delta = law(c, x_end, 0.0, 0.0)[0] - y
        length = x_end - x
        if length * c.direction <= 1e-12 * max(1.0, abs(x_end)):
            # no leading value distance left (MasterStartDistance 0, or the synchronous position passed
            # in the servo cycle that started the synchronization): synchronous at once (decision 19)
            self._synchronous_at_once(c, t, x, p - y, x_end)
            return
        if abs(xv) > 1e-9:
            sx = v / xv
            sxx = (a - sx * xa) / (xv * xv)
        else:
            sx, sxx = dy, ddy
        d0, dd0 = (sx - dy) * length, (sxx - ddy) * length * length
        chosen = None
        one_way = c.job.extra.get("sync_direction", 3) in (1, 2)   # 3: direction changes allowed
        for k in self._revolutions(c, p - y, law_delta):
            coef = quintic(p - y - k * self._modulo_length(), d0, dd0)
            if chosen is None:
                chosen = (k, coef)
            if not one_way or self._monotonic(c, coef, x, length, law_delta):
                chosen = (k, coef)
                break
        assert chosen is not None
        k, c.blend = chosen
        self._shift_law(c, k)
        c.blend_x0 = x
        c.blend_len = length
        c.extra["sync_x"] = x_end
        if c.law == CAM:
            c.extra["inside"] = self._cam_inside(c, x)
        self._couple(c, t, Planner.hold(t, 0.0))

    def _synchronous_at_once(self: "Axis", c: Coupling, t: float, x: float, e0: float, x_end: float) -> None:
        """Synchronous in this servo cycle at the leading value ``x``: the following axis takes the
        synchronous operation function (of the nearest revolution in SyncDirection) at once."""
        k = self._revolutions(c, e0, 0.0)[0]
        self._shift_law(c, k)
        c.blend = None
        c.job.in_sync = True
        c.extra["sync_x"] = x_end
        if c.law == CAM:
            c.extra["inside"] = self._cam_inside(c, x)
        self._couple(c, t, Planner.hold(t, 0.0))
        self._end_if_cam_over(c, t)

    def _end_if_cam_over(self: "Axis", c: Coupling, t: float) -> None:
        """A cam run once whose end the leading value has reached or passed by the time the following
        axis is synchronous (the synchronization ended at or beyond the cam end): the camming is over at
        once - EndOfProfile, Busy and InSync FALSE (§9.1.5.1) - not Busy for ever on a cam end already
        left behind."""
        if c.law != CAM or c.app_mode != ONCE or c is not self.coupling or not c.job.in_sync:
            return
        x, xv, _ = self._lv_now(c.source, c.mode, t)
        u, uv = (x - c.master_offset) / c.master_scaling, xv / c.master_scaling
        curve = c.curve
        if (uv > 0.0 and u >= curve.end) or (uv < 0.0 and u <= curve.start):
            self._cam_end(c, t)

    def _cam_inside(self: "Axis", c: Coupling, x: float) -> bool:
        u = (x - c.master_offset) / c.master_scaling
        return bool(c.curve.start <= u <= c.curve.end)

    def _trigger(self: "Axis", c: Coupling, t: float) -> None:
        """The leading value crossed the start position of a waiting GearInPos/CamIn (SPR 1, 3)."""
        if c is not self.waiting:
            return
        if c.mode in SETPOINTS and not c.source.lv_position_controlled():
            c.poll = True                       # §3.3.5: wait for a position-controlled leading axis
            self.ctl.sync.changed()
            return
        job = c.job
        spr = job.extra["spr"]
        d = c.direction
        self._override(O.SYNC_ACTIVE, t, job)
        self._leave_waiting(c)
        end = job.extra["sync_u"] if spr == 1 else job.extra["sync_u"] + d * job.extra["start_distance"]
        self._activate_blend(c, t, end, None)

    def _leave_waiting(self: "Axis", c: Coupling) -> None:
        if self.waiting is c:
            self.waiting = None
        c.waiting = c.poll = False

    # --- coupling in force -------------------------------------------------------------------------------
    def _couple(self: "Axis", c: Coupling, t: float, relative: Profile) -> None:
        """Make ``c`` the active synchronous operation: the own profile becomes the offset ``relative``."""
        old = self.coupling
        if old is not None and old is not c:
            self._end_coupling(old, JobState.ABORTED, t, replan=False)
        lv = self._lv_now(c.source, c.mode, t)
        c.lv = lv                    # what an invalid leading value is replaced with (carried forward)
        if c.law == CAM and c.cam is not None:
            c.cam.acquire(c.job)
            if c.app_mode != ONCE:
                u = (lv[0] - c.master_offset) / c.master_scaling
                r = (u - c.curve.start) / c.curve.length
                # a cycle count beyond exact integers (e.g. MasterScaling 1e-300) is not countable: the
                # sync stage reports it as an invalid leading value and ends the job
                c.cam_cycle = math.floor(r) if abs(r) < _CYCLE_LIMIT else 0
        self.coupling = c
        self._watch_sw_limits()
        c.waiting = c.poll = False
        c.job.start_sync = True
        self._set_position_control(True)
        self.holding_zero_velocity = False
        if c not in self.ctl.sync.couplings:
            self.ctl.sync.add(c)
        else:
            self.ctl.sync.changed()
        self._interpolating = False
        self._start_profile(relative)

    def _take_over(self: "Axis", t: float) -> tuple[float, float, float]:
        """The total setpoint now; the superimposed part is handed over (it is aborted, §9.3.1)."""
        p, v, a = self.total_state_at(t)
        self._sup_clear()
        return p, v, a

    def _on_sync_profile_end(self: "Axis", t: float) -> None:
        """The time-based synchronization offset has reached its end: synchronous (GearIn, SPR 0)."""
        c = self.coupling
        if c is None or c.job.in_sync or c.blend is not None:
            return
        e_end = self.profile.final.p
        if c.law == GEAR:
            c.offset += e_end
        else:
            c.slave_offset += e_end
        c.job.in_sync = True
        self.ctl.sync.changed()
        self._start_profile(Planner.hold(t, 0.0))
        self._end_if_cam_over(c, t)

    def _sync_event(self: "Axis", kind: str, c: Coupling, arg: Any, t: float) -> None:
        """Events of the sync stage (called inside the servo cycle)."""
        if kind == "lv_invalid":
            if c is self.coupling or c is self.waiting:
                self._sync_failure(c, LeadingValueInvalid(
                    f"leading value of {getattr(c.source, 'name', c.source)} is not a valid number"))
        elif kind == "trigger":
            self._trigger(c, t)
        elif kind == "poll":
            if c is self.waiting:
                self._poll(c, t)
        elif kind == "blend_end":
            if c is self.coupling and c.blend is not None:
                c.blend = None
                c.job.in_sync = True
                self.ctl.sync.changed()
                self._end_if_cam_over(c, t)
        elif kind == "cam_wrap":
            if c is self.coupling:
                # EndOfProfile reports a cam end passed in synchronous operation: the cycle boundary
                # that a synchronization crosses (e.g. at MasterSyncPosition 0) is not one (§9.1.5)
                if c.job.in_sync and self._cam_end_passed(c, arg):
                    c.job.end_of_profile += 1
                c.cam_cycle = arg
        elif kind == "cam_end":
            if c is self.coupling and c.job.in_sync:
                self._cam_end(c, t)

    # --- SW limit switches in synchronous operation (§4.4.1, §6.1.5.4) ------------------------------------
    def _watch_sw_limits(self: "Axis") -> None:
        """Have the sync stage watch the SW limit switches while the axis moves with a coupling."""
        c = self.coupling
        watch = self.ctl.sync.sw_limits
        if c is not None and not c.simulated and self.sw_limits_effective():
            cfg = self.config
            watch.set(self, cfg.software_limits.minimum, cfg.software_limits.maximum,
                      cfg.limits.max_deceleration, cfg.limits.max_jerk or INF)
        else:
            watch.clear(self)

    def _replan(self: "Axis") -> None:
        self._watch_sw_limits()              # limits, their activation or the homed state may have changed
        super()._replan()                    # type: ignore[misc]

    def _sw_limit_in_reach(self: "Axis", side: str, t: float) -> None:
        """The coupled axis would pass a SW limit switch: the synchronous operation ends with the alarm
        and the axis stops at the switch position with its configured dynamic limits (§4.4.1)."""
        c = self.coupling
        if c is None or c.simulated:
            self._watch_sw_limits()
            return
        sw = self.config.software_limits
        limit = sw.maximum if side == "max" else sw.minimum
        fault = F.alarm(F.SW_LIMIT_MAX if side == "max" else F.SW_LIMIT_MIN, "reached")
        if self.sup_job is not None and self.sup_job.busy:
            self._finish_job(self.sup_job, JobState.ERROR, t, fault)
        p, v, a = self._take_over(t)
        self._end_coupling(c, JobState.ERROR, t, replan=False, fault=fault)
        self._start_profile(self._stop_at(t, p, v, a, limit))
        self.raise_alarm(fault)

    def _stop_at(self: "Axis", t: float, p: float, v: float, a: float, limit: float) -> Profile:
        """Braking to a standstill at ``limit`` without reversing; harder than the limits only where the
        remaining distance needs it, and without a jerk limit before overshooting."""
        dl = self.config.limits
        dec = dl.max_deceleration
        jerk = dl.max_jerk or INF
        dist = limit - p
        lo, hi = min(v, 0.0), max(v, 0.0)
        planner = self.motion.planner
        if dist * v > 0.0:
            need = v * v / (2.0 * abs(dist))
            for amax, j in ((max(dec, need), jerk), (max(dec, need) * (1 + 1e-6), INF)):
                try:
                    return planner.free(t, p, v, a, target_p=limit, vmin=lo, vmax=hi, amin=-amax, amax=amax,
                                        jerk=j)
                except PlanningError:
                    continue
        return planner.free(t, p, v, a, target_p=None, vmin=lo, vmax=hi, amin=-dec, amax=dec, jerk=INF)

    def _cam_end_passed(self: "Axis", c: Coupling, cycle: int) -> bool:
        """Is the cycle boundary just crossed (from ``c.cam_cycle`` to ``cycle``) the end of a cam cycle
        the following axis has run in synchronism, i.e. does it lie beyond the synchronous position?"""
        step = cycle - c.cam_cycle
        if not step:
            return False
        u = c.curve.start + max(cycle, c.cam_cycle) * c.curve.length
        x_b = c.master_offset + u * c.master_scaling
        sync_x = c.extra.get("sync_x")
        return sync_x is None or (x_b - sync_x) * step > 1e-9 * max(1.0, abs(c.curve.length * c.master_scaling))

    def _cam_end(self: "Axis", c: Coupling, t: float) -> None:
        """Non-cyclic camming ends at the cam's end point (§5.3): EndOfProfile, Busy and InSync FALSE."""
        c.job.end_of_profile += 1
        p, v, a = self._coupled_state_at(t)
        sp, _, _ = self.sup_state_at(t)
        job = c.job
        self._end_coupling(c, JobState.DONE, t, replan=False)
        self._start_profile(Planner.hold(t, p - sp))
        job.in_sync = False

    def _end_coupling(self: "Axis", c: Coupling, state: JobState, t: float, *, replan: bool = True,
                      fault: Fault | None = None) -> None:
        """The active synchronous operation ends (overridden, stopped, disabled, cam end)."""
        if self.coupling is not c:
            return
        if replan:
            p, v, a = self._coupled_state_at(t) if c.applied else self.total_state_at(t)
            sp, sv, sa = self.sup_state_at(t)
            self._decoupled_state = (p - sp, v - sv, a - sa)
        self.coupling = None
        self._watch_sw_limits()
        self.ctl.sync.remove(c)
        if self.phasing_job is not None and self.phasing_job.busy:
            self._finish_job(self.phasing_job, JobState.ABORTED, t)
        self.phasing_job = None
        self._finish_coupling_job(c, state, t, fault)
        if replan:
            p, v, a = self._decoupled_state
            self._decoupled_state = None
            # the motion goes on from where the synchronous operation left it (braked by the caller)
            self._start_profile(Planner.cruise(t, p, v) if abs(a) < 1e-12 else
                                _constant_accel(t, p, v, a))

    def _finish_coupling_job(self: "Axis", c: Coupling, state: JobState, t: float,
                             fault: Fault | None = None) -> None:
        job = c.job
        if c.cam is not None:
            c.cam.release(job)
        else:
            cam = job.extra.get("cam")
            if cam is not None:
                cam.release(job)
        if job.busy:
            self._finish_job(job, state, t, fault)
        if state != JobState.DONE:
            job.in_sync = False

    def _abort_sync(self: "Axis", t: float, *, waiting: bool = True, active: bool = True,
                    fault: Fault | None = None) -> None:
        state = JobState.ERROR if fault is not None else JobState.ABORTED
        if waiting and self.waiting is not None:
            w = self.waiting
            self.waiting = None
            self.ctl.sync.remove(w)
            self._finish_coupling_job(w, state, t, fault)
        if active and self.coupling is not None:
            self._end_coupling(self.coupling, state, t, replan=True, fault=fault)


def _arrival_time(remaining: float, speed: float, acc: float) -> float:
    """Time the leading value needs for ``remaining`` at its present velocity and acceleration (§4.3.2:
    synchronous when the leading axis reaches the synchronous position, also while it accelerates);
    a leading value that would stop short is taken at its present velocity."""
    if remaining <= 0.0:
        return 0.0
    if abs(acc) > 1e-12:
        disc = speed * speed + 2.0 * acc * remaining
        if disc >= 0.0:
            return 2.0 * remaining / (speed + math.sqrt(disc))   # the root without cancellation
    return remaining / speed


def _constant_accel(t: float, p: float, v: float, a: float) -> Profile:
    from .profiles import Segment

    return Profile([Segment(t, p, v, a, 0.0)], t)


__all__ = ["SynchronousMixin", "COUPLING_TYPES", "APPENDING", "np"]
