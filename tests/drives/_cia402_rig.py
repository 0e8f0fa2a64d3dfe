"""A controller with one S7-1200 drive axis on a simulated CiA 402 drive over the virtual CAN bus."""
from __future__ import annotations

import itertools
import os
from collections.abc import Callable
from typing import Any

from plcmotion import Controller
from plcmotion.drives.cia402 import Cia402Link
from plcmotion.s7_1200 import MC_Power, MC_Reset

_channels = itertools.count()


def channel() -> str:
    """A virtual CAN channel of its own for each test (the virtual bus is process-wide)."""
    return f"plcmotion-test-{os.getpid()}-{next(_channels)}"


AXIS = {
    "Actor.Type": 1,                      # a drive axis (PROFIdrive in the S7 tags; the link replaces it)
    "DynamicLimits.MaxVelocity": 100.0,
    "DynamicLimits.MinVelocity": 0.0,
    "DynamicDefaults.Acceleration": 500.0,
    "DynamicDefaults.Deceleration": 500.0,
    "DynamicDefaults.EmergencyDeceleration": 2000.0,
    "DynamicDefaults.Jerk": 0.0,
    "Mechanics.LeadScrew": 10.0,          # mm per motor revolution
    "Actor.Interface.DriveReadyInput": "",
    "PositioningMonitoring.Window": 0.05,  # mm: Done only within 0.05 mm of the target
}


class Rig:
    """``Rig(mode)``: an S7-1200 axis ``Axis_1`` on node 1 of a fresh virtual bus; FBs added with ``add`` run
    once per application cycle."""

    def __init__(self, mode: str = "csp", *, enable: bool = True, heartbeat_ms: int = 20,
                 extra: dict[str, Any] | None = None, node_id: int = 1):
        self.ctl = Controller()
        self.link = Cia402Link(interface="virtual", channel=channel(), node_id=node_id, mode=mode, simulate=True,
                               heartbeat_ms=heartbeat_ms)
        self.ctl.connect_drive("Axis_1", self.link)
        self.axis = self.ctl.add_positioning_axis("Axis_1", {**AXIS, **(extra or {})})
        self.drive = self.axis.drive
        self.sim = self.drive.simulated
        self.fbs: list[Any] = []
        self.power = self.add(MC_Power(Enable=enable))
        self.ctl.program(self._scan)
        if enable:
            self.until(lambda: self.power.Status, 0.2, "axis enabled")

    def add(self, fb: Any, **inputs: Any) -> Any:
        fb.Axis = self.axis
        for k, v in inputs.items():
            setattr(fb, k, v)
        self.fbs.append(fb)
        return fb

    def _scan(self) -> None:
        for fb in self.fbs:
            fb()

    def until(self, pred: Callable[[], bool], timeout: float, what: str) -> None:
        end = self.ctl.time + timeout
        while not pred():
            assert self.ctl.time < end, f"{what}: not within {timeout} s (t = {self.ctl.time:.3f})"
            self.ctl.step()

    def steps(self, n: int) -> None:
        for _ in range(n):
            self.ctl.step()

    def start(self, fb: Any, **inputs: Any) -> Any:
        if fb not in self.fbs:
            self.add(fb)
        for k, v in inputs.items():
            setattr(fb, k, v)
        fb.Execute = True
        self.ctl.step()
        return fb

    def reset(self) -> MC_Reset:
        rs = self.start(MC_Reset())
        self.until(lambda: rs.Done or rs.Error, 0.1, "MC_Reset done")
        rs.Execute = False
        return rs

    def close(self) -> None:
        self.ctl.close()
