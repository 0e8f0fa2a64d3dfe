"""S7-1500 positioning axis and synchronous axis technology objects (S7-1500T V5 §3.1, §6.1, §9.3, §A.1).

They share the kernel's motion with the S7-1200 axis and differ where the S7-1500 does: every job
brings its own dynamics (limited by ``DynamicLimits``), ``MC_Stop`` locks the axis while its Execute is
TRUE, a superimposed motion can run on top of any basic motion, jobs override each other by the tables
of §9.3, and the synchronous axis follows leading values (``kernel.sync_axis``).
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Iterator, Mapping

from ...kernel import faults as F
from . import override as O
from . import tags as T
from ...kernel.axis import DISABLED, ENABLED, ENABLING, PositioningAxis
from ...kernel.faults import Fault, Reaction
from ...kernel.jobs import Job, JobKind, JobState
from ...kernel.leading import LeadingValueMixin
from ...kernel.policy import Activity
from .parameters import S7_1500
from ...kernel.profiles import INF, Planner, Profile
from ...kernel.superimposed import SuperimposedMixin
from ...kernel.sync_axis import SynchronousMixin

if TYPE_CHECKING:  # pragma: no cover
    from ...kernel.runtime import Controller

_EPS_T = 1e-9
STOP_MODES = O.STOP_MODES


class PositioningAxis1500(SuperimposedMixin, LeadingValueMixin, PositioningAxis):
    """Positioning axis technology object of the S7-1500 (TO_PositioningAxis)."""

    schema = S7_1500
    _dynamic = T.DYNAMIC
    _dynamic_types = T.TYPES
    _dynamic_aliases: dict[str, str] = {}
    _status_groups = T.GROUPS
    _read_param_tags = frozenset(T.DYNAMIC)
    # defaults read before __init__ has set everything up
    _sup_carry = None
    coupling = None
    stop_job: Job | None = None
    command_not_accepted = False
    #: active homing of a virtual/simulated axis is a job like on a drive axis (§6.1.5.5, §9.3.1, §9.3.2)
    _sim_homing_at_once = False

    def __init__(self, ctl: "Controller", name: str, cfg: Mapping[str, Any], **kw: Any):
        self._sup_init()
        self.stop_job = None
        self.warnings: set[str] = set()          # dynamic values limited (alarms 501-504)
        self.command_not_accepted = False        # WarningWord.X3: a job was rejected (until MC_Reset)
        self._decoupled_state = None
        self._lv_init()
        super().__init__(ctl, name, cfg, **kw)

    # --- state ------------------------------------------------------------------------------------------
    def _state_at(self, t: float) -> tuple[float, float, float]:
        p, v, a = super()._state_at(t)
        carry = self._sup_carry
        if carry is not None:
            p, v, a = p + carry[0], v + carry[1], a + carry[2]
        return p, v, a

    def _start_profile(self, profile: Profile, plan=None) -> None:
        super()._start_profile(profile, plan)
        self._sup_carry = None

    def actual_acceleration(self) -> float:
        return float(self.ctl.bank.sp_a[self.index])

    # --- alarms -----------------------------------------------------------------------------------------
    def _blocking_alarm(self) -> Fault | None:
        """Alarms without a reaction (warnings, SynchronousError) do not block new jobs."""
        for a in self.alarms:
            if a.reaction != Reaction.NONE or a.kind not in (F.SYNC_MASTER,):
                return Fault(F.PENDING_ALARM, a.kind + "/" + a.detail, False, text=str(a))
        return None

    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None:
        if fault.reaction == Reaction.NONE and fault.kind in (F.SYNC_MASTER,):
            if fault not in self.alarms:
                self.alarms.append(fault)
            return
        t = self.now
        if fault.reaction != Reaction.NONE:
            self._abort_sync(t, fault=fault)
            if self.sup_job is not None and self.sup_job.busy:
                self._finish_job(self.sup_job, JobState.ERROR, t, fault)
            self._sup_take_over(t)
            stop = self.stop_job
            if stop is not None and stop.busy and fault.reaction == Reaction.REMOVE_ENABLE:
                self._finish_job(stop, JobState.ERROR, t, fault)
        super().raise_alarm(fault, job)

    def acknowledge(self) -> Fault | None:
        self.warnings.clear()
        self.command_not_accepted = False
        return super().acknowledge()

    def note_rejected(self, fault: Fault) -> None:
        """An instruction's job was rejected (not enabled, not homed, MC_Stop lock, ...): §7.1.1 "Job
        rejected" shows WarningWord.X3 (CommandNotAccepted) until MC_Reset (docs/s7_1500/decisions.md)."""
        if not fault.ack:
            self.command_not_accepted = True

    # synchronous operation hooks (no-ops on the positioning axis) -------------------------------------
    def _abort_sync(self, t: float, *, waiting: bool = True, active: bool = True, fault: Fault | None = None) -> None:
        return None

    def _sync_activities(self) -> Iterator[Activity]:
        return iter(())

    # --- jobs -------------------------------------------------------------------------------------------
    def check_start(self, job: Job) -> Fault | None:
        """The kernel's start conditions, and the lock of a running or held MC_Stop."""
        if self.stop_job is not None and job.kind != JobKind.STOP and self.ctl.mode == "RUN" \
                and self.state == ENABLED and self._blocking_alarm() is None:
            return F.reject(F.STOP_ACTIVE)
        return super().check_start(job)

    def _activities(self) -> Iterator[Activity]:
        """A running or held MC_Stop, the kernel's (axis job, passive homing), the synchronous operation and
        the superimposed motion: the order in which a new job ends them (§9.3.1, §9.3.2)."""
        if self.stop_job is not None:
            yield Activity(O.STOP, self.stop_job, self._end_stop)
        yield from super()._activities()
        yield from self._sync_activities()
        if self.sup_profile is not None:
            # a basic motion job that ends it takes the superimposed state over
            yield Activity(O.SUPERIMPOSED, self.sup_job, self._sup_take_over)

    def _end_stop(self, t: float) -> None:
        old = self.stop_job
        if old is not None and old.busy:
            self._finish_job(old, JobState.ABORTED, t)
        self.stop_job = None

    def _begin(self, job: Job, t: float) -> None:
        if job.kind == JobKind.STOP:
            # MC_Stop brakes and keeps the axis locked (check_start) while its Execute is TRUE
            self.stop_job = job
            self.job = None
            self._interpolating = True
            self._plan_stop(job, t)
            return
        super()._begin(job, t)

    def _replan(self) -> None:
        """A changed tag (velocity override, dynamic limits) acts at once on the running job, with the
        job's dynamics (§A.1.21); WarningWord.X6 follows the new plan."""
        stop = self.stop_job
        if stop is not None and stop.busy and stop.mode == 0 and abs(self._state_now()[1]) > 1e-12:
            # MC_Stop Mode 0 runs down the emergency-stop ramp (§6.1.5.3): a re-plan keeps that ramp, never
            # a stop with the dynamic defaults (fuzz seed 201112)
            self._plan_stop(stop, self.now)
            return
        job = self.job
        before = self.motion.last_limits
        if job is not None and job.busy and job.kind in (JobKind.VELOCITY, JobKind.JOG) and not self._interpolating \
                and not job.jog_released:
            job.in_velocity = False
            self._plan_job(job, self.now, replan=True)
        else:
            super()._replan()
        self._renote_limits(job, before)

    def _note_limits(self, lim, job: Job | None = None) -> None:
        """WarningWord.X6: the job's dynamics were cut to the dynamic limits (§A.1.16, alarms 501-503)."""
        limited = set(lim.limited) if lim is not None else set()
        if lim is not None and job is not None and job.kind in (JobKind.VELOCITY, JobKind.JOG) \
                and not job.jog_released and abs(self.commanded_velocity(job.velocity)) > lim.velocity * (1 + 1e-12):
            limited.add("velocity")              # a velocity job runs at the velocity limit
        self.warnings = limited

    def _renote_limits(self, job: Job | None, before) -> None:
        """The running ``job`` was planned anew (the planner's limits are not ``before``): renew X6."""
        lim = self.motion.last_limits
        if lim is not before and job is not None and job is self.job and job.busy:
            self._note_limits(lim, job)

    def change_jog_velocity(self, job: Job, velocity: float) -> None:
        before = self.motion.last_limits
        super().change_jog_velocity(job, velocity)
        self._renote_limits(job, before)

    def _plan_stop(self, job: Job, t: float) -> None:
        if job.mode == 0:
            plan = self.motion.stop(t, *self._state_now(), emergency=True, jerk=False)
            self._start_profile(plan.profile, plan)
        else:
            job.extra["max_dynamics"] = True
            self._plan_job(job, t)

    def release_stop(self, job: Job) -> None:
        """MC_Stop.Execute went FALSE: the axis accepts jobs again once the stop has ended (§9.3.1)."""
        job.extra["released"] = True
        if self.stop_job is job and not job.busy:
            self.stop_job = None

    def _on_milestone(self, name: str, t: float) -> None:
        stop = self.stop_job
        if name == "end" and stop is not None and stop.busy:
            self._interpolating = False
            self._finish_job(stop, JobState.DONE, t)
            if stop.extra.get("released"):
                self.stop_job = None
            return
        if name == "end" and self.coupling is not None and self.coupling.applied:
            self._on_sync_profile_end(t)
            return
        super()._on_milestone(name, t)

    def _on_timer(self, name: str, t: float) -> None:
        if name == "superimposed":
            self._on_superimposed_timer(t)
            return
        if name == "phase":
            c = self.coupling
            if c is not None and c.phase is not None:
                self._phase_segment(c, t)
            return
        super()._on_timer(name, t)

    def _on_sync_profile_end(self, t: float) -> None:
        return None

    # --- enable / disable (MC_Power StopMode: 0 emergency stop, 1 immediate stop, 2 maximum dynamics) ----
    _enabled_once = False

    def _has_start_mode(self) -> bool:
        """A simulated axis (Simulation.Mode 1) runs as the drive axis it stands for, also without position
        control (StatusWord.X28, §A.1.37); a virtual axis has no drive and stays position-controlled."""
        return self.servo or (self.sim and self.ueff["Simulation.Mode"] == 1 and not self.ueff["VirtualAxis.Mode"])

    def _zero_at_enable(self) -> bool:
        """An unhomed S7-1500 axis counts from the position at its first enable after the technology object
        started (§7.1.2); enabling it again keeps the position, so a follower sees no leading value step
        (§9.1.1: it follows its leading axis after that is enabled again).  docs: issue 8 decision."""
        first = not self._enabled_once
        self._enabled_once = True
        return first and super()._zero_at_enable()

    def _disable(self, stop_mode: int) -> None:
        t = self.now
        self._abort_all(t)
        if self.state == ENABLING:
            self._remove_enable(t, by_power=True)
            return
        self.state = "disabling"
        p, v, a = self._state_now()
        self._after_stop = "disable"
        if stop_mode == 1:
            self._remove_enable(t, by_power=True)
            return
        if stop_mode == 2:
            lim = self._max_dynamics()
            plan_profile = self.motion.stop_with(t, p, v, a, lim)
            self._start_profile(plan_profile)
        else:
            plan = self.motion.stop(t, p, v, a, emergency=True, jerk=False)
            self._start_profile(plan.profile, plan)
        if self.profile.t_end <= t + _EPS_T:
            self._remove_enable(t, by_power=True)

    def _max_dynamics(self):
        from ...kernel.motion import max_dynamics
        return max_dynamics(self)

    def _abort_all(self, t: float, *, keep_simulated: bool = True) -> None:
        if self.sup_job is not None and self.sup_job.busy:
            self._finish_job(self.sup_job, JobState.ABORTED, t)
        self._sup_take_over(t)
        stop = self.stop_job
        if stop is not None and stop.busy:
            self._finish_job(stop, JobState.ABORTED, t)
        self.stop_job = None
        self._abort_sync(t)
        super()._abort_all(t)

    def reinitialize(self, reason: str) -> None:
        self._enabled_once = False               # a restarted technology object counts anew (§7.1.2)
        self._abort_all(self.now, keep_simulated=False)
        self._sup_clear()
        self.warnings.clear()
        self.command_not_accepted = False
        super().reinitialize(reason)


class SynchronousAxis(SynchronousMixin, PositioningAxis1500):
    """Synchronous axis technology object (TO_SynchronousAxis): a positioning axis that can follow a
    leading value (§3.1).  ``leading_values``: the possible leading values, as names or
    ``(name, "setpoint" | "actual" | "delayed")`` pairs (§6.1.3)."""

    _dynamic = T.SYNC_DYNAMIC
    _dynamic_types = T.SYNC_TYPES
    _status_groups = T.SYNC_GROUPS
    _read_param_tags = frozenset(T.SYNC_DYNAMIC)
    waiting = None

    def __init__(self, ctl: "Controller", name: str, cfg: Mapping[str, Any], *, leading_values=(), **kw: Any):
        self._sync_init(leading_values)
        super().__init__(ctl, name, cfg, **kw)

    def _state_at(self, t: float) -> tuple[float, float, float]:
        c = self.coupling
        if c is not None and c.applied:
            p, v, a = self._coupled_state_at(t)
            sp, sv, sa = self.sup_state_at(t)
            p, v, a = p - sp, v - sv, a - sa
            carry = self._sup_carry
            if carry is not None:
                p, v, a = p + carry[0], v + carry[1], a + carry[2]
            return p, v, a
        return super()._state_at(t)

    def _sync_activities(self) -> Iterator[Activity]:
        """The synchronous operation (§9.3.2 columns): the coupling, a waiting coupling, a phasing and an
        additive leading value; a simulated synchronous operation is no running job (§9.1.6)."""
        c = self.coupling
        if c is not None and not c.simulated:
            column = O.GEAR_IN if c.job.kind == JobKind.GEAR_IN else O.SYNC_ACTIVE
            yield Activity(column, c.job, lambda t: self._end_coupling(c, JobState.ABORTED, t, replan=True))
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

    def _end_waiting(self, w: Any, t: float) -> None:
        self.waiting = None
        self.ctl.sync.remove(w)
        self._finish_coupling_job(w, JobState.ABORTED, t)

    def _end_phasing(self, ph: Job, t: float) -> None:
        self._finish_job(ph, JobState.ABORTED, t)
        c = self.coupling
        if c is not None and c.phase is not None:
            p = c.phase.at(t)[0]
            c.phase = Planner.hold(t, p)
            c.phase_seg = 0
            self._phase_segment(c, t)

    def _end_additive(self, add: Job, t: float) -> None:
        self.lv_additive_job = None
        self.lv_additive = None
        self._push_additive()
        self._finish_job(add, JobState.ABORTED, t)

    def _abort_sync(self, t: float, *, waiting: bool = True, active: bool = True, fault: Fault | None = None,
                    keep_simulated: bool = True) -> None:
        c = self.coupling
        if c is not None and c.simulated and keep_simulated and fault is None:
            active = False                       # a simulated synchronous operation survives (§9.1.6)
        SynchronousMixin._abort_sync(self, t, waiting=waiting, active=active, fault=fault)

    def _abort_all(self, t: float, *, keep_simulated: bool = True) -> None:
        if not keep_simulated:
            if self.sim_job is not None:
                job = self.sim_job
                self.sim_job = None
                if job.busy:
                    self._finish_job(job, JobState.ABORTED, t)
            c = self.coupling
            if c is not None:
                c.simulated = False
                self.ctl.sync.changed()
        add = self.lv_additive_job
        if add is not None and not keep_simulated:
            self.lv_additive_job = None
            self.lv_additive = None
            if add.busy:
                self._finish_job(add, JobState.ABORTED, t)
        super()._abort_all(t, keep_simulated=keep_simulated)
        if not keep_simulated:
            SynchronousMixin._abort_sync(self, t)

    def _set_loop_flags(self) -> None:
        super()._set_loop_flags()

    def _remove_enable(self, t: float, by_power: bool = False) -> None:
        c = self.coupling
        if c is not None and not c.simulated:
            self._abort_sync(t)
        super()._remove_enable(t, by_power)

    def _on_sync_profile_end(self, t: float) -> None:
        SynchronousMixin._on_sync_profile_end(self, t)


__all__ = ["PositioningAxis1500", "SynchronousAxis", "DISABLED", "INF", "math"]
