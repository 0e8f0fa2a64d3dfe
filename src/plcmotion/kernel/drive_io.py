"""The digital signals between an axis and its drive: the enable output and the "drive ready" input.

S7-1200 V6 §5.4.3.2 ("Drive enable and feedback"): the controller sets the enable output while the axis is
enabled and reads the drive's readiness on the ready input; without a ready input the drive counts as ready.
Losing "drive ready" while enabled removes the enable (§12.8 16#8000).  A simulated axis (Simulation.Mode
= 1, a virtual axis) ignores the drive feedback (§5.4.3.1).  ``DriveIO`` is a component of an axis
(``axis.drive_io``).
"""
from __future__ import annotations

from typing import MutableMapping, Protocol

from . import faults as F
from .axis_config import AxisConfig
from .faults import Fault, Reaction


class ProcessImage(Protocol):
    """The controller's digital inputs and outputs."""

    inputs: MutableMapping[str, bool]
    outputs: MutableMapping[str, bool]


class DriveIOHost(Protocol):
    """What the drive signals need from their axis."""

    ctl: ProcessImage
    config: AxisConfig
    state: str                      # "disabled", "enabling", "enabled", "disabling"
    sim: bool

    def raise_alarm(self, fault: Fault) -> None: ...


class DriveIO:
    """Enable output and ready input of one axis (addresses of the configuration it was created with)."""

    def __init__(self, axis: DriveIOHost):
        self.axis = axis
        signals = axis.config.signals
        self.ready_input = signals.ready_input
        self.enable_output = signals.enable_output
        if self.enable_output:
            axis.ctl.outputs[self.enable_output] = False

    def ready(self) -> bool:
        """'Drive ready' as the controller sees it (True when no ready input is configured)."""
        if not self.ready_input or self.axis.sim:
            return True
        return self.axis.ctl.inputs[self.ready_input]

    def set_enable_output(self, on: bool) -> None:
        if self.enable_output:
            self.axis.ctl.outputs[self.enable_output] = on

    def check(self) -> None:
        """Every servo cycle of a watched axis: "drive ready" lost while enabled (16#8000)."""
        if self.ready_input and self.axis.state in ("enabled", "disabling") and not self.ready():
            self.axis.raise_alarm(F.alarm(F.DRIVE_NOT_READY, "", Reaction.REMOVE_ENABLE))
