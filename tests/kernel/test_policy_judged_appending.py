"""Two policy cells beyond fixed marks, on a kernel axis without any dialect.

* A ``Judged`` cell answers from both jobs: here a running velocity job is aborted by a move in the other
  direction and refuses a move in its own direction (a rule a fixed mark cannot give).
* The ``appending`` table refuses a job that is to wait behind a running one (Buffered) because of what
  runs; the same job taking the axis over at once (Aborting) does not look at it.
* A refusal applies also to a job the policy starts in the superimposed slot.

Expected outcomes are the cells of the small policy below, written out as data, and the PLCopen buffer
mode rules; nothing is taken from the code under test.
"""
from __future__ import annotations

import dataclasses

import pytest

from plcmotion.kernel import faults as F
from plcmotion.kernel.job_queue import BufferMode
from plcmotion.kernel.jobs import Job, JobKind, JobState
from plcmotion.kernel.policy import (ABORT, HALT, KEEP, MOTION, SUPERIMPOSED, Activity, Judged, OverridePolicy,
                                     Reject, table)

from .test_submit_policy import enabled_axis, moving, policy_families  # noqa: F401  (the test families)

SAME_WAY = Reject(F.REJECTED, "same_way")
NO_APPEND = Reject(F.NOT_APPENDABLE, "halt")
LOCKED = Reject(F.REJECTED, "locked")


def _other_way(new: Job | None, running: Job | None) -> ABORT.__class__ | Reject:
    """Abort a running velocity job when the new one moves against it; refuse one in its direction."""
    if new is None or running is None:
        return SAME_WAY
    if new.kind == JobKind.RELATIVE and running.kind == JobKind.VELOCITY and new.position * running.velocity < 0:
        return ABORT
    return SAME_WAY


CELLS = table((HALT, MOTION), {
    #              halt  motion
    MOTION:       "A     J",
    HALT:         "A     A",
    SUPERIMPOSED: "L     -",
}, J=Judged(_other_way), L=LOCKED)
POLICY = OverridePolicy("judged", CELLS, queue_depth=1, appending={MOTION: {HALT: NO_APPEND}},
                        buffer_modes={0: BufferMode.ABORTING, 1: BufferMode.BUFFERED},
                        classify=lambda job: {JobKind.HALT: HALT, JobKind.SUPERIMPOSED: SUPERIMPOSED}.get(job.kind,
                                                                                                         MOTION),
                        slots={SUPERIMPOSED: "superimposed"})


def _axis():
    ctl, axis = enabled_axis()
    axis.policy = POLICY
    return ctl, axis


def test_kernel_policy_judged_cell_answers_from_both_jobs():
    running = Activity(MOTION, Job(JobKind.VELOCITY, velocity=20.0), lambda t: None)
    assert POLICY.decide(MOTION, Job(JobKind.RELATIVE, position=-5.0), running) is ABORT
    assert POLICY.decide(MOTION, Job(JobKind.RELATIVE, position=5.0), running) == SAME_WAY
    assert POLICY.decide(MOTION, None, running) == SAME_WAY          # a query without a job
    assert POLICY.aborts(MOTION, MOTION) and POLICY.cell(HALT, SUPERIMPOSED) is KEEP


def test_kernel_policy_judged_cell_on_the_job_path():
    ctl, axis = _axis()
    run = moving(ctl, axis, 20.0)
    same = Job(JobKind.RELATIVE, position=50.0, velocity=10.0)
    axis.submit(same)
    assert same.state == JobState.ERROR and same.fault.detail == "same_way" and run.active
    back = Job(JobKind.RELATIVE, position=-50.0, velocity=10.0)
    axis.submit(back)
    assert run.state == JobState.ABORTED and back.active and axis.job is back


def test_kernel_policy_appending_refuses_a_waiting_job_only():
    ctl, axis = _axis()
    moving(ctl, axis, 20.0)
    halt = Job(JobKind.HALT)
    axis.submit(halt)
    waiting = Job(JobKind.RELATIVE, position=10.0, velocity=10.0)
    axis.submit(waiting, POLICY.buffer_mode(1))
    assert waiting.state == JobState.ERROR and waiting.fault == NO_APPEND.fault()
    assert halt.active and axis.queue.pending == ()
    at_once = Job(JobKind.RELATIVE, position=10.0, velocity=10.0)
    axis.submit(at_once, POLICY.buffer_mode(0))                      # MOTION / halt: "A"
    assert halt.state == JobState.ABORTED and at_once.active


def test_kernel_policy_appending_allows_what_it_does_not_list():
    ctl, axis = _axis()
    first = Job(JobKind.RELATIVE, position=20.0, velocity=20.0)
    axis.submit(first)
    second = Job(JobKind.RELATIVE, position=10.0, velocity=20.0)
    axis.submit(second, BufferMode.BUFFERED)
    assert axis.queue.pending == (second,) and second.busy and not second.active
    ctl.run_until(lambda: not second.busy, 20.0)
    assert first.state == JobState.DONE and second.state == JobState.DONE


def test_kernel_policy_without_appending_table_refuses_nothing():
    assert OverridePolicy("plain", {}).append_refusal(Job(JobKind.RELATIVE), [
        Activity(HALT, Job(JobKind.HALT), lambda t: None)]) is None


@pytest.mark.parametrize("running_halt", [True, False])
def test_kernel_policy_refusal_applies_to_a_slotted_job(running_halt):
    """A job of a class the policy starts in the superimposed slot is still refused by a Reject cell (here:
    SUPERIMPOSED / halt "L"); with nothing refusing it, it reaches the slot."""
    ctl, axis = _axis()
    started = []
    axis.start_superimposed = lambda job, lim: started.append(job)     # the ability, as a probe
    if running_halt:
        moving(ctl, axis, 20.0)
        axis.submit(Job(JobKind.HALT))
    job = Job(JobKind.SUPERIMPOSED, position=1.0, velocity=1.0)
    axis.submit(job)
    if running_halt:
        assert job.state == JobState.ERROR and job.fault == LOCKED.fault() and started == []
        assert axis.job.kind == JobKind.HALT and axis.job.busy
    else:
        assert started == [job] and job.busy


def test_kernel_policy_dataclass_replace_keeps_appending():
    assert dataclasses.replace(POLICY, queue_depth=2).appending == POLICY.appending
