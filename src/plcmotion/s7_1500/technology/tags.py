"""Status tags of the S7-1500 positioning and synchronous axis (S7-1500T V5 §A.1).

Computed when read from the kernel state (``kernel.axis_status``, the jobs, the alarms) (nothing is copied per cycle).  The
status words are DWORDs whose bits read as ``axis.StatusWord.X22`` or by name
(``axis.StatusWord.Synchronous``).

Technology alarms (``ErrorDetail``, the ErrorWord/WarningWord bits, StatusWord.X3 RestartRequired) come
from the table of ``alarms.py`` with the CPU's numbers; docs/s7_1500/alarms.md lists them.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable

import numpy as np

from ...kernel import faults as F
from ...kernel.faults import Fault
from ...kernel.jobs import JobKind
from ...kernel import axis_status as S
from ...kernel.words import pack, word_type
from . import alarms as A

if TYPE_CHECKING:  # pragma: no cover
    from .axes import PositioningAxis1500 as Axis

StatusWord = word_type("StatusWord", {
    "Enable": 0, "Error": 1, "RestartActive": 2, "OnlineStartValuesChanged": 3, "ControlPanelActive": 4,
    "HomingDone": 5, "Done": 6, "StandStill": 7, "PositioningCommand": 8, "JogCommand": 9,
    "VelocityCommand": 10, "HomingCommand": 11, "ConstantVelocity": 12, "Accelerating": 13, "Decelerating": 14,
    "SWLimitMinActive": 15, "SWLimitMaxActive": 16, "HWLimitMinActive": 17, "HWLimitMaxActive": 18,
    "Synchronizing": 21, "Synchronous": 22, "SuperimposedMotionCommand": 23, "PhasingCommand": 24,
    "AxisSimulation": 25, "TorqueLimitingCommand": 26, "InLimitation": 27, "NonPositionControlled": 28,
    "KinematicsMotionCommand": 29, "InClamping": 30, "MotionInCommand": 31},
    # §A.1.37 / §A.1.26 spell bit 7 "Standstill", §7.1.1 "StandStill"; §7.1.1 shows bit 3 as "Restart required"
    aliases={"Standstill": 7, "RestartRequired": 3})
StatusWord2 = word_type("StatusWord2", {"StopCommand": 0})
ErrorWord = word_type("ErrorWord", {
    "SystemFault": 0, "ConfigFault": 1, "UserFault": 2, "CommandNotAccepted": 3, "DriveFault": 4,
    "SensorFault": 5, "DynamicError": 6, "CommunicationFault": 7, "SWLimit": 8, "HWLimit": 9, "HomingError": 10,
    "FollowingErrorFault": 11, "PositioningFault": 12, "PeripheralError": 13, "SynchronousError": 14,
    "AdaptionError": 15})
WarningWord = word_type("WarningWord", {
    "SystemWarning": 0, "ConfigWarning": 1, "UserWarning": 2, "CommandNotAccepted": 3, "DriveWarning": 4,
    "SensorWarning": 5, "DynamicWarning": 6, "CommunicationWarning": 7, "SWLimitMin": 8, "SWLimitMax": 9,
    "HomingWarning": 10, "FollowingErrorWarning": 11, "PositioningWarning": 12, "PeripheralWarning": 13,
    "SynchronousWarning": 14, "AdaptionWarning": 15})
SyncStatusWord = word_type("StatusSynchronizedMotion.StatusWord", {
    "MaxVelocityExceeded": 0, "MaxAccelerationExceeded": 1, "MaxDecelerationExceeded": 2, "InSimulation": 3,
    "LeadingValueAdditiveCommand": 4})

def alarm_description(fault: Fault) -> str:
    """A kernel fault as an S7-1500 technology alarm with its number, text and reaction."""
    return A.describe(fault)


def _b(ax: "Axis"):
    return ax.ctl.bank


def _kind(ax: "Axis") -> JobKind | None:
    job = ax.job
    return job.kind if job is not None and job.busy else None


def _kinds(ax: "Axis") -> set[str]:
    return {a.kind for a in ax.alarms}


def _fe_limit(ax: "Axis") -> float:
    b, i = _b(ax), ax.index
    speed = abs(float(b.sp_v[i]))
    return min(float(b.fe_max[i]), float(b.fe_min[i]) + float(b.fe_slope[i]) * max(speed - float(b.fe_vmin[i]), 0.0))


def _fe_warning(ax: "Axis") -> bool:
    b, i = _b(ax), ax.index
    if not b.fe_on[i]:
        return False
    warning = ax.config.following_error.warning_level
    level = (100.0 if warning is None else warning) / 100.0
    return abs(float(b.fe[i])) > level * _fe_limit(ax)


def _follower(ax: "Axis") -> Any:
    """The following-axis component of a synchronous axis (None on the other axes)."""
    return getattr(ax, "follower", None)


def status_word(ax: "Axis") -> int:
    kind = _kind(ax)
    fol = _follower(ax)
    sync = fol.coupling if fol is not None else None
    enabled = ax.state in ("enabled", "disabling")
    # §A.1.37 bit 6 "Done": 0 while a motion job is in progress - MC_Stop braking the axis is one (it lives
    # in stop_job, not in job); passive homing is not, it moves nothing (§6.1.5.5; docs/s7_1500/decisions.md)
    stop = ax.stop_job
    moving_job = kind is not None or ax.superimposed_active or sync is not None or (
        fol is not None and fol.waiting is not None) or (stop is not None and stop.busy)
    accelerating, decelerating = S.accelerating(ax), S.decelerating(ax)
    bits = {
        0: enabled,
        1: bool(ax.alarms),
        3: A.restart_required(ax.alarms),
        5: ax.homed,
        6: not moving_job,
        7: S.standstill(ax),
        8: kind in (JobKind.ABSOLUTE, JobKind.RELATIVE),
        9: kind == JobKind.JOG,
        10: kind == JobKind.VELOCITY or ax.holding_zero_velocity,
        11: kind == JobKind.HOME_ACTIVE or (ax.passive_home is not None and ax.passive_home.busy),
        # §7.1.1: "moved with constant velocity or is stationary" (unlike the S7-1200 bit, TRUE at standstill)
        12: not (accelerating or decelerating),
        13: accelerating,
        14: decelerating,
        15: S.software_limit_active(ax, "min"),
        16: S.software_limit_active(ax, "max"),
        17: ax.hw_approached["min"],
        18: ax.hw_approached["max"],
        21: bool(sync is not None and fol.synchronizing),
        22: bool(sync is not None and fol.synchronous),
        23: ax.superimposed_active,
        24: bool(fol is not None and fol.phasing_job is not None and fol.phasing_job.busy),
        25: ax.ueff["Simulation.Mode"] == 1,
        28: enabled and not ax.position_controlled,
    }
    return StatusWord(pack(bits))


def error_word(ax: "Axis") -> int:
    return ErrorWord(pack(A.error_bits(ax.alarms)))


def warning_word(ax: "Axis") -> int:
    # bit 3: a job of an instruction was rejected (§7.1.1 "Job rejected"; decisions.md), bit 6: dynamics limited
    # (501-503), bit 11: following error warning level (522)
    bits = {3: ax.command_not_accepted, A.ALARMS[501].bit: bool(ax.warnings), A.ALARMS[522].bit: _fe_warning(ax)}
    return WarningWord(pack(bits))


def sync_status_word(ax: "Axis") -> int:
    b, i = _b(ax), ax.index
    fol = _follower(ax)
    c = fol.coupling if fol is not None else None
    lim = ax.config.limits
    exceeded = {}
    if c is not None and c.applied:
        v, a = float(b.sp_v[i]), float(b.sp_a[i])
        exceeded = {0: abs(v) > lim.max_velocity * (1 + 1e-9),
                    1: a * v > 0 and abs(a) > lim.max_acceleration * (1 + 1e-9),
                    2: a * v < 0 and abs(a) > lim.max_deceleration * (1 + 1e-9)}
    bits = dict(exceeded)
    bits[3] = c is not None and c.simulated
    job = fol.lv_additive_job if fol is not None else None
    bits[4] = job is not None and job.busy
    return SyncStatusWord(pack(bits))


def _coupling_value(ax: "Axis", name: str, default: float) -> float:
    fol = _follower(ax)
    c = fol.coupling if fol is not None else None
    if c is None or c.cam is None:
        return default
    return getattr(c, name)


def _target(ax: "Axis") -> float:
    job = ax.job
    if job is not None and job.busy and job.kind in (JobKind.ABSOLUTE, JobKind.RELATIVE):
        return ax._wrap(job.target)
    return 0.0


def _distance(ax: "Axis") -> float:
    job = ax.job
    if job is not None and job.busy and job.kind in (JobKind.ABSOLUTE, JobKind.RELATIVE):
        return job.target - float(_b(ax).sp_p[ax.index])
    return 0.0


def _modulo_cycle(ax: "Axis", value: float) -> int:
    m = ax.config.modulo
    if not m.enabled:
        return 0
    return int(np.floor((value - m.start) / m.length))


def _setpoint_execution_time(ax: "Axis") -> float:
    """T_Ipo + (T_vtc with velocity precontrol, 1/Kv without) + send/output delays (none simulated)."""
    e = ax.ueff
    if e["PositionControl.Kpc"] > 0.0:
        lag = e["DynamicAxisModel.VelocityTimeConstant"]
    else:
        lag = 1.0 / e["PositionControl.Kv"]
    return ax.ctl.servo_cycle + lag


DYNAMIC: dict[str, Callable[["Axis"], Any]] = {
    "Position": S.position,
    "Velocity": S.velocity,
    "Acceleration": S.acceleration,
    "ActualPosition": S.actual_position,
    "ActualVelocity": S.actual_velocity,
    "ActualAcceleration": lambda ax: float(_b(ax).sp_a[ax.index]) if not ax.servo else ax.actual_acceleration(),
    "ActualSpeed": lambda ax: float(_b(ax).act_v[ax.index]) / ax.config.drive.length_per_revolution * 60.0
    if ax.servo else 0.0,
    "VelocitySetpoint": lambda ax: float(_b(ax).cmd_v[ax.index]) if ax.servo else float(_b(ax).sp_v[ax.index]),
    "OperativeSensor": lambda ax: 1,
    "ModuloCycle": lambda ax: _modulo_cycle(ax, float(_b(ax).sp_p[ax.index])),
    "ActualModuloCycle": lambda ax: _modulo_cycle(ax, float(_b(ax).act_p[ax.index])),
    "StatusWord": status_word,
    "StatusWord2": lambda ax: StatusWord2(pack({0: ax.stop_job is not None})),
    "ErrorWord": error_word,
    "WarningWord": warning_word,
    "ErrorDetail.Number": lambda ax: A.error_detail(ax.alarms)[0],
    "ErrorDetail.Reaction": lambda ax: A.error_detail(ax.alarms)[1],
    "StatusPositioning.Distance": _distance,
    "StatusPositioning.TargetPosition": _target,
    "StatusPositioning.TargetPositionModuloCycle": lambda ax: _modulo_cycle(ax, _target(ax)),
    "StatusPositioning.FollowingError": lambda ax: float(_b(ax).fe[ax.index]) if ax.servo else 0.0,
    "StatusPositioning.SetpointExecutionTime": _setpoint_execution_time,
    "StatusDrive.InOperation": S.drive_in_operation,
    "StatusDrive.CommunicationOK": S.drive_communication_ok,
    "StatusDrive.Disabled": lambda ax: ax.state == "disabled",
    "StatusDrive.Error": lambda ax: bool(_kinds(ax) & {F.DRIVE_ALARM, F.DRIVE_NOT_READY}),
    "StatusDrive.AdaptionState": lambda ax: 3,
    "StatusServo.BalancedPosition": lambda ax: float(_b(ax).sp_p[ax.index]),
    "StatusServo.ControlDifference": lambda ax: float(_b(ax).fe[ax.index]) if ax.servo else 0.0,
    "StatusSensor[1].State": lambda ax: 2 if (ax.sim or ax.sensor_valid) else 0,
    "StatusSensor[1].CommunicationOK": S.encoder_communication_ok,
    "StatusSensor[1].Error": lambda ax: F.ENCODER in _kinds(ax),
    "StatusSensor[1].AbsEncoderOffset": lambda ax: ax.abs_offset,
    "StatusSensor[1].Control": lambda ax: True,
    "StatusSensor[1].Position": S.actual_position,
    "StatusSensor[1].Velocity": S.actual_velocity,
    "StatusSensor[1].AdaptionState": lambda ax: 3,
    "StatusSensor[1].ModuloCycle": lambda ax: _modulo_cycle(ax, float(_b(ax).act_p[ax.index])),
}

#: the synchronous axis adds its synchronous operation status (§A.1.33)
SYNC_DYNAMIC: dict[str, Callable[["Axis"], Any]] = dict(DYNAMIC)
SYNC_DYNAMIC.update({
    "StatusSynchronizedMotion.FunctionState": lambda ax: ax.follower.function_state(),
    "StatusSynchronizedMotion.WaitingFunctionState": lambda ax: ax.follower.waiting_function_state(),
    "StatusSynchronizedMotion.PhaseShift": lambda ax: ax.follower.phase_shift(),
    "StatusSynchronizedMotion.ActualMaster": lambda ax: ax.follower.coupling.source.db_number
    if ax.follower.coupling else 0,
    "StatusSynchronizedMotion.ActualCam": lambda ax: ax.follower.coupling.cam.db_number
    if ax.follower.coupling is not None and ax.follower.coupling.cam is not None else 0,
    "StatusSynchronizedMotion.MasterOffset": lambda ax: _coupling_value(ax, "master_offset", 0.0),
    "StatusSynchronizedMotion.MasterScaling": lambda ax: _coupling_value(ax, "master_scaling", 1.0),
    "StatusSynchronizedMotion.SlaveOffset": lambda ax: _coupling_value(ax, "slave_offset", 0.0),
    "StatusSynchronizedMotion.SlaveScaling": lambda ax: _coupling_value(ax, "slave_scaling", 1.0),
    "StatusSynchronizedMotion.EffectiveLeadingValue.Position": lambda ax: ax.follower.effective_leading_value()[0],
    "StatusSynchronizedMotion.EffectiveLeadingValue.Velocity": lambda ax: ax.follower.effective_leading_value()[1],
    "StatusSynchronizedMotion.EffectiveLeadingValue.Acceleration": lambda ax: ax.follower.effective_leading_value()[2],
    "StatusSynchronizedMotion.StatusWord": sync_status_word,
})

#: leading value tags every S7-1500 axis has (extrapolation, provided leading value)
_LV_DYNAMIC: dict[str, Callable[["Axis"], Any]] = {
    "StatusExtrapolation.FilteredPosition": lambda ax: ax.lv_provider.extrapolation_status()[0],
    "StatusExtrapolation.FilteredVelocity": lambda ax: ax.lv_provider.extrapolation_status()[1],
    "StatusExtrapolation.ExtrapolatedPosition": lambda ax: ax.lv_provider.extrapolation_status()[2],
    "StatusExtrapolation.ExtrapolatedVelocity": lambda ax: ax.lv_provider.extrapolation_status()[3],
    "Extrapolation.LeadingAxisDependentTime": lambda ax: ax.lv_provider.leading_axis_dependent_time(),
    "StatusProvidedLeadingValue.DelayedLeadingValue.Position": lambda ax: ax.lv_provider.delayed_leading_value()[0],
    "StatusProvidedLeadingValue.DelayedLeadingValue.Velocity": lambda ax: ax.lv_provider.delayed_leading_value()[1],
    "StatusProvidedLeadingValue.DelayedLeadingValue.Acceleration": lambda ax: ax.lv_provider.delayed_leading_value()[2],
}
DYNAMIC.update(_LV_DYNAMIC)
SYNC_DYNAMIC.update(_LV_DYNAMIC)

_WORDS = ("StatusWord", "StatusWord2", "ErrorWord", "WarningWord", "StatusSynchronizedMotion.StatusWord")


def _type(path: str) -> str:
    if path in _WORDS:
        return "DWord"
    if path.endswith(("State", "FunctionState", "ModuloCycle", "Reaction")) and "Status" in path or path.endswith(
            ("ModuloCycle", "Reaction")):
        return "DInt"
    if path in ("OperativeSensor", "ErrorDetail.Number"):
        return "UDInt"
    if path.endswith(("ActualMaster", "ActualCam")):
        return "DB_ANY"
    if path.startswith(("StatusDrive.", "StatusSensor[1].")) and path.rsplit(".", 1)[1] in (
            "InOperation", "CommunicationOK", "Disabled", "Error", "Control"):
        return "Bool"
    return "LReal"


TYPES = {p: _type(p) for p in DYNAMIC}
SYNC_TYPES = {p: _type(p) for p in SYNC_DYNAMIC}
GROUPS = ("StatusPositioning", "StatusDrive", "StatusServo", "ErrorDetail", "StatusExtrapolation",
          "StatusProvidedLeadingValue")
SYNC_GROUPS = GROUPS + ("StatusSynchronizedMotion",)
