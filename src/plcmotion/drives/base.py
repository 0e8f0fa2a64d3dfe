"""The narrow interface between the kernel and whatever moves the axis.

Drives of one kind form a *group* that is updated for all its members at once (the kernel keeps per-cycle
values in arrays, see ``kernel.bank``).  Each member axis gets a *channel* for the few things that happen
on events: switching the enable signal, asking whether the drive is ready, re-referencing the actual value.

Per servo cycle the kernel calls ``group.read`` before interpolation (actual values into the bank) and
``group.write`` after position control (commands out of the bank).
"""
from __future__ import annotations

from abc import ABC, abstractmethod
from typing import Any, Mapping


class DriveChannel(ABC):
    """Event-time access to one member of a drive group."""

    @abstractmethod
    def set_enable(self, on: bool, t: float) -> None:
        """Switch the drive enable (the 'Drive enabled' output / control word)."""

    @abstractmethod
    def ready(self, t: float) -> bool:
        """'Drive ready': the drive executes setpoints."""

    @abstractmethod
    def set_actual(self, bank: Any, value: float) -> None:
        """Re-reference the actual position so that it reads ``value`` now (homing)."""

    @abstractmethod
    def mechanical_position(self) -> float:
        """Where the load really is, in machine coordinates (what switches and zero marks see)."""

    @property
    def communication_ok(self) -> bool:
        return True

    def reconfigure(self, cfg: Mapping[str, Any]) -> None:
        """Configuration tags that became effective at runtime (mechanics)."""

    def set_fault(self, on: bool) -> None:
        """A fault of the drive itself (fault injection): it stops executing setpoints and is not ready."""

    def disturb(self, jump: float = 0.0, force: float | None = None, blocked: bool | None = None) -> None:
        """A disturbance of the load (fault injection): ``jump`` moves the load at once, ``force`` is an
        external force given as the speed it costs the drive's speed loop, ``blocked`` holds the load."""
        raise ValueError("this drive has no simulated load to disturb")

    # encoder zero marks (reference mark search of a PROFIdrive encoder); drives without them ignore it
    def arm_zero_mark(self, direction: float) -> None:
        """Latch the actual value at the next zero mark passed in ``direction`` (+1 / -1)."""

    def disarm_zero_mark(self) -> None:
        """Stop a zero mark search."""

    def zero_mark_latched(self) -> float | None:
        """The actual value latched at a zero mark since arming (once), or None."""
        return None


class DriveGroup(ABC):
    @abstractmethod
    def add(self, index: int, cfg: Mapping[str, Any], servo_cycle: float, t: float) -> DriveChannel:
        """Attach the axis with bank index ``index``."""

    @abstractmethod
    def read(self, bank: Any, t: float, dt: float) -> None:
        """Bring actual values of time ``t`` into ``bank.act_p``/``bank.act_v``."""

    @abstractmethod
    def write(self, bank: Any, t: float) -> None:
        """Take this cycle's commands from the bank."""
