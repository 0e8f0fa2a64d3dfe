"""MC_CommandTable (S7-1200 Motion Control V6 §11.1.9): run the steps of a command table on a PTO axis."""
from __future__ import annotations

from typing import Any

from .technology.command_table import STEPS, CommandTable
from ..kernel.jobs import Job, JobKind
from . import errors as E
from .base import ExecuteInstruction, InstructionError, as_int

COMMAND_TABLE = 0x8409
START_STEP = 0x840A
END_STEP = 0x840B


class MC_CommandTable(ExecuteInstruction):  # noqa: N801
    """Run StartStep..EndStep of a command table; CurrentStep and StepCode show the running step.

    Only for axes with a PTO drive.  The command running on the axis is aborted when the first
    positioning, velocity or halt step starts, not at Execute.
    """

    INPUTS = {"Axis": None, "CommandTable": None, "Execute": False, "StartStep": 1, "EndStep": 32}
    OUTPUTS = {"Done": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0,
               "ErrorInfo": 0, "CurrentStep": 0, "StepCode": 0}

    def _start(self, axis: Any) -> Job:
        runner = getattr(axis, "table_runner", None)
        if not axis.pto or runner is None:
            raise InstructionError(E.AXIS, 0x001B)          # the command table needs a PTO axis (§11.1.9)
        table = self.CommandTable
        if not isinstance(table, CommandTable):
            raise InstructionError(COMMAND_TABLE, 0x001B if hasattr(table, "tag") else 0x001C)
        start, end = as_int(self.StartStep), as_int(self.EndStep)
        if start is None or start <= 0:
            raise InstructionError(START_STEP, E.NOT_POSITIVE)
        if start > STEPS:
            raise InstructionError(START_STEP, 0x001E)
        if end is None or end <= 0:
            raise InstructionError(END_STEP, E.NOT_POSITIVE)
        if end > STEPS:
            raise InstructionError(END_STEP, 0x001E)
        if start > end:
            raise InstructionError(START_STEP, 0x001D)
        job = Job(JobKind.TABLE, owner=self, extra={"table": table, "start": start, "end": end})
        runner.start(job)
        return job

    def _running(self, execute: bool) -> None:
        job = self._job
        if job is not None:
            self._out(CurrentStep=job.extra.get("current", 0), StepCode=job.extra.get("step_code", 0))

    def _clear_outputs(self) -> None:
        keep = (self.CurrentStep, self.StepCode)       # the last step stays visible after the end
        super()._clear_outputs()
        self._out(CurrentStep=keep[0], StepCode=keep[1])
