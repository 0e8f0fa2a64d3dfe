"""The drive signals component (``kernel.drive_io.DriveIO``: enable output, "drive ready" input): alone on a
fake axis, then on a kernel ``Controller`` axis enabled the way MC_Power asks it (no dialect).

Expected behaviour from S7-1200 Motion Control V6 (seeds/000): §5.4.3.2 "Drive enable and feedback" (the
enable output enables the drive, the ready input reports "Drive ready"), §11.1.1 (MC_Power: the axis is
enabled once "Drive ready" is present), §5.4.3.1 (simulation: drive feedback has no effect), §12.8
16#8000/16#0001 ("Drive ready" lost; reaction remove enable, project decision #38).
"""
from __future__ import annotations

from types import SimpleNamespace

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel.axis_config import DriveSignals
from plcmotion.kernel.drive_io import DriveIO
from plcmotion.kernel.faults import Reaction


class FakeAxis:
    """A DriveIOHost with enable output Q0.0 and (optionally) ready input I0.3."""

    def __init__(self, ready_input: str = "I0.3", *, sim: bool = False):
        self.config = SimpleNamespace(signals=DriveSignals(enable_output="Q0.0", ready_input=ready_input))
        self.ctl = SimpleNamespace(inputs={"I0.3": False}, outputs={"Q0.0": True})
        self.state = "disabled"
        self.sim = sim
        self.alarms: list[F.Fault] = []

    def raise_alarm(self, fault):
        self.alarms.append(fault)


def test_kernel_drive_io_enable_output_starts_off_and_follows_the_axis():
    """S7-1200 V6 §5.4.3.2: the enable output is the drive enable; it is FALSE until the axis enables."""
    ax = FakeAxis()
    io = DriveIO(ax)
    assert ax.ctl.outputs["Q0.0"] is False
    io.set_enable_output(True)
    assert ax.ctl.outputs["Q0.0"] is True
    io.set_enable_output(False)
    assert ax.ctl.outputs["Q0.0"] is False


def test_kernel_drive_io_ready_input_or_always_ready():
    """S7-1200 V6 §5.4.3.2: "Drive ready" comes from the ready input; without one the drive counts as ready;
    §5.4.3.1 a simulated axis ignores the drive feedback."""
    ax = FakeAxis()
    io = DriveIO(ax)
    assert io.ready() is False
    ax.ctl.inputs["I0.3"] = True
    assert io.ready() is True
    assert DriveIO(FakeAxis(ready_input="")).ready() is True
    assert DriveIO(FakeAxis(sim=True)).ready() is True


def test_kernel_drive_io_losing_ready_while_enabled_removes_the_enable():
    """S7-1200 V6 §12.8 16#8000: "Drive ready" lost while enabled is an alarm with reaction remove enable;
    a disabled axis does not expect the drive to be ready."""
    ax = FakeAxis()
    io = DriveIO(ax)
    io.check()
    assert ax.alarms == []
    ax.state = "enabled"
    io.check()
    assert [(a.kind, a.reaction) for a in ax.alarms] == [(F.DRIVE_NOT_READY, Reaction.REMOVE_ENABLE)]


def test_kernel_drive_io_enable_waits_for_drive_ready_on_a_controller_axis():
    """S7-1200 V6 §11.1.1: the axis is enabled only once "Drive ready" is present (the enable output is set
    at once); §12.8 16#8000: when the signal drops the axis loses its enable and the output goes FALSE."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004, input_filter=0.0)
    axis = ctl.add_positioning_axis("Axis_1", {
        "Actor.Type": 1, "Actor.Interface.EnableDriveOutput": "Q0.0", "Actor.Interface.DriveReadyInput": "I0.3",
        "DynamicLimits.MaxVelocity": 100.0})
    assert ctl.outputs["Q0.0"] is False
    ctl.inputs.force("I0.3", False)                 # the simulated drive does not report ready
    owner = object()
    assert axis.power(owner, True, 1, 0) is None
    ctl.run(0.1)
    assert axis.state == "enabling" and ctl.outputs["Q0.0"] is True
    ctl.inputs.force("I0.3", None)                  # the drive's own "ready" again
    ctl.run_until(lambda: axis.state == "enabled", 0.1)
    ctl.inputs.force("I0.3", False)
    ctl.run_until(lambda: axis.state == "disabled", 0.1)
    assert [a.kind for a in axis.alarms] == [F.DRIVE_NOT_READY] and ctl.outputs["Q0.0"] is False
