"""MC_Home of the S7-1500 (technology version V5).

Mode 0: position := Position; 1: position := position + Position; 2 passive homing (the homing status
is reset first), 8 passive homing without reset, 10 passive homing to ``Homing.HomePosition``; 3 active
homing, 5 active homing to ``Homing.HomePosition``; 6/7 absolute encoder adjustment (relative/absolute);
9 cancel passive homing.  Active homing aborts running motions, passive and direct homing do not
(§6.1.5.5, §9.3.1).
"""
from __future__ import annotations

from typing import Any

from .technology.axes import PositioningAxis1500
from .technology.external_encoder import ExternalEncoder
from ..kernel.jobs import Job, JobKind, JobState
from .. import fb
from . import errors as E
from .base import ExecuteInstruction, InstructionError, as_int, real

MODES = (0, 1, 2, 3, 5, 6, 7, 8, 9, 10)


class MC_Home(fb.ReferenceMarkOutput, ExecuteInstruction):  # noqa: N801
    INPUTS = {"Axis": None, "Execute": False, "Position": 0.0, "Mode": 0}
    OUTPUTS = {"Done": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0,
               "ReferenceMarkPosition": 0.0}
    AXIS_TYPES = (PositioningAxis1500, ExternalEncoder)

    def _start(self, axis: Any) -> Job:
        mode = as_int(self.Mode)
        if mode not in MODES or (isinstance(axis, ExternalEncoder) and mode not in (0, 1, 6, 7)):
            raise InstructionError(E.parameter("Mode"))
        position = real("Position", self.Position)
        if mode in (5, 10):
            position = axis.ueff["Homing.HomePosition"]
        absolute = axis.absolute_encoder()
        if mode in (6, 7) and not absolute:
            raise InstructionError(E.MODE_NEEDS_ABSOLUTE)      # absolute encoder adjustment
        if mode in (2, 3, 5, 8, 10):
            if absolute and not axis.sim:
                raise InstructionError(E.MODE_NOT_ABSOLUTE)    # homing with an incremental encoder only
            if not axis.homing_configured(3 if mode in (3, 5) else 2):
                raise InstructionError(E.parameter("Mode"))
        if mode == 9:
            job = Job(JobKind.HOME_CANCEL, mode=mode, owner=self)
            axis.homing.end_passive(JobState.ABORTED)
            job.finish(JobState.DONE)
            return job
        if mode in (0, 1, 6, 7):
            job = Job(JobKind.HOME_DIRECT, position=position, mode=mode, owner=self)
            axis.home_direct(job)
            return job
        kind = JobKind.HOME_ACTIVE if mode in (3, 5) else JobKind.HOME_PASSIVE
        job = Job(kind, position=position, mode=2 if kind == JobKind.HOME_PASSIVE else 3, owner=self)
        if mode == 2 and axis.state == "enabled":
            axis.homed = False                  # passive homing with reset of the homing status
        axis.home(job)
        return job
