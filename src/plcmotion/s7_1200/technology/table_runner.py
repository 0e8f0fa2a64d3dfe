"""Running a command table on an axis (MC_CommandTable, S7-1200 V6 §11.1.9, §6.4.3).

The table job takes the axis over only when its first Positioning, Velocity set point or Halt step
starts; leading Wait steps leave the running command alone.  Steps run in order from StartStep to
EndStep, Empty steps are skipped:

* Positioning Relative / Absolute: to the target at Velocity.  "Complete command" stops there before the
  next step; "Blend motion" arrives with the next step's velocity when the next step moves on in the
  same direction (Positioning or Velocity set point), otherwise it stops.  A relative step counts from
  the previous step's target when that step was a positioning, else from the position at its start.
* Velocity set point: ramps to Velocity; the next step starts when Duration (ramp included) has passed,
  from whatever the axis does at that moment.
* Halt: brakes with the configured deceleration if the axis is moving (after a velocity set point).
* Wait: waits Duration; motion goes on.
At the end of the table a still moving axis is braked to standstill; then the table is Done.

``TableRunner`` is a component of the S7-1200 positioning axis (``axis.table_runner``, attached by the
family's factory): a kernel job runner (``kernel.job_runner``) for jobs of kind ``JobKind.TABLE``.  It
plans each step with the axis's own planner; the progress of the table is kept in the job's ``extra``
(``current`` and ``step_code`` are MC_CommandTable's CurrentStep and StepCode, ``phase`` tells the status
views whether a positioning step runs).
"""
from __future__ import annotations

from typing import Any, Protocol

from ...kernel import faults as F
from ...kernel.jobs import Job, JobKind, JobState
from ...kernel.motion import MotionPlanner, limits
from ...kernel.profiles import Profile
from .command_table import ABSOLUTE, BLEND, EMPTY, HALT, RELATIVE, VELOCITY, WAIT, CommandTable

TIMER = "table"


class TableHost(Protocol):
    """What the runner needs from its axis: the job slot, the start checks, the timers and the planner."""

    job: Job | None
    passive_home: Job | None
    homed: bool
    holding_zero_velocity: bool
    alarms: list[F.Fault]
    eff: Any                       # tag values in effect (the step checks read the velocity limits)
    config: Any                    # the axis configuration and its pulse output flag: the dynamics of
    pto: bool                      # the stop at the end of a table (kernel.motion.limits)
    motion: MotionPlanner
    _timers: dict[str, float]
    _interpolating: bool

    @property
    def now(self) -> float: ...

    def check_start(self, job: Job) -> F.Fault | None: ...

    def _apply_dirty(self, moment: str) -> F.Fault | None: ...

    def _finish_job(self, job: Job, state: JobState, t: float, fault: F.Fault | None = None) -> None: ...

    def _schedule(self) -> None: ...

    def _slice_start(self, t: float) -> float: ...

    def _state_at(self, t: float) -> tuple[float, float, float]: ...

    def _plan_job(self, job: Job, t: float, spec: Job | None = None, *, new_command: bool = True,
                  replan: bool = False) -> bool: ...

    def _stop_positioning_monitor(self) -> None: ...

    def _start_profile(self, profile: Profile, plan: Any = None) -> None: ...


class TableRunner:
    """Runs MC_CommandTable jobs on one axis (a ``kernel.job_runner.JobRunner`` for ``JobKind.TABLE``)."""

    kind = JobKind.TABLE
    timer = TIMER

    def __init__(self, axis: TableHost):
        self.axis = axis
        self.job: Job | None = None          # the table job, also before it takes the axis over

    def __repr__(self) -> str:
        return f"<TableRunner {self.job!r}>"

    def start(self, job: Job) -> None:
        """MC_CommandTable starts ``job`` (extra: table, start, end).  Leading Wait steps run before the
        job takes the axis over; a table job that has not taken over yet is replaced by the new one."""
        ax = self.axis
        table: CommandTable = job.extra["table"]
        fault = ax.check_start(job)
        if fault is None and ax.passive_home is not None and ax.passive_home.busy:
            fault = F.reject(F.REJECTED, "table_homing")
        if fault is not None:
            job.finish(JobState.ERROR, fault)
            return
        if ax._apply_dirty("command") is not None:
            job.finish(JobState.ERROR, ax.alarms[-1])
            return
        waiting = self.job
        if waiting is not None and waiting.busy:
            ax._finish_job(waiting, JobState.ABORTED, ax.now)
        job.extra.update(index=job.extra["start"] - 1, current=0, step_code=0, took_over=False, prev_type=None,
                         prev_target=None, phase="")
        self.job = job
        table.in_use_by = job
        self._next(job, ax.now)

    # --- events the axis hands over (kernel.job_runner) ----------------------------------------------------
    def on_profile_end(self, job: Job, t: float) -> None:
        """The profile of the current step ended."""
        phase = job.extra["phase"]
        if phase in ("position", "halt"):
            self._next(job, t)
        elif phase == "final_stop":
            self.axis._finish_job(job, JobState.DONE, t)
            self.release(job)

    def on_timer(self, t: float) -> None:
        """A Wait step or the Duration of a Velocity set point step has passed."""
        job = self.job
        if job is not None and job.busy and job.extra["phase"] in ("wait", "velocity"):
            self._next(job, t)

    def release(self, job: Job) -> None:
        """``job`` ended: the table is free again."""
        table: CommandTable = job.extra["table"]
        if table.in_use_by is job:
            table.in_use_by = None
        if self.job is job:
            self.job = None
        self.axis._timers.pop(TIMER, None)

    # --- sequencing -----------------------------------------------------------------------------------------
    def _take_over(self, job: Job, t: float) -> None:
        if job.extra["took_over"]:
            return
        job.extra["took_over"] = True
        ax = self.axis
        previous = ax.job
        if previous is not None and previous.busy and previous is not job:
            ax._finish_job(previous, JobState.ABORTED, t)
        if ax.passive_home is not None and ax.passive_home.busy:
            ax._finish_job(ax.passive_home, JobState.ABORTED, t)
            ax.passive_home = None
        ax._stop_positioning_monitor()
        ax.holding_zero_velocity = False
        ax.job = job

    def _next(self, job: Job, t: float) -> None:
        ax = self.axis
        table: CommandTable = job.extra["table"]
        x = job.extra
        ax._timers.pop(TIMER, None)
        while True:
            x["index"] += 1
            n = x["index"]
            if n > x["end"]:
                self._finish(job, t)
                return
            step = table.Command[n]
            if step.Type == EMPTY:
                continue
            break
        fault = table.check_step(n, ax)
        if fault is None and step.Type == ABSOLUTE and not ax.homed:
            fault = F.reject(F.NOT_HOMED)
        if fault is not None:
            self._fail(job, fault)                           # the axis motion continues (§9.6)
            return
        x["current"], x["step_code"] = n, step.StepCode
        kind = step.Type
        if kind == WAIT:
            x["phase"] = "wait"
            ax._timers[TIMER] = t + step.Duration
            ax._schedule()
            x["prev_type"] = WAIT
            return
        first = not x["took_over"]
        self._take_over(job, t)
        t0 = ax._slice_start(t) if first else t         # the first motion step is a new command (slice time)
        p, v, a = ax._state_at(t0)
        if kind == HALT:
            x["prev_type"] = HALT
            if abs(v) <= 1e-12:
                self._next(job, t)                           # nothing to stop
                return
            x["phase"] = "halt"
            ax._plan_job(job, t, Job(JobKind.HALT), new_command=first)
            return
        if kind == VELOCITY:
            x["phase"] = "velocity"
            x["prev_type"] = VELOCITY
            if ax._plan_job(job, t, Job(JobKind.VELOCITY, velocity=step.Velocity), new_command=first):
                ax._timers[TIMER] = t0 + step.Duration        # the duration includes the acceleration
                ax._schedule()
            return
        base = x["prev_target"] if x["prev_type"] in (RELATIVE, ABSOLUTE) else p
        target = step.Position if kind == ABSOLUTE else base + step.Position
        spec = Job(JobKind.ABSOLUTE if kind == ABSOLUTE else JobKind.RELATIVE, velocity=step.Velocity,
                   extra={"end_velocity": self._blend_velocity(job, n, target, p)})
        spec.target = job.target = target
        x["phase"] = "position"
        x["prev_type"], x["prev_target"] = kind, target
        ax._plan_job(job, t, spec, new_command=first)

    def _blend_velocity(self, job: Job, n: int, target: float, p: float) -> float:
        """Speed at the target of a blended positioning step (0 = no blending)."""
        table: CommandTable = job.extra["table"]
        step = table.Command[n]
        if step.NextStep != BLEND:
            return 0.0
        nxt = n + 1
        while nxt <= job.extra["end"] and table.Command[nxt].Type == EMPTY:
            nxt += 1
        if nxt > job.extra["end"]:
            return 0.0
        follow = table.Command[nxt]
        here = 1.0 if target > p else -1.0
        if follow.Type == VELOCITY:
            return abs(follow.Velocity) if follow.Velocity * here > 0 else 0.0
        if follow.Type in (RELATIVE, ABSOLUTE):
            goal = follow.Position if follow.Type == ABSOLUTE else target + follow.Position
            return abs(follow.Velocity) if (goal - target) * here > 0 else 0.0
        return 0.0

    def _finish(self, job: Job, t: float) -> None:
        """After the last step: a moving axis brakes to standstill first (decision 41), then Done."""
        ax = self.axis
        p, v, a = ax._state_at(t)
        if job.extra["took_over"] and abs(v) > 1e-12:
            job.extra["phase"] = "final_stop"
            ax._start_profile(ax.motion.stop_with(t, p, v, a, limits(ax)))
            ax._interpolating = True
            return
        ax._finish_job(job, JobState.DONE, t)
        self.release(job)

    def _fail(self, job: Job, fault: F.Fault) -> None:
        """A step with a configuration error ends the job; the axis goes on with what it does."""
        ax = self.axis
        job.finish(JobState.ERROR, fault)
        if ax.job is job:
            ax.job = None
        self.release(job)
