"""FB 437 MC_SetTorqueLimit and FB 439 MC_SetCharacteristic (S7-Technology V4.1 §6.2.12, §6.2.13): the two
single commands of table (3) that change the drive rather than move the axis.

Both complete in the call that starts them (Done), so a new rising edge never finds the previous command of
an instance running; the one that came last is in force.
"""
from __future__ import annotations

from typing import Any

from ..kernel.jobs import Job, JobKind, JobState
from . import errors as E
from .base import ALL_AXES, ExecuteInstruction, InstructionError, as_bool, integer, real
from .technology import override as O
from .technology.axes import AxisT
from .technology.cam_disk import CamDisk
from .technology.device import TechnologyDevice, current
from .technology.hydraulic_params import MAX_TORQUE, TORQUE_TELEGRAMS, VALVE_PROFILES


def _refused(axis: AxisT, command: str) -> None:
    """8045 (MC_Stop active, restart running) or 8056 (clamped) from the override policy (§6.8.3)."""
    reject = O.refusal(command, axis._activities())
    if reject is not None:
        code = O.error_id(reject.fault())
        raise InstructionError(code if code is not None else E.NOT_ALLOWED_IN_STATE)


def _done(owner: Any) -> Job:
    job = Job(JobKind.RESET, owner=owner)
    job.finish(JobState.DONE)
    return job


def torque_limit(axis: AxisT) -> float | None:
    """The limit [N m] MC_SetTorqueLimit put in force on ``axis`` (None: none)."""
    return axis.__dict__.get("set_torque_limit")


class MC_SetTorqueLimit(ExecuteInstruction):  # noqa: N801 - instruction name of the manual
    """FB 437: limit the drive torque to MaxTorque [N m] (EnableLimit TRUE; MaxTorque = 0: the configured
    torque reference ``TypeOfAxis.SetPointDriverInfo.DriveData.maxTorque``) or lift the limit (EnableLimit
    FALSE).  Statusword.TorqueLimitingCommand while the limit is set, Statusword.TorqueLimiting while the
    drive gives as much torque as it allows.  The limit stays when MC_Power disables the axis (V4.1).  Real
    electric axes on a telegram with torque reduction (101-106) only: a virtual or hydraulic axis 16#804D,
    another telegram 16#8043."""

    INPUTS = {"Axis": 0, "Execute": False, "EnableLimit": True, "MaxTorque": 3.2, "DoneFlag": 0}
    TECHNOLOGIES = ALL_AXES

    def _start(self, axis: AxisT) -> Job:
        enable = as_bool(self, "EnableLimit", self.EnableLimit)
        value = real("MaxTorque", self.MaxTorque)
        self._flag()
        if axis.virtual or axis.hydraulic:
            raise InstructionError(E.INVALID_AXIS_TYPE)
        if value < 0.0 or axis.cfg["Wizard.Telegram"] not in TORQUE_TELEGRAMS:
            raise InstructionError(E.ILLEGAL_PARAMETER)
        _refused(axis, O.SET_TORQUE_LIMIT)
        if axis.state != "enabled":
            raise InstructionError(E.NOT_ALLOWED_IN_STATE)     # its table has no 8040 (§6.2.12)
        limit = (value if value > 0.0 else axis.eff[MAX_TORQUE]) if enable else None
        axis.__dict__["set_torque_limit"] = limit
        if not clamping_active(axis):          # MC_MoveToEndPos keeps its own limit until it ends
            axis.drive.set_torque_limit(limit)
            axis.torque_limiting_command = limit is not None
        return _done(self)


def clamping_active(axis: AxisT) -> bool:
    from .end_pos import watch_of
    return watch_of(axis) is not None


class MC_SetCharacteristic(ExecuteInstruction):  # noqa: N801
    """FB 439: activate the valve profile of cam disk ``CamTable`` (its technology DB number, or the cam disk)
    on a hydraulic axis (Mode 0: Q-valve profile).  The output jump of the changeover is compensated at
    ``userdefaultqfaxis.maxderivative.qoutput`` (100 %/s by default).  The cam disk must be one of the axis's
    valve profiles (``Drive.ValveProfile1..4``, else 16#804A); not a hydraulic axis 16#804D; CamTable no cam
    disk 16#8044.  Outputs Done, Busy, Error, ErrorID (no CommandAborted)."""

    INPUTS = {"Axis": 0, "CamTable": 0, "Execute": False, "Mode": 0, "DoneFlag": 0}
    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0}
    TECHNOLOGIES = ALL_AXES

    def _start(self, axis: AxisT) -> Job:
        integer("Mode", self.Mode, (0,))
        self._flag()
        cam = self._cam(getattr(self, "CamTable", 0))
        if not axis.hydraulic:
            raise InstructionError(E.INVALID_AXIS_TYPE)
        if cam.db_number not in [axis.cfg[tag] for tag in VALVE_PROFILES]:
            raise InstructionError(E.MISSING_CONNECTION)
        _refused(axis, O.SET_CHARACTERISTIC)
        axis.drive.set_characteristic(cam.characteristic)
        axis.__dict__["valve_profile"] = cam
        return _done(self)

    @staticmethod
    def _cam(value: Any) -> CamDisk:
        if isinstance(value, CamDisk):
            return value
        ext = current()
        obj = ext.object(value) if isinstance(ext, TechnologyDevice) else None
        if not isinstance(obj, CamDisk):
            raise InstructionError(E.NOT_SUPPORTED_BY_TO)
        return obj

    def _final_for(self, job: Job):
        final = super()._final_for(job)
        return None if final is not None and final[0] == "CommandAborted" else final


def valve_profile(axis: AxisT) -> CamDisk | None:
    """The cam disk MC_SetCharacteristic activated last on ``axis`` (None: the straight line)."""
    return axis.__dict__.get("valve_profile")


__all__ = ["MC_SetTorqueLimit", "MC_SetCharacteristic", "torque_limit", "valve_profile"]
