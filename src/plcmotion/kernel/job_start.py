"""Starting a motion job on an axis: start conditions, the family's override policy, target and plan.

S7-1200 V6 §11.1 ("Requirements" of each motion instruction, §12.8 16#82xx) says when a job may start: the
CPU in RUN, the axis enabled and holding its pulse generator, no pending alarm, not too many commands, a
homed axis for absolute positioning, valid actual values for position control.  What the new job then does
to what already runs on the axis (abort it, let it go on, or be refused) is the family's override policy as
data (``kernel.policy``; S7-1200 §11.1 override tables, S7-1500T §9.3).  A positioning's target comes from
the state at its start; the motion plan starts at once, or on a pulse output at the next segment boundary
(PTOSliceTime).

A running job is planned anew the same way when its parameters change (a tag, the jog input, a coordinate
shift).  ``JobStart`` is a component of an axis (``axis.job_start``).  The steps a family changes
(``check_start``, ``_activities``, ``_override``, ``_begin``, ``_plan_job``, ``_note_limits``) are called
back through the axis so that a family's override wins.
"""
from __future__ import annotations

import math
from typing import Any, Iterator, Protocol

from . import faults as F
from . import schema as P
from .family import PULSE_SLICE_TIME
from .faults import Fault, Reaction
from .jobs import MOTION_KINDS, POSITIONING_KINDS, Job, JobKind, JobState
from .motion import DirectionFault, Plan, limits, modulo_target
from .policy import ABORT, SUPERIMPOSED_SLOT, Activity, OverridePolicy, Reject
from .profiles import PlanningError, Profile, velocity_reach

ENABLED, DISABLING = "enabled", "disabling"
_EPS_T = 1e-9


def _homing_required(ax: Any) -> bool:
    """Absolute positioning needs a homed axis unless its configuration says otherwise ("Homing required"
    = No); a host without a configuration requires it."""
    config = getattr(ax, "config", None)
    return config is None or config.homing.required


class JobStartHost(Protocol):
    """What starting a job needs from its axis."""

    ctl: Any                        # the controller: ``mode``, ``rules``, ``servo_cycle``
    config: Any                     # kernel.axis_config.AxisConfig
    motion: Any                     # kernel.motion.MotionPlanner
    homing: Any                     # kernel.homing.Homing
    limit_switches: Any             # kernel.limit_switches.LimitSwitches
    policy: OverridePolicy
    runners: dict[JobKind, Any]
    job: Job | None
    profile: Profile
    state: str
    homed: bool
    alarms: list[Fault]
    busy_commands: set[int]
    max_commands: int
    holding_zero_velocity: bool
    pto: bool
    servo: bool
    _interpolating: bool
    _plan: Plan | None              # the plan of the running profile

    @property
    def now(self) -> float: ...
    @property
    def activated(self) -> bool: ...
    @property
    def sensor_valid(self) -> bool: ...

    def pto_used_by_other(self) -> bool: ...
    def sw_limits_effective(self) -> bool: ...
    def _state_now(self) -> tuple[float, float, float]: ...
    def check_start(self, job: Job) -> Fault | None: ...
    def _blocking_alarm(self) -> Fault | None: ...
    def _apply_dirty(self, moment: str) -> Fault | None: ...
    def _activities(self) -> Iterator[Activity]: ...
    def _override(self, new: str, t: float, new_job: Job | None) -> None: ...
    def _begin(self, job: Job, t: float) -> None: ...
    def _plan_job(self, job: Job, t: float, spec: Job | None = None, *, new_command: bool = True,
                  replan: bool = False) -> bool: ...
    def _note_limits(self, lim: Any, job: Job | None = None) -> None: ...
    def _set_position_control(self, on: bool) -> None: ...
    def _stop_positioning_monitor(self) -> None: ...
    def _finish_job(self, job: Job, state: JobState, t: float, fault: Fault | None = None) -> None: ...
    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None: ...
    def _start_profile(self, profile: Profile, plan: Plan | None = None) -> None: ...
    def _state_at(self, t: float) -> tuple[float, float, float]: ...


class JobStart:
    """The start path of one axis's motion jobs: check, override, resolve the target, plan."""

    def __init__(self, axis: JobStartHost):
        self.axis = axis
        #: the last plan started: (its start time, its profile, the state it started from)
        self.planned: tuple[float, Profile, tuple[float, float, float]] | None = None

    def check_start(self, job: Job) -> Fault | None:
        """Conditions every motion job needs (§11.1 'Requirements', §12.8 16#82xx)."""
        ax = self.axis
        if ax.ctl.mode != "RUN":
            return F.reject(F.REJECTED, "starting_up")    # STOP/STARTUP: no motion jobs (§2.2.7.4)
        if ax.pto_used_by_other():
            return F.reject(F.HW_USED)
        if not ax.activated:
            return F.reject(F.NOT_ACTIVATED)                # shared PTO not yet taken over (§12.1)
        if ax.state != ENABLED:
            return F.reject(F.NOT_ENABLED)
        blocking = ax._blocking_alarm()
        if blocking is not None:
            return blocking
        if len(ax.busy_commands) >= ax.max_commands:
            return F.reject(F.TOO_MANY_COMMANDS)
        if job.kind == JobKind.ABSOLUTE and not ax.homed and _homing_required(ax):
            return F.reject(F.NOT_HOMED)
        if job.kind in (JobKind.HOME_ACTIVE, JobKind.HOME_PASSIVE) and not ax.homing.available:
            return F.reject(F.NOT_AVAILABLE, "homing")      # an axis kind without homing
        needs_control = job.kind in POSITIONING_KINDS or job.kind == JobKind.HOME_ACTIVE or (
            job.kind in (JobKind.VELOCITY, JobKind.JOG) and job.position_controlled)
        if ax.servo and needs_control and not ax.sensor_valid:
            return F.reject(F.REJECTED, "position_control_required")   # §12.7: invalid actual values
        return None

    def start_job(self, job: Job) -> None:
        """Start ``job`` now: the start conditions, then the family's policy decides what the job does to
        every running activity, and the job takes the axis (or its superimposed slot)."""
        ax = self.axis
        fault = ax.check_start(job)
        if fault is not None:
            job.finish(JobState.ERROR, fault)
            return
        t = ax.now
        if ax.pto and ax._apply_dirty("command") is not None:
            job.finish(JobState.ERROR, ax.alarms[-1])
            return
        policy = ax.policy
        new = policy.classify(job)
        slotted = policy.slot(new) == SUPERIMPOSED_SLOT
        if slotted and getattr(ax, "start_superimposed", None) is None:
            job.finish(JobState.ERROR, F.reject(F.NOT_AVAILABLE, job.kind.value))
            return
        # a refusal applies to every job, also one that starts in a slot beside the running ones
        for activity in ax._activities():
            if activity.job is job:
                continue
            answer = policy.decide(new, job, activity)
            if isinstance(answer, Reject):
                job.finish(JobState.ERROR, answer.fault())
                return
        if slotted:
            self.start_superimposed_job(job)
            return
        if not policy.plan_after_override and not self.resolve_target(job):
            return
        ax._override(new, t, job)
        if policy.plan_after_override and not self.resolve_target(job):
            return
        ax.holding_zero_velocity = False
        ax._stop_positioning_monitor()
        ax._begin(job, t)

    def activities(self) -> Iterator[Activity]:
        """What runs on the axis that a new job may end, in the order it is ended; lazy, so that each one
        is looked at after the one before has been ended (ending a job can end others with it)."""
        ax = self.axis
        classify = ax.policy.classify
        run = ax.job
        if run is not None and run.busy:
            yield Activity(classify(run), run, lambda t: ax._finish_job(run, JobState.ABORTED, t))
        for runner in ax.runners.values():
            waiting = runner.job
            if waiting is not None and waiting.busy:            # a program that has not taken over yet
                yield Activity(classify(waiting), waiting,
                               lambda t, w=waiting: ax._finish_job(w, JobState.ABORTED, t))
        passive = ax.homing.passive
        if passive is not None and passive.busy:
            yield Activity(classify(passive), passive, lambda t: ax.homing.end_passive(JobState.ABORTED))

    def override(self, new: str, t: float, new_job: Job | None) -> None:
        """End every running activity that a new job of class ``new`` aborts (the family's policy)."""
        ax = self.axis
        policy = ax.policy
        for activity in ax._activities():
            if activity.job is not None and activity.job is new_job:
                continue
            if policy.decide(new, new_job, activity) is ABORT:
                activity.end(t)

    def resolve_target(self, job: Job) -> bool:
        """The absolute target of a positioning from the state at its start (False: the job was refused)."""
        p, v, a = self.start_state(self.axis.now)
        if job.kind == JobKind.RELATIVE:
            job.target = job.extra.pop("relative_base", p) + job.position
            if abs(job.target) > P.E12:
                job.finish(JobState.ERROR, F.reject(F.REJECTED, "numeric_limit"))
                return False
        elif job.kind == JobKind.ABSOLUTE:
            job.target = self.absolute_target(job, p, v, a)
        elif job.kind == JobKind.VELOCITY and job.current:
            job.velocity = v
        return True

    def begin(self, job: Job, t: float) -> None:
        """The job takes the axis over: position control as it needs, then homing or its motion plan."""
        ax = self.axis
        ax.job = job
        if job.kind in ax.policy.position_control:
            ax._set_position_control(True)
        elif job.kind in (JobKind.VELOCITY, JobKind.JOG):
            ax._set_position_control(job.position_controlled)
        if job.kind == JobKind.HOME_ACTIVE:
            ax.homing.start_active(job, t)
            return
        if ax._plan_job(job, t):
            ax._note_limits(ax.motion.last_limits, job)

    def start_superimposed_job(self, job: Job) -> None:
        """A job in the superimposed slot: it adds to whatever runs and replaces a running superimposed job."""
        ax = self.axis
        start = getattr(ax, "start_superimposed", None)
        if start is None:
            job.finish(JobState.ERROR, F.reject(F.NOT_AVAILABLE, job.kind.value))
            return
        lim = limits(ax, job.velocity, job=job)
        ax._note_limits(lim)
        start(job, lim)

    def absolute_target(self, job: Job, p: float, v: float, a: float) -> float:
        ax = self.axis
        if ax.config.modulo.enabled:
            lim = limits(ax, job.velocity)
            return modulo_target(ax, job.position, job.direction, math.copysign(1.0, job.extra.get("sign", 1.0)),
                                 p, v, a, lim, ax.motion.planner)
        return job.position

    def plan_job(self, job: Job, t: float, spec: Job | None = None, *, new_command: bool = True,
                 replan: bool = False) -> bool:
        """Plan and start the motion of ``job`` (or of ``spec``, a step of ``job`` planned by a runner).

        A new command on a PTO axis starts at the next segment boundary (V7 PTOSliceTime).  Faults found
        while planning end ``job``.  Returns whether the motion started.
        """
        ax = self.axis
        t_plan = self.slice_start(t) if new_command else t
        p, v, a = self.start_state(t_plan)
        try:
            # a re-plan may use the velocities the running plan reaches anyway (no jerk above the limit
            # to avoid an overshoot the old plan had too)
            reach = velocity_reach(ax.profile, t_plan) if replan else None
            plan = ax.motion.plan(spec or job, t_plan, p, v, a, replan=replan, reach=reach)
        except DirectionFault as exc:
            ax.raise_alarm(F.alarm(F.DIRECTION, exc.detail, Reaction.STOP), job=job)
            return False
        except PlanningError as exc:
            ax.raise_alarm(F.alarm(F.INTERNAL, "planning", Reaction.EMERGENCY, str(exc)), job=job)
            return False
        fault = ax.limit_switches.direction_fault(plan.profile, p)
        if fault is not None:
            ax.raise_alarm(fault, job=job)
            return False
        if t_plan != t:
            # the running profile goes on until the next PTO segment boundary (V7 Actor.PTOSliceTime)
            plan.profile.segments[:0] = [seg for seg in ax.profile.segments if seg.t < t_plan]
        ax._interpolating = True
        ax._start_profile(plan.profile, plan)
        self.planned = (t_plan, ax.profile, (p, v, a))
        return True

    def start_state(self, t: float) -> tuple[float, float, float]:
        """The state a plan for time ``t`` starts from: the setpoint at ``t``, but when a job planned for the
        same instant still holds the axis (it never ran a servo cycle: two jobs in one application cycle),
        the acceleration that plan started from, not the step a Jerk-0 profile makes at its start.  Only
        where position and velocity agree: anything that moved the profile in between (a coordinate shift,
        a velocity step) leaves the setpoint as it is."""
        p, v, a = self.axis._state_at(t)
        planned = self.planned
        if planned is not None and planned[0] == t and planned[1] is self.axis.profile and planned[2][:2] == (p, v):
            a = planned[2][2]
        return p, v, a

    def slice_start(self, t: float) -> float:
        """When a new command takes effect: at once, or on a PTO at the next segment boundary."""
        ax = self.axis
        if not ax.pto or PULSE_SLICE_TIME not in ax.ctl.rules:
            return t
        period = ax.config.pulse_output.slice_time
        if period <= ax.ctl.servo_cycle * (1 + 1e-9):
            return t
        k = math.ceil(t / period - 1e-9)
        return max(t, k * period)

    # ------------------------------------------------------------------------------------------------
    # the running job planned anew
    def replan(self) -> None:
        """Re-plan the running motion from the current state (parameter change, coordinate shift)."""
        ax = self.axis
        job = ax.job
        t = ax.now
        if job is not None and job.busy and (job.kind == JobKind.HOME_ACTIVE or job.kind in ax.runners):
            return                                          # homing and runners plan their own steps
        if job is not None and job.busy and job.kind in MOTION_KINDS and ax._interpolating:
            ax._plan_job(job, t, replan=True)
        elif ax.sw_limits_effective() and ax.state in (ENABLED, DISABLING):
            p, v, a = ax._state_now()
            if abs(v) > 1e-12:
                # an internal stop in force (error reaction, disabling) keeps its ramp: the emergency ramp
                # has no jerk limit and its own deceleration (S7-1200 V6 §12.8; fuzz seed 124621)
                running = ax._plan.stop if ax._plan is not None else None
                emergency, jerk = running if running is not None else (False, True)
                plan = ax.motion.stop(t, p, v, a, emergency=emergency, jerk=jerk)
                ax._start_profile(plan.profile, plan)

    def release_jog(self, job: Job) -> None:
        """Jog input released: brake with the configured deceleration (§11.1.8)."""
        ax = self.axis
        if job is not ax.job or not job.busy or job.jog_released:
            return
        job.jog_released = True
        job.in_velocity = False
        if ax.pto:
            ax._apply_dirty("jog_stop")
            if not job.busy:
                return
        ax._plan_job(job, ax.now)

    def change_jog_velocity(self, job: Job, velocity: float) -> None:
        """MC_MoveJog takes a new Velocity while the jog input is TRUE (§9.3)."""
        ax = self.axis
        if job is not ax.job or not job.busy or job.jog_released or velocity == job.velocity:
            return
        job.velocity = velocity
        job.in_velocity = False
        ax._plan_job(job, ax.now)
