"""Runners: components that run a kind of job the axis does not plan itself.

The axis plans the single-move jobs of the motion instructions itself.  A family may add a kind of job
that is a program of motion steps (one job, several moves planned one after the other, e.g. a table of
steps with waits between them).  Its component - the *runner* - plans those steps; the family attaches it
to the axis (``axis.attach_runner(runner)``, kept in ``axis.runners`` by job kind), and the axis only
hands it the events of such a job:

* the end of the profile of the runner's current step (``on_profile_end``);
* the runner's own timer in the axis's timer list (``on_timer``);
* the end of the job, whoever ended it (``release``).

A runner's job is Busy from its start, possibly before it takes the axis over (while it waits for its
first motion step).  Until then it is a *secondary* job of the axis: a new motion job, an alarm with a
stop reaction and disabling end it too, which the axis does through ``runner.job``.  While the runner's
job runs, re-planning after a parameter change is left to the runner (it plans its own steps).
"""
from __future__ import annotations

from typing import Protocol

from .jobs import Job, JobKind


class JobRunner(Protocol):
    """What the axis needs from a runner."""

    kind: JobKind            # the jobs it runs
    timer: str               # the name of its timer in the axis's timer list
    job: Job | None          # its job, also before it takes the axis over; None when it runs none

    def on_timer(self, t: float) -> None:
        """The runner's timer is due at servo time ``t``."""

    def on_profile_end(self, job: Job, t: float) -> None:
        """The profile of the current step of ``job`` (the axis's running job) ended at ``t``."""

    def release(self, job: Job) -> None:
        """``job`` has ended (Done, Aborted or Error): forget it."""
