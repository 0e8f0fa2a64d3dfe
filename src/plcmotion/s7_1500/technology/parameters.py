"""Configuration tags of the S7-1500 positioning and synchronous axis (S7-1500T V5 §6.1, §A.1).

The tags are declared with the names, ranges and effectiveness of the appendix (DIR and CAL tags may be
written by the user program, RES and RON tags are configuration), and turned into the neutral
typed configuration the kernel reads by ``builder.axis_config``: the kernel runs the same motion,
monitoring and drive models for every family.  Start values: the manual gives ranges only (catalog §11.2
item 12); the values chosen here are documented in docs/s7_1500/decisions.md #36.
"""
from __future__ import annotations

from typing import Any, Mapping

from ...kernel.schema import ADDR, BOOL, E12, INT, P, R, REAL, RW, AxisSchema, Issue, Param
from ...kernel.plant_schema import PLANT_PARAMS
from .builder import axis_config, distance_per_motor_revolution, load_revolution  # noqa: F401

#: effectiveness codes of §A.1.1: DIR (next MC-Servo), CAL (next MC-Servo after an instruction call),
#: RES (start value, after a restart), RON (read only)
DIR, CAL = (10,), (10,)
_S = "Sensor[1]"

#: length units (§A.1.13): code -> name; rotary units are 1004 rad, 1005 deg, 1537 deg (high resolution)
LENGTH_UNITS = {1010: "m", 1013: "mm", 1536: "mm", 1011: "km", 1014: "µm", 1015: "nm", 1019: "in", 1018: "ft",
                1021: "mi", 1004: "rad", 1005: "°", 1537: "°"}
VELOCITY_UNITS = (1521, 1539, 1522, 1086, 1523, 1062, 1538, 1061, 1524, 1525, 1526, 1063, 1527, 1064, 1066, 1069,
                  1067, 1070, 1075)

# fmt: off
_PARAMS_1500: list[Param] = [
    # --- axis type, simulation §A.1.3, §A.1.4, §A.1.12 --------------------------------------------------
    Param("VirtualAxis.Mode", INT, 0, R, (), choices=(0, 1), doc="1: virtual axis, no drive and no encoder"),
    Param("Simulation.Mode", INT, 0, R, (), choices=(0, 1), doc="1: the axis is simulated without drive/encoder"),
    Param("Properties.MotionType", INT, 0, R, (), choices=(0, 1), doc="0 linear, 1 rotary"),
    Param("Units.LengthUnit", INT, 1013, R, (), choices=tuple(LENGTH_UNITS)),
    Param("Units.VelocityUnit", INT, 1062, R, (), choices=VELOCITY_UNITS),
    Param("Units.TimeUnit", INT, 1054, R, (), choices=(1054,)),
    # --- drive §A.1.5 ---------------------------------------------------------------------------------
    Param("Actor.Type", INT, 1, R, (), choices=(0, 1), doc="0 analog output, 1 PROFIdrive telegram"),
    Param("Actor.InverseDirection", BOOL, False, R),
    Param("Actor.DataAdaption", INT, 0, R, (), choices=(0, 1)),
    Param("Actor.Efficiency", REAL, 1.0, R, (), 0.0, 1.0),
    Param("Actor.Interface.Telegram", INT, 3, R, (), choices=(1, 2, 3, 4),
          doc="PROFIdrive telegram of the drive (device configuration)"),
    Param("Actor.Interface.EnableDriveOutput", BOOL, False, R, doc="analog drive: enable output used"),
    Param("Actor.Interface.EnableDriveOutputAddress", ADDR, "", R, (), choices=("Q",)),
    Param("Actor.Interface.DriveReadyInput", BOOL, False, R, doc="analog drive: ready input used"),
    Param("Actor.Interface.DriveReadyInputAddress", ADDR, "", R, (), choices=("I",)),
    Param("Actor.DriveParameter.ReferenceSpeed", REAL, 6000.0, R, (), 0.0, E12, lo_open=True,
          doc="motor speed [1/min] of 100 % speed setpoint"),
    Param("Actor.DriveParameter.MaxSpeed", REAL, 6000.0, R, (), 0.0, E12, lo_open=True,
          doc="maximum motor speed [1/min]: the only limit of a synchronized following axis"),
    Param("Actor.DriveParameter.ReferenceTorque", REAL, 1.0, R, (), 0.0, E12),
    # --- encoder Sensor[1] §A.1.8 ---------------------------------------------------------------------
    Param(f"{_S}.Type", INT, 0, R, (), choices=(0, 1, 2), doc="0 incremental, 1 absolute, 2 cyclic absolute"),
    Param(f"{_S}.InverseDirection", BOOL, False, R),
    Param(f"{_S}.System", INT, 1, R, (), choices=(0, 1), doc="0 linear, 1 rotary"),
    Param(f"{_S}.MountingMode", INT, 0, R, (), choices=(0, 1, 2), doc="0 motor shaft, 1 load side, 2 external"),
    Param(f"{_S}.DataAdaption", INT, 0, R, (), choices=(0, 1)),
    Param(f"{_S}.Interface.Number", INT, 1, R, (), 1, 2),
    Param(f"{_S}.Parameter.Resolution", REAL, 0.001, R, (), 0.0, E12, lo_open=True),
    Param(f"{_S}.Parameter.StepsPerRevolution", INT, 2048, R, (), 1, 8388608),
    Param(f"{_S}.Parameter.FineResolutionXist1", INT, 11, R, (), 0, 31),
    Param(f"{_S}.Parameter.FineResolutionXist2", INT, 9, R, (), 0, 31),
    Param(f"{_S}.Parameter.DeterminableRevolutions", INT, 0, R, (), 0, 8388608),
    Param(f"{_S}.Parameter.DistancePerRevolution", REAL, 10.0, R, (), 0.0, E12, lo_open=True),
    Param(f"{_S}.Parameter.BehaviorGx_XIST1", INT, 1, R, (), choices=(0, 1)),
    Param(f"{_S}.ActiveHoming.Mode", INT, 2, R, (), choices=(0, 1, 2),
          doc="0 zero mark, 1 zero mark and reference cam, 2 digital input"),
    Param(f"{_S}.ActiveHoming.SideInput", BOOL, False, RW, CAL, doc="FALSE negative side, TRUE positive side"),
    Param(f"{_S}.ActiveHoming.Direction", INT, 0, RW, CAL, choices=(0, 1), doc="homing direction: 0 positive, 1 negative"),
    Param(f"{_S}.ActiveHoming.DigitalInputAddress", ADDR, "", R, (), choices=("I",)),
    Param(f"{_S}.ActiveHoming.HomePositionOffset", REAL, 0.0, RW, CAL, -E12, E12),
    Param(f"{_S}.ActiveHoming.SwitchLevel", BOOL, True, R),
    Param(f"{_S}.PassiveHoming.Mode", INT, 2, R, (), choices=(0, 1, 2)),
    Param(f"{_S}.PassiveHoming.SideInput", BOOL, False, RW, CAL),
    Param(f"{_S}.PassiveHoming.Direction", INT, 2, RW, CAL, choices=(0, 1, 2), doc="0 positive, 1 negative, 2 current"),
    Param(f"{_S}.PassiveHoming.DigitalInputAddress", ADDR, "", R, (), choices=("I",)),
    Param(f"{_S}.PassiveHoming.SwitchLevel", BOOL, True, R),
    # --- mechanics, modulo §A.1.11, §A.1.14, §A.1.15 --------------------------------------------------
    Param("LoadGear.Numerator", INT, 1, R, (), 1, 4294967295, doc="motor revolutions"),
    Param("LoadGear.Denominator", INT, 1, R, (), 1, 4294967295, doc="load revolutions"),
    Param("Mechanics.LeadScrew", REAL, 10.0, R, (), 0.0, E12, lo_open=True,
          doc="linear axis: load travel per leadscrew revolution"),
    Param("Modulo.Enable", BOOL, False, R),
    Param("Modulo.Length", REAL, 360.0, R, (), 0.001, E12),
    Param("Modulo.StartValue", REAL, 0.0, R, (), -E12, E12),
    # --- dynamics §A.1.16, §A.1.17 --------------------------------------------------------------------
    Param("DynamicLimits.MaxVelocity", REAL, 1000.0, R, (), 0.0, E12, lo_open=True),
    Param("DynamicLimits.Velocity", REAL, 1000.0, RW, DIR, 0.0, E12, lo_open=True,
          doc="maximum velocity currently in force (<= MaxVelocity)"),
    Param("DynamicLimits.MaxAcceleration", REAL, 10000.0, RW, DIR, 0.0, E12, lo_open=True),
    Param("DynamicLimits.MaxDeceleration", REAL, 10000.0, RW, DIR, 0.0, E12, lo_open=True),
    Param("DynamicLimits.MaxJerk", REAL, 1.0e6, RW, DIR, 0.0, E12, doc="0: no jerk limitation"),
    Param("DynamicDefaults.Velocity", REAL, 100.0, RW, CAL, 0.0, E12, lo_open=True),
    Param("DynamicDefaults.Acceleration", REAL, 1000.0, RW, CAL, 0.0, E12, lo_open=True),
    Param("DynamicDefaults.Deceleration", REAL, 1000.0, RW, CAL, 0.0, E12, lo_open=True),
    Param("DynamicDefaults.Jerk", REAL, 1.0e5, RW, CAL, 0.0, E12, doc="0: trapezoidal velocity profile"),
    Param("DynamicDefaults.EmergencyDeceleration", REAL, 5000.0, RW, DIR, 0.0, E12, lo_open=True),
    Param("Override.Velocity", REAL, 100.0, RW, DIR, 0.0, 200.0, doc="velocity override [%]"),
    # --- limits §A.1.18, §A.1.19 ----------------------------------------------------------------------
    Param("PositionLimits_SW.Active", BOOL, False, RW, DIR),
    Param("PositionLimits_SW.MinPosition", REAL, -10000.0, RW, DIR, -E12, E12),
    Param("PositionLimits_SW.MaxPosition", REAL, 10000.0, RW, DIR, -E12, E12),
    Param("PositionLimits_HW.Active", BOOL, False, R),
    Param("PositionLimits_HW.MinSwitchLevel", BOOL, False, R, doc="FALSE low active, TRUE high active"),
    Param("PositionLimits_HW.MaxSwitchLevel", BOOL, False, R),
    Param("PositionLimits_HW.MinSwitchAddress", ADDR, "", R, (), choices=("I",)),
    Param("PositionLimits_HW.MaxSwitchAddress", ADDR, "", R, (), choices=("I",)),
    # --- homing §A.1.20 -------------------------------------------------------------------------------
    Param("Homing.AutoReversal", BOOL, False, R),
    Param("Homing.ApproachDirection", BOOL, False, RW, CAL, doc="FALSE positive, TRUE negative"),
    Param("Homing.ApproachVelocity", REAL, 200.0, RW, CAL, 0.0, 360000.0),
    Param("Homing.ReferencingVelocity", REAL, 40.0, RW, CAL, 0.0, 36000.0),
    Param("Homing.HomePosition", REAL, 0.0, RW, CAL, -E12, E12),
    # --- position control, axis model §A.1.22, §A.1.23 ------------------------------------------------
    Param("PositionControl.Kv", REAL, 30.0, RW, DIR, 0.0, 2147480.0, lo_open=True),
    Param("PositionControl.Kpc", REAL, 100.0, RW, DIR, 0.0, 150.0),
    Param("DynamicAxisModel.VelocityTimeConstant", REAL, 0.002, RW, DIR, 0.0, E12,
          doc="speed control loop substitute time [s]"),
    Param("DynamicAxisModel.AdditionalPositionTimeConstant", REAL, 0.0, RW, DIR, 0.0, E12),
    # --- monitoring §A.1.24 - §A.1.26 -----------------------------------------------------------------
    Param("FollowingError.EnableMonitoring", BOOL, True, R),
    Param("FollowingError.MinValue", REAL, 10.0, RW, DIR, 0.0, E12),
    Param("FollowingError.MaxValue", REAL, 100.0, RW, DIR, 0.0, E12),
    Param("FollowingError.MinVelocity", REAL, 10.0, RW, DIR, 0.0, E12),
    Param("FollowingError.WarningLevel", REAL, 90.0, RW, DIR, 0.0, 100.0, doc="warning (alarm 522) in % of the limit"),
    Param("PositioningMonitoring.ToleranceTime", REAL, 1.0, RW, DIR, 0.0, E12),
    Param("PositioningMonitoring.MinDwellTime", REAL, 0.0, RW, DIR, 0.0, E12),
    Param("PositioningMonitoring.Window", REAL, 1.0, RW, DIR, 0.0, E12),
    Param("StandstillSignal.VelocityThreshold", REAL, 5.0, RW, DIR, 0.0, E12),
    Param("StandstillSignal.MinDwellTime", REAL, 0.01, RW, DIR, 0.0, E12),
    # --- leading value: extrapolation and cross-PLC output §A.1.9, §A.1.10 -------------------------------
    Param("Extrapolation.FollowingAxisDependentTime", REAL, 0.0, RW, DIR, 0.0, E12),
    Param("Extrapolation.Settings.SystemDefinedExtrapolation", INT, 1, R, (), choices=(0, 1)),
    Param("Extrapolation.Settings.ExtrapolatedVelocityMode", INT, 1, R, (), choices=(0, 1),
          doc="0 filtered velocity, 1 velocity by differentiation of the extrapolated position"),
    Param("Extrapolation.PositionFilter.T1", REAL, 0.0, RW, DIR, 0.0, E12),
    Param("Extrapolation.PositionFilter.T2", REAL, 0.0, RW, DIR, 0.0, E12),
    Param("Extrapolation.VelocityFilter.T1", REAL, 0.004, RW, DIR, 0.0, E12),
    Param("Extrapolation.VelocityFilter.T2", REAL, 0.004, RW, DIR, 0.0, E12),
    Param("Extrapolation.VelocityTolerance.Range", REAL, 0.0, RW, DIR, 0.0, E12),
    Param("Extrapolation.Hysteresis.Value", REAL, 0.0, RW, DIR, 0.0, E12),
    Param("CrossPlcSynchronousOperation.Interface[1].EnableLeadingValueOutput", BOOL, False, R),
    Param("CrossPlcSynchronousOperation.LocalLeadingValueDelayTime", REAL, 0.0, RW, DIR, 0.0, E12),
]
# fmt: on

#: the simulated machine (the same parameters for every family's axes)
_PLANT = PLANT_PARAMS

_INT_TYPES = {"VirtualAxis.Mode": "UDInt", "Simulation.Mode": "UDInt", "Units.LengthUnit": "UDInt",
              "Units.VelocityUnit": "UDInt", "Units.TimeUnit": "UDInt", "LoadGear.Numerator": "UDInt",
              "LoadGear.Denominator": "UDInt", f"{_S}.Parameter.StepsPerRevolution": "UDInt",
              f"{_S}.Parameter.FineResolutionXist1": "UDInt", f"{_S}.Parameter.FineResolutionXist2": "UDInt",
              f"{_S}.Parameter.DeterminableRevolutions": "UDInt", f"{_S}.Interface.Number": "UDInt"}

_ALIASES = (("PositionLimitsSW.", "PositionLimits_SW."), ("PositionLimitsHW.", "PositionLimits_HW."),
            ("Sensor.Sensor[1].", "Sensor[1]."), ("CrossPlcSynchronousOperation.Interface.",
                                                  "CrossPlcSynchronousOperation.Interface[1]."))

def canonical(path: str) -> str:
    for old, new in _ALIASES:
        if path.startswith(old):
            return new + path[len(old):]
    return path


PROFIDRIVE_OVERDRIVE, ANALOG_OVERDRIVE = 2.0, 1.17      # §A.1.5: MaxSpeed <= 2 (PROFIdrive) / 1.17 (analog) x ref


def rule_issues(cfg: Mapping[str, Any]) -> list[Issue]:
    issues: list[Issue] = []

    def add(path: str, rule: str, allowed: str) -> None:
        issues.append(Issue(path, "rule:" + rule, cfg[path], allowed))

    ref, nmax = cfg["Actor.DriveParameter.ReferenceSpeed"], cfg["Actor.DriveParameter.MaxSpeed"]
    factor = PROFIDRIVE_OVERDRIVE if cfg["Actor.Type"] == 1 else ANALOG_OVERDRIVE
    if nmax > factor * ref * (1 + 1e-12):
        add("Actor.DriveParameter.MaxSpeed", "above_reference", f"at most {factor:g} x ReferenceSpeed = {factor * ref:g}")
    if cfg["DynamicLimits.Velocity"] > cfg["DynamicLimits.MaxVelocity"] * (1 + 1e-12):
        add("DynamicLimits.Velocity", "above_max", f"at most DynamicLimits.MaxVelocity = {cfg['DynamicLimits.MaxVelocity']:g}")
    if cfg["PositionLimits_SW.MinPosition"] >= cfg["PositionLimits_SW.MaxPosition"] and not cfg["Modulo.Enable"]:
        add("PositionLimits_SW.MinPosition", "low_above_high",
            f"below PositionLimits_SW.MaxPosition = {cfg['PositionLimits_SW.MaxPosition']:g}")
    if cfg["Actor.Type"] == 1 and cfg["Actor.Interface.Telegram"] not in (3, 4) and cfg["VirtualAxis.Mode"] == 0:
        add("Actor.Interface.Telegram", "no_encoder_in_telegram", "3 or 4 (the encoder comes with the drive telegram)")
    for flag, addr in (("Actor.Interface.EnableDriveOutput", "Actor.Interface.EnableDriveOutputAddress"),
                       ("Actor.Interface.DriveReadyInput", "Actor.Interface.DriveReadyInputAddress")):
        if cfg[flag] and not cfg[addr]:
            add(addr, "missing", f"an address when {flag} is TRUE")
    if cfg["PositionLimits_HW.Active"]:
        for path in ("PositionLimits_HW.MinSwitchAddress", "PositionLimits_HW.MaxSwitchAddress"):
            if not cfg[path]:
                add(path, "missing", "an input address like 'I0.1' when PositionLimits_HW.Active is TRUE")
    lo_sw, hi_sw = cfg["Plant.HWLimitMinPosition"], cfg["Plant.HWLimitMaxPosition"]
    if lo_sw is not None and hi_sw is not None and lo_sw >= hi_sw:
        add("Plant.HWLimitMinPosition", "low_above_high", f"below Plant.HWLimitMaxPosition = {hi_sw:g}")
    unit_rotary = cfg["Units.LengthUnit"] in (1004, 1005, 1537)
    if unit_rotary != (cfg["Properties.MotionType"] == 1):
        add("Units.LengthUnit", "motion_type", "a rotary unit (1004, 1005, 1537) for a rotary axis, a linear unit "
                                               "for a linear axis")
    if cfg["VirtualAxis.Mode"] == 0 and cfg["Simulation.Mode"] == 0:
        vmax_drive = nmax / 60.0 * distance_per_motor_revolution(cfg)
        if cfg["DynamicLimits.MaxVelocity"] > vmax_drive * (1 + 1e-9):
            add("DynamicLimits.MaxVelocity", "unreachable",
                f"at most {vmax_drive:g} with MaxSpeed {nmax:g} 1/min and {distance_per_motor_revolution(cfg):g} "
                f"per motor revolution")
    return issues


S7_1500 = AxisSchema("S7-1500 axis", _PARAMS_1500 + _PLANT, rules=rule_issues, canonical=canonical,
                     build=axis_config, int_types=_INT_TYPES)
