"""FB 409 MC_ChangeDataset: switch the data set of an axis while it runs (S7-Technology V4.1 §6.2.5, §3.1.10).

``Dataset`` (1..numberOfDataSets, else 16#8043) is put in force at the moment
``TypeOfAxis.NumberOfDataSets.changeMode`` names: NEVER - refused (16#8045); IN_POSITION - once the running
motion has reached its positioning window, on an axis enabled position-controlled, at once after the axis is
enabled again, never while it is synchronized; IN_STANDSTILL - once the axis stands still; IMMEDIATELY - now.
``Done`` follows at that moment, at once when ``Dataset`` is already in force.  A virtual axis has one data
set (16#804D).  A data set that measures with another encoder changes the actual value over to it at that
moment (``technology.encoders``): ``SyncEncoder`` = TRUE sets the actual value of the old encoder on the new
one, FALSE takes the new encoder's own (the axis may make a compensating motion); the new encoder must give
valid values at the start (16#8045) and at the moment (else the change waits).  MC_Power Enable = FALSE
aborts a waiting change (§6.8.3, CommandAborted).
"""
from __future__ import annotations

from ..kernel.jobs import Job, JobKind, JobState
from . import errors as E
from .base import ALL_AXES, ExecuteInstruction, InstructionError, as_bool, integer
from .technology import datasets as D
from .technology import override
from .technology.axes import AxisT
from .technology.encoders import dataset_encoder


def due(axis: AxisT, mode: int) -> bool:
    """Has the moment of ``changeMode`` come for ``axis``?"""
    if mode == D.IMMEDIATELY:
        return True
    if mode == D.IN_STANDSTILL:
        return bool(axis.ctl.bank.standstill[axis.index])
    # IN_POSITION: no motion left and the positioning window reached; a disabled axis waits for its enable
    if axis.state != "enabled" or not axis.position_controlled:
        return False
    follower = axis.follower
    if follower is not None and follower.coupling is not None:
        return False
    job = axis.job
    moving = job is not None and job.busy or axis.superimposed_active or axis.queue_waiting()
    return not moving and axis.positioning_monitor.job is None


class MC_ChangeDataset(ExecuteInstruction):  # noqa: N801 - instruction name of the manual
    """FB 409 (see the module docstring)."""

    INPUTS = {"Axis": 0, "Execute": False, "SyncEncoder": False, "Dataset": 1, "DoneFlag": 0}
    TECHNOLOGIES = ALL_AXES

    def _start(self, axis: AxisT) -> Job:
        sync = as_bool(self, "SyncEncoder", self.SyncEncoder)
        eff = axis.eff
        wanted = integer("Dataset", self.Dataset, range(1, eff[f"{D.DATA_SETS}.numberOfDataSets"] + 1))
        self._flag()
        if axis.virtual:
            raise InstructionError(E.INVALID_AXIS_TYPE)
        mode = eff[f"{D.DATA_SETS}.changeMode"]
        if mode == D.NEVER:
            raise InstructionError(E.NOT_ALLOWED_IN_STATE)
        reject = override.refusal(override.CHANGE_DATASET, axis._activities())
        if reject is not None:                              # §6.8.3: only a running restart refuses it (8045)
            code = E.fb_error(reject.fault())
            raise InstructionError(E.NOT_ALLOWED_IN_STATE if code is None else code)
        encoder = dataset_encoder(eff, wanted)
        if wanted != D.active(eff) and encoder != axis.encoders.active and not axis.encoders.is_valid(encoder):
            raise InstructionError(E.NOT_ALLOWED_IN_STATE)  # the new data set's encoder gives no valid values
        job = Job(JobKind.RESET, mode=wanted, owner=self)   # no motion: a command of the object itself
        job.extra.update(dataset=wanted, change_mode=mode, axis=axis, sync=sync, encoder=encoder)
        self._try(job)
        if job.busy:
            axis.dataset_change = job                       # waiting: MC_Power Enable = FALSE aborts it
        return job

    def _try(self, job: Job) -> None:
        axis = job.extra["axis"]
        encoder = job.extra["encoder"]
        if D.active(axis.eff) == job.extra["dataset"]:
            job.finish(JobState.DONE)                       # already in force: Done at once
        elif due(axis, job.extra["change_mode"]) and axis.encoders.is_valid(encoder):
            D.switch(axis, job.extra["dataset"], job.extra["sync"])
            job.finish(JobState.DONE)
        if not job.busy and axis.dataset_change is job:
            axis.dataset_change = None

    def _update(self, execute: bool) -> None:
        job = self._job
        if job is not None and job.busy:
            self._try(job)
        super()._update(execute)


__all__ = ["MC_ChangeDataset", "due"]
