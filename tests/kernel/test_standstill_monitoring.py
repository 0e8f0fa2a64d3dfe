"""Standstill monitoring after a positioning (``PositioningMonitoring.standstill_window``), on a kernel
Controller axis with a simulated servo drive; a slip of the load is simulated with ``drive.disturb``.

S7-Technology V4.1 §4.5.11.2: standstill monitoring begins when the setpoint has reached the target and its
delay has passed; the axis leaving the standstill window then is an error (8018 in that family).  Without
the setting the axis behaves as before (the positioning monitoring ends with Done).
"""
from __future__ import annotations

from dataclasses import replace

import pytest

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel.faults import Reaction
from plcmotion.kernel.jobs import Job, JobKind, JobState

DT = 0.001


def _axis(window: float | None, delay: float = 0.0, move: bool = True):
    ctl = Controller(servo_cycle=DT)
    axis = ctl.add_positioning_axis("Axis_1", {
        "Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0, "DynamicDefaults.Acceleration": 200.0,
        "DynamicDefaults.Deceleration": 200.0, "DynamicDefaults.Jerk": 0.0})
    axis.config = replace(axis.config, positioning=replace(
        axis.config.positioning, standstill_window=window, standstill_delay=delay))
    assert axis.power(object(), True, 1, 0) is None
    ctl.run_until(lambda: axis.state == "enabled", 5.0)
    if move:
        job = Job(JobKind.RELATIVE, position=10.0, velocity=50.0)
        axis.submit(job)
        ctl.run_until(lambda: not job.busy, 10.0)
        assert job.state == JobState.DONE
    return ctl, axis


def test_kernel_standstill_monitoring_off_keeps_the_old_behaviour():
    """Without a standstill window a slip after the positioning raises nothing."""
    ctl, axis = _axis(None)
    axis.drive.disturb(jump=3.0)
    ctl.run(0.5)
    assert axis.alarms == [] and axis.state == "enabled"


def test_kernel_standstill_monitoring_trips_when_the_axis_leaves_the_window():
    """S7-Technology V4.1 §4.5.11.2: after the positioning the axis slips 3 out of a 0.5 window: the
    standstill alarm ("left") removes the enable; the positioning itself had ended Done."""
    ctl, axis = _axis(0.5)
    ctl.run(0.2)
    assert axis.alarms == []
    axis.drive.disturb(jump=3.0)
    ctl.run(0.01)
    assert [(a.kind, a.detail, a.reaction) for a in axis.alarms] == [(F.STANDSTILL, "left", Reaction.REMOVE_ENABLE)]
    assert axis.state != "enabled"


def test_kernel_standstill_monitoring_ends_with_a_new_job():
    """A new motion job ends the watch: a slip during the next positioning is no standstill fault (the
    following error monitoring covers the motion), and the watch starts again after it."""
    ctl, axis = _axis(0.5)
    move = Job(JobKind.RELATIVE, position=-10.0, velocity=50.0)
    axis.submit(move)
    ctl.run(0.05)
    axis.drive.disturb(jump=1.0)
    ctl.run_until(lambda: not move.busy, 10.0)
    assert move.state == JobState.DONE and axis.alarms == []
    axis.drive.disturb(jump=1.0)
    ctl.run(0.01)
    assert [a.kind for a in axis.alarms] == [F.STANDSTILL]


@pytest.mark.parametrize("late", [False, True])
def test_kernel_standstill_monitoring_delay(late):
    """The load slips 0.5 and sticks (a blocked drive) while the positioning waits for its window (1.0): the
    positioning ends Done, but the axis is outside the standstill window (0.2).  The standstill fault
    ("not_reached") comes once the delay of 2 s after the setpoint's end has passed, and only then - unless
    the drive is freed before, so that the position loop brings the axis back inside."""
    ctl, axis = _axis(0.2, delay=2.0, move=False)
    move = Job(JobKind.RELATIVE, position=10.0, velocity=50.0)
    axis.submit(move)
    ctl.run_until(lambda: axis.positioning_monitor.job is move, 10.0)
    reached = ctl.time
    axis.drive.disturb(jump=0.5, blocked=True)
    ctl.run_until(lambda: not move.busy, 10.0)
    assert move.state == JobState.DONE and axis.alarms == []
    ctl.run(reached + 1.0 - ctl.time)
    if not late:
        axis.drive.disturb(blocked=False)
    ctl.run(reached + 1.99 - ctl.time)
    assert axis.alarms == []
    ctl.run(0.5)
    expected = [(F.STANDSTILL, "not_reached")] if late else []
    assert [(a.kind, a.detail) for a in axis.alarms] == expected
