"""MC_Home (S7-1200 Motion Control V6 §11.1.3, §2.5, §5.4.4.5)."""
from __future__ import annotations

from typing import Any

from ..kernel.jobs import Job, JobKind
from .. import fb
from . import errors as E
from ..fb import as_number
from .base import ExecuteInstruction, InstructionError, as_int, as_real

POSITION_LIMIT = 1.0e12


def check_position(value: Any, error_id: int = E.POSITION) -> float:
    """A position/distance input: number format and the +-1E12 range (§12.8 16#8400/16#8401); an
    integer beyond the REAL range is out of that range."""
    x = as_number(value)
    if x is None:
        raise InstructionError(error_id, E.INVALID_FORMAT)
    if x > POSITION_LIMIT:
        raise InstructionError(error_id, E.ABOVE_1E12)
    if x < -POSITION_LIMIT:
        raise InstructionError(error_id, E.BELOW_MINUS_1E12)
    return x


class MC_Home(fb.ReferenceMarkOutput, ExecuteInstruction):  # noqa: N801
    """Home the axis or set its reference point.

    Mode 0: position := Position; 1: position := position + Position; 2 passive and 3 active homing
    need a configured homing switch; 6/7 absolute encoder adjustment (PROFIdrive/analog with absolute
    encoder).  ReferenceMarkPosition gives the position the axis was homed to.
    """

    INPUTS = {"Axis": None, "Execute": False, "Position": 0.0, "Mode": 0}
    OUTPUTS = {"Done": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0,
               "ErrorInfo": 0, "ReferenceMarkPosition": 0.0}

    def _start(self, axis: Any) -> Job:
        mode = as_int(self.Mode)
        if mode not in (0, 1, 2, 3, 6, 7):
            raise InstructionError(E.MODE, E.INVALID_SELECTION)
        position = check_position(self.Position)
        absolute_encoder = (not axis.pto) and axis.eff["Sensor[1].Type"] == 1
        if mode in (6, 7):
            if axis.pto:
                raise InstructionError(E.MODE, E.INVALID_SELECTION)     # only analog/PROFIdrive (§11.1.3)
            if not absolute_encoder:
                raise InstructionError(E.MODE, 0x0055)
        if mode in (2, 3):
            if absolute_encoder:
                raise InstructionError(E.MODE, 0x0056)
            homing = getattr(axis, "homing", None)                     # an axis kind without homing: None
            if homing is None or not homing.configured(mode):
                raise InstructionError(E.MODE, 0x0015)                  # no homing switch configured
            if mode == 3 and axis.eff["Homing.AutoReversal"] and not axis.eff["PositionLimits_HW.Active"]:
                raise InstructionError(E.MODE, 0x0017)                  # reversal needs the HW limit switches
        kind = {0: JobKind.HOME_DIRECT, 1: JobKind.HOME_DIRECT, 6: JobKind.HOME_DIRECT, 7: JobKind.HOME_DIRECT,
                2: JobKind.HOME_PASSIVE, 3: JobKind.HOME_ACTIVE}[mode]
        job = Job(kind, position=position, mode=mode, owner=self)
        if kind == JobKind.HOME_DIRECT:
            axis.home_direct(job)
        else:
            axis.home(job)
        return job
