"""The alarm component (``kernel.alarm_reactions.AlarmReactions``): alone on a fake axis, then on a kernel
``Controller`` axis (no dialect).

Expected behaviour from S7-1200 Motion Control V6 (seeds/000): §12.8 (an alarm ends the running job with an
error and reacts: none, stop, emergency stop or remove enable), §11.1.2 MC_Reset (acknowledges alarms whose
cause is gone; Restart = TRUE only on a disabled axis, §9.7).
"""
from __future__ import annotations

from types import SimpleNamespace

import pytest

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel.alarm_reactions import AlarmReactions
from plcmotion.kernel.faults import Reaction
from plcmotion.kernel.jobs import Job, JobKind, JobState


class FakeAxis:
    """An AlarmHost of a disabled axis that records the reactions it is asked for."""

    def __init__(self, state="disabled"):
        self.now = 1.0
        self.alarms: list[F.Fault] = []
        self.job: Job | None = None
        self.state = state
        self.power_owner = None
        self.homing = SimpleNamespace(end_passive=lambda state, fault: self.calls.append(("end_passive",)))
        self.calls: list[tuple] = []

    def _finish_job(self, job, state, t, fault=None):
        job.finish(state, fault)
        self.calls.append(("finish", state))

    def _end_runner_jobs(self, state, t, fault=None):
        self.calls.append(("runners", state))

    def _remove_enable(self, t, by_power=False):
        self.calls.append(("remove_enable", by_power))

    def reinitialize(self, reason):
        self.calls.append(("reinitialize", reason))


def test_kernel_alarm_reactions_warning_ends_the_job_only():
    """§12.8: an alarm ends the job it belongs to with an error; without a reaction nothing else happens."""
    ax = FakeAxis(state="enabled")
    job = Job(JobKind.RELATIVE, position=1.0)
    ax.job = job
    warning = F.alarm(F.INTERNAL, "test", Reaction.NONE)
    AlarmReactions(ax).raise_alarm(warning)
    assert ax.alarms == [warning] and job.state == JobState.ERROR and job.fault is warning
    assert ax.calls == [("finish", JobState.ERROR)]


def test_kernel_alarm_reactions_remove_enable():
    """§12.8 reaction "remove enable": the runners' jobs end, passive homing ends, the enable is removed."""
    ax = FakeAxis(state="enabled")
    fault = F.alarm(F.INTERNAL, "test", Reaction.REMOVE_ENABLE)
    alarms = AlarmReactions(ax)
    alarms.raise_alarm(fault)
    alarms.raise_alarm(fault)                         # the same alarm is listed once
    assert ax.alarms == [fault]
    assert ax.calls[:3] == [("runners", JobState.ERROR), ("end_passive",), ("remove_enable", False)]


def test_kernel_alarm_reactions_restart_only_when_disabled():
    """§11.1.2 / §9.7: MC_Reset Restart = TRUE restarts a disabled axis; an enabled one is refused."""
    ax = FakeAxis(state="enabled")
    ax.power_owner = object()
    fault = AlarmReactions(ax).restart()
    assert fault is not None and fault.kind == F.RESTART_IMPOSSIBLE and ax.calls == []
    ax.state, ax.power_owner = "disabled", None
    assert AlarmReactions(ax).restart() is None and ax.calls == [("reinitialize", "restart")]


def test_kernel_alarm_reactions_controller_axis_acknowledge_and_enable_again():
    """§12.8 / §11.1.2: an alarm with "remove enable" disables the axis and blocks enabling until MC_Reset
    acknowledges it (its cause is gone); then MC_Power enables the axis again."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004, input_filter=0.0)
    axis = ctl.add_positioning_axis("Axis_1", {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0})
    owner = object()
    axis.power(owner, True, 1, 0)
    ctl.run(0.1)
    assert axis.state == "enabled"
    axis.raise_alarm(F.alarm(F.INTERNAL, "test", Reaction.REMOVE_ENABLE))
    assert axis.state == "disabled" and axis.alarms
    axis.power(owner, True, 1, 0)
    ctl.run(0.1)
    assert axis.state == "disabled"
    assert axis.acknowledge() is None and axis.alarms == []
    axis.power(owner, True, 1, 0)
    ctl.run(0.1)
    assert axis.state == "enabled"


def test_kernel_alarm_reactions_max_dynamics_brakes_with_the_configured_limits():
    """A family's reaction "stop with the maximum dynamic values" (kernel ``Reaction.MAX_DYNAMICS``): the
    running job ends with the alarm and the axis brakes with the configured maximum deceleration (here a
    family with dynamic limits of its own), not with the deceleration of the defaults or the emergency ramp."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.001, family="S7-1500")
    axis = ctl.add_positioning_axis("Axis_1", {"VirtualAxis.Mode": 1, "DynamicLimits.MaxDeceleration": 700.0,
                                               "DynamicLimits.MaxJerk": 0.0,
                                               "DynamicDefaults.Deceleration": 100.0,
                                               "DynamicDefaults.EmergencyDeceleration": 300.0,
                                               "DynamicDefaults.Jerk": 0.0})
    owner = object()
    axis.power(owner, True, 1, 0)
    ctl.run(0.05)
    job = Job(JobKind.VELOCITY, velocity=50.0)
    axis.submit(job)
    ctl.run(1.0)
    dec = 700.0
    v0 = axis.ctl.bank.sp_v[axis.index]
    fault = F.alarm(F.INTERNAL, "test", Reaction.MAX_DYNAMICS)
    axis.alarm_reactions.raise_alarm(fault)           # the kernel component, without the family's table
    assert job.state == JobState.ERROR and job.fault is fault
    velocities = []
    for _ in range(int(v0 / dec / 0.001) + 20):
        ctl.step()
        velocities.append(float(axis.ctl.bank.sp_v[axis.index]))
    drops = [a - b for a, b in zip([v0] + velocities, velocities)]
    assert max(drops) == pytest.approx(dec * 0.001, rel=1e-6) and velocities[-1] == 0.0
    assert axis.state == "enabled"


def test_kernel_alarm_reactions_software_limit_braking_with_maximum_deceleration():
    """An axis that brakes at a software limit switch with its maximum dynamic values (a family's alarm
    reaction "stop with maximum dynamic values", ``sw_limit_max_deceleration``) gets the configured maximum
    deceleration for that braking; an axis without it keeps the deceleration of its job."""
    from plcmotion.kernel.motion import _limit_braking
    from plcmotion.kernel.profiles import Limits
    config = SimpleNamespace(limits=SimpleNamespace(max_deceleration=6000.0, max_acceleration=5000.0, max_jerk=0.0,
                                                    max_velocity=1000.0),
                             defaults=SimpleNamespace(deceleration=800.0, acceleration=500.0))
    job = Limits(velocity=100.0, acceleration=500.0, deceleration=800.0, jerk=1.0e5)
    strong = _limit_braking(SimpleNamespace(config=config, sw_limit_max_deceleration=True), job)
    assert (strong.deceleration, strong.acceleration, strong.jerk, strong.velocity) == (6000.0, 500.0, 1.0e5, 100.0)
    assert _limit_braking(SimpleNamespace(config=config), job) is job
