"""The positioning monitoring component (``kernel.positioning_monitor.PositioningMonitor``): alone on a fake
axis, then on a kernel ``Controller`` axis (no dialect).

Expected behaviour from S7-1200 Motion Control V6 (seeds/000) §5.4.4.6 "Positioning monitoring": after the
setpoint reached the target the actual value must reach the positioning window within the tolerance time and
stay there for the minimum dwell time, then the job is done; otherwise a positioning error (§12.8 16#8011,
reaction remove enable).
"""
from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel.faults import Reaction
from plcmotion.kernel.jobs import Job, JobKind, JobState
from plcmotion.kernel.positioning_monitor import PositioningMonitor


class FakeAxis:
    def __init__(self):
        bank = SimpleNamespace(pm_target=[0.0], pm_deadline=[0.0], pm_in_since=[0.0], pm_on=[False])
        self.ctl = SimpleNamespace(bank=bank, _n_pm=0)
        self.index = 0
        self.config = SimpleNamespace(positioning=SimpleNamespace(tolerance_time=1.0))
        self.profile = SimpleNamespace(final=SimpleNamespace(p=25.0))
        self.finished: list[tuple] = []
        self.alarms: list[tuple] = []

    def _finish_job(self, job, state, t, fault=None):
        job.finish(state, fault)
        self.finished.append((job, state, t))

    def raise_alarm(self, fault, job=None):
        self.alarms.append((fault, job))


def test_kernel_positioning_monitor_arms_the_window_check_at_the_target():
    """§5.4.4.6: the check watches the target of the setpoint and allows the tolerance time from now on."""
    ax = FakeAxis()
    pm = PositioningMonitor(ax)
    job = Job(JobKind.ABSOLUTE, position=25.0)
    pm.start(job, 2.0)
    b = ax.ctl.bank
    assert b.pm_on[0] and b.pm_target[0] == 25.0 and b.pm_deadline[0] == 3.0 and math.isnan(b.pm_in_since[0])
    assert ax.ctl._n_pm == 1 and pm.job is job
    pm.start(job, 2.5)                               # armed again: still counted once
    assert ax.ctl._n_pm == 1
    pm.stop()
    assert not b.pm_on[0] and ax.ctl._n_pm == 0 and pm.job is None
    pm.stop()
    assert ax.ctl._n_pm == 0


def test_kernel_positioning_monitor_in_window_ends_the_job_done():
    """§5.4.4.6: in the window for the dwell time - the positioning is done."""
    ax = FakeAxis()
    pm = PositioningMonitor(ax)
    job = Job(JobKind.RELATIVE, position=5.0)
    pm.start(job, 0.0)
    pm.on_positioned(0.4)
    assert job.state == JobState.DONE and ax.finished == [(job, JobState.DONE, 0.4)] and ax.ctl._n_pm == 0


def test_kernel_positioning_monitor_fault_removes_the_enable():
    """§5.4.4.6, §12.8: not in the window in time - a positioning alarm with reaction remove enable that
    ends the job."""
    ax = FakeAxis()
    pm = PositioningMonitor(ax)
    job = Job(JobKind.ABSOLUTE, position=25.0)
    pm.start(job, 0.0)
    pm.on_fault(1.0, "not_reached")
    (fault, victim), = ax.alarms
    assert fault.kind == F.POSITIONING and fault.reaction == Reaction.REMOVE_ENABLE and victim is job
    assert ax.ctl._n_pm == 0 and pm.job is None


def test_kernel_positioning_monitor_controller_axis_positioning_ends_in_the_window():
    """§5.4.4.6 on a drive axis: a relative positioning is done with the actual value in the window and the
    monitoring disarmed again."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004, input_filter=0.0)
    axis = ctl.add_positioning_axis("Axis_1", {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0})
    axis.power(object(), True, 1, 0)
    ctl.run(0.1)
    p0 = float(ctl.bank.act_p[axis.index])
    job = Job(JobKind.RELATIVE, position=10.0, velocity=20.0)
    axis.submit(job)
    ctl.run_until(lambda: not job.busy, 10.0)
    assert job.state == JobState.DONE and not axis.alarms
    window = axis.config.positioning.window
    assert float(ctl.bank.act_p[axis.index]) == pytest.approx(p0 + 10.0, abs=window)
    assert axis.positioning_monitor.job is None and not ctl.bank.pm_on[axis.index]
