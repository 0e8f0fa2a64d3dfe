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
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from . import faults as F
from .command_table import ABSOLUTE, BLEND, EMPTY, HALT, RELATIVE, VELOCITY, WAIT, CommandTable
from .jobs import Job, JobKind, JobState
from .motion import limits

if TYPE_CHECKING:  # pragma: no cover
    from .axis import PositioningAxis


class TableMixin:
    """Mixed into PositioningAxis."""

    def start_table(self: "PositioningAxis", job: Job) -> None:
        table: CommandTable = job.extra["table"]
        fault = self.check_start(job)
        if fault is None and self.passive_home is not None and self.passive_home.busy:
            fault = F.reject(F.REJECTED, "table_homing")
        if fault is not None:
            job.finish(JobState.ERROR, fault)
            return
        if self._apply_dirty("command") is not None:
            job.finish(JobState.ERROR, self.alarms[-1])
            return
        waiting = self.table_job
        if waiting is not None and waiting.busy:
            self._finish_job(waiting, JobState.ABORTED, self.now)
        job.extra.update(index=job.extra["start"] - 1, current=0, step_code=0, took_over=False, prev_type=None,
                         prev_target=None, phase="")
        self.table_job = job
        table.in_use_by = job
        self._table_next(job, self.now)

    # --- sequencing -------------------------------------------------------------------------------------
    def _table_take_over(self: "PositioningAxis", job: Job, t: float) -> None:
        if job.extra["took_over"]:
            return
        job.extra["took_over"] = True
        previous = self.job
        if previous is not None and previous.busy and previous is not job:
            self._finish_job(previous, JobState.ABORTED, t)
        if self.passive_home is not None and self.passive_home.busy:
            self._finish_job(self.passive_home, JobState.ABORTED, t)
            self.passive_home = None
        self._stop_positioning_monitor()
        self.holding_zero_velocity = False
        self.job = job

    def _table_next(self: "PositioningAxis", job: Job, t: float) -> None:
        table: CommandTable = job.extra["table"]
        x = job.extra
        self._timers.pop("table", None)
        while True:
            x["index"] += 1
            n = x["index"]
            if n > x["end"]:
                self._table_finish(job, t)
                return
            step = table.Command[n]
            if step.Type == EMPTY:
                continue
            break
        fault = table.check_step(n, self)
        if fault is None and step.Type == ABSOLUTE and not self.homed:
            fault = F.reject(F.NOT_HOMED)
        if fault is not None:
            self._table_fail(job, fault, t)                   # the axis motion continues (§9.6)
            return
        x["current"], x["step_code"] = n, step.StepCode
        kind = step.Type
        if kind == WAIT:
            x["phase"] = "wait"
            self._timers["table"] = t + step.Duration
            self._schedule()
            x["prev_type"] = WAIT
            return
        first = not x["took_over"]
        self._table_take_over(job, t)
        t0 = self._slice_start(t) if first else t     # the first motion step is a new command (slice time)
        p, v, a = self._state_at(t0)
        if kind == HALT:
            x["prev_type"] = HALT
            if abs(v) <= 1e-12:
                self._table_next(job, t)                      # nothing to stop
                return
            x["phase"] = "halt"
            self._plan_job(job, t, Job(JobKind.HALT), new_command=first)
            return
        if kind == VELOCITY:
            x["phase"] = "velocity"
            x["prev_type"] = VELOCITY
            if self._plan_job(job, t, Job(JobKind.VELOCITY, velocity=step.Velocity), new_command=first):
                self._timers["table"] = t0 + step.Duration      # the duration includes the acceleration
                self._schedule()
            return
        base = x["prev_target"] if x["prev_type"] in (RELATIVE, ABSOLUTE) else p
        target = step.Position if kind == ABSOLUTE else base + step.Position
        spec = Job(JobKind.ABSOLUTE if kind == ABSOLUTE else JobKind.RELATIVE, velocity=step.Velocity,
                   extra={"end_velocity": self._table_blend_velocity(job, n, target, p)})
        spec.target = job.target = target
        x["phase"] = "position"
        x["prev_type"], x["prev_target"] = kind, target
        self._plan_job(job, t, spec, new_command=first)

    def _table_blend_velocity(self: "PositioningAxis", job: Job, n: int, target: float, p: float) -> float:
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

    def _table_end(self: "PositioningAxis", job: Job, t: float) -> None:
        """The profile of the current step ended."""
        phase = job.extra["phase"]
        if phase in ("position", "halt"):
            self._table_next(job, t)
        elif phase == "final_stop":
            self._finish_job(job, JobState.DONE, t)
            self._table_release(job)

    def _table_timer(self: "PositioningAxis", t: float) -> None:
        job = self.table_job
        if job is not None and job.busy and job.extra["phase"] in ("wait", "velocity"):
            self._table_next(job, t)

    def _table_finish(self: "PositioningAxis", job: Job, t: float) -> None:
        p, v, a = self._state_at(t)
        if job.extra["took_over"] and abs(v) > 1e-12:
            job.extra["phase"] = "final_stop"
            self._start_profile(self.motion.stop_with(t, p, v, a, limits(self)))
            self._interpolating = True
            return
        self._finish_job(job, JobState.DONE, t)
        self._table_release(job)

    def _table_fail(self: "PositioningAxis", job: Job, fault: F.Fault, t: float) -> None:
        job.finish(JobState.ERROR, fault)
        if self.job is job:
            self.job = None
        self._table_release(job)

    def _table_release(self: "PositioningAxis", job: Job) -> None:
        table: CommandTable = job.extra["table"]
        if table.in_use_by is job:
            table.in_use_by = None
        if self.table_job is job:
            self.table_job = None
        self._timers.pop("table", None)
