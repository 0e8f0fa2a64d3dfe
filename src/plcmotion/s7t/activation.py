"""FB 460 MC_ActivateTO and FB 457 MC_ActivateDPSlave (S7-Technology V4.1 §6.7.2, §6.7.3).

``Mode`` 0 reads the state into ``Status`` (Done in the same call), 1 activates, 2 deactivates; a change
takes its time in the technology (``technology.activation``, ``technology.dp_drive``) and the FB is Busy
until it is done.  Neither FB aborts a command nor can be aborted (§6.8).

MC_ActivateTO deactivates an axis only when nothing uses it: disabled (else 16#8045), no command of it
still running and no restart (16#8045), not the leading axis of a coupled synchronization axis (16#8054);
a second activation command while one runs gives 16#8057.  MC_ActivateDPSlave addresses the slave by its
diagnostic address (the manual's input "Diagnostic address", here ``DiagnosticAddress``); an address that
names no slave on DP(DRIVE) gives 16#8090.
"""
from __future__ import annotations

from ..kernel.jobs import Job, JobKind, JobState
from . import fb_errors as FE
from .base import ALL_AXES, ExecuteInstruction, InstructionError, integer
from .service import ServiceInstruction, int_input
from .technology import activation as A
from .technology import dp_drive as DP
from .technology import parameter_access as PA
from .technology.axes import AxisT
from .technology.device import TechnologyDevice

MODES = (0, 1, 2)
READ_STATUS, ACTIVATE, DEACTIVATE = MODES


def _running(axis: AxisT) -> bool:
    """A command of the axis still runs (motion, MC_Stop, a waiting command, superimposed motion)."""
    job, stop = axis.job, axis.stop_job
    return bool((job is not None and job.busy) or (stop is not None and stop.busy) or axis.queue_waiting()
                or axis.superimposed_active)


def _leading_in_use(axis: AxisT) -> bool:
    """Another axis is coupled to ``axis`` as its leading axis."""
    for other in axis.ctl.axes.values():
        follower = getattr(other, "follower", None)
        coupling = getattr(follower, "coupling", None) if follower is not None else None
        if coupling is not None and getattr(coupling, "source", None) is axis:
            return True
    return False


def _reactivated(axis: AxisT) -> None:
    """Activated again: system variables as after a restart (§6.7.2) - a "Restart" parameter change still
    waits for its restart -, the drive only if its slave is active."""
    PA.reinitialize_keeping_pending(axis)
    DP.bus(axis.ctl.extension).to_activated(axis)


class MC_ActivateTO(ExecuteInstruction):  # noqa: N801 - instruction name of the manual
    """FB 460: activate or deactivate a technology object, or read whether it is (Status 1..4)."""

    INPUTS = {"Axis": 0, "Execute": False, "Mode": 0}
    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0, "Status": 0}
    TECHNOLOGIES = ALL_AXES
    WHILE_DEACTIVATED = True

    def _start(self, to: AxisT) -> Job:
        mode = integer("Mode", self.Mode, MODES)
        job = Job(JobKind.RESET, owner=self)     # the kernel's kind of a job that never moves the axis
        state = A.state(to)
        if mode == READ_STATUS:
            job.extra["status"] = state
            job.finish(JobState.DONE)
            return job
        if state in (A.ACTIVATING, A.DEACTIVATING):
            raise InstructionError(FE.ACTIVATION_ALREADY_ACTIVE)
        if mode == ACTIVATE:
            if state == A.DEACTIVATED:
                A.activate(to, lambda: _reactivated(to))
                job.extra["axis"] = to
            else:
                job.finish(JobState.DONE)
            return job
        if state == A.DEACTIVATED:
            job.finish(JobState.DONE)
            return job
        if to.power_owner is not None or to.state != "disabled" or to.restarting or _running(to):
            raise InstructionError(FE.NOT_ALLOWED)                   # enabled, or a command still runs
        if _leading_in_use(to):
            raise InstructionError(FE.DEACTIVATION_NOT_PERMITTED)
        A.begin(to, A.DEACTIVATED)
        job.extra["axis"] = to
        return job

    def _update(self, execute: bool) -> None:
        job = self._job
        if job is not None and job.busy and not A.busy(job.extra["axis"]):
            job.finish(JobState.DONE)
        super()._update(execute)

    def _final_for(self, job: Job):
        object.__setattr__(self, "_status", job.extra.get("status", 0))
        return super()._final_for(job)

    def _show(self, output: str, error_id: int, error_info: int) -> None:
        super()._show(output, error_id, error_info)
        if output == "Done":
            self._out(Status=self.__dict__.get("_status", 0))


class MC_ActivateDPSlave(ServiceInstruction):  # noqa: N801
    """FB 457: activate or deactivate a DP slave on DP(DRIVE), or read its Status (1 activated, 2
    deactivated, 3 being activated).  Done says the command was initiated; Mode 0 shows when an
    activation is complete."""

    INPUTS = {"DiagnosticAddress": 0, "Execute": False, "Mode": 0}
    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0, "Status": 0}

    def _submit(self, device: TechnologyDevice, job: Job) -> None:
        mode = int_input(self.Mode, range(0, 3))
        address = int_input(self.DiagnosticAddress, range(-32768, 32768))
        slave = DP.bus(device).by_diagnostic(address)
        if slave is None:
            raise InstructionError(FE.INVALID_ADDRESS)
        if mode == READ_STATUS:
            job.extra["status"] = slave.status
            job.finish(JobState.DONE)
            return
        if slave.pending or slave.status == DP.ACTIVATING:
            raise InstructionError(FE.ACTIVATION_ALREADY_ACTIVE)
        DP.bus(device).set_active(slave, mode == ACTIVATE, lambda: self.complete(job))

    def _final_for(self, job: Job):
        object.__setattr__(self, "_status", job.extra.get("status", 0))
        return super()._final_for(job)

    def _show(self, output: str, error_id: int, error_info: int) -> None:
        super()._show(output, error_id, error_info)
        if output == "Done":
            self._out(Status=self.__dict__.get("_status", 0))


__all__ = ["MC_ActivateTO", "MC_ActivateDPSlave"]
