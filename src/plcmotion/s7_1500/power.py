"""MC_Power and MC_Reset of the S7-1500 (technology version V5)."""
from __future__ import annotations

from typing import Any, ClassVar

from .technology.axes import PositioningAxis1500
from .technology.external_encoder import ExternalEncoder
from ..kernel.jobs import Job, JobKind, JobState
from .. import fb
from . import errors as E
from .base import ExecuteInstruction, _S71500, as_bool


class MC_Power(_S71500, fb.PowerInstruction):  # noqa: N801 - instruction name of the manual
    """Enable or disable a technology object.

    StartMode: 0 not position-controlled, 1 position-controlled.  StopMode: 0 emergency stop
    (DynamicDefaults.EmergencyDeceleration), 1 immediate stop (enable removed), 2 stop with the maximum
    dynamic values (DynamicLimits.MaxDeceleration, MaxJerk).  Error also reports a pending technology
    alarm of the axis (16#8001, details in ErrorDetail).  Disabling a following axis ends its synchronous
    operation; disabling a leading axis does not (§9.1).
    """

    OUTPUTS = {"Status": False, "Busy": False, "Error": False, "ErrorID": 0}
    AXIS_TYPES: ClassVar[tuple[type, ...]] = (PositioningAxis1500, ExternalEncoder)

    def _mode_error(self, name: str) -> tuple[int, int]:
        return E.parameter(name), 0

    def _alarm_codes(self, axis: Any) -> tuple[int, int]:
        return E.TO_ALARM, 0                     # the cause is in <TO>.ErrorDetail / ErrorWord


class MC_Reset(ExecuteInstruction):  # noqa: N801
    """Acknowledge the technology alarms of a technology object; Restart = TRUE re-initializes it with
    its start values (only while it is disabled / not in use)."""

    INPUTS = {"Axis": None, "Execute": False, "Restart": False}
    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0}
    AXIS_TYPES: ClassVar[tuple[type, ...]] = ()

    def _accept(self, value: Any, types: tuple[type, ...]) -> bool:
        return callable(getattr(value, "acknowledge", None)) and callable(getattr(value, "restart", None)) and \
            getattr(getattr(value, "ctl", None), "family", None) in ("S7-1500", "S7-1500T")

    def _start(self, axis: Any) -> Job:
        restart = as_bool(self, "Restart", self.Restart)
        job = Job(JobKind.RESET, owner=self)
        fault = axis.restart() if restart else axis.acknowledge()
        job.finish(JobState.DONE if fault is None else JobState.ERROR, fault)
        return job
