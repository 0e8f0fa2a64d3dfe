"""The enable state machine component (``kernel.power.PowerControl``, MC_Power): alone on a fake axis, then
on a kernel ``Controller`` axis (no dialect).

Expected behaviour from S7-1200 Motion Control V6 (seeds/000): §11.1.1 MC_Power (Enable TRUE enables the
axis, only the instance that enabled it disables it, StopMode 0 emergency stop / 1 immediate stop / 2
emergency stop with jerk limit), §12.8 "Remove enable" (setpoint zero, enable off), §2.2.7.4 (no enabling
in STOP/STARTUP).
"""
from __future__ import annotations

from types import SimpleNamespace

import pytest

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel.jobs import Job, JobKind
from plcmotion.kernel.power import DISABLED, ENABLED, PowerControl


class FakeAxis:
    """A PowerHost that records which steps the state machine calls back (a family could override them)."""

    def __init__(self):
        self.ctl = SimpleNamespace(mode="RUN", _pto_holder={})
        self.config = SimpleNamespace(pulse_output=SimpleNamespace(generator=0))
        self.state = DISABLED
        self.power_owner = None
        self.stop_mode = 0
        self.alarms: list[F.Fault] = []
        self.pto = False
        self._after_stop = None
        self.calls: list[tuple] = []

    def _enable(self, start_mode):
        self.calls.append(("enable", start_mode))
        self.state = ENABLED

    def _disable(self, stop_mode):
        self.calls.append(("disable", stop_mode))
        self.state = DISABLED


def test_kernel_power_enable_and_disable_by_the_owner():
    """S7-1200 V6 §11.1.1: Enable = TRUE enables the axis (with the call's StartMode); Enable = FALSE of the
    same instance disables it with its StopMode, and the axis is free for another instance afterwards."""
    ax = FakeAxis()
    power = PowerControl(ax)
    owner = object()
    assert power.power(owner, True, 1, 2) is None
    assert ax.calls == [("enable", 1)] and ax.power_owner is owner and ax.stop_mode == 2
    assert power.power(owner, True, 1, 2) is None          # called again: nothing new
    assert ax.calls == [("enable", 1)]
    assert power.power(owner, False, 1, 0) is None
    assert ax.calls == [("enable", 1), ("disable", 0)] and ax.power_owner is None


def test_kernel_power_another_instance_is_refused_and_cannot_disable():
    """S7-1200 V6 §11.1.1: an axis enabled by one MC_Power cannot be enabled by a second one (error), and
    Enable = FALSE of the second one does not disable it."""
    ax = FakeAxis()
    power = PowerControl(ax)
    first, second = object(), object()
    power.power(first, True, 1, 0)
    fault = power.power(second, True, 1, 0)
    assert fault is not None and fault.kind == F.ALREADY_ENABLED
    assert power.power(second, False, 1, 0) is None
    assert ax.state == ENABLED and ax.power_owner is first and ax.calls == [("enable", 1)]


def test_kernel_power_no_enable_outside_run_and_none_while_an_alarm_is_pending():
    """S7-1200 V6 §2.2.7.4: no enabling while the CPU is not in RUN; §11.1.1: a pending error keeps the axis
    disabled until it is acknowledged."""
    ax = FakeAxis()
    ax.ctl.mode = "STARTUP"
    power = PowerControl(ax)
    fault = power.power(object(), True, 1, 0)
    assert fault is not None and fault.kind == F.REJECTED and ax.calls == []
    ax.ctl.mode = "RUN"
    ax.alarms.append(F.alarm(F.INTERNAL, "test"))
    assert power.power(object(), True, 1, 0) is None and ax.calls == [] and ax.state == DISABLED


@pytest.fixture
def controller_axis():
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004, input_filter=0.0)
    axis = ctl.add_positioning_axis("Axis_1", {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0})
    return ctl, axis


def test_kernel_power_controller_axis_enables_and_stop_mode_1_removes_the_enable_at_once(controller_axis):
    """S7-1200 V6 §11.1.1: a drive axis is enabled once its drive is ready; StopMode 1 (immediate stop)
    removes the enable of a drive axis at once (§12.8: the drive stops by itself)."""
    ctl, axis = controller_axis
    owner = object()
    assert axis.power(owner, True, 1, 1) is None
    ctl.run(0.1)
    assert axis.state == "enabled" and axis.power_control is not None
    assert axis.power(owner, False, 1, 1) is None
    assert axis.state == "disabled" and axis.power_owner is None


def test_kernel_power_controller_axis_stop_mode_0_brakes_before_the_enable_goes(controller_axis):
    """S7-1200 V6 §11.1.1: StopMode 0 brakes with the emergency deceleration and then removes the enable;
    while it brakes the axis is disabling and its setpoint velocity falls to zero."""
    ctl, axis = controller_axis
    owner = object()
    axis.power(owner, True, 1, 0)
    ctl.run(0.1)
    axis.submit(Job(JobKind.VELOCITY, velocity=50.0))
    ctl.run(5.0)
    assert axis._state_now()[1] == pytest.approx(50.0)
    axis.power(owner, False, 1, 0)
    assert axis.state == "disabling"
    ctl.run(5.0)
    assert axis.state == "disabled" and axis._state_now()[1] == 0.0
