"""A drive that homes by itself reports it through the drive interface (``DriveReports.homed``): the kernel's
homing part makes the axis homed at the position the drive reads, family-neutrally (``axis.homed``, the
reference mark, the coordinates).  A fake bus link on a kernel ``Controller`` axis, no bus and no dialect;
what "homed" means: S7-1200 Motion Control V6 §2.5 (the axis is homed, absolute positioning possible)."""
from __future__ import annotations

import math

import pytest

from plcmotion import Controller
from plcmotion.kernel.homing import NoHoming

from .test_drive_link import AXIS, _enabled, _Link


def _axis():
    ctl = Controller()
    ctl.connect_drive("A", _Link("homed"))
    ax = ctl.add_positioning_axis("A", AXIS)
    ctl.run(0.01)
    return ctl, ax


def test_kernel_drive_homed_marks_the_axis_homed():
    """S7-1200 V6 §2.5: the drive reports "homed, actual value 12.5" while the axis is disabled: the axis is
    homed, its actual and setpoint position are 12.5 and the reference mark is there; once enabled an
    absolute positioning job (which needs a homed axis) runs to its target."""
    from plcmotion.kernel.jobs import Job, JobKind
    ctl, ax = _axis()
    b, i = ctl.bank, ax.index
    b.act_p[i] = 3.0                           # where the drive's count put the axis before it reported
    assert not ax.homed
    ax.drive.reports.homed(12.5)
    assert ax.homed and ax.homing.reference_mark == 12.5
    assert b.act_p[i] == 12.5
    ctl.run(0.01)
    assert b.sp_p[i] == pytest.approx(12.5)
    _enabled(ctl, ax)
    job = Job(JobKind.ABSOLUTE, position=20.0, velocity=10.0)
    ax.submit(job)
    ctl.run(2.0)
    assert job.state.name == "DONE" and b.act_p[i] == pytest.approx(20.0, abs=0.05)


@pytest.mark.parametrize("value", [math.nan, math.inf, "12"])
def test_kernel_drive_homed_refuses_a_bad_position(value):
    """A position that is no finite number is refused with a clear error; the axis stays not homed."""
    ctl, ax = _axis()
    with pytest.raises((ValueError, TypeError), match="position"):
        ax.drive.reports.homed(value)
    assert not ax.homed


def test_kernel_drive_homed_on_an_axis_kind_without_homing():
    """An axis kind without homing (``NoHoming``) has no "homed" to set: the report changes nothing."""
    ctl, ax = _axis()
    ax.homing = NoHoming(ax)
    ax.drive.reports.homed(5.0)
    assert not ax.homed
