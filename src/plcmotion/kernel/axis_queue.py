"""The job queue of a positioning axis: ``QueueOwner`` (kernel/job_queue.py) over ``PositioningAxis``.

The queue takes every job of the axis (``PositioningAxis.submit``) and decides when it starts; this binding
starts it through the axis's one start path (``PositioningAxis.start_job``: start conditions, the family's
override policy, the plan), answers the kinematic questions from the axis's planner and limits, and
re-plans the running positioning for a blend (kernel/blending.py).
"""
from __future__ import annotations

import math
from typing import Any

from .blending import stoppable_speed
from .faults import Fault
from .job_queue import BufferMode, JobQueue
from .jobs import POSITIONING_KINDS, Job, JobKind, JobState
from .motion import limits, modulo_target

__all__ = ["AxisQueueOwner", "BufferMode", "axis_queue"]


def axis_queue(axis: Any, depth: int = 1) -> JobQueue:
    return JobQueue(AxisQueueOwner(axis), depth)


class AxisQueueOwner:
    """``QueueOwner`` of a ``PositioningAxis`` (typed loosely: the kernel's axis imports this module)."""

    def __init__(self, axis: Any):
        self.axis = axis

    def running_job(self) -> Job | None:
        job = self.axis.job
        return job if job is not None and job.busy else None

    def admit(self, job: Job) -> Fault | None:
        fault = self.axis.check_start(job)
        if fault is None:
            # the family may refuse waiting behind some running activities (kernel/policy.py ``appending``)
            refusal = self.axis.policy.append_refusal(job, self.axis._activities())
            if refusal is not None:
                fault = refusal.fault()
        return fault

    def take_over(self, job: Job, after: Job | None = None) -> None:
        ax = self.axis
        previous = after
        if (job.kind == JobKind.RELATIVE and previous is not None and previous.kind in POSITIONING_KINDS
                and previous.state == JobState.DONE):
            # PLCopen: relative to the set position when the job starts, which after a positioning is its
            # target -- also in a blend, which is taken over up to a servo cycle after passing it
            job.extra["relative_base"] = previous.target
        ax.start_job(job)

    def finish(self, job: Job, state: JobState) -> None:
        self.axis._finish_job(job, state, self.axis.now)

    def commanded_speed(self, job: Job) -> float:
        if job.kind in POSITIONING_KINDS or job.kind == JobKind.VELOCITY:
            return limits(self.axis, self.axis.commanded_velocity(job.velocity), job=job).velocity
        return 0.0

    def _heading(self, running: Job) -> float:
        p = self.axis._state_now()[0]
        d = running.target - p
        if abs(d) > 1e-12:
            return math.copysign(1.0, d)
        return math.copysign(1.0, self.axis._state_now()[1] or 1.0)

    def _next_way(self, running: Job, job: Job) -> float | None:
        """Signed way of ``job`` from the target of ``running`` (None: no target, e.g. a velocity job)."""
        if job.kind == JobKind.RELATIVE:
            return job.position
        if job.kind == JobKind.ABSOLUTE:
            ax = self.axis
            if ax.config.modulo.enabled:
                sign = self._heading(running)
                lim = limits(ax, job.velocity)
                goal = modulo_target(ax, job.position, job.direction, sign, running.target, 0.0, 0.0, lim,
                                     ax.motion.planner)
                return goal - running.target
            return job.position - running.target
        return None

    def reverses(self, running: Job, job: Job) -> bool:
        heading = self._heading(running)
        if job.kind == JobKind.VELOCITY:
            return job.velocity * heading <= 0.0
        way = self._next_way(running, job)
        return way is None or way * heading <= 0.0

    def plan_blend(self, running: Job, job: Job | None, speed: float) -> float:
        ax = self.axis
        if job is None:
            # the job it was to blend into is gone: the positioning stops at its target again (from beyond
            # it, if it has passed it already)
            if running.extra.pop("blend_speed", None) and running is ax.job and running.busy:
                ax._plan_job(running, ax.now, new_command=False)
            return 0.0
        if running is not ax.job or not ax._interpolating:
            return 0.0                       # its motion has ended already: the handover is at Done
        way = self._next_way(running, job)
        if way is not None:
            # the next positioning must still be able to stop at its target from the transition speed, and
            # it takes over in the first servo cycle after the target is passed: up to one cycle later
            lim = limits(ax, self.commanded_speed(job), job=job)
            first = stoppable_speed(ax.motion.planner, abs(way), lim)
            late = abs(way) - first * ax.ctl.servo_cycle
            speed = min(speed, stoppable_speed(ax.motion.planner, late, lim) if late > 0 else 0.0)
        if speed <= 0.0:
            return 0.0
        running.extra["blend_speed"] = speed
        if not ax._plan_job(running, ax.now, new_command=False):
            return 0.0
        return abs(ax.profile.final.v)

    def passed_target(self, job: Job) -> bool:
        ax = self.axis
        return bool(job.extra.get("blend_speed")) and job is ax.job and not ax._interpolating

    def settle(self) -> None:
        ax = self.axis
        if ax.job is not None and ax.job.busy:
            return
        t = ax.now
        p, v, a = ax._state_now()
        if abs(ax.profile.final.v) > 0.0 and ax.state == "enabled":
            ax._start_profile(ax.motion.stop_with(t, p, v, a, limits(ax)))
