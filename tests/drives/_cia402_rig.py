"""A controller with one S7-1200 drive axis on a simulated CiA 402 drive over the virtual CAN bus."""
from __future__ import annotations

import itertools
import os
from typing import Any

from _fb_program import FbProgram
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


class Rig(FbProgram):
    """``Rig(mode)``: an S7-1200 axis ``Axis_1`` on node 1 of a fresh virtual bus; FBs added with ``add`` run
    once per application cycle."""

    def __init__(self, mode: str = "csp", *, enable: bool = True, heartbeat_ms: int = 20,
                 extra: dict[str, Any] | None = None, node_id: int = 1):
        ctl = Controller()
        self.link = Cia402Link(interface="virtual", channel=channel(), node_id=node_id, mode=mode, simulate=True,
                               heartbeat_ms=heartbeat_ms)
        ctl.connect_drive("Axis_1", self.link)
        axis = ctl.add_positioning_axis("Axis_1", {**AXIS, **(extra or {})})
        self.drive = axis.drive
        self.sim = self.drive.simulated
        super().__init__(ctl, axis, MC_Power(Enable=enable), enable=enable, enable_timeout=0.2)

    def reset(self) -> MC_Reset:
        return self.finish(self.start(MC_Reset()), 0.1, "MC_Reset done", release=False)

    def close(self) -> None:
        self.ctl.close()
