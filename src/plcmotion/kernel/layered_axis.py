"""A positioning axis with motion layers: basic motion, a superimposed motion on top, a stop that locks
the axis, and (on a following axis) a coupling to a leading value.

The S7-1200 axis runs one job at a time.  The S7-1500 and S7-Technology axes add a superimposed motion
layer (MC_MoveSuperimposed / MC_MoveSuperImposed), a stop job that keeps the axis locked while its
instruction holds Execute (MC_Stop), per-job dynamics cut to the dynamic limits (the cut is noted in
``warnings``) and, on a synchronous axis, a :class:`~kernel.follower.Follower`.  That behaviour is the
same in those families, so it lives here once; a family subclass adds its tags, its disabling stop modes
and its rules for enabling.  Which running activity a new job ends is the family's ``OverridePolicy``.
"""
from __future__ import annotations

from typing import Any, Iterator, Mapping

from . import faults as F
from .axis import ENABLED, PositioningAxis
from .faults import Fault, Reaction
from .follower import Follower
from .jobs import Job, JobKind, JobState
from .policy import STOP, SUPERIMPOSED, Activity
from .profiles import Profile
from .protocols import ServoHost
from .superimposed import TIMER as SUPERIMPOSED_TIMER, SuperimposedMotion


class LayeredAxis(PositioningAxis):
    """Positioning axis with a superimposed motion layer, a locking stop job and an optional follower."""

    follower: Follower | None = None             # the following-axis ability (a synchronous axis sets it)
    stop_job: Job | None = None
    #: active homing of a virtual/simulated axis is a job like on a drive axis
    _sim_homing_at_once = False

    def __init__(self, ctl: ServoHost, name: str, cfg: Mapping[str, Any], **kw: Any):
        self.superimposed = SuperimposedMotion(self)
        self.stop_job = None
        self.warnings: set[str] = set()          # which dynamic values of the running job were limited
        super().__init__(ctl, name, cfg, **kw)

    # --- the superimposed motion (kernel.superimposed): one-line hand-overs ------------------------------
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
        f = self.follower
        if f is not None:
            c = f.coupling
            if c is not None and c.applied:
                # the coupling gives the total setpoint: the basic part is it minus the superimposed part
                p, v, a = f.coupled_state_at(t)
                sp, sv, sa = self.sup_state_at(t)
                p, v, a = p - sp, v - sv, a - sa
                carry = self._sup_carry
                if carry is not None:
                    p, v, a = p + carry[0], v + carry[1], a + carry[2]
                return p, v, a
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
        """Alarms without a reaction (warnings, a leading value problem) do not block new jobs."""
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
        return super().acknowledge()

    # --- jobs -------------------------------------------------------------------------------------------
    def check_start(self, job: Job) -> Fault | None:
        """The kernel's start conditions, and the lock of a running or held stop job."""
        if self.stop_job is not None and job.kind != JobKind.STOP and self.ctl.mode == "RUN" \
                and self.state == ENABLED and self._blocking_alarm() is None:
            return F.reject(F.STOP_ACTIVE)
        return super().check_start(job)

    def _activities(self) -> Iterator[Activity]:
        """A running or held stop, the kernel's (axis job, passive homing), the synchronous operation and
        the superimposed motion: the order in which a new job ends them."""
        if self.stop_job is not None:
            yield Activity(STOP, self.stop_job, self._end_stop)
        yield from super()._activities()
        if self.follower is not None:
            yield from self.follower.activities()
        if self.sup_profile is not None:
            # a basic motion job that ends it takes the superimposed state over
            yield Activity(SUPERIMPOSED, self.sup_job, self._sup_take_over)

    def _end_stop(self, t: float) -> None:
        old = self.stop_job
        if old is not None and old.busy:
            self._finish_job(old, JobState.ABORTED, t)
        self.stop_job = None

    def _begin(self, job: Job, t: float) -> None:
        if job.kind == JobKind.STOP:
            # the stop brakes and keeps the axis locked (check_start) until its instruction releases it
            self.stop_job = job
            self.job = None
            self._interpolating = True
            self._plan_stop(job, t)
            return
        super()._begin(job, t)

    def _plan_stop(self, job: Job, t: float) -> None:
        """Brake for a stop job: with the job's own dynamics (a family overrides this for stop modes)."""
        self._plan_job(job, t)

    def _replan_stop(self, stop: Job) -> bool:
        """A changed tag while a stop runs: True when the family re-planned the stop itself."""
        return False

    def _replan(self) -> None:
        """A changed tag (velocity override, dynamic limits) acts at once on the running job, with the
        job's dynamics; ``warnings`` follow the new plan."""
        if self.follower is not None:
            self.follower.watch_sw_limits()  # limits, their activation or the homed state may have changed
        stop = self.stop_job
        if stop is not None and stop.busy and self._replan_stop(stop):
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
        """Which of the job's dynamic values were cut to the dynamic limits (``warnings``)."""
        limited = set(lim.limited) if lim is not None else set()
        if lim is not None and job is not None and job.kind in (JobKind.VELOCITY, JobKind.JOG) \
                and not job.jog_released and abs(self.commanded_velocity(job.velocity)) > lim.velocity * (1 + 1e-12):
            limited.add("velocity")              # a velocity job runs at the velocity limit
        self.warnings = limited

    def _renote_limits(self, job: Job | None, before) -> None:
        """The running ``job`` was planned anew (the planner's limits are not ``before``): renew the notes."""
        lim = self.motion.last_limits
        if lim is not before and job is not None and job is self.job and job.busy:
            self._note_limits(lim, job)

    def change_jog_velocity(self, job: Job, velocity: float) -> None:
        before = self.motion.last_limits
        super().change_jog_velocity(job, velocity)
        self._renote_limits(job, before)

    def release_stop(self, job: Job) -> None:
        """The stop's instruction released it (Execute FALSE): the axis accepts jobs again once the stop
        has ended."""
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

    def _max_dynamics(self):
        from .motion import max_dynamics
        return max_dynamics(self)

    def _abort_all(self, t: float, *, keep_simulated: bool = True) -> None:
        f = self.follower
        if f is not None and not keep_simulated:
            f.end_simulation_and_additive(t)
        self.superimposed.take_over(t)
        stop = self.stop_job
        if stop is not None and stop.busy:
            self._finish_job(stop, JobState.ABORTED, t)
        self.stop_job = None
        if f is not None:
            f.abort(t)
        super()._abort_all(t)
        if f is not None and not keep_simulated:
            f.abort(t, keep_simulated=False)

    def _remove_enable(self, t: float, by_power: bool = False) -> None:
        if self.follower is not None:
            self.follower.on_enable_removed(t)
        super()._remove_enable(t, by_power)

    def reinitialize(self, reason: str) -> None:
        self._abort_all(self.now, keep_simulated=False)
        self.superimposed.clear()
        self.warnings.clear()
        super().reinitialize(reason)


__all__ = ["LayeredAxis"]
