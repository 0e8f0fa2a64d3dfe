"""Drive technology of an S7-Technology axis: electric or hydraulic, the torque settings and the fixed end stop
(S7-Technology V4.1 §3.1.4, §4.5.7.5, §4.6, §9.3.2.2, §9.4).

``Wizard.DriveTechnology`` is the axis wizard's choice (§4.5, §4.6.1): 0 an electric drive, 1 a hydraulic
axis on a Q valve (flow valve), 2 a hydraulic axis on a P/Q valve (flow valve with pressure limiting, so the
cylinder force can be limited).  Hydraulic axes are real axes only (§3.1.4).  The hydraulic tags:

* ``userdefaultqfaxis.maxderivative.qoutput`` (parameter 5009): the rate [%/s] of the output ramp of
  MC_Power StopMode 3 and of the output compensation when MC_SetCharacteristic changes the profile;
* ``TypeOfAxis.SpeedLimitation.MinSpeed`` / ``MaxSpeed`` (1401/1402, "manipulated variable limit"): on a
  hydraulic axis the output limits in % of 10 V;
* family tags ``Drive.ValveReferenceVelocity`` (velocity at 100 % output while no valve profile is active:
  the straight line), ``Drive.ValveProfile1`` ... ``4`` (technology DB numbers of the cam disks assigned as
  valve profiles, S7T Config "Axis > Profile", §4.6.5) and ``Drive.ForceLimit`` (the P/Q valve's force
  limit [N], none when absent);
* the simulated cylinder ``Plant.Cylinder.*`` (``kernel.plant_schema.CYLINDER_PARAMS``).

Electric axes: ``TypeOfAxis.SetPointDriverInfo.DriveData.maxTorque`` is the torque reference [N m] of the
torque reduction (MC_SetTorqueLimit MaxTorque = 0, the largest Torque of MC_MoveToEndPos; §9.3.2.2, start
value 3.2 as the manual's default), and the fixed end stop tags of data set 1 (2010-2012) with
``userdefaultclamping.clampingvalue`` (4231).
"""
from __future__ import annotations

from typing import Any, Mapping

from ...drives.hydraulic_spec import HydraulicSpec, ValveType
from ...drives.spec import ActuatorKind, DriveSpec, EncoderSpec, SetpointInterface
from ...drives.spec_errors import DriveSpecError
from ...kernel.errors import ConfigurationError
from ...kernel.plant_schema import CYLINDER_PARAMS, cylinder_spec, plant_spec
from ...kernel.schema import E12, INT, REAL, WP, Issue, Param, R

DS = "TypeOfAxis.NumberOfDataSets.DataSet_1"
DRIVE_TECHNOLOGY = "Wizard.DriveTechnology"
#: Wizard.DriveTechnology values
ELECTRIC, HYDRAULIC_Q, HYDRAULIC_PQ = 0, 1, 2
QOUTPUT_RAMP = "userdefaultqfaxis.maxderivative.qoutput"          # parameter 5009
OUTPUT_MIN = "TypeOfAxis.SpeedLimitation.MinSpeed"                 # parameter 1401
OUTPUT_MAX = "TypeOfAxis.SpeedLimitation.MaxSpeed"                 # parameter 1402
REFERENCE_VELOCITY = "Drive.ValveReferenceVelocity"
FORCE_LIMIT = "Drive.ForceLimit"
VALVE_PROFILES = tuple(f"Drive.ValveProfile{k}" for k in range(1, 5))
MAX_TORQUE = "TypeOfAxis.SetPointDriverInfo.DriveData.maxTorque"
FE_DEVIATION = f"{DS}.ClampingMonitoring.followingErrorDeviation"  # parameter 2010
POSITION_TOLERANCE = f"{DS}.ClampingMonitoring.positionTolerance"  # parameter 2011
RECOGNITION_MODE = f"{DS}.ClampingMonitoring.recognitionMode"      # parameter 2012
CLAMPING_VALUE = "userdefaultclamping.clampingvalue"               # parameter 4231
#: §9.4.12.39 EnumRecognitionMode ValueDint
DO_NOT_CLAMP, CLAMP_BY_FOLLOWING_ERROR_DEVIATION, CLAMP_WHEN_TORQUE_LIMIT_REACHED = 105, 106, 107
#: the telegrams with torque reduction (§6.2.11, §6.2.12)
TORQUE_TELEGRAMS = (101, 102, 103, 104, 105, 106)

_NOW = (10,)
# fmt: off
PARAMS: list[Param] = [
    Param(DRIVE_TECHNOLOGY, INT, ELECTRIC, R, (), choices=(ELECTRIC, HYDRAULIC_Q, HYDRAULIC_PQ),
          doc="drive technology (§4.5, §4.6): 0 electric, 1 hydraulic Q valve, 2 hydraulic P/Q valve"),
    Param(QOUTPUT_RAMP, REAL, 100.0, WP, _NOW, 0.0, E12, lo_open=True,
          doc="hydraulic axis: rate [%/s] of the output ramp (MC_Power StopMode 3, MC_SetCharacteristic)"),
    Param(OUTPUT_MIN, REAL, -100.0, WP, (), -100.0, 100.0,
          doc="hydraulic axis: lower output limit [% of 10 V] (manipulated variable limit)"),
    Param(OUTPUT_MAX, REAL, 100.0, WP, (), -100.0, 100.0,
          doc="hydraulic axis: upper output limit [% of 10 V] (manipulated variable limit)"),
    Param(REFERENCE_VELOCITY, REAL, 500.0, R, (), 0.0, E12, lo_open=True,
          doc="hydraulic axis: velocity at 100 % output while no valve profile is active"),
    Param(FORCE_LIMIT, REAL, None, R, (), 0.0, E12, lo_open=True, optional=True,
          doc="hydraulic axis on a P/Q valve: cylinder force limit [N] (pressure limiting)"),
    *[Param(path, INT, None, R, (), 1, 65535, optional=True,
            doc="technology DB number of a cam disk assigned as valve profile (Axis > Profile, §4.6.5)")
      for path in VALVE_PROFILES],
    Param(MAX_TORQUE, REAL, 3.2, WP, _NOW, 0.0, E12, lo_open=True,
          doc="torque reference [N m] of the torque reduction (§9.3.2.2)"),
    Param(FE_DEVIATION, REAL, 1.0, WP, _NOW, 0.0, E12,
          doc="following error [length unit] that detects the fixed end stop"),
    Param(POSITION_TOLERANCE, REAL, 0.1, WP, _NOW, 0.0, E12,
          doc="clamping tolerance window [length unit] after fixed end stop detection"),
    Param(RECOGNITION_MODE, INT, DO_NOT_CLAMP, WP, (), choices=(DO_NOT_CLAMP, CLAMP_BY_FOLLOWING_ERROR_DEVIATION,
                                                              CLAMP_WHEN_TORQUE_LIMIT_REACHED),
          doc="fixed end stop detection (EnumRecognitionMode): 105 none, 106 following error, 107 torque"),
    Param(CLAMPING_VALUE, REAL, 0.0, WP, _NOW, 0.0, E12, doc="clamping value (system variable, kept only)"),
    *CYLINDER_PARAMS,
]
# fmt: on


def hydraulic(p: Mapping[str, Any]) -> bool:
    return p[DRIVE_TECHNOLOGY] in (HYDRAULIC_Q, HYDRAULIC_PQ)


def rule_issues(cfg: Mapping[str, Any]) -> list[Issue]:
    """The rules of the drive technology: a hydraulic axis is real, its output limits are ordered, only a P/Q
    valve has a force limit."""
    out: list[Issue] = []
    if hydraulic(cfg):
        if cfg["Wizard.Virtual"]:
            out.append(Issue(DRIVE_TECHNOLOGY, "rule:virtual", cfg[DRIVE_TECHNOLOGY],
                             "0 (electric) on a virtual axis: a hydraulic axis is a real axis (§3.1.4)"))
        if cfg[OUTPUT_MIN] >= cfg[OUTPUT_MAX]:
            out.append(Issue(OUTPUT_MIN, "rule:low_above_high", cfg[OUTPUT_MIN], f"below {OUTPUT_MAX} = "
                                                                                 f"{cfg[OUTPUT_MAX]:g}"))
    if cfg[FORCE_LIMIT] is not None and cfg[DRIVE_TECHNOLOGY] != HYDRAULIC_PQ:
        out.append(Issue(FORCE_LIMIT, "rule:pq_valve", cfg[FORCE_LIMIT],
                         f"only with {DRIVE_TECHNOLOGY} = 2 (a P/Q valve limits the force)"))
    return out


def hydraulic_drive_spec(p: Mapping[str, Any], encoder: EncoderSpec, per_revolution: float,
                         wiring: Mapping[str, Any] | None = None) -> DriveSpec:
    """The valve output, cylinder and encoder of a hydraulic axis with valid tag values ``p``; ``wiring``: the
    simulated switches on the controller's inputs (keyword arguments of ``plant_spec``)."""
    pq = p[DRIVE_TECHNOLOGY] == HYDRAULIC_PQ
    try:
        spec = HydraulicSpec(valve=ValveType.PQ if pq else ValveType.Q,
                             reference_velocity=p[REFERENCE_VELOCITY], output_min=p[OUTPUT_MIN],
                             output_max=p[OUTPUT_MAX], off_output=0.0, output_ramp=p[QOUTPUT_RAMP],
                             force_limit=p[FORCE_LIMIT] if pq else None)
        return DriveSpec(
            actuator=ActuatorKind.HYDRAULIC, interface=SetpointInterface.ANALOG, telegram=3,
            length_per_revolution=per_revolution, ready_delay=p["Plant.ReadyDelay"],
            encoder=encoder, hydraulic=spec,
            plant=plant_spec(p, **(wiring or dict(hw_min=("", False), hw_max=("", False), homing_inputs=(),
                                                        ready_input="")), cylinder=cylinder_spec(p)))
    except DriveSpecError as exc:
        raise ConfigurationError("hydraulic axis", [Issue(exc.field, "rule:hydraulic", exc.value,
                                                          exc.allowed)]) from None


__all__ = ["PARAMS", "rule_issues", "hydraulic", "hydraulic_drive_spec", "DRIVE_TECHNOLOGY", "ELECTRIC",
           "HYDRAULIC_Q", "HYDRAULIC_PQ", "QOUTPUT_RAMP", "OUTPUT_MIN", "OUTPUT_MAX", "REFERENCE_VELOCITY",
           "FORCE_LIMIT", "VALVE_PROFILES", "MAX_TORQUE", "FE_DEVIATION", "POSITION_TOLERANCE", "RECOGNITION_MODE",
           "CLAMPING_VALUE", "DO_NOT_CLAMP", "CLAMP_BY_FOLLOWING_ERROR_DEVIATION", "CLAMP_WHEN_TORQUE_LIMIT_REACHED",
           "TORQUE_TELEGRAMS", "P"]
