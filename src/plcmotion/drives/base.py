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

    @property
    def communication_ok(self) -> bool:
        return True


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
