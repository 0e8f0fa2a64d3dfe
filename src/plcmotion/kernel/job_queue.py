"""Per-axis job queue with the PLCopen buffer modes.

A motion job either takes the axis over at once (``BufferMode.ABORTING``, what every family did so far) or
waits behind the running job and starts when that one is finished (``BUFFERED``) or passes its target
without stopping (``BLENDING_*``).  The rules follow PLCopen Motion Control Part 1 (v2.0), section 2.4
"BufferMode" and the "Active" output:

* Aborting: the new job starts at once; the running job and every waiting job end aborted (unless the
  family's override policy lets the running job go on beside the new one, kernel/policy.py).
* Buffered: the job starts when the running job is Done; for a velocity job that never is Done, when it has
  reached its velocity (InVelocity) -- it then ends aborted (PLCopen gives a continuous motion no Done).
  On an axis without a running job a buffered or blended job starts at once.
* BlendingLow / Previous / Next / High: the running positioning passes its target without stopping, at the
  lower / its own / the next job's / the higher commanded velocity; 0 when the next job reverses the
  direction, lowered when the remaining distance or the dynamics cannot reach it (kernel/blending.py).  A
  running job without a target (velocity, halt) cannot blend: the job waits as a buffered one.
* Outputs: a waiting job is Busy but not Active (``Job.pending``); the running job is Done (or aborted, for
  a velocity job) in the same instant in which the next one takes over.
* A waiting job ends aborted with the job it waits for when that one is aborted or fails; a job that cannot
  start when its turn comes ends with its fault, and the jobs behind it are aborted.

The depth (how many jobs may wait) is the family's: PLCopen implementations commonly buffer one job, as
do the S7-Technology examples (V4.1 manual, MC_MoveAbsolute "Append motion", ErrorID 8005 "command memory
is full") and the Pilz motion core (one "buffered subsequent motion block", I83).  A full queue rejects the
job with ``faults.QUEUE_FULL``; the running job goes on.

The queue knows the axis only through ``QueueOwner``: it decides *when* a job starts and *which*
transition velocity it asks for; the owner starts jobs and plans the kinematics.
"""
from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from enum import IntEnum
from typing import Protocol

from . import faults as F
from .faults import Fault
from .jobs import POSITIONING_KINDS, Job, JobKind, JobState


class BufferMode(IntEnum):
    """PLCopen MC_BufferMode, numbered in the order of PLCopen Part 1 (mcAborting = 0 ... mcBlendingHigh = 5)."""

    ABORTING = 0
    BUFFERED = 1
    BLENDING_LOW = 2
    BLENDING_PREVIOUS = 3
    BLENDING_NEXT = 4
    BLENDING_HIGH = 5

    @property
    def blending(self) -> bool:
        return self >= BufferMode.BLENDING_LOW


#: running jobs a job can wait behind: their end is defined (Done, or InVelocity for a velocity job)
CHAINABLE = frozenset({JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.VELOCITY, JobKind.HALT})
#: running jobs that end in a continuous motion: a waiting job takes over at InVelocity
CONTINUOUS = frozenset({JobKind.VELOCITY})


def transition_velocity(mode: BufferMode, previous: float, following: float, *, reverses: bool) -> float:
    """Speed at which a blend passes the first job's target (PLCopen Part 1, BufferMode table).

    ``previous`` / ``following``: the commanded speeds (magnitudes) of the running and of the waiting job;
    ``reverses``: the waiting job moves the other way, so the axis has to stand at the target.
    Aborting and Buffered pass no target in motion: 0.
    """
    if reverses or not mode.blending:
        return 0.0
    previous, following = abs(previous), abs(following)
    if mode == BufferMode.BLENDING_LOW:
        return min(previous, following)
    if mode == BufferMode.BLENDING_PREVIOUS:
        return previous
    if mode == BufferMode.BLENDING_NEXT:
        return following
    return max(previous, following)


class QueueOwner(Protocol):
    """What the queue needs from the axis it belongs to."""

    def running_job(self) -> Job | None:
        """The busy job that controls the axis (None at rest)."""

    def admit(self, job: Job) -> Fault | None:
        """Whether ``job`` may be accepted now (axis enabled, homed for an absolute target, ...)."""

    def take_over(self, job: Job, after: Job | None = None) -> None:
        """Start ``job`` now, aborting whatever runs (the aborting path); a rejection ends ``job``.
        ``after``: the job it was queued behind (Done, or still running when it is a velocity job)."""

    def finish(self, job: Job, state: JobState) -> None:
        """End the running ``job`` (the owner then reports it back through ``JobQueue.finished``)."""

    def commanded_speed(self, job: Job) -> float:
        """The speed ``job`` asks for, within the axis limits (0 for a job without one)."""

    def reverses(self, running: Job, job: Job) -> bool:
        """Whether ``job``, started at the target of ``running``, moves against its direction of travel."""

    def plan_blend(self, running: Job, job: Job | None, speed: float) -> float:
        """Re-plan the running positioning to pass its target at ``speed`` (lowered where the distance or the
        dynamics do not allow it) on the way to ``job``; returns the planned speed (0: it stops there).
        ``job`` None: the blend is cancelled, the positioning stops at its target again."""

    def passed_target(self, job: Job) -> bool:
        """Whether the running positioning ``job`` has passed its target in a blend."""

    def settle(self) -> None:
        """No job controls the axis any more: brake a motion a blend left running."""


@dataclass(eq=False)
class _Waiting:
    job: Job
    mode: BufferMode
    velocity: float | None = None      # transition velocity given by the family (Pilz "End velocity")


class JobQueue:
    """The running job of one axis and the jobs waiting behind it."""

    def __init__(self, owner: QueueOwner, depth: int = 1):
        self.owner = owner
        self.depth = depth              # how many jobs may wait (family setting; 0: no buffering)
        self._waiting: deque[_Waiting] = deque()
        self._running: Job | None = None   # the job the first waiting one follows

    @property
    def pending(self) -> tuple[Job, ...]:
        """The waiting jobs in the order they will start."""
        return tuple(w.job for w in self._waiting)

    def mode_of(self, job: Job) -> BufferMode | None:
        for w in self._waiting:
            if w.job is job:
                return w.mode
        return None

    # --- entry ---------------------------------------------------------------------------------------
    def submit(self, job: Job, mode: BufferMode = BufferMode.ABORTING, *,
               transition_velocity: float | None = None) -> None:
        """Hand ``job`` to the axis with a buffer mode; a rejection ends ``job`` with its fault.

        ``transition_velocity``: for the blending modes, a speed the family commands for the transition
        instead of the PLCopen choice between the two commanded velocities (the Pilz motion core's "End
        velocity" I429 of the running block); it is lowered and zeroed like the PLCopen one.
        """
        mode = BufferMode(mode)
        running = self.owner.running_job()
        if mode == BufferMode.ABORTING:
            self.owner.take_over(job)
            if job.busy and running is not None and not running.busy:
                # the waiting jobs go with the job they wait for (normally done already when the owner
                # reported it aborted); a job that lets the running one go on (a superimposed motion, by
                # the family's policy) leaves them waiting
                self._abort_waiting()
            return
        if running is None or not running.busy:
            self.owner.take_over(job)        # nothing to wait for: starts at once
            return
        fault = self.owner.admit(job)
        if fault is None and len(self._waiting) >= self.depth:
            fault = F.reject(F.QUEUE_FULL, str(self.depth))
        if fault is None and not self._waiting and running.kind not in CHAINABLE:
            fault = F.reject(F.NOT_APPENDABLE, running.kind.value)
        if fault is not None:
            job.finish(JobState.ERROR, fault)
            return
        job.pending = True
        self._waiting.append(_Waiting(job, mode, transition_velocity))
        if len(self._waiting) == 1:
            self._running = running
            self._prepare_transition()
            self.poll()                      # a velocity job may be at its velocity already

    # --- events the owner reports -----------------------------------------------------------------------
    def finished(self, job: Job) -> None:
        """``job`` has ended (any state); called by the owner for every job that ends."""
        if not self._waiting or job is not self._running:
            return
        if job.state == JobState.DONE:
            self._advance()
        else:
            self._abort_waiting()

    def poll(self) -> None:
        """Check the start condition of the first waiting job (the owner calls this after its events)."""
        if not self._waiting:
            return
        running = self._running
        if running is None or not running.busy:
            # ended without being reported: follow it as ``finished`` would
            if running is not None and running.state == JobState.DONE:
                self._advance()
            else:
                self._abort_waiting()
            return
        if running.kind in CONTINUOUS and running.in_velocity:
            self._advance()                  # taking over ends the velocity job aborted (no Done in PLCopen)
        elif running.kind in POSITIONING_KINDS and self.owner.passed_target(running):
            self.owner.finish(running, JobState.DONE)    # reported back through finished() -> _advance

    def abort_all(self) -> None:
        """End every waiting job aborted; a running positioning planned to blend into one stops at its target."""
        running = self._running
        blended = bool(self._waiting) and self._waiting[0].mode.blending
        self._abort_waiting()
        if blended and running is not None and running.busy and running.kind in POSITIONING_KINDS:
            self.owner.plan_blend(running, None, 0.0)

    # --- rules ----------------------------------------------------------------------------------------
    def _advance(self) -> None:
        w = self._waiting.popleft()
        job = w.job
        job.pending = False
        previous, self._running = self._running, job   # first: ending the previous must not abort the rest
        self.owner.take_over(job, previous)
        if not job.busy:
            # rejected at its start (or ended at once by an alarm): the jobs meant to follow it go too
            self._abort_waiting()
            if self.owner.running_job() is None:
                self.owner.settle()
            return
        if self._waiting:
            self._prepare_transition()

    def _prepare_transition(self) -> None:
        """Plan how the running job hands over to the first waiting one (only blending needs planning)."""
        w = self._waiting[0]
        running = self._running
        if not w.mode.blending or running is None or running.kind not in POSITIONING_KINDS:
            return                           # buffered, or nothing to blend at (velocity, halt): stop/InVelocity
        reverses = self.owner.reverses(running, w.job)
        if w.velocity is not None:
            speed = 0.0 if reverses else abs(w.velocity)
        else:
            speed = transition_velocity(w.mode, self.owner.commanded_speed(running),
                                        self.owner.commanded_speed(w.job), reverses=reverses)
        if speed > 0.0:
            self.owner.plan_blend(running, w.job, speed)

    def _abort_waiting(self) -> None:
        while self._waiting:
            job = self._waiting.popleft().job
            job.pending = False
            job.finish(JobState.ABORTED)
        self._running = None
