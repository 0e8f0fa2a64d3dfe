"""Status tags of the S7-1200 positioning axis (S7-1200 V6 §12.9, V7 §12.9) and its class of the family.

``axis.StatusBits.Enable`` reads the same value as ``axis.tag("StatusBits.Enable")``: the tables here map
the S7-1200 names onto the kernel's state (``kernel.axis_status``, the jobs, the alarms), computed when
read (nothing is copied per cycle); ``kernel.tag_views`` presents them.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable

from ...kernel import axis_status as S
from ...kernel import faults as F
from ...kernel.axis_status import communication_fault
from ...kernel.jobs import JobKind

if TYPE_CHECKING:  # pragma: no cover
    from ...kernel.axis import PositioningAxis



def _b(ax: "PositioningAxis"):
    return ax.ctl.bank


def _job_kind(ax: "PositioningAxis") -> JobKind | None:
    job = ax.job
    return job.kind if job is not None and job.busy else None


def _alarm_kinds(ax: "PositioningAxis") -> set[str]:
    return {a.kind for a in ax.alarms}


def _constant_velocity(ax: "PositioningAxis") -> bool:
    b, i = _b(ax), ax.index
    if S.accel_state(ax) != 0:
        return False
    if float(b.sp_v[i]) != 0.0:
        return True
    # §11.1.7: MC_MoveVelocity with Velocity 0 reports ConstantVelocity at standstill
    return ax.holding_zero_velocity


def _positioning_job(ax: "PositioningAxis"):
    """The running positioning: MC_MoveAbsolute/-Relative or a positioning step of a command table (§10.2)."""
    job = ax.job
    if job is None or not job.busy:
        return None
    if job.kind in (JobKind.ABSOLUTE, JobKind.RELATIVE):
        return job
    if job.kind == JobKind.TABLE and job.extra.get("phase") == "position":
        return job
    return None


def _distance(ax: "PositioningAxis") -> float:
    job = _positioning_job(ax)
    return 0.0 if job is None else abs(job.target - float(_b(ax).sp_p[ax.index]))


def _target(ax: "PositioningAxis") -> float:
    job = _positioning_job(ax)
    return 0.0 if job is None else ax._wrap(job.target)


#: status tags: path -> getter
DYNAMIC: dict[str, Callable[["PositioningAxis"], Any]] = {
    "Position": S.position,
    "Velocity": S.velocity,
    "Acceleration": S.acceleration,
    "ActualPosition": S.actual_position,
    "ActualVelocity": S.actual_velocity,
    "StatusPositioning.Distance": _distance,
    "StatusPositioning.TargetPosition": _target,
    "StatusPositioning.FollowingError": lambda ax: float(_b(ax).fe[ax.index]) if ax.servo else 0.0,
    "StatusDrive.InOperation": S.drive_in_operation,
    "StatusDrive.CommunicationOK": S.drive_communication_ok,
    "StatusDrive.AdaptionState": lambda ax: 3,
    "StatusSensor.State": lambda ax: 0 if ax.pto else (2 if ax.sensor_valid else 0),
    "StatusSensor.CommunicationOK": S.encoder_communication_ok,
    "StatusSensor.AbsEncoderOffset": lambda ax: ax.abs_offset,
    "StatusSensor.AdaptionState": lambda ax: 3,
    "StatusBits.Activated": lambda ax: ax.activated,
    "StatusBits.Enable": lambda ax: ax.state in ("enabled", "disabling"),
    "StatusBits.HomingDone": lambda ax: ax.homed,
    "StatusBits.Done": lambda ax: _job_kind(ax) is None,
    "StatusBits.Error": lambda ax: bool(ax.alarms),
    "StatusBits.StandStill": S.standstill,
    "StatusBits.PositioningCommand": lambda ax: _job_kind(ax) in (JobKind.ABSOLUTE, JobKind.RELATIVE),
    # §11.1.7: after MC_MoveVelocity(0) reached standstill both bits stay until the next motion command
    "StatusBits.VelocityCommand": lambda ax: _job_kind(ax) in (JobKind.VELOCITY, JobKind.JOG)
    or ax.holding_zero_velocity,
    "StatusBits.HomingCommand": lambda ax: _job_kind(ax) in (JobKind.HOME_ACTIVE,) or (
        ax.passive_home is not None and ax.passive_home.busy),
    "StatusBits.CommandTableActive": lambda ax: _job_kind(ax) == JobKind.TABLE,
    "StatusBits.ConstantVelocity": _constant_velocity,
    "StatusBits.Accelerating": S.accelerating,
    "StatusBits.Decelerating": S.decelerating,
    "StatusBits.ControlPanelActive": lambda ax: False,
    "StatusBits.DriveReady": lambda ax: ax.state in ("enabled", "disabling") and ax.drive.ready(ax.now),
    "StatusBits.RestartRequired": lambda ax: False,
    "StatusBits.SWLimitMinActive": lambda ax: S.software_limit_active(ax, "min"),
    "StatusBits.SWLimitMaxActive": lambda ax: S.software_limit_active(ax, "max"),
    "StatusBits.HWLimitMinActive": lambda ax: ax.hw_approached["min"],
    "StatusBits.HWLimitMaxActive": lambda ax: ax.hw_approached["max"],
    "StatusBits.AxisSimulation": lambda ax: ax.sim,
    "StatusBits.NonPositionControlled": lambda ax: ax.servo and ax.state in ("enabled", "disabling")
    and not ax.position_controlled,
    "ErrorBits.SystemFault": lambda ax: F.INTERNAL in _alarm_kinds(ax),
    "ErrorBits.ConfigFault": lambda ax: bool(_alarm_kinds(ax) & {F.CONFIG, F.HOMING_APPROACH_ZERO,
                                                                 F.HOMING_REFERENCING_ZERO}),
    "ErrorBits.DriveFault": lambda ax: bool(_alarm_kinds(ax) & {F.DRIVE_NOT_READY, F.DRIVE_ALARM}),
    "ErrorBits.SWLimit": lambda ax: bool(_alarm_kinds(ax) & {F.SW_LIMIT_MIN, F.SW_LIMIT_MAX, F.SW_LIMIT_ORDER}),
    "ErrorBits.HWLimit": lambda ax: bool(_alarm_kinds(ax) & {F.HW_LIMIT_MIN, F.HW_LIMIT_MAX, F.HW_LIMIT_FREE}),
    "ErrorBits.DirectionFault": lambda ax: F.DIRECTION in _alarm_kinds(ax),
    "ErrorBits.HWUsed": lambda ax: F.HW_USED in _alarm_kinds(ax) or ax.pto_used_by_other(),
    "ErrorBits.SensorFault": lambda ax: F.ENCODER in _alarm_kinds(ax),
    "ErrorBits.CommunicationFault": lambda ax: communication_fault(ax),
    "ErrorBits.FollowingErrorFault": lambda ax: F.FOLLOWING_ERROR in _alarm_kinds(ax),
    "ErrorBits.PositioningFault": lambda ax: F.POSITIONING in _alarm_kinds(ax),
}
#: data types of the status tags (§12.9.1 - §12.9.4, §12.9.20 - §12.9.24)
DYNAMIC_TYPES: dict[str, str] = {path: ("Bool" if path.startswith(("StatusBits.", "ErrorBits."))
                                        or path in ("StatusDrive.InOperation", "StatusDrive.CommunicationOK",
                                                    "StatusSensor.CommunicationOK")
                                        else "DInt" if path.endswith(("State", "AdaptionState")) else "Real")
                                 for path in DYNAMIC}
#: status tags that MC_ReadParam may read ("RP" in §12.9); ErrorBits.HWLimit is RCCP only (§12.9.24)
READ_PARAM_TAGS = frozenset(p for p in DYNAMIC if p != "ErrorBits.HWLimit" and p != "Acceleration")

_DYNAMIC_ALIASES = {
    "StatusSensor[1].AdaptionState": "StatusSensor.AdaptionState",
    "ErrorBits.FollowingError": "ErrorBits.FollowingErrorFault",      # V7 table spelling
}

#: S7-1200 V7 (technology_version 7): the encoder status is the structure StatusSensor[1] (V7 §12.9.20; the
#: V6 names stay, they are V7's Openness names) and ErrorBits has AdaptionError (V7 §12.9.22).  The
#: simulated drives take no parameters from the drive (AdaptionState 3), so no transfer can fail.
DYNAMIC_V7: dict[str, Callable[["PositioningAxis"], Any]] = {
    **DYNAMIC,
    **{f"StatusSensor[1].{name}": DYNAMIC[f"StatusSensor.{name}"]
       for name in ("State", "CommunicationOK", "AbsEncoderOffset", "AdaptionState")},
    "ErrorBits.AdaptionError": lambda ax: False,
}
DYNAMIC_TYPES_V7: dict[str, str] = {**DYNAMIC_TYPES, **{
    path: DYNAMIC_TYPES[path.replace("[1]", "")] for path in DYNAMIC_V7 if path.startswith("StatusSensor[1].")},
    "ErrorBits.AdaptionError": "Bool"}
READ_PARAM_TAGS_V7 = frozenset(p for p in DYNAMIC_V7 if p != "ErrorBits.HWLimit" and p != "Acceleration")
_DYNAMIC_ALIASES_V7 = {"ErrorBits.FollowingError": "ErrorBits.FollowingErrorFault"}
_STATUS_GROUPS = ("StatusBits", "ErrorBits", "StatusPositioning", "StatusDrive", "StatusSensor")

__all__ = ["DYNAMIC", "DYNAMIC_TYPES", "DYNAMIC_V7", "DYNAMIC_TYPES_V7", "READ_PARAM_TAGS", "READ_PARAM_TAGS_V7",
           "communication_fault"]
