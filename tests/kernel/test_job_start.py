"""The job start component (``kernel.job_start.JobStart``): its start conditions alone on a fake axis, then the
start of jobs on a kernel ``Controller`` axis (no dialect).

Expected behaviour from S7-1200 Motion Control V6 (seeds/000): §11.1 "Requirements" of the motion
instructions and §12.8 (16#8xxx rejections: axis not enabled, not homed for absolute positioning, too many
simultaneous commands), §2.2.7.4 (no motion jobs while the CPU is not in RUN), §11.1.4 (MC_MoveRelative:
the target is the start position plus the distance).
"""
from __future__ import annotations

from types import SimpleNamespace

import pytest

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel.jobs import Job, JobKind, JobState
from plcmotion.kernel.job_start import JobStart


class FakeAxis:
    """A JobStartHost with what ``check_start`` reads: an enabled, homed, simulated axis."""

    def __init__(self):
        self.ctl = SimpleNamespace(mode="RUN", rules=frozenset(), servo_cycle=0.001)
        self.state = "enabled"
        self.homed = True
        self.alarms: list[F.Fault] = []
        self.busy_commands: set[int] = set()
        self.max_commands = 2
        self.pto = self.servo = False
        self.activated = True
        self.sensor_valid = True

    def pto_used_by_other(self):
        return False

    def _blocking_alarm(self):
        return self.alarms[0] if self.alarms else None


@pytest.mark.parametrize("change, kind", [
    (lambda ax: setattr(ax.ctl, "mode", "STARTUP"), F.REJECTED),          # §2.2.7.4
    (lambda ax: setattr(ax, "state", "disabled"), F.NOT_ENABLED),         # §11.1: the axis must be enabled
    (lambda ax: ax.busy_commands.update({1, 2}), F.TOO_MANY_COMMANDS),    # §12.8: too many commands
    (lambda ax: setattr(ax, "homed", False), F.NOT_HOMED),                # §11.1.3: absolute needs homed
])
def test_kernel_job_start_conditions_reject(change, kind):
    """S7-1200 V6 §11.1 "Requirements", §12.8: a job that may not start is rejected with the reason."""
    ax = FakeAxis()
    start = JobStart(ax)
    job = Job(JobKind.ABSOLUTE, position=10.0, velocity=5.0)
    assert start.check_start(job) is None
    change(ax)
    fault = start.check_start(job)
    assert fault is not None and fault.kind == kind


def test_kernel_job_start_relative_needs_no_homing():
    """S7-1200 V6 §11.1.4: MC_MoveRelative does not require a homed axis."""
    ax = FakeAxis()
    ax.homed = False
    assert JobStart(ax).check_start(Job(JobKind.RELATIVE, position=1.0, velocity=1.0)) is None


def test_kernel_job_start_on_a_controller_axis():
    """S7-1200 V6 §11.1: a job on a disabled axis ends with an error at once; on the enabled axis a relative
    positioning goes from the position at its start by the distance (§11.1.4), and a new job aborts it."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004, input_filter=0.0)
    axis = ctl.add_positioning_axis("Axis_1", {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0})
    early = Job(JobKind.RELATIVE, position=10.0, velocity=20.0)
    axis.submit(early)
    assert early.state == JobState.ERROR and early.fault.kind == F.NOT_ENABLED
    axis.power(object(), True, 1, 0)
    ctl.run(0.1)
    p0 = axis._state_now()[0]
    first = Job(JobKind.RELATIVE, position=10.0, velocity=20.0)
    axis.submit(first)
    assert first.busy and axis.job is first and first.target == pytest.approx(p0 + 10.0)
    ctl.run(0.2)
    second = Job(JobKind.RELATIVE, position=1.0, velocity=20.0)
    axis.submit(second)
    assert first.state == JobState.ABORTED and axis.job is second
