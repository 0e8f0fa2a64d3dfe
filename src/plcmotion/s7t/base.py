"""The S7-Technology flavour of the instruction machinery (S7-Technology V4.1 §5.8, §5.10, §6.1, §6.9).

* ``Axis`` takes the technology object or, as in the manual, the number of its technology DB (INT; a DB
  number above 32767 may be given as number - 65536, §6.9.3).  An INT that is no technology DB gives
  16#8083, a technology object the instruction does not support 16#8044.
* Dynamic REAL inputs (§6.9.3): < 0 the configured default, = 0 16#8043 (Jerk: trapezoidal profile),
  > 0 the value; every REAL input must lie in -1E12 < x < 1E12 (else 16#8043) and be a valid REAL (NaN,
  infinity, not a number: 16#808B).  INT inputs outside their values: 16#8043.
* Two error channels (§5.10, §5.12): ``Error``/``ErrorID`` only when the command could not be started; a
  command ended by the technology object (an error while it ran, or a check made after accepting it) shows
  ``CommandAborted`` and the ErrorID is in the technology DB, acknowledged with MC_Reset.
* ``DoneFlag`` (INT 0..32, §6.9.2) toggles ``MCDevice.DoneFlag[n]`` when the command completes.
* After every call ``ENO`` (alias ``BIE``, the binary result of §5.10) is FALSE when ``Error`` is TRUE.
  The call returns the instance, as the other families' instructions do.
"""
from __future__ import annotations

import math
import numbers
from typing import Any, Callable, ClassVar

from .. import fb
from ..fb import InstructionError, ProgramError, as_bool, as_int, as_number
from ..kernel.faults import Fault
from ..kernel.jobs import Job, JobState
from ..kernel.profiles import INF
from . import errors as E
from .fb_tables import FB_BY_NAME
from .technology import activation
from .technology.axes import AxisT
from .technology.builder import POSITIONING, SPEED, SYNCHRONIZATION
from .technology.device import TechnologyDevice, current
from .technology.tdb import TechnologyDB

ALL_AXES = (SPEED, POSITIONING, SYNCHRONIZATION)
POSITION_AXES = (POSITIONING, SYNCHRONIZATION)
REAL_LIMIT = 1.0e12


class _S7T:
    """Axis input, ErrorIDs and ENO of the S7-Technology instructions."""

    #: the axis technologies the instruction supports (§6.2 "Supported technology objects")
    TECHNOLOGIES: ClassVar[tuple[int, ...]] = ALL_AXES
    #: the instruction also takes the MCDevice DB (MC_Reset)
    TAKES_MCDEVICE: ClassVar[bool] = False
    #: the instruction serves a deactivated technology object (MC_ActivateTO); others give DEACTIVATED_ERROR
    WHILE_DEACTIVATED: ClassVar[bool] = False
    #: the refusal at a deactivated object (§6.7.2: it takes no commands): 16#8045 (docs/s7t/decisions.md D75)
    DEACTIVATED_ERROR: ClassVar[int] = E.NOT_ALLOWED_IN_STATE

    ENO = True

    @property
    def BIE(self) -> bool:  # noqa: N802 - the manual's name of the binary result
        return self.ENO

    def __call__(self, **inputs: Any) -> Any:
        out = super().__call__(**inputs)  # type: ignore[misc]
        object.__setattr__(self, "ENO", not self.__dict__.get("Error", False))
        return out

    # --- Axis: a technology object or the number of its technology DB ----------------------------------
    def _resolve(self, value: Any) -> tuple[TechnologyDevice | None, Any]:
        """(device, technology object or technology DB) at an input; raises the InstructionError."""
        if isinstance(value, AxisT):
            ext = getattr(value.ctl, "extension", None)
            return (ext if isinstance(ext, TechnologyDevice) else None), value
        if isinstance(value, TechnologyDB):
            ext = current()
            if ext is not None and ext.db(value.number) is value:
                return ext, ext.object(value.number) or value
            raise InstructionError(E.INVALID_TECHNOLOGY_DB)
        if isinstance(value, (bool,)) or not isinstance(value, numbers.Integral):
            raise InstructionError(E.NOT_A_TECHNOLOGY_DB)
        number = int(value)
        if -32768 <= number < 0:
            number += 65536                      # DB 32768..65535 passed as an INT (§6.9.3)
        ext = current()
        db = ext.db(number) if ext is not None else None
        if db is None:
            raise InstructionError(E.NOT_A_TECHNOLOGY_DB)
        return ext, ext.object(number) or db

    def _listed(self, code: int, instead: int) -> InstructionError:
        """``code`` if the instruction's ErrorID table of §6 lists it, else ``instead`` (the code of that table
        that says the same thing for this FB, docs: the fuzz report's decisions)."""
        table = FB_BY_NAME.get(type(self).__name__)
        return InstructionError(code if table is None or code in table.all_codes() else instead)

    def _axis(self, name: str = "Axis") -> Any:
        ext, to = self._resolve(getattr(self, name, None))
        if to is getattr(ext, "mcdevice", None):
            if self.TAKES_MCDEVICE:
                object.__setattr__(self, "_to", ext)
                return ext
            # MC_ActivateTO's table has no 8044: the MCDevice DB belongs to no technology object (8084)
            raise self._listed(E.NOT_SUPPORTED_BY_TO, E.INVALID_TECHNOLOGY_DB)
        if not isinstance(to, AxisT) or to.technology not in self.TECHNOLOGIES:
            raise self._listed(E.NOT_SUPPORTED_BY_TO, E.INVALID_TECHNOLOGY_DB)
        if not self.WHILE_DEACTIVATED and activation.deactivated(to):
            raise InstructionError(self.DEACTIVATED_ERROR)      # deactivated by MC_ActivateTO (§6.7.2)
        self._register(to)
        object.__setattr__(self, "_to", to)
        return to

    def _internal_failure(self, exc: Exception) -> None:
        to = self.__dict__.get("_to")
        if to is not None and self.__dict__.get("Axis") is not to:
            try:                                 # the Axis input is a DB number: stop the object it named
                to._internal_error(exc)
            except Exception:  # noqa: BLE001 - the axis is stopped as far as it can be
                pass
        super()._internal_failure(exc)  # type: ignore[misc]

    def _axis_error(self, kind: str) -> InstructionError:
        return InstructionError(E.NOT_SUPPORTED_BY_TO if kind == "other_type" else E.NOT_A_TECHNOLOGY_DB)

    def _fault_codes(self, fault: Fault) -> tuple[int, int]:
        code = E.fb_error(fault)
        return (E.INTERNAL_ERROR if code is None else code), 0


class Instruction(_S7T, fb.Instruction):
    """Base of the S7-Technology instructions without Execute (MC_Power)."""


class ExecuteInstruction(_S7T, fb.ExecuteInstruction):
    """S7-Technology instructions started by a rising edge at Execute (§5.8)."""

    OUTPUTS = {"Done": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0}

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_cmd_seq", 0)         # commands started by this instance (DoneFlag)
        object.__setattr__(self, "_starting", False)
        object.__setattr__(self, "_done_flag", 0)
        object.__setattr__(self, "_to", None)

    def _begin(self) -> None:
        object.__setattr__(self, "_cmd_seq", self._cmd_seq + 1)
        object.__setattr__(self, "_done_flag", 0)
        object.__setattr__(self, "_to", None)
        object.__setattr__(self, "_starting", True)     # until the end of this call (see _evaluate)
        super()._begin()
        job = self._job
        to = self.__dict__.get("_to")
        if job is not None and isinstance(to, AxisT):
            ext = to.ctl.extension
            if isinstance(ext, TechnologyDevice):
                ext.note_command()                       # CmdLoopDuration / MaxLoopDuration (§7.10)
                if self._done_flag:
                    ext.watch_done_flag(self, self._cmd_seq, job, self._done_flag, self._completed)

    def _evaluate(self) -> None:
        try:
            super()._evaluate()
        finally:
            object.__setattr__(self, "_starting", False)

    def _completed(self, job: Job) -> bool:
        """The event that toggles the DoneFlag (§6.9.2): the command is done."""
        return job.state == JobState.DONE

    def _final_for(self, job: Job):
        if job.state == JobState.ERROR and job.fault is not None:
            fault = job.fault
            code = None if fault.ack else E.fb_error(fault)
            if self._starting and code is not None:
                if E.is_warning(code):
                    return ("CommandAborted", code, 0)   # not executed, a warning: Error stays FALSE (§6.8)
                return ("Error", code, 0)            # could not be started: the instruction's channel
            to = self.__dict__.get("_to")
            if not fault.ack and isinstance(to, AxisT):
                to.note_rejected(fault)              # accepted, then refused: the technology DB's channel
            return ("CommandAborted", 0, 0)
        return super()._final_for(job)

    def _set_busy(self, busy: bool) -> None:
        """Busy, and the count of busy commands of the object (the Axis input may be a DB number)."""
        self._out(Busy=busy)
        axis = self._busy_axis
        to = self.__dict__.get("_to")
        if busy and axis is None and isinstance(to, AxisT):
            to.busy_commands.add(id(self))
            object.__setattr__(self, "_busy_axis", to)
        elif not busy and axis is not None:
            axis.busy_commands.discard(id(self))
            object.__setattr__(self, "_busy_axis", None)

    # --- inputs ---------------------------------------------------------------------------------------
    def _flag(self) -> int:
        """The DoneFlag input (0 none, 1..32 a flag of the MCDevice DB), else 16#8043."""
        flag = integer("DoneFlag", getattr(self, "DoneFlag", 0), range(0, 33))
        object.__setattr__(self, "_done_flag", flag)
        return flag


def real(name: str, value: Any) -> float:
    """A REAL input: 16#808B when it is no valid REAL, 16#8043 outside -1E12 < x < 1E12 (§6.9.3)."""
    if isinstance(value, (bool,)) or not isinstance(value, numbers.Real):
        raise InstructionError(E.INVALID_REAL)
    if isinstance(value, float) and not math.isfinite(value):
        raise InstructionError(E.INVALID_REAL)
    x = as_number(value)
    if x is None:
        raise InstructionError(E.INVALID_REAL)
    if not -REAL_LIMIT < x < REAL_LIMIT:
        raise InstructionError(E.ILLEGAL_PARAMETER)
    return x


def dynamic(name: str, value: Any, default: float, *, jerk: bool = False, zero: Callable[[], bool] | None = None,
            above: float | None = None) -> float:
    """A dynamic input (§6.9.3): < 0 ``default``, = 0 not permitted (Jerk: trapezoidal, INF; ``zero()`` TRUE:
    permitted where no such dynamics is needed), > 0 the value.  ``above``: a value beyond +1E12 means this
    (MC_Stop: the maximum); otherwise the range rule applies."""
    if above is not None and isinstance(value, numbers.Real) and not isinstance(value, bool):
        x = as_number(value)
        if x is not None and x >= REAL_LIMIT:
            return above
    x = real(name, value)
    if x < 0.0:
        return INF if jerk and default <= 0.0 else default
    if x == 0.0:
        if jerk:
            return INF
        if zero is not None and zero():
            return default
        raise InstructionError(E.ILLEGAL_PARAMETER)
    return x


def integer(name: str, value: Any, allowed) -> int:
    """An INT input with one of the ``allowed`` values, else 16#8043."""
    x = as_int(value)
    if x is None or x not in allowed:
        raise InstructionError(E.ILLEGAL_PARAMETER)
    return x


__all__ = ["Instruction", "ExecuteInstruction", "InstructionError", "ProgramError", "as_bool", "real", "dynamic",
           "integer", "ALL_AXES", "POSITION_AXES", "REAL_LIMIT"]
