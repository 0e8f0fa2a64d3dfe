"""Machinery of the basic-function FBs that address the technology as a whole rather than an axis
(S7-Technology V4.1 §6.7.3, §6.7.6-§6.7.11): MC_ActivateDPSlave, MC_Read/WritePeriphery, MC_Read/WriteRecord,
MC_Read/WriteDriveParameter.

Their commands run in the technology's command slices (``technology.dp_drive.Slices``): Busy from the call
of the rising edge until the slice that completes them, then Done or Error (these FBs report errors found
while the command ran at ``Error``, not in a technology DB).  They neither abort nor can be aborted by
another command (§6.8).  A technology takes at most ``MAX_COMMANDS`` such commands at once; one more is
refused with 16#8005.
"""
from __future__ import annotations

import weakref
from typing import Any

from ..fb import as_int
from ..kernel.jobs import Job, JobKind, JobState
from . import fb_errors as FE
from .base import ExecuteInstruction, InstructionError
from .technology.device import TechnologyDevice, current

#: commands of these FBs a technology runs at the same time (the manual names no number; plcmotion's)
MAX_COMMANDS = 8

_RUNNING: "weakref.WeakKeyDictionary[TechnologyDevice, set[int]]" = weakref.WeakKeyDictionary()


def running(device: TechnologyDevice) -> set[int]:
    found = _RUNNING.get(device)
    if found is None:
        found = _RUNNING[device] = set()
    return found


def int_input(value: Any, allowed: range) -> int:
    """An INT / DINT input with a value in ``allowed``, else 16#8043."""
    x = as_int(value)
    if x is None or x not in allowed:
        raise InstructionError(FE.ILLEGAL_PARAMETER)
    return x


def data_area(value: Any, *, writable: bool, maximum: int, too_long: int) -> bytearray | bytes:
    """The ``Data`` ANY input: a bytearray (destination) or bytes-like (source).  None: no data area
    (16#8088); another type: invalid pointer format (16#808C); empty: 16#8089; longer than ``maximum``
    bytes: ``too_long``."""
    if value is None:
        raise InstructionError(FE.INVALID_ANY_DB)
    if writable:
        if not isinstance(value, bytearray):
            raise InstructionError(FE.INVALID_POINTER)
    elif not isinstance(value, (bytes, bytearray)):
        raise InstructionError(FE.INVALID_POINTER)
    if len(value) == 0:
        raise InstructionError(FE.INVALID_DATA_LENGTH)
    if len(value) > maximum:
        raise InstructionError(too_long)
    return value


class ServiceInstruction(ExecuteInstruction):
    """An Execute FB of the technology without an Axis input; ``_start`` gets the TechnologyDevice."""

    INPUTS = {"Execute": False, "DoneFlag": 0}

    def _axis(self, name: str = "Axis") -> TechnologyDevice:
        ext = current()
        if ext is None:
            raise InstructionError(FE.TECHNOLOGY_NOT_READY)
        if ext.ctl.mode != "RUN":
            raise InstructionError(FE.TECHNOLOGY_NOT_READY)
        self._register(ext)
        return ext

    def _start(self, device: TechnologyDevice) -> Job:
        flag = self._flag() if "DoneFlag" in self.INPUTS else 0
        work = running(device)
        if len(work) >= MAX_COMMANDS:
            raise InstructionError(FE.COMMAND_MEMORY_FULL)
        job = Job(JobKind.RESET, owner=self)     # the kernel's kind of a job that never moves an axis
        self._submit(device, job)
        if job.busy:
            work.add(id(job))
            job.extra["device"] = device
        if flag:
            device.watch_done_flag(self, self._cmd_seq, job, flag, self._completed)
        return job

    def _submit(self, device: TechnologyDevice, job: Job) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    @staticmethod
    def complete(job: Job, error_id: int = 0) -> None:
        """End a command in a command slice: Done, or Error with ``error_id``."""
        if not job.busy:
            return
        job.extra["error_id"] = error_id
        job.finish(JobState.ERROR if error_id else JobState.DONE)
        device = job.extra.get("device")
        if device is not None:
            running(device).discard(id(job))

    def _final_for(self, job: Job):
        if job.state == JobState.ERROR:
            return ("Error", job.extra.get("error_id", FE.INTERNAL_ERROR), 0)
        return super()._final_for(job)


__all__ = ["ServiceInstruction", "running", "int_input", "data_area", "MAX_COMMANDS"]
