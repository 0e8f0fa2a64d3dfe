"""MC_Power and MC_Reset of the S7-1500 (technology version V5)."""
from __future__ import annotations

from typing import Any, ClassVar

from ..kernel.axis1500 import PositioningAxis1500
from ..kernel.external_encoder import ExternalEncoder
from ..kernel.jobs import Job, JobKind, JobState
from . import errors as E
from .base import ExecuteInstruction, Instruction, InstructionError, as_bool, as_int


class MC_Power(Instruction):  # noqa: N801 - instruction name of the manual
    """Enable or disable a technology object.

    StartMode: 0 not position-controlled, 1 position-controlled.  StopMode: 0 emergency stop
    (DynamicDefaults.EmergencyDeceleration), 1 immediate stop (enable removed), 2 stop with the maximum
    dynamic values (DynamicLimits.MaxDeceleration, MaxJerk).  Error also reports a pending technology
    alarm of the axis (16#8001, details in ErrorDetail).  Disabling a following axis ends its synchronous
    operation; disabling a leading axis does not (§9.1).
    """

    INPUTS = {"Axis": None, "Enable": False, "StartMode": 1, "StopMode": 0}
    OUTPUTS = {"Status": False, "Busy": False, "Error": False, "ErrorID": 0}
    AXIS_TYPES: ClassVar[tuple[type, ...]] = (PositioningAxis1500, ExternalEncoder)

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_stop_mode", 0)

    def _evaluate(self) -> None:
        enable = as_bool(self, "Enable", self.Enable)
        try:
            axis = self._axis()
        except InstructionError as err:
            self._out(Status=False, Busy=enable, Error=True, ErrorID=err.error_id)
            return
        own: int | None = None
        stop_mode, start_mode = as_int(self.StopMode), as_int(self.StartMode)
        if stop_mode not in (0, 1, 2):
            own = E.parameter("StopMode")
        elif start_mode not in (0, 1):
            own = E.parameter("StartMode")
        else:
            object.__setattr__(self, "_stop_mode", stop_mode)
        if own is not None and enable and axis.power_owner is not self and axis.state == "disabled":
            self._status(axis, enable, own)
            return
        reject = axis.power(self, enable, start_mode if start_mode in (0, 1) else 1, self._stop_mode)
        if reject is not None:
            self._status(axis, enable, E.code(reject))
            return
        self._status(axis, enable, own)

    def _status(self, axis: Any, enable: bool, own: int | None) -> None:
        owner = axis.power_owner is self
        status = owner and axis.state in ("enabled", "disabling")
        busy = enable or (owner and axis.state == "disabling")
        if own is None and axis.alarms:
            own = E.TO_ALARM                 # the cause is in <TO>.ErrorDetail / ErrorWord
        self._out(Status=status, Busy=busy, Error=own is not None, ErrorID=own or 0)


class MC_Reset(ExecuteInstruction):  # noqa: N801
    """Acknowledge the technology alarms of a technology object; Restart = TRUE re-initializes it with
    its start values (only while it is disabled / not in use)."""

    INPUTS = {"Axis": None, "Execute": False, "Restart": False}
    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0}
    AXIS_TYPES: ClassVar[tuple[type, ...]] = ()

    def _accept(self, value: Any, types: tuple[type, ...]) -> bool:
        return callable(getattr(value, "acknowledge", None)) and callable(getattr(value, "restart", None)) and \
            getattr(type(value), "family", "S7-1500") != "S7-1200" and hasattr(value, "ctl")

    def _start(self, axis: Any) -> Job:
        restart = as_bool(self, "Restart", self.Restart)
        job = Job(JobKind.RESET, owner=self)
        fault = axis.restart() if restart else axis.acknowledge()
        job.finish(JobState.DONE if fault is None else JobState.ERROR, fault)
        return job
