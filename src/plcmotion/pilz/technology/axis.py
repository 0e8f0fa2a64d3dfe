"""The Pilz drive axis technology object: the kernel's positioning axis with a motion core in the drive.

``DriveAxis`` carries the Pilz parameter schema and owns the motion core (``axis.core``: command register,
status words, per-cycle sequence) and the Pilz referencing (``axis.referencing``, its homing part).  The
motion core runs every servo cycle (= A150) in the axis's input stage.  A program uses the register interface
(``axis.registers``, ``axis.write``, ``axis.read``) or the PLCopen-style wrappers of ``plcmotion.pilz``.
"""
from __future__ import annotations

import dataclasses
from typing import Any

from ...kernel import faults as F
from ...kernel.axis import PositioningAxis
from ...kernel.faults import Fault, Reaction
from ...kernel.job_start import JobStart
from ...kernel.jobs import Job, JobKind, JobState
from . import registers as R
from .core import MotionCore
from .parameters import PILZ_AXIS
from .referencing import Referencing
from .starts import endless_target

_LIMIT_SWITCH_FAULTS = (F.HW_LIMIT_MIN, F.HW_LIMIT_MAX)
_TYPES = {bool: "Bool", int: "DInt", float: "LReal"}


def _status_getter(name: str) -> Any:
    return lambda ax: getattr(ax.core.status, name)


def _register_getter(name: str) -> Any:
    return lambda ax: ax.core.registers.live[name]


#: the status words and the command register as read-only tags (``axis.tag("I92")``, ``axis.I89``, traces)
_DYNAMIC = {**{n: _status_getter(n) for n in R.STATUS_NAMES}, **{n: _register_getter(n) for n in R.BY_NAME}}
_DYNAMIC_TYPES = {**{n: _TYPES[type(getattr(R.StatusWords(), n))] for n in R.STATUS_NAMES},
                  **{n: _TYPES[r.kind] for n, r in R.BY_NAME.items()}}


class _JobStart(JobStart):
    """The kernel's job start; the endless-axis target of MC_MoveAbsolute is placed with the command's own
    dynamics (its deceleration decides how many turns the axis needs to brake, §1.2.4)."""

    def absolute_target(self, job: Job, p: float, v: float, a: float) -> float:
        ax = self.axis
        if not ax.config.modulo.enabled:
            return job.position
        return endless_target(ax, job, p, v, a)


class DriveAxis(PositioningAxis):
    """A drive controller axis with the Pilz motion core (PMC SC6 / SI6, Pilz V6.5)."""

    schema = PILZ_AXIS
    homing_class = Referencing
    _dynamic = _DYNAMIC
    _dynamic_types = _DYNAMIC_TYPES
    _sim_homing_at_once = False

    def __init__(self, ctl: Any, name: str, cfg: Any, **kw: Any):
        super().__init__(ctl, name, cfg, **kw)
        self.job_start = _JobStart(self)
        self.core = MotionCore(self)
        self.referencing: Referencing = self.homing      # type: ignore[assignment]
        ls = self.limit_switches                          # its inputs are fixed when the axis is created
        self._wired_inputs = bool(ls.range_check or ls.inputs["min"] or ls.inputs["max"]
                                  or self.drive_io.ready_input)
        if self not in ctl._input_axes:
            ctl._input_axes.append(self)                 # the motion core runs every cycle

    # --- the register interface -----------------------------------------------------------------------------
    @property
    def registers(self) -> R.CommandRegister:
        """The command register (I400 ... I431, I216, I217, I230) as typed attributes."""
        return self.core.registers

    @property
    def status(self) -> R.StatusWords:
        """The status words of the motion core (I82, I83, I85, I86, I89, I90, I91, I92, I180, I183, I190 ...)."""
        return self.core.status

    def write(self, name: str, value: Any) -> None:
        """Write a parameter of the command register (``axis.write("I401", 1)``); RegisterError if refused."""
        self.core.registers.write(name, value)

    def read(self, name: str) -> Any:
        """Read a status word (``"I92"``), a command register parameter or an axis parameter (``"I10"``)."""
        if name in R.STATUS_NAMES:
            return getattr(self.core.status, name)
        if name in R.BY_NAME:
            return self.core.registers.read(name)
        if name in self.schema.params:
            return self.eff[name]
        raise R.RegisterError(f"{name} is no parameter of {self.name}")

    def enable(self, on: bool = True) -> None:
        """Switch the drive's enable on or off (off: the drive stops with a quick stop, then its power stage
        goes off).  Enable is not a motion command: in the applications it is a control word bit."""
        self.power(self.core, on, 1, 0)

    def reset(self) -> Fault | None:
        """Acknowledge the drive's faults (fault reset of the control word); returns one that persists."""
        return self.acknowledge()

    # --- kernel hooks ---------------------------------------------------------------------------------------
    def reinitialize(self, reason: str) -> None:
        super().reinitialize(reason)
        core = getattr(self, "core", None)
        if core is not None:
            core.reset()

    def _check_inputs(self, t: float) -> None:
        if not self.sim and self._kernel_inputs():
            super()._check_inputs(t)
        self.core.cycle(t)

    def _kernel_inputs(self) -> bool:
        """The kernel's inputs have something to watch this cycle (the axis is listed for its motion core in
        any case): wired switches, a drive-ready input, the actual value range, a switch still approached,
        a running active or passive homing, the torque limit of a torque-stop referencing.  Without them the kernel's check is a no-op."""
        if self._wired_inputs:
            return True
        approached = self.limit_switches.approached
        if approached["min"] or approached["max"] or self.homing.passive is not None:
            return True
        if self.referencing.torque_job is not None:
            return True
        job = self.job
        return job is not None and job.kind == JobKind.HOME_ACTIVE

    def commanded_velocity(self, velocity: float) -> float:
        """The velocity override I230 (read every cycle) scales the commanded velocity (§1.2.5)."""
        core = getattr(self, "core", None)
        return velocity if core is None else velocity * core.override / 100.0

    def _zero_at_enable(self) -> bool:
        return False                                     # the drive keeps counting when enabled again

    def _start_positioning_monitor(self, job: Job, t: float) -> None:
        # the motion core reports the window itself (I180, I87); the kernel job ends with its profile, so that
        # a command that waits for it (I409 = 1) starts at the end of the running command
        self._finish_job(job, JobState.DONE, t)

    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None:
        # a limit switch stops the axis with a quick stop (limit switch fault, §1.8.3); the enable stays
        if fault.kind in _LIMIT_SWITCH_FAULTS and fault.reaction is Reaction.REMOVE_ENABLE:
            fault = dataclasses.replace(fault, reaction=Reaction.EMERGENCY)
        super().raise_alarm(fault, job)

    def _homing_hw_limit(self, side: str, t: float) -> bool:
        return self.referencing.hw_limit(side, t)


__all__ = ["DriveAxis"]
