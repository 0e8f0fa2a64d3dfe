"""Job runners at kernel level (``kernel.job_runner``): a family's component that runs a kind of job the
axis does not plan itself (no dialect; a throw-away family gives a bare kernel axis).

The toy runner runs a program of relative moves, optionally after a wait before it takes the axis over.
Expected values come from kinematics (the moves add up) and the PLCopen job states (a job ends exactly
once, as Done, Aborted or Error), never from the code under test.
"""
from __future__ import annotations

import pytest

from ._schema_axis import with_schema

from plcmotion import Controller
from plcmotion.kernel import family as families
from plcmotion.kernel import faults as F
from plcmotion.kernel.axis import PositioningAxis
from plcmotion.kernel.faults import Reaction
from plcmotion.kernel.jobs import Job, JobKind, JobState

PARAMS = {"Actor.Type": 1, "Simulation.Mode": 1, "DynamicDefaults.Acceleration": 10.0,
          "DynamicDefaults.Deceleration": 10.0, "DynamicLimits.MaxVelocity": 100.0, "DynamicDefaults.Jerk": 0.0}


class Moves:
    """A runner: its job (kind TABLE) moves by each distance in ``job.extra["moves"]`` in turn."""

    kind = JobKind.TABLE
    timer = "moves"

    def __init__(self, axis):
        self.axis = axis
        self.job: Job | None = None
        self.log: list[tuple[str, float]] = []

    def start(self, job: Job, wait: float = 0.0) -> None:
        self.job = job
        job.extra["left"] = list(job.extra["moves"])
        if wait:
            self.axis._timers[self.timer] = self.axis.now + wait      # waits before it takes over
            self.axis._schedule()
        else:
            self.on_timer(self.axis.now)

    def on_timer(self, t: float) -> None:
        self.log.append(("timer", t))
        ax = self.axis
        if ax.job is not None and ax.job.busy:
            ax._finish_job(ax.job, JobState.ABORTED, t)
        ax.job = self.job
        self._move(t)

    def on_profile_end(self, job: Job, t: float) -> None:
        self.log.append(("end", t))
        if job.extra["left"]:
            self._move(t)
        else:
            self.axis._finish_job(job, JobState.DONE, t)

    def release(self, job: Job) -> None:
        self.log.append(("release", job.state.name))
        if self.job is job:
            self.job = None
        self.axis._timers.pop(self.timer, None)        # the runner's timer belongs to its job

    def _move(self, t: float) -> None:
        distance = self.job.extra["left"].pop(0)
        p = self.axis._state_at(t)[0]
        step = Job(JobKind.RELATIVE, velocity=20.0)
        step.target = p + distance
        self.axis._plan_job(self.job, t, step)


@pytest.fixture
def axis():
    # the kernel axis takes its schema from a family's axis class: borrow the default family's, without its
    # factory (so no runner of that family is attached)
    axis_class = with_schema(PositioningAxis, PARAMS)

    def factory(ctl, name, flat, where):
        return ctl.new_axis(axis_class, name, flat, where)

    fam = families.register(families.Family("Kernel-Test", versions=(1,), default_version=1,
                                            factories={families.POSITIONING_AXIS: factory}))
    try:
        ctl = Controller(family="Kernel-Test")
        ax = ctl.add_positioning_axis("A", PARAMS)
        assert ax.runners == {}                       # a bare kernel axis runs no family's jobs
        assert ax.power(object(), True, 1, 0) is None
        ctl.run(0.02)
        assert ax.state == "enabled"
        yield ax
    finally:
        families._REGISTRY.pop(fam.name)


def test_kernel_job_runner_plans_the_steps_of_its_job(axis):
    """The axis hands the runner the end of each step's profile; the moves add up (10 + 15 - 5 = 20)."""
    runner = axis.attach_runner(Moves(axis))
    assert axis.runners == {JobKind.TABLE: runner}
    job = Job(JobKind.TABLE, extra={"moves": [10.0, 15.0, -5.0]})
    p0 = axis._state_now()[0]
    runner.start(job)
    axis.ctl.run_until(lambda: not job.busy, 20.0)
    assert job.state == JobState.DONE and axis.job is None and runner.job is None
    assert axis._state_now()[0] == pytest.approx(p0 + 20.0, abs=1e-9)
    assert [e for e, _ in runner.log] == ["timer", "end", "end", "end", "release"]


def test_kernel_job_runner_waiting_job_is_ended_by_a_new_motion_job(axis):
    """A runner's job that has not taken the axis over yet is aborted by a new motion job."""
    runner = axis.attach_runner(Moves(axis))
    job = Job(JobKind.TABLE, extra={"moves": [10.0]})
    runner.start(job, wait=1.0)
    axis.ctl.run(0.1)
    assert job.busy and axis.job is None
    move = Job(JobKind.RELATIVE, position=1.0, velocity=5.0)
    axis.submit(move)
    assert job.state == JobState.ABORTED and move.busy and runner.job is None
    axis.ctl.run(1.5)
    assert runner.log == [("release", "ABORTED")] and move.state == JobState.DONE and not axis.alarms


@pytest.mark.parametrize("reaction, ends", [(Reaction.STOP, True), (Reaction.NONE, False)])
def test_kernel_job_runner_waiting_job_and_alarms(axis, reaction, ends):
    """An alarm with a stop reaction ends a waiting runner job with the alarm; a warning does not."""
    runner = axis.attach_runner(Moves(axis))
    job = Job(JobKind.TABLE, extra={"moves": [10.0]})
    runner.start(job, wait=1.0)
    fault = F.alarm(F.INTERNAL, "test", reaction)
    axis.raise_alarm(fault)
    assert (job.state, job.fault) == ((JobState.ERROR, fault) if ends else (JobState.BUSY, None))


def test_kernel_job_runner_jobs_end_when_the_axis_is_disabled(axis):
    """Disabling aborts the runner's job, running or still waiting."""
    runner = axis.attach_runner(Moves(axis))
    job = Job(JobKind.TABLE, extra={"moves": [50.0]})
    runner.start(job)
    axis.ctl.run(0.2)
    assert job.busy and axis.job is job
    axis.power(axis.power_owner, False, 1, 0)
    assert job.state == JobState.ABORTED and runner.job is None and axis.job is None


def test_kernel_job_runner_job_is_not_replanned_by_the_axis(axis):
    """A changed dynamic default re-plans the axis's own motion jobs, not a runner's step (it plans its
    own steps): the step keeps its profile."""
    runner = axis.attach_runner(Moves(axis))
    job = Job(JobKind.TABLE, extra={"moves": [50.0]})
    runner.start(job)
    axis.ctl.run(0.2)
    profile = axis.profile
    axis._replan()
    assert axis.profile is profile
