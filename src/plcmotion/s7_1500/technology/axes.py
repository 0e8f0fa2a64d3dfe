"""S7-1500 positioning axis and synchronous axis technology objects (S7-1500T V5 §3.1, §6.1, §9.3, §A.1).

They share the kernel's motion with the S7-1200 axis and differ where the S7-1500 does: every job
brings its own dynamics (limited by ``DynamicLimits``), ``MC_Stop`` locks the axis while its Execute is
TRUE, a superimposed motion can run on top of any basic motion, jobs override each other by the tables
of §9.3, and the synchronous axis follows leading values (its ``kernel.follower.Follower``).
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
from ...kernel.leading import AxisLeadingValue
from ...kernel.policy import Activity
from .parameters import S7_1500
from ...kernel.profiles import INF, Profile
from ...kernel.follower import Follower
from ...kernel.superimposed import TIMER as SUPERIMPOSED_TIMER, SuperimposedMotion

if TYPE_CHECKING:  # pragma: no cover
    from ...kernel.runtime import Controller

_EPS_T = 1e-9
STOP_MODES = O.STOP_MODES


class PositioningAxis1500(PositioningAxis):
    """Positioning axis technology object of the S7-1500 (TO_PositioningAxis)."""

    schema = S7_1500
    _dynamic = T.DYNAMIC
    _dynamic_types = T.TYPES
    _dynamic_aliases: dict[str, str] = {}
    _status_groups = T.GROUPS
    _read_param_tags = frozenset(T.DYNAMIC)
    # defaults read before __init__ has set everything up
    follower: Follower | None = None             # the following-axis ability (synchronous axis only)
    stop_job: Job | None = None
    command_not_accepted = False
    #: active homing of a virtual/simulated axis is a job like on a drive axis (§6.1.5.5, §9.3.1, §9.3.2)
    _sim_homing_at_once = False

    # a leading TO (S7-1500T V5 §3.3): setpoints, actual values and the delayed value (see lv_provider)
    provides_setpoints = True
    provides_actual_values = True
    provides_delayed_values = True

    def __init__(self, ctl: "Controller", name: str, cfg: Mapping[str, Any], **kw: Any):
        self.superimposed = SuperimposedMotion(self)     # MC_MoveSuperimposed (§6.1.5.4)
        self.stop_job = None
        self.warnings: set[str] = set()          # dynamic values limited (alarms 501-504)
        self.command_not_accepted = False        # WarningWord.X3: a job was rejected (until MC_Reset)
        super().__init__(ctl, name, cfg, **kw)
        self.lv_provider = AxisLeadingValue(self)        # the leading value it provides (§3.3, §8.1.3)

    # --- the leading value it provides: what followers call (kernel.leading) ---------------------------
    def lv_value(self, mode: str, t: float) -> tuple[float, float, float]:
        return self.lv_provider.lv_value(mode, t)

    def lv_slot(self, mode: str) -> int:
        return self.lv_provider.lv_slot(mode)

    def lv_position_controlled(self) -> bool:
        return self.lv_provider.lv_position_controlled()

    def lv_modulo(self) -> tuple[float, float] | None:
        return self.lv_provider.lv_modulo()

    def leading_value_invalid(self, mode: str) -> str | None:
        return self.lv_provider.leading_value_invalid(mode)

    def provide_leading_value(self, sink: Any) -> None:
        self.lv_provider.provide_leading_value(sink)

    # --- the superimposed motion (kernel.superimposed): what submit, the override and the synchronous
    # operation call; one-line hand-overs to ``self.superimposed``
    @property
    def superimposed_active(self) -> bool:
        return self.superimposed.active

    @property
    def sup_job(self) -> Job | None:
        return self.superimposed.job

    @property
    def sup_profile(self) -> Profile | None:
        return self.superimposed.profile

    def start_superimposed(self, job: Job, lim: Any) -> None:
        self.superimposed.start(job, lim)

    def _sup_take_over(self, t: float) -> None:
        self.superimposed.take_over(t)

    @property
    def _sup_carry(self) -> tuple[float, float, float] | None:
        return self.superimposed.carry

    def sup_state_at(self, t: float) -> tuple[float, float, float]:
        return self.superimposed.state_at(t)

    def _sup_clear(self) -> None:
        self.superimposed.clear()

    # --- state ------------------------------------------------------------------------------------------
    def _state_at(self, t: float) -> tuple[float, float, float]:
        p, v, a = super()._state_at(t)
        carry = self.superimposed.carry
        if carry is not None:
            p, v, a = p + carry[0], v + carry[1], a + carry[2]
        return p, v, a

    def _start_profile(self, profile: Profile, plan=None) -> None:
        super()._start_profile(profile, plan)
        self.superimposed.carry = None

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
            if self.follower is not None:
                self.follower.abort(t, fault=fault)
            self.superimposed.take_over(t, JobState.ERROR, fault)
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
        if self.follower is not None:
            yield from self.follower.activities()
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
        f = self.follower
        if name == "end" and f is not None and f.coupling is not None and f.coupling.applied:
            f.on_profile_end(t)
            return
        super()._on_milestone(name, t)

    def _on_timer(self, name: str, t: float) -> None:
        if name == SUPERIMPOSED_TIMER:
            self.superimposed.on_timer(t)
            return
        if name == "phase":
            if self.follower is not None:
                self.follower.on_phase_timer(t)
            return
        super()._on_timer(name, t)

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
        self.superimposed.take_over(t)
        stop = self.stop_job
        if stop is not None and stop.busy:
            self._finish_job(stop, JobState.ABORTED, t)
        self.stop_job = None
        if self.follower is not None:
            self.follower.abort(t)
        super()._abort_all(t)

    def reinitialize(self, reason: str) -> None:
        self._enabled_once = False               # a restarted technology object counts anew (§7.1.2)
        self._abort_all(self.now, keep_simulated=False)
        self.superimposed.clear()
        self.warnings.clear()
        self.command_not_accepted = False
        super().reinitialize(reason)


class SynchronousAxis(PositioningAxis1500):
    """Synchronous axis technology object (TO_SynchronousAxis): a positioning axis that can follow a
    leading value (§3.1) - its ``follower`` component.  ``leading_values``: the possible leading values,
    as names or ``(name, "setpoint" | "actual" | "delayed")`` pairs (§6.1.3)."""

    _dynamic = T.SYNC_DYNAMIC
    _dynamic_types = T.SYNC_TYPES
    _status_groups = T.SYNC_GROUPS
    _read_param_tags = frozenset(T.SYNC_DYNAMIC)

    def __init__(self, ctl: "Controller", name: str, cfg: Mapping[str, Any], *, leading_values=(), **kw: Any):
        self.follower: Follower = Follower(self, leading_values, name)
        super().__init__(ctl, name, cfg, **kw)

    # what the synchronous instructions call (s7_1500/sync.py) --------------------------------------------
    @property
    def possible_leading_values(self) -> dict[str, str]:
        return self.follower.possible_leading_values

    def sync_submit(self, job: Job) -> None:
        self.follower.submit(job)

    def phase_shift(self, t: float | None = None) -> float:
        return self.follower.phase_shift(t)

    def covered_phase_shift(self, job: Job) -> float:
        return self.follower.covered_phase_shift(job)

    def set_lv_additive(self, job: Job, p: float, v: float, a: float) -> Fault | None:
        return self.follower.set_lv_additive(job, p, v, a)

    def end_lv_additive(self, job: Job) -> None:
        self.follower.end_lv_additive(job)

    def start_simulation(self, job: Job) -> Fault | None:
        return self.follower.start_simulation(job)

    def end_simulation(self, job: Job) -> None:
        self.follower.end_simulation(job)

    # the axis core with a coupling -------------------------------------------------------------------------
    def _state_at(self, t: float) -> tuple[float, float, float]:
        c = self.follower.coupling
        if c is not None and c.applied:
            p, v, a = self.follower.coupled_state_at(t)
            sp, sv, sa = self.sup_state_at(t)
            p, v, a = p - sp, v - sv, a - sa
            carry = self._sup_carry
            if carry is not None:
                p, v, a = p + carry[0], v + carry[1], a + carry[2]
            return p, v, a
        return super()._state_at(t)

    def _replan(self) -> None:
        self.follower.watch_sw_limits()      # limits, their activation or the homed state may have changed
        super()._replan()

    def _abort_all(self, t: float, *, keep_simulated: bool = True) -> None:
        if not keep_simulated:
            self.follower.end_simulation_and_additive(t)
        super()._abort_all(t, keep_simulated=keep_simulated)
        if not keep_simulated:
            self.follower.abort(t, keep_simulated=False)

    def _remove_enable(self, t: float, by_power: bool = False) -> None:
        self.follower.on_enable_removed(t)
        super()._remove_enable(t, by_power)


__all__ = ["PositioningAxis1500", "SynchronousAxis", "DISABLED", "INF", "math"]
