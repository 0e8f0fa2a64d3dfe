"""MC_Power and MC_Reset (S7-1200 Motion Control V6 §11.1.1, §11.1.2)."""
from __future__ import annotations

from typing import Any

from ..kernel.jobs import Job, JobKind, JobState
from . import errors as E
from .base import ExecuteInstruction, Instruction, InstructionError, as_bool, as_int


class MC_Power(Instruction):  # noqa: N801 - instruction name of the manual
    """Enable or disable an axis.

    Inputs: Axis, Enable, StartMode (0 not position-controlled, 1 position-controlled; ignored for PTO),
    StopMode (0 emergency stop, 1 immediate stop, 2 emergency stop with jerk).
    Outputs: Status, Busy, Error, ErrorID, ErrorInfo.  Error also reports errors of the axis (§9.6).
    """

    INPUTS = {"Axis": None, "Enable": False, "StartMode": 1, "StopMode": 0}
    OUTPUTS = {"Status": False, "Busy": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_stop_mode", 0)
        object.__setattr__(self, "_axis_used", None)

    def _evaluate(self) -> None:
        enable = as_bool(self, "Enable", self.Enable)
        try:
            axis = self._axis()
        except InstructionError as err:
            self._out(Status=False, Busy=enable, Error=True, ErrorID=err.error_id, ErrorInfo=err.error_info)
            return
        own_error: tuple[int, int] | None = None
        stop_mode = as_int(self.StopMode)
        start_mode = as_int(self.StartMode)
        if stop_mode not in (0, 1, 2):
            own_error = (E.STOP_MODE, E.INVALID_SELECTION)
        elif start_mode not in (0, 1):
            own_error = (E.START_MODE, E.INVALID_SELECTION)
        else:
            object.__setattr__(self, "_stop_mode", stop_mode)   # taken over while Enable = TRUE (§9.3)
        if own_error is not None and enable and axis.power_owner is not self and axis.state == "disabled":
            # an invalid mode keeps the axis from being enabled; correct it and the enable proceeds
            self._show(axis, enable, own_error)
            return
        reject = axis.power(self, enable, start_mode if start_mode in (0, 1) else 1, self._stop_mode)
        if reject is not None:
            self._show(axis, enable, E.codes(reject))
            return
        object.__setattr__(self, "_axis_used", axis)
        self._show(axis, enable, own_error)

    def _show(self, axis: Any, enable: bool, own_error: tuple[int, int] | None) -> None:
        owner = axis.power_owner is self
        status = owner and axis.state in ("enabled", "disabling")
        busy = enable or (owner and axis.state == "disabling")
        if own_error is None and axis.alarms:
            own_error = E.codes(axis.alarms[0])
        if own_error is None:
            self._out(Status=status, Busy=busy, Error=False, ErrorID=0, ErrorInfo=0)
        else:
            self._out(Status=status, Busy=busy, Error=True, ErrorID=own_error[0], ErrorInfo=own_error[1])


class MC_Reset(ExecuteInstruction):  # noqa: N801
    """Acknowledge errors of the axis; with Restart = TRUE reload its configuration (axis disabled)."""

    INPUTS = {"Axis": None, "Execute": False, "Restart": False}
    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}

    def _start(self, axis: Any) -> Job:
        restart = as_bool(self, "Restart", self.Restart)
        job = Job(JobKind.RESET, owner=self)
        fault = axis.restart() if restart else axis.acknowledge()
        job.finish(JobState.DONE if fault is None else JobState.ERROR, fault)
        return job
