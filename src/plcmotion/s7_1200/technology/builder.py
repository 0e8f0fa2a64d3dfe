"""The kernel's typed configuration of an S7-1200 positioning axis, built from its tags (S7-1200 V6 §12.9).

:func:`axis_config` is the one place that knows which tag of the technology data block gives which value
of the neutral :class:`~plcmotion.kernel.axis_config.AxisConfig`, :func:`drive_spec` the one for the drive,
encoder and simulated machine (``Actor.*``, ``Sensor[1].*``, ``Mechanics.*`` and the ``Plant.*``
parameters): a :class:`~plcmotion.drives.spec.DriveSpec`, so that a drive never reads a tag path.  The
schema (``parameters.S7_1200``) calls :func:`axis_config` whenever tag values take effect (creation, the
moment a written tag takes effect, MC_Reset, restart).
"""
from __future__ import annotations

import math
from types import MappingProxyType
from typing import Any, Mapping

from ...drives.spec import (ActuatorKind, DriveSpec, EncoderInterface, EncoderKind, EncoderSpec, PlantSpec,
                           SetpointInterface)
from ...kernel.axis_config import (AxisConfig, DriveSignals, DynamicDefaults, DynamicLimits,
                                   FollowingErrorMonitoring, HardwareLimits, Homing, HomingMethod,
                                   LeadingValueOutput, Modulo, PositionControl, PositioningMonitoring, PulseOutput,
                                   SoftwareLimits, StandstillMonitoring, Units)
from ...kernel.plant_schema import plant_spec

_S = "Sensor[1]"

#: Actor.Type (§12.9.5): 0 analog output, 1 PROFIdrive telegram, 2 pulse output (PTO)
_SETPOINT_INTERFACE = {0: SetpointInterface.ANALOG, 1: SetpointInterface.PROFIDRIVE, 2: SetpointInterface.PULSES}
#: Sensor[1].Type (§12.9.6): 0 incremental, 1 absolute, 2 cyclic absolute
_ENCODER_KIND = {0: EncoderKind.INCREMENTAL, 1: EncoderKind.ABSOLUTE, 2: EncoderKind.CYCLIC_ABSOLUTE}
#: Sensor[1].Interface.Type (§12.9.6): 0 PROFIdrive encoder, 1 technology module, 2 encoder on drive, 4 HSC
_ENCODER_INTERFACE = {0: EncoderInterface.PROFIDRIVE, 1: EncoderInterface.TECHNOLOGY_MODULE,
                      2: EncoderInterface.DRIVE_TELEGRAM, 4: EncoderInterface.HIGH_SPEED_COUNTER}


def drive_spec(p: Mapping[str, Any]) -> DriveSpec:
    """The drive, encoder and simulated machine of an S7-1200 axis with valid tag values ``p``."""
    actor = p["Actor.Type"]
    if actor == 2:
        actuator = ActuatorKind.PULSE
    elif p["Simulation.Mode"] == 1:
        actuator = ActuatorKind.IDEAL
    else:
        actuator = ActuatorKind.SPEED_SERVO
    return DriveSpec(
        actuator=actuator,
        interface=_SETPOINT_INTERFACE[actor] if actuator is not ActuatorKind.IDEAL else SetpointInterface.NONE,
        telegram=p["Actor.Interface.Telegram"],
        reference_speed=p["Actor.DriveParameter.ReferenceSpeed"],
        max_speed=p["Actor.DriveParameter.MaxSpeed"],
        length_per_revolution=p["Mechanics.LeadScrew"],
        pulses_per_revolution=p["Actor.DriveParameter.PulsesPerDriveRevolution"],
        ready_delay=p["Plant.ReadyDelay"],
        off_ramp_time=p["Plant.OffRampTime"],
        encoder=_encoder(p),
        plant=_plant(p),
    )


def _encoder(p: Mapping[str, Any]) -> EncoderSpec:
    kind = _ENCODER_KIND[p[f"{_S}.Type"]]
    # the encoder turns with the motor (mounting 0: one revolution per lead) or with the load (2: external,
    # its own distance per revolution), §12.9.6.3
    per_rev = (p["Mechanics.LeadScrew"] if p[f"{_S}.MountingMode"] == 0
               else p[f"{_S}.Parameter.DistancePerRevolution"])
    return EncoderSpec(
        kind=kind,
        rotary=p[f"{_S}.System"] == 1,
        steps_per_revolution=p[f"{_S}.Parameter.StepsPerRevolution"],
        fine_bits=p[f"{_S}.Parameter.FineResolutionXist1"],
        fine_bits_absolute=p[f"{_S}.Parameter.FineResolutionXist2"],
        distance_per_revolution=per_rev,
        step_length=p[f"{_S}.Parameter.Resolution"],
        determinable_revolutions=(p[f"{_S}.Parameter.DeterminableRevolutions"]
                                  if kind is not EncoderKind.INCREMENTAL else 0),
        inverse_direction=bool(p[f"{_S}.InverseDirection"]),
        interface=_ENCODER_INTERFACE[p[f"{_S}.Interface.Type"]],
    )


def _plant(p: Mapping[str, Any]) -> PlantSpec:
    return plant_spec(p, hw_min=(p["PositionLimits_HW.MinSwitchAddress"], p["PositionLimits_HW.MinSwitchLevel"]),
                      hw_max=(p["PositionLimits_HW.MaxSwitchAddress"], p["PositionLimits_HW.MaxSwitchLevel"]),
                      homing_inputs=[(p[f"{_S}.{kind}.DigitalInputAddress"], p[f"{_S}.{kind}.SwitchLevel"])
                                     for kind in ("ActiveHoming", "PassiveHoming")],
                      ready_input=p["Actor.Interface.DriveReadyInput"] or "")


#: Units.LengthUnit (S7-1200 V6 §12.9.7): unit codes
_LENGTH_UNITS = {-1: "pulse", 1005: "°", 1010: "m", 1013: "mm", 1018: "ft", 1019: "in"}
#: S7-1200 V6 §5.4.4.4: a pulse drive plans without jerk limit below 0.004 pulses/s^3, a drive with
#: position control at and below 1e-9
_PTO_JERK_ENABLE = 4.0e-3
_SERVO_JERK_ENABLE = 1.0e-9

_TAG_NAMES = MappingProxyType({
    "homing.approach_velocity": "Homing.ApproachVelocity",
    "homing.referencing_velocity": "Homing.ReferencingVelocity",
    "software_limits.minimum": "PositionLimits_SW.MinPosition",
})


def _jerk(p: Mapping[str, Any], drive: DriveSpec) -> float:
    jerk = p["DynamicDefaults.Jerk"]
    if p["Actor.Type"] == 2:
        return jerk if jerk >= _PTO_JERK_ENABLE * drive.pulse_length else math.inf
    return jerk if jerk > _SERVO_JERK_ENABLE else math.inf


def _homing_method(p: Mapping[str, Any], kind: str) -> HomingMethod:
    k = f"{_S}.{kind}Homing"
    return HomingMethod(mode=p[f"{k}.Mode"], input=p[f"{k}.DigitalInputAddress"], active_high=p[f"{k}.SwitchLevel"],
                        upper_side=p[f"{k}.SideInput"], home_offset=p.get(f"{k}.HomePositionOffset", 0.0))


def axis_config(p: Mapping[str, Any]) -> AxisConfig:
    """The configuration of an S7-1200 positioning axis with valid tag values ``p``."""
    drive = drive_spec(p)
    return AxisConfig(
        units=Units(length=_LENGTH_UNITS.get(p["Units.LengthUnit"], str(p["Units.LengthUnit"]))),
        modulo=Modulo(enabled=p["Modulo.Enable"], start=p["Modulo.StartValue"], length=p["Modulo.Length"]),
        limits=DynamicLimits(
            max_velocity=p["DynamicLimits.MaxVelocity"],
            start_stop_velocity=p["DynamicLimits.MinVelocity"],
            # no current velocity limit and no maximum acceleration, deceleration or jerk of their own
            velocity=None, max_acceleration=None, max_deceleration=None, max_jerk=None),
        defaults=DynamicDefaults(
            acceleration=p["DynamicDefaults.Acceleration"],
            deceleration=p["DynamicDefaults.Deceleration"],
            emergency_deceleration=p["DynamicDefaults.EmergencyDeceleration"],
            jerk=_jerk(p, drive),
            velocity_override=None),                  # no velocity override tag
        software_limits=SoftwareLimits(
            enabled=p["PositionLimits_SW.Active"],
            minimum=p["PositionLimits_SW.MinPosition"],
            maximum=p["PositionLimits_SW.MaxPosition"]),
        hardware_limits=HardwareLimits(
            enabled=p["PositionLimits_HW.Active"],
            min_input=p["PositionLimits_HW.MinSwitchAddress"],
            max_input=p["PositionLimits_HW.MaxSwitchAddress"],
            min_active_high=p["PositionLimits_HW.MinSwitchLevel"],
            max_active_high=p["PositionLimits_HW.MaxSwitchLevel"]),
        homing=Homing(
            approach_positive=p["Homing.ApproachDirection"],
            approach_velocity=p["Homing.ApproachVelocity"],
            referencing_velocity=p["Homing.ReferencingVelocity"],
            auto_reversal=p["Homing.AutoReversal"],
            active=_homing_method(p, "Active"),
            passive=_homing_method(p, "Passive")),
        position_control=PositionControl(kv=p["PositionControl.Kv"], precontrol=p["PositionControl.Kpc"]),
        following_error=FollowingErrorMonitoring(
            enabled=p["FollowingError.EnableMonitoring"],
            min_value=p["FollowingError.MinValue"],
            max_value=p["FollowingError.MaxValue"],
            min_velocity=p["FollowingError.MinVelocity"],
            warning_level=None),
        positioning=PositioningMonitoring(
            tolerance_time=p["PositioningMonitoring.ToleranceTime"],
            min_dwell_time=p["PositioningMonitoring.MinDwellTime"],
            window=p["PositioningMonitoring.Window"]),
        standstill=StandstillMonitoring(
            velocity_threshold=p["StandstillSignal.VelocityThreshold"],
            min_dwell_time=p["StandstillSignal.MinDwellTime"]),
        signals=DriveSignals(enable_output=p["Actor.Interface.EnableDriveOutput"] or "",
                             ready_input=p["Actor.Interface.DriveReadyInput"] or ""),
        pulse_output=PulseOutput(generator=p["Actor.Interface.PTO"], direction_mode=p["Actor.DirectionMode"],
                                 slice_time=p["Actor.PTOSliceTime"] / 1000.0),
        drive=drive,
        extrapolation=None,                            # no leading value extrapolation, no cross-PLC output
        leading_value_output=LeadingValueOutput(),
        tag_names=_TAG_NAMES,
    )
