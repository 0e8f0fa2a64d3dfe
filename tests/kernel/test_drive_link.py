"""Drives on a bus behind the kernel (``Controller.connect_drive``, ``drives.base.DriveLink``): the axis's
drive spec gets the link, drives of one link key form one group, the position controller runs for them,
and a drive that finds a fault itself reports it to the axis, which reacts as to any device fault; MC_Reset
reaches the drive.  A fake link on a kernel ``Controller`` axis, no bus and no dialect.

Expected behaviour: S7-1200 Motion Control V6 (seeds/000) §12.8 (16#800C alarm from the drive, reaction
remove enable; 16#003E station failure), §11.1.2 (MC_Reset acknowledges), §11.1.1 (enabled once the drive
is ready).
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np
import pytest

from plcmotion import Controller
from plcmotion.drives.base import DriveChannel, DriveGroup, DriveLink
from plcmotion.drives.spec import ActuatorKind, DriveSpec, SetpointInterface
from plcmotion.kernel import faults as F

AXIS = {"Actor.Type": 1, "DynamicLimits.MinVelocity": 0.0, "Actor.Interface.DriveReadyInput": ""}


class _Channel(DriveChannel):
    def __init__(self, group: "_Group", index: int):
        self.group, self.index = group, index
        self.enabled = False
        self.reports: Any = None
        self.set_fault_calls: list[bool] = []

    def attach(self, reports) -> None:
        self.reports = reports

    def set_enable(self, on: bool, t: float) -> None:
        self.enabled = on

    def ready(self, t: float) -> bool:
        return self.enabled

    def set_actual(self, bank, value: float) -> None:
        bank.act_p[self.index] = value

    def mechanical_position(self) -> float:
        return 0.0

    def set_fault(self, on: bool) -> None:
        self.set_fault_calls.append(on)


class _Group(DriveGroup):
    closed_loop = True          # a drive that takes the position controller's speed command (cmd_v)
    """A drive that moves with the speed command it got (the kernel's position loop closes around it)."""

    closed = 0

    def __init__(self) -> None:
        self.members: list[_Channel] = []
        self.cmd: dict[int, float] = {}

    def add(self, index: int, spec: DriveSpec, servo_cycle: float, t: float) -> DriveChannel:
        self.members.append(_Channel(self, index))
        return self.members[-1]

    def read(self, bank, t: float, dt: float) -> None:
        for ch in self.members:
            v = self.cmd.get(ch.index, 0.0) if ch.enabled else 0.0
            bank.act_p[ch.index] += v * dt
            bank.act_v[ch.index] = v

    def write(self, bank, t: float) -> None:
        for ch in self.members:
            self.cmd[ch.index] = float(bank.cmd_v[ch.index])

    def close(self) -> None:
        _Group.closed += 1


@dataclass(frozen=True)
class _Link(DriveLink):
    bus: str = "bus0"

    @property
    def group_key(self) -> str:          # type: ignore[override]
        return f"fake:{self.bus}"

    def new_group(self, bank) -> DriveGroup:
        return _Group()

    def bind(self, spec: DriveSpec) -> DriveSpec:
        if spec.actuator is not ActuatorKind.SPEED_SERVO:
            raise ValueError("needs a servo axis")
        return replace(spec, interface=SetpointInterface.CANOPEN, link=self)


def _enabled(ctl: Controller, ax) -> None:
    ax.power(object(), True, 1, 0)
    for _ in range(5):
        ctl.step()
    assert ax.state == "enabled"


def test_kernel_drive_link_groups_and_spec():
    """connect_drive before add: the axis's DriveSpec carries the link and its interface; axes with the same
    group key share one group, another key gets its own; no simulated servo group exists."""
    ctl = Controller()
    ctl.connect_drive("A", _Link("bus0"))
    ctl.connect_drive("B", _Link("bus0"))
    ctl.connect_drive("C", _Link("bus1"))
    a, b, c = (ctl.add_positioning_axis(n, AXIS) for n in "ABC")
    assert a.config.drive.link == _Link("bus0") and a.config.drive.interface is SetpointInterface.CANOPEN
    assert a.drive.group is b.drive.group and a.drive.group is not c.drive.group
    assert sorted(ctl._groups) == ["fake:bus0", "fake:bus1"]
    ctl.close()
    assert _Group.closed >= 2


def test_kernel_drive_link_position_control_runs():
    """A linked servo axis is position controlled like a simulated one (S7-1200 V6 §11.1.8 MC_MoveVelocity
    as a kernel velocity job): the drive gets a speed command and its actual velocity reaches 20 units/s;
    the control stage does not depend on a simulated servo group being present."""
    from plcmotion.kernel.jobs import Job, JobKind
    ctl = Controller()
    ctl.connect_drive("A", _Link())
    ax = ctl.add_positioning_axis("A", AXIS)
    _enabled(ctl, ax)
    ax.submit(Job(JobKind.VELOCITY, velocity=20.0))
    ctl.run(1.0)
    b = ctl.bank
    assert b.cmd_v[ax.index] == pytest.approx(20.0, abs=0.05)
    assert b.act_v[ax.index] == pytest.approx(20.0, abs=0.05)
    assert "servo" not in ctl._groups


def test_kernel_drive_link_errors():
    """connect_drive after the axis exists, or with something that is no DriveLink, is refused; a link that
    cannot drive the axis (here: a stepper, Actor.Type 2) stops the axis from being created."""
    ctl = Controller()
    ctl.add_positioning_axis("A", AXIS)
    with pytest.raises(ValueError, match="exists already"):
        ctl.connect_drive("A", _Link())
    with pytest.raises(TypeError, match="DriveLink"):
        ctl.connect_drive("B", "can0")
    ctl.connect_drive("S", _Link())
    with pytest.raises(ValueError, match="needs a servo axis"):
        ctl.add_positioning_axis("S", {"Actor.Type": 2})
    assert "S" not in ctl.axes


def test_kernel_drive_link_reports_faults():
    """S7-1200 V6 §12.8: a fault the drive reports itself (``reports.inject("drive")``) is the axis's drive
    alarm 16#800C with reaction remove enable; the echo of it reaches the drive as set_fault(True).  MC_Reset
    (§11.1.2) acknowledges it and tells the drive (set_fault(False): a fault reset).  A communication loss
    of a CANopen axis is the station failure (16#003E) and CommunicationOK FALSE."""
    ctl = Controller()
    ctl.connect_drive("A", _Link())
    ax = ctl.add_positioning_axis("A", AXIS)
    _enabled(ctl, ax)
    ch = ax.drive
    assert ch.reports is ax.fault_injection
    ch.reports.inject("drive", "")
    assert ax.state == "disabled" and [a.kind for a in ax.alarms] == [F.DRIVE_ALARM]
    assert ch.set_fault_calls == [True]
    assert ax.alarm_reactions.acknowledge() is None and not ax.alarms
    assert ch.set_fault_calls == [True, False]
    ch.reports.inject("communication_loss", "")
    assert not ax.communication_ok("drive")
    assert any(a.kind == F.DRIVE_ALARM and a.detail == "station" for a in ax.alarms)
