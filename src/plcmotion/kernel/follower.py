"""The following-axis ability of an axis: synchronous operation jobs (S7-1500T V5 §3 - §5, §9.1, §9.3.2).

A following axis has at most one active synchronous operation (GearIn, GearInPos or CamIn, or one that
is simulated) and at most one waiting job (GearInPos/CamIn before its start condition).  The active one
is a :class:`~plcmotion.kernel.sync.Coupling` that the controller's sync stage evaluates for all
following axes together every servo cycle; the :class:`Follower` component of an axis owns the jobs and
their couplings and runs the event code: admission, coupling in force, the end of a synchronous
operation, and what other jobs of the axis do to it.  How a job synchronizes is in ``sync_planning``,
what modifies a running one (phasing, additive leading value, simulation) in ``sync_modifiers``.
"""
from __future__ import annotations

import math
from typing import Any, Iterator, Protocol

from . import faults as F
from . import policy as O
from . import sync_modifiers as modifiers
from . import sync_planning as planning
from .family import ACTUAL_VALUE_COUPLING
from .faults import Fault, Reaction
from .jobs import Job, JobKind, JobState
from .policy import Activity
from .leading import setpoint_at
from .profiles import INF, Planner, PlanningError, Profile, Segment
from .sync import _CYCLE_LIMIT, CAM, GEAR, LV_LIMIT, ONCE, Coupling

COUPLING_TYPES = ("setpoint", "actual", "delayed")


class LeadingValueInvalid(ValueError):
    """The leading value of a coupling is not a number (or absurdly large): its job cannot go on."""


class FollowerHost(Protocol):
    """What the follower component uses of its axis (kernel ``PositioningAxis`` and the family's axis)."""

    name: str
    index: int
    ctl: Any                   # mode, sync (the SyncStage), offers_job, features, servo_cycle, _lookup
    config: Any                # AxisConfig: modulo, limits, software_limits, leading_value_output
    motion: Any                # MotionPlanner (its ``planner`` plans offsets and stops)
    profile: Profile
    state: str
    job: Job | None
    stop_job: Job | None
    sup_job: Job | None
    holding_zero_velocity: bool
    last_internal_error: str | None
    _interpolating: bool
    _timers: dict[str, float]

    @property
    def now(self) -> float: ...
    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None: ...
    def _blocking_alarm(self) -> Fault | None: ...
    def _finish_job(self, job: Job, state: JobState, t: float, fault: Fault | None = None) -> None: ...
    def _start_profile(self, profile: Profile) -> None: ...
    def _state_at(self, t: float) -> tuple[float, float, float]: ...
    def _set_position_control(self, on: bool) -> None: ...
    def _schedule(self) -> None: ...
    def _override(self, new: str, t: float, new_job: Job | None) -> None: ...
    def _note_limits(self, lim: Any, job: Job | None = None) -> None: ...
    def sw_limits_effective(self) -> bool: ...
    def sup_state_at(self, t: float) -> tuple[float, float, float]: ...
    def _sup_clear(self) -> None: ...


class Follower:
    """Following axis: couples its host axis to a leading value (§3.1).  ``leading_values``: the possible
    leading values, names or ``(name, "setpoint" | "actual" | "delayed")`` pairs (§6.1.3)."""

    def __init__(self, host: FollowerHost, leading_values: Any = (), name: str = "") -> None:
        self.host = host
        self.coupling: Coupling | None = None          # the active synchronous operation
        self.waiting: Coupling | None = None           # GearInPos/CamIn waiting for its start condition
        self.phasing_job: Job | None = None
        self.lv_additive: tuple[float, float, float] | None = None
        self.lv_additive_job: Job | None = None
        self.sim_job: Job | None = None
        self._leading_values: dict[str, str] = {}
        for item in leading_values or ():
            source, mode = (item, "setpoint") if isinstance(item, str) else tuple(item)
            if mode not in COUPLING_TYPES:
                raise ValueError(f"{name}: leading value {source!r}: type of coupling {mode!r} is not one of "
                                 f"{', '.join(COUPLING_TYPES)}")
            self._leading_values[str(source)] = mode

    # --- status -----------------------------------------------------------------------------------------
    @property
    def possible_leading_values(self) -> dict[str, str]:
        """Configured leading value interconnections: source name -> type of coupling (§6.1.3)."""
        return dict(self._leading_values)

    @property
    def sync_job(self) -> Job | None:
        c = self.coupling
        return c.job if c is not None else None

    @property
    def synchronizing(self) -> bool:
        c = self.coupling
        return c is not None and not c.simulated and not c.job.in_sync

    @property
    def synchronous(self) -> bool:
        c = self.coupling
        return c is not None and c.job.in_sync

    def function_state(self) -> int:
        c = self.coupling
        if c is None:
            return 0
        return {JobKind.GEAR_IN: 1, JobKind.GEAR_IN_POS: 2, JobKind.CAM_IN: 3}[c.job.kind]

    def waiting_function_state(self) -> int:
        w = self.waiting
        if w is None or w.job.kind == JobKind.GEAR_IN:
            return 0
        return 2 if w.job.kind == JobKind.GEAR_IN_POS else 3

    def phase_shift(self, t: float | None = None) -> float:
        c = self.coupling
        if c is None or c.phase is None:
            return 0.0
        return c.phase.at(self.host.now if t is None else t)[0]

    def effective_leading_value(self) -> tuple[float, float, float]:
        c = self.coupling or self.waiting
        if c is None:
            return 0.0, 0.0, 0.0
        return self.host.ctl.sync.effective_lv(c)

    def modulo_length(self) -> float:
        m = self.host.config.modulo
        return m.length if m.enabled else 0.0

    # --- leading value ----------------------------------------------------------------------------------
    def _resolve_master(self, master: Any) -> tuple[Any, str] | Fault:
        axis = self.host
        name = getattr(master, "name", None)
        mode = self._leading_values.get(name) if name is not None else None
        if mode is None or axis.ctl._lookup(name) is not master:
            axis.raise_alarm(F.alarm(F.SYNC_MASTER, str(name), Reaction.NONE,
                                     f"{name} is not configured as a possible leading value of {axis.name}"))
            return F.reject(F.SYNC_MASTER, str(name))
        if master is axis:
            return F.reject(F.COUPLING_CYCLE, "self")
        if mode == "actual" and not getattr(master, "provides_actual_values", False):
            return F.reject(F.LV_NOT_READY, "no_actual_values")
        if mode == "setpoint" and not getattr(master, "provides_setpoints", False):
            return F.reject(F.LV_NOT_READY, "no_setpoints")
        if mode == "delayed" and not getattr(master, "provides_delayed_values", False):
            return F.reject(F.LV_NOT_READY, "no_delayed_values")      # §3.3.3: not a proxy
        if mode != "setpoint" and ACTUAL_VALUE_COUPLING not in axis.ctl.features:
            return F.reject(F.NOT_AVAILABLE, "actual_value_coupling")
        if mode == "setpoint" and getattr(master, "cascade_delay", 0.0) and axis.config.leading_value_output.enabled:
            # §8.1.3 cascade: an axis that provides its value to other controllers (§6.1.4) runs ahead
            # by the proxy's Parameter.LocalLeadingValueDelayTime, the delay it sends with (decisions #31)
            mode = "cascade"
        return master, mode

    def lv_now(self, source: Any, mode: str, t: float) -> tuple[float, float, float]:
        """Effective leading value (source value plus additive value) at time ``t``."""
        p, v, a = source.lv_value(mode, t)
        add = self.lv_additive
        if add is not None:
            p, v, a = p + add[0], v + add[1], a + add[2]
        if not abs(p) + abs(v) + abs(a) <= LV_LIMIT:
            raise LeadingValueInvalid(f"leading value of {getattr(source, 'name', source)} is ({p!r}, {v!r}, {a!r})")
        return p, v, a

    # --- the setpoint of the following axis ------------------------------------------------------------
    def coupled_state_at(self, t: float) -> tuple[float, float, float]:
        """Setpoint of a coupled axis at ``t``: the last servo cycle's values carried forward."""
        return setpoint_at(self.host, t)

    def total_state_at(self, t: float) -> tuple[float, float, float]:
        """Total setpoint (basic motion, synchronous operation and superimposed motion)."""
        axis = self.host
        if self.coupling is not None and self.coupling.applied:
            return self.coupled_state_at(t)
        p, v, a = axis._state_at(t)
        sp, sv, sa = axis.sup_state_at(t)
        return p + sp, v + sv, a + sa

    def take_over(self, t: float) -> tuple[float, float, float]:
        """The total setpoint now; the superimposed part is handed over (it is aborted, §9.3.1)."""
        p, v, a = self.total_state_at(t)
        self.host._sup_clear()
        return p, v, a

    # --- job entry ---------------------------------------------------------------------------------------
    def submit(self, job: Job) -> None:
        """Start MC_GearIn, MC_GearInPos, MC_CamIn or a phasing job.  Whatever goes wrong inside ends
        the job with an error (never an exception out of the instruction, never Busy forever)."""
        try:
            self._submit(job)
        except Exception as exc:
            c = next((c for c in (self.waiting, self.coupling) if c is not None and c.job is job), None)
            self.failure(c if c is not None else Coupling(self.host, None, job), exc)

    def failure(self, c: Coupling, exc: Exception) -> None:
        """A synchronous job failed in the kernel: it ends with Error - 16#8FFF for an internal error,
        the alarm of an invalid leading value otherwise - and the axis gets the technology alarm."""
        axis = self.host
        t = axis.now
        job = c.job
        if isinstance(exc, LeadingValueInvalid):
            alarm = F.alarm(F.LV_INVALID, str(getattr(c.source, "name", "")), Reaction.STOP, str(exc))
            own = alarm
        else:
            import traceback

            axis.last_internal_error = "".join(traceback.format_exception(exc))
            alarm = F.alarm(F.INTERNAL, "", Reaction.REMOVE_ENABLE, f"{type(exc).__name__}: {exc}")
            own = F.reject(F.INTERNAL, "", f"{type(exc).__name__}: {exc}")
        try:
            if c is self.coupling:
                self.end_coupling(c, JobState.ERROR, t, replan=True, fault=own)
            else:
                if c is self.waiting:
                    self.waiting = None
                axis.ctl.sync.remove(c)
                self.finish_coupling_job(c, JobState.ERROR, t, own)
        finally:
            job.finish(JobState.ERROR, own)          # whatever happened above, the job has ended
            axis.raise_alarm(alarm)

    def _submit(self, job: Job) -> None:
        axis = self.host
        t = axis.now
        if not axis.ctl.offers_job(job.kind):
            job.finish(JobState.ERROR, F.reject(F.NOT_AVAILABLE, job.kind.value))
            return
        fault = self._check(job)
        if fault is not None:
            job.finish(JobState.ERROR, fault)
            return
        if job.kind == JobKind.PHASING:
            modifiers.start_phasing(self, job, t)
            return
        resolved = self._resolve_master(job.extra["master"])
        if isinstance(resolved, Fault):
            job.finish(JobState.ERROR, resolved)
            return
        source, mode = resolved
        invalid = source.leading_value_invalid(mode)
        if invalid is not None:
            # the same as a leading value that becomes invalid while coupled: alarm, job ends with Error
            self.failure(Coupling(axis, source, job, mode), LeadingValueInvalid(invalid))
            return
        if axis.ctl.sync.would_cycle(axis, source, mode):
            job.finish(JobState.ERROR, F.reject(F.COUPLING_CYCLE))
            return
        if job.kind == JobKind.CAM_IN:
            fault = _check_cam(job)
            if fault is not None:
                job.finish(JobState.ERROR, fault)
                return
        c = Coupling(axis, source, job, mode)
        if mode != "setpoint" or getattr(source, "index", None) is None:
            c.extra["ext_slot"] = source.lv_slot(mode)
        if job.kind == JobKind.GEAR_IN:
            planning.start_gear_in(self, c, t)
        else:
            planning.prepare_positioned(self, c, t)

    def _check(self, job: Job) -> Fault | None:
        axis = self.host
        if axis.ctl.mode != "RUN":
            return F.reject(F.REJECTED, "starting_up")
        if axis.state != "enabled":
            return F.reject(F.NOT_ENABLED)
        fault = axis._blocking_alarm()
        if fault is not None:
            return fault
        if axis.stop_job is not None:
            return F.reject(F.STOP_ACTIVE)
        if self.sim_job is not None and self.sim_job.busy:
            return F.reject(F.SYNC_SIMULATION)
        if job.kind == JobKind.PHASING:
            c = self.coupling
            # the detail says what is missing, so a family can name the case
            if c is None:
                return F.reject(F.NOT_SYNCHRONOUS, "none")
            if c.simulated:
                return F.reject(F.NOT_SYNCHRONOUS, "simulated")
            if c.job.kind == JobKind.CAM_IN:
                return F.reject(F.NOT_SYNCHRONOUS, "camming")
            if not c.job.in_sync:
                return F.reject(F.NOT_SYNCHRONOUS, "not_in_sync")
            if job.extra.get("master") is not c.source:
                return F.reject(F.NOT_SYNCHRONOUS, "master")
        return None

    # --- modifiers of the running synchronous operation (sync_modifiers) ---------------------------------
    def covered_phase_shift(self, job: Job) -> float:
        return modifiers.covered_phase_shift(self, job)

    def set_lv_additive(self, job: Job, p: float, v: float, a: float) -> Fault | None:
        return modifiers.set_lv_additive(self, job, p, v, a)

    def end_lv_additive(self, job: Job) -> None:
        modifiers.end_lv_additive(self, job)

    def start_simulation(self, job: Job) -> Fault | None:
        return modifiers.start_simulation(self, job)

    def end_simulation(self, job: Job) -> None:
        modifiers.end_simulation(self, job)

    # --- coupling in force -------------------------------------------------------------------------------
    def couple(self, c: Coupling, t: float, relative: Profile) -> None:
        """Make ``c`` the active synchronous operation: the own profile becomes the offset ``relative``."""
        axis = self.host
        sync = axis.ctl.sync
        old = self.coupling
        if old is not None and old is not c:
            self.end_coupling(old, JobState.ABORTED, t, replan=False)
        lv = self.lv_now(c.source, c.mode, t)
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
        self.watch_sw_limits()
        c.waiting = c.poll = False
        c.job.start_sync = True
        axis._set_position_control(True)
        axis.holding_zero_velocity = False
        if c not in sync.couplings:
            sync.add(c)
        else:
            sync.changed()
        axis._interpolating = False
        axis._start_profile(relative)

    def on_profile_end(self, t: float) -> None:
        """The time-based synchronization offset has reached its end: synchronous (GearIn, SPR 0)."""
        c = self.coupling
        if c is None or c.job.in_sync or c.blend is not None:
            return
        axis = self.host
        e_end = axis.profile.final.p
        if c.law == GEAR:
            c.offset += e_end
        else:
            c.slave_offset += e_end
        c.job.in_sync = True
        axis.ctl.sync.changed()
        axis._start_profile(Planner.hold(t, 0.0))
        self.end_if_cam_over(c, t)

    def on_phase_timer(self, t: float) -> None:
        """The phase shift's profile reached the end of a segment."""
        c = self.coupling
        if c is not None and c.phase is not None:
            modifiers.phase_segment(self, c, t)

    def sync_event(self, kind: str, c: Coupling, arg: Any, t: float) -> None:
        """Events of the sync stage (called inside the servo cycle)."""
        if kind == "lv_invalid":
            if c is self.coupling or c is self.waiting:
                self.failure(c, LeadingValueInvalid(
                    f"leading value of {getattr(c.source, 'name', c.source)} is not a valid number"))
        elif kind == "trigger":
            planning.trigger(self, c, t)
        elif kind == "poll":
            if c is self.waiting:
                planning.poll(self, c, t)
        elif kind == "blend_end":
            if c is self.coupling and c.blend is not None:
                c.blend = None
                c.job.in_sync = True
                self.host.ctl.sync.changed()
                self.end_if_cam_over(c, t)
        elif kind == "cam_wrap":
            if c is self.coupling:
                # EndOfProfile reports a cam end passed in synchronous operation: the cycle boundary
                # that a synchronization crosses (e.g. at MasterSyncPosition 0) is not one (§9.1.5)
                if c.job.in_sync and _cam_end_passed(c, arg):
                    c.job.end_of_profile += 1
                c.cam_cycle = arg
        elif kind == "cam_end":
            if c is self.coupling and c.job.in_sync:
                self._cam_end(c, t)

    def end_if_cam_over(self, c: Coupling, t: float) -> None:
        """A cam run once whose end the leading value has reached or passed by the time the following
        axis is synchronous (the synchronization ended at or beyond the cam end): the camming is over at
        once - EndOfProfile, Busy and InSync FALSE (§9.1.5.1) - not Busy for ever on a cam end already
        left behind."""
        if c.law != CAM or c.app_mode != ONCE or c is not self.coupling or not c.job.in_sync:
            return
        x, xv, _ = self.lv_now(c.source, c.mode, t)
        u, uv = (x - c.master_offset) / c.master_scaling, xv / c.master_scaling
        curve = c.curve
        if (uv > 0.0 and u >= curve.end) or (uv < 0.0 and u <= curve.start):
            self._cam_end(c, t)

    def _cam_end(self, c: Coupling, t: float) -> None:
        """Non-cyclic camming ends at the cam's end point (§5.3): EndOfProfile, Busy and InSync FALSE."""
        axis = self.host
        c.job.end_of_profile += 1
        p, v, a = self.coupled_state_at(t)
        sp, _, _ = axis.sup_state_at(t)
        job = c.job
        self.end_coupling(c, JobState.DONE, t, replan=False)
        axis._start_profile(Planner.hold(t, p - sp))
        job.in_sync = False

    # --- the end of a synchronous operation ----------------------------------------------------------
    def end_coupling(self, c: Coupling, state: JobState, t: float, *, replan: bool = True,
                     fault: Fault | None = None) -> None:
        """The active synchronous operation ends (overridden, stopped, disabled, cam end); with ``replan``
        the axis moves on from where the synchronous operation left it (braked by the caller)."""
        if self.coupling is not c:
            return
        axis = self.host
        decoupled = None
        if replan:
            p, v, a = self.coupled_state_at(t) if c.applied else self.total_state_at(t)
            sp, sv, sa = axis.sup_state_at(t)
            decoupled = (p - sp, v - sv, a - sa)
        self.coupling = None
        self.watch_sw_limits()
        axis.ctl.sync.remove(c)
        if self.phasing_job is not None and self.phasing_job.busy:
            axis._finish_job(self.phasing_job, JobState.ABORTED, t)
        self.phasing_job = None
        self.finish_coupling_job(c, state, t, fault)
        if decoupled is not None:
            p, v, a = decoupled
            axis._start_profile(Planner.cruise(t, p, v) if abs(a) < 1e-12 else
                                Profile([Segment(t, p, v, a, 0.0)], t))

    def finish_coupling_job(self, c: Coupling, state: JobState, t: float, fault: Fault | None = None) -> None:
        job = c.job
        if c.cam is not None:
            c.cam.release(job)
        else:
            cam = job.extra.get("cam")
            if cam is not None:
                cam.release(job)
        if job.busy:
            self.host._finish_job(job, state, t, fault)
        if state != JobState.DONE:
            job.in_sync = False

    def abort(self, t: float, *, waiting: bool = True, active: bool = True, fault: Fault | None = None,
              keep_simulated: bool = True) -> None:
        """End the waiting and/or the active job (ERROR with ``fault``, ABORTED otherwise).  With
        ``keep_simulated`` a simulated synchronous operation survives what is no alarm (§9.1.6)."""
        c = self.coupling
        if c is not None and c.simulated and keep_simulated and fault is None:
            active = False
        state = JobState.ERROR if fault is not None else JobState.ABORTED
        if waiting and self.waiting is not None:
            w = self.waiting
            self.waiting = None
            self.host.ctl.sync.remove(w)
            self.finish_coupling_job(w, state, t, fault)
        if active and self.coupling is not None:
            self.end_coupling(self.coupling, state, t, replan=True, fault=fault)

    # --- what other jobs and state changes of the axis do to it (§9.3.2) -----------------------------
    def activities(self) -> Iterator[Activity]:
        """The synchronous operation as a family's override policy sees it: the coupling, a waiting coupling,
        a phasing and an additive leading value, each with its policy class and how it ends aborted.  A
        simulated synchronous operation is no running job (S7-1500T V5 §9.1.6).  Lazy: each one is looked at
        after the one before has been ended."""
        c = self.coupling
        if c is not None and not c.simulated:
            column = O.GEAR_IN if c.job.kind == JobKind.GEAR_IN else O.SYNC_ACTIVE
            yield Activity(column, c.job, lambda t: self.end_coupling(c, JobState.ABORTED, t, replan=True))
        w = self.waiting
        if w is not None:
            column = O.GEAR_IN if w.job.kind == JobKind.GEAR_IN else O.SYNC_WAITING
            yield Activity(column, w.job, lambda t: self._end_waiting(w, t))
        ph = self.phasing_job
        if ph is not None and ph.busy:
            yield Activity(O.PHASING, ph, lambda t: self._end_phasing(ph, t))
        add = self.lv_additive_job
        if add is not None and add.busy:
            yield Activity(O.LV_ADDITIVE, add, lambda t: self._end_additive(add, t))

    def _end_waiting(self, w: Coupling, t: float) -> None:
        if self.waiting is w:
            self.waiting = None
        self.host.ctl.sync.remove(w)
        self.finish_coupling_job(w, JobState.ABORTED, t)

    def _end_phasing(self, ph: Job, t: float) -> None:
        self.host._finish_job(ph, JobState.ABORTED, t)
        modifiers.hold_phase(self, t)

    def _end_additive(self, add: Job, t: float) -> None:
        self.lv_additive_job = None
        self.lv_additive = None
        modifiers.push_additive(self)
        self.host._finish_job(add, JobState.ABORTED, t)

    def end_simulation_and_additive(self, t: float) -> None:
        """The technology object restarts: simulation and additive value end with the synchronous
        operation (they survive everything else, §9.1.6)."""
        axis = self.host
        if self.sim_job is not None:
            job = self.sim_job
            self.sim_job = None
            if job.busy:
                axis._finish_job(job, JobState.ABORTED, t)
        c = self.coupling
        if c is not None:
            c.simulated = False
            axis.ctl.sync.changed()
        add = self.lv_additive_job
        if add is not None:
            self.lv_additive_job = None
            self.lv_additive = None
            if add.busy:
                axis._finish_job(add, JobState.ABORTED, t)

    def on_enable_removed(self, t: float) -> None:
        """The enable is removed: an active (not simulated) synchronous operation ends, with the waiting job."""
        c = self.coupling
        if c is not None and not c.simulated:
            self.abort(t)

    # --- SW limit switches in synchronous operation (§4.4.1, §6.1.5.4) ------------------------------------
    def watch_sw_limits(self) -> None:
        """Have the sync stage watch the SW limit switches while the axis moves with a coupling."""
        axis = self.host
        c = self.coupling
        watch = axis.ctl.sync.sw_limits
        if c is not None and not c.simulated and axis.sw_limits_effective():
            cfg = axis.config
            watch.set(axis, cfg.software_limits.minimum, cfg.software_limits.maximum,
                      cfg.limits.max_deceleration, cfg.limits.max_jerk or INF)
        else:
            watch.clear(axis)

    def sw_limit_in_reach(self, side: str, t: float) -> None:
        """The coupled axis would pass a SW limit switch: the synchronous operation ends with the alarm
        and the axis stops at the switch position with its configured dynamic limits (§4.4.1)."""
        axis = self.host
        c = self.coupling
        if c is None or c.simulated:
            self.watch_sw_limits()
            return
        sw = axis.config.software_limits
        limit = sw.maximum if side == "max" else sw.minimum
        fault = F.alarm(F.SW_LIMIT_MAX if side == "max" else F.SW_LIMIT_MIN, "reached")
        if axis.sup_job is not None and axis.sup_job.busy:
            axis._finish_job(axis.sup_job, JobState.ERROR, t, fault)
        p, v, a = self.take_over(t)
        self.end_coupling(c, JobState.ERROR, t, replan=False, fault=fault)
        axis._start_profile(self._stop_at(t, p, v, a, limit))
        axis.raise_alarm(fault)

    def _stop_at(self, t: float, p: float, v: float, a: float, limit: float) -> Profile:
        """Braking to a standstill at ``limit`` without reversing; harder than the limits only where the
        remaining distance needs it, and without a jerk limit before overshooting."""
        dl = self.host.config.limits
        dec = dl.max_deceleration
        jerk = dl.max_jerk or INF
        dist = limit - p
        lo, hi = min(v, 0.0), max(v, 0.0)
        planner = self.host.motion.planner
        if dist * v > 0.0:
            need = v * v / (2.0 * abs(dist))
            for amax, j in ((max(dec, need), jerk), (max(dec, need) * (1 + 1e-6), INF)):
                try:
                    return planner.free(t, p, v, a, target_p=limit, vmin=lo, vmax=hi, amin=-amax, amax=amax,
                                        jerk=j)
                except PlanningError:
                    continue
        return planner.free(t, p, v, a, target_p=None, vmin=lo, vmax=hi, amin=-dec, amax=dec, jerk=INF)


def _check_cam(job: Job) -> Fault | None:
    cam = job.extra["cam"]
    if cam.curve is None:
        return F.reject(F.CAM_NOT_INTERPOLATED)
    x = job.extra
    span = cam.curve.length * x["master_scaling"]
    if x["spr"] in (0, 1, 2, 3) and not (-1e-9 * max(1.0, abs(span)) <= x["master_sync"] <= span * (1 + 1e-12)):
        return F.reject(F.SYNC_POSITION_RANGE, "", f"MasterSyncPosition {x['master_sync']!r} outside 0 .. {span!r}")
    return None


def _cam_end_passed(c: Coupling, cycle: int) -> bool:
    """Is the cycle boundary just crossed (from ``c.cam_cycle`` to ``cycle``) the end of a cam cycle
    the following axis has run in synchronism, i.e. does it lie beyond the synchronous position?"""
    step = cycle - c.cam_cycle
    if not step:
        return False
    u = c.curve.start + max(cycle, c.cam_cycle) * c.curve.length
    x_b = c.master_offset + u * c.master_scaling
    sync_x = c.extra.get("sync_x")
    return sync_x is None or (x_b - sync_x) * step > 1e-9 * max(1.0, abs(c.curve.length * c.master_scaling))
