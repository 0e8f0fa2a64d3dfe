"""The holding brake of a Pilz drive axis under the motion core (Pilz V6.5 §1.2.4, §1.2.6, §1.6.4, §1.6.6).

With brake control on (F00 = 1) a command that starts the axis from standstill releases the brake; a
positioning, MC_Stop or MC_Halt with "engage brake at the end" (I410 = 1) engages it when the wait time I42
has run out after the command ended (Done, which is reported before the brake engages); a command started
within I42 keeps it released.  MC_Stop and MC_Halt started at standstill leave it released and engage it by
the same rule.  The brake drives the output ``BrakeOutput`` (TRUE while released) when one is configured.
"""
from __future__ import annotations

from typing import Any

from . import command as C

#: commands with "engage brake at the end" (Tab. 4, 7, 10, 17, 37)
WITH_BRAKE = C.POSITIONING | C.STOPPING


class Brake:
    """The brake state of one axis (``core.brake``)."""

    def __init__(self, core: Any):
        self.core = core
        self.engaged = True                 # a drive starts with its holding brake applied
        self.due: float | None = None      # when the brake engages (I42 after the end of the command)
        self._armed_for: C.Command | None = None
        self._output()

    @property
    def controlled(self) -> bool:
        return self.core.axis.eff["F00"] == 1

    def _output(self) -> None:
        ax = self.core.axis
        address = ax.eff["BrakeOutput"]
        if address:
            ax.ctl.outputs[address] = not self.engaged

    def on_start(self, cmd: C.Command) -> None:
        """A command started: the wait time is over; a motion command releases the brake."""
        self.due = None
        if self.controlled and cmd.number not in C.STOPPING and cmd.denied is None and self.engaged:
            self.engaged = False
            self._output()

    def on_done(self, cmd: C.Command, t: float) -> None:
        """The command reported Done: with I410 the brake engages after I42."""
        if self._armed_for is cmd:
            return
        self._armed_for = cmd
        if self.controlled and cmd.number in WITH_BRAKE and cmd.value("I410"):
            self.due = t + self.core.axis.eff["I42"]

    def cycle(self, t: float) -> None:
        if self.due is not None and t >= self.due - 1e-9:
            self.due = None
            if not self.engaged:
                self.engaged = True
                self._output()

    def disabled(self) -> None:
        """The enable went off: the brake engages (the drive cannot hold the axis any more)."""
        self.due = None
        if self.controlled and not self.engaged:
            self.engaged = True
            self._output()


__all__ = ["Brake", "WITH_BRAKE"]
