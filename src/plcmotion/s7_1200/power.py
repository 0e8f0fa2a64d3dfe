"""MC_Power and MC_Reset (S7-1200 Motion Control V6 §11.1.1, §11.1.2)."""
from __future__ import annotations

from typing import Any

from ..kernel.jobs import Job, JobKind, JobState
from . import errors as E
from .. import fb
from .base import ExecuteInstruction, _S71200, as_bool


class MC_Power(_S71200, fb.PowerInstruction):  # noqa: N801 - instruction name of the manual
    """Enable or disable an axis.

    Inputs: Axis, Enable, StartMode (0 not position-controlled, 1 position-controlled; ignored for PTO),
    StopMode (0 emergency stop, 1 immediate stop, 2 emergency stop with jerk).
    Outputs: Status, Busy, Error, ErrorID, ErrorInfo.  Error also reports errors of the axis (§9.6).
    """

    OUTPUTS = {"Status": False, "Busy": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}

    def _mode_error(self, name: str) -> tuple[int, int]:
        return (E.STOP_MODE if name == "StopMode" else E.START_MODE), E.INVALID_SELECTION

    def _alarm_codes(self, axis: Any) -> tuple[int, int]:
        return E.codes(axis.alarms[0])


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
