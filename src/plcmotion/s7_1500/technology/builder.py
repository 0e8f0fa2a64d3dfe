"""The kernel's typed configuration of an S7-1500 axis or encoder, built from its own tags (S7-1500T V5 §A.1).

:func:`axis_config` is the one place that knows which S7-1500 tag gives which value of the neutral
:class:`~plcmotion.kernel.axis_config.AxisConfig` and :func:`drive_spec` the one for the drive and encoder
(:class:`~plcmotion.drives.spec.DriveSpec`); :func:`source_config` gives the leading value part of an
external encoder.  The schema (``parameters.S7_1500``) calls them whenever tag values take effect.
"""
from __future__ import annotations

import math
from types import MappingProxyType
from typing import Any, Mapping

from ...drives.spec import ActuatorKind, DriveSpec, EncoderInterface, EncoderKind, EncoderSpec, SetpointInterface
from ...kernel.axis_config import (AxisConfig, DriveSignals, DynamicDefaults, DynamicLimits, Extrapolation,
                                   FollowingErrorMonitoring, HardwareLimits, Homing, HomingMethod,
                                   LeadingValueOutput, LeadingValueSourceConfig, Modulo, PositionControl,
                                   PositioningMonitoring, PulseOutput, SoftwareLimits, StandstillMonitoring, Units)
from ...kernel.plant_schema import plant_spec

_S = "Sensor[1]"
#: §A.1.5 Actor.Type: 0 analog output, 1 PROFIdrive telegram
_SETPOINT_INTERFACE = {0: SetpointInterface.ANALOG, 1: SetpointInterface.PROFIDRIVE}
#: §A.1.8 Sensor[1].Type: 0 incremental, 1 absolute, 2 cyclic absolute
_ENCODER_KIND = {0: EncoderKind.INCREMENTAL, 1: EncoderKind.ABSOLUTE, 2: EncoderKind.CYCLIC_ABSOLUTE}
#: S7-1500T V5 §A.1.22: a jerk at and below this value switches the jerk limit off (trapezoidal profile)
_JERK_ENABLE = 1.0e-9

_TAG_NAMES = MappingProxyType({
    "homing.approach_velocity": "Homing.ApproachVelocity",
    "homing.referencing_velocity": "Homing.ReferencingVelocity",
    "software_limits.minimum": "PositionLimits_SW.MinPosition",
})


def load_revolution(cfg: Mapping[str, Any]) -> float:
    """Load travel of one load revolution [user unit]: the leadscrew pitch (linear) or 360° / 2π rad."""
    if cfg["Properties.MotionType"] == 0:
        return cfg["Mechanics.LeadScrew"]
    return 2.0 * math.pi if cfg["Units.LengthUnit"] == 1004 else 360.0


def distance_per_motor_revolution(cfg: Mapping[str, Any]) -> float:
    """Load travel per motor revolution: load revolution x LoadGear (motor revolutions : load revolutions)."""
    return load_revolution(cfg) * cfg["LoadGear.Denominator"] / cfg["LoadGear.Numerator"]


def simulated(cfg: Mapping[str, Any]) -> bool:
    """A simulated axis (Simulation.Mode 1) and a virtual axis (VirtualAxis.Mode 1) have no drive (§A.1.3)."""
    return cfg["Simulation.Mode"] == 1 or cfg["VirtualAxis.Mode"] == 1


def modulo_config(p: Mapping[str, Any]) -> Modulo:
    return Modulo(enabled=p["Modulo.Enable"], start=p["Modulo.StartValue"], length=p["Modulo.Length"])


def extrapolation_config(p: Mapping[str, Any]) -> Extrapolation:
    """The leading value extrapolation (S7-1500T V5 §3.3.6, §A.1.9)."""
    return Extrapolation(
        position_filter_t1=p["Extrapolation.PositionFilter.T1"],
        position_filter_t2=p["Extrapolation.PositionFilter.T2"],
        velocity_filter_t1=p["Extrapolation.VelocityFilter.T1"],
        velocity_filter_t2=p["Extrapolation.VelocityFilter.T2"],
        velocity_tolerance=p["Extrapolation.VelocityTolerance.Range"],
        hysteresis=p["Extrapolation.Hysteresis.Value"],
        following_axis_time=p["Extrapolation.FollowingAxisDependentTime"],
        include_leading_axis_time=p["Extrapolation.Settings.SystemDefinedExtrapolation"] == 1,
        differentiated_velocity=p["Extrapolation.Settings.ExtrapolatedVelocityMode"] == 1,
    )


def leading_value_output_config(p: Mapping[str, Any]) -> LeadingValueOutput:
    """The leading value provided to other controllers (§A.1.10)."""
    return LeadingValueOutput(
        enabled=bool(p.get("CrossPlcSynchronousOperation.Interface[1].EnableLeadingValueOutput")),
        local_delay_time=p.get("CrossPlcSynchronousOperation.LocalLeadingValueDelayTime", 0.0))


def source_config(p: Mapping[str, Any]) -> LeadingValueSourceConfig:
    """The leading value part of a configuration (an external encoder that is a leading value source)."""
    return LeadingValueSourceConfig(modulo=modulo_config(p), extrapolation=extrapolation_config(p),
                                    leading_value_output=leading_value_output_config(p))


def _homing_method(p: Mapping[str, Any], kind: str) -> HomingMethod:
    k = f"{_S}.{kind}Homing"
    return HomingMethod(mode=p[f"{k}.Mode"], input=p[f"{k}.DigitalInputAddress"], active_high=p[f"{k}.SwitchLevel"],
                        upper_side=p[f"{k}.SideInput"], home_offset=p.get(f"{k}.HomePositionOffset", 0.0))


def _address(p: Mapping[str, Any], flag: str) -> str:
    """An analog drive's enable output / ready input: its address when the signal is used (§A.1.5)."""
    return (p[f"{flag}Address"] or "") if p[flag] else ""


def drive_spec(p: Mapping[str, Any]) -> DriveSpec:
    """The drive, encoder and simulated machine of an S7-1500 axis with valid tag values ``p``."""
    actuator = ActuatorKind.IDEAL if simulated(p) else ActuatorKind.SPEED_SERVO
    per_motor_revolution = distance_per_motor_revolution(p)
    mounting = p[f"{_S}.MountingMode"]
    # §A.1.8: the encoder turns with the motor (0), with the load (1: one load revolution) or is external (2)
    per_encoder_revolution = (per_motor_revolution if mounting == 0 else load_revolution(p) if mounting == 1
                              else p[f"{_S}.Parameter.DistancePerRevolution"])
    kind = _ENCODER_KIND[p[f"{_S}.Type"]]
    encoder = EncoderSpec(
        kind=kind,
        rotary=p[f"{_S}.System"] == 1,
        steps_per_revolution=p[f"{_S}.Parameter.StepsPerRevolution"],
        fine_bits=p[f"{_S}.Parameter.FineResolutionXist1"],
        fine_bits_absolute=p[f"{_S}.Parameter.FineResolutionXist2"],
        distance_per_revolution=per_encoder_revolution,
        step_length=p[f"{_S}.Parameter.Resolution"],
        determinable_revolutions=(p[f"{_S}.Parameter.DeterminableRevolutions"]
                                  if kind is not EncoderKind.INCREMENTAL else 0),
        inverse_direction=bool(p[f"{_S}.InverseDirection"]),
        # the encoder of a PROFIdrive axis comes with the drive telegram; an analog axis reads a PROFIdrive
        # encoder of its own
        interface=EncoderInterface.DRIVE_TELEGRAM if p["Actor.Type"] == 1 else EncoderInterface.PROFIDRIVE,
    )
    homing_inputs = [(p[f"{_S}.{kind}.DigitalInputAddress"], p[f"{_S}.{kind}.SwitchLevel"])
                     for kind in ("ActiveHoming", "PassiveHoming")]
    return DriveSpec(
        actuator=actuator,
        interface=_SETPOINT_INTERFACE[p["Actor.Type"]] if actuator is not ActuatorKind.IDEAL
        else SetpointInterface.NONE,
        telegram=p["Actor.Interface.Telegram"],
        reference_speed=p["Actor.DriveParameter.ReferenceSpeed"],
        max_speed=p["Actor.DriveParameter.MaxSpeed"],
        length_per_revolution=per_motor_revolution,
        ready_delay=p["Plant.ReadyDelay"],
        off_ramp_time=p["Plant.OffRampTime"],
        encoder=encoder,
        plant=plant_spec(p, hw_min=(p["PositionLimits_HW.MinSwitchAddress"], p["PositionLimits_HW.MinSwitchLevel"]),
                         hw_max=(p["PositionLimits_HW.MaxSwitchAddress"], p["PositionLimits_HW.MaxSwitchLevel"]),
                         homing_inputs=homing_inputs,
                         ready_input=_address(p, "Actor.Interface.DriveReadyInput")),
    )


def axis_config(p: Mapping[str, Any]) -> AxisConfig:
    """The configuration of an S7-1500 positioning or synchronous axis with valid tag values ``p``."""
    jerk = p["DynamicDefaults.Jerk"]
    return AxisConfig(
        # the kernel needs only linear or rotary: its messages name mm or degrees (§A.1.13 units are the
        # user's; the values are not converted)
        units=Units(length="°" if p["Properties.MotionType"] == 1 else "mm"),
        modulo=modulo_config(p),
        limits=DynamicLimits(
            max_velocity=p["DynamicLimits.MaxVelocity"],
            start_stop_velocity=0.0,                      # no stepper drives on the S7-1500
            velocity=p["DynamicLimits.Velocity"],
            max_acceleration=p["DynamicLimits.MaxAcceleration"],
            max_deceleration=p["DynamicLimits.MaxDeceleration"],
            max_jerk=p["DynamicLimits.MaxJerk"]),
        defaults=DynamicDefaults(
            acceleration=p["DynamicDefaults.Acceleration"],
            deceleration=p["DynamicDefaults.Deceleration"],
            emergency_deceleration=p["DynamicDefaults.EmergencyDeceleration"],
            jerk=jerk if jerk > _JERK_ENABLE else math.inf,
            velocity_override=p["Override.Velocity"]),
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
            approach_positive=not p["Homing.ApproachDirection"],     # §A.1.20: FALSE = positive direction
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
            warning_level=p["FollowingError.WarningLevel"]),
        positioning=PositioningMonitoring(
            tolerance_time=p["PositioningMonitoring.ToleranceTime"],
            min_dwell_time=p["PositioningMonitoring.MinDwellTime"],
            window=p["PositioningMonitoring.Window"]),
        standstill=StandstillMonitoring(
            velocity_threshold=p["StandstillSignal.VelocityThreshold"],
            min_dwell_time=p["StandstillSignal.MinDwellTime"]),
        signals=DriveSignals(enable_output=_address(p, "Actor.Interface.EnableDriveOutput"),
                             ready_input=_address(p, "Actor.Interface.DriveReadyInput")),
        pulse_output=PulseOutput(),                       # no pulse output on the S7-1500
        drive=drive_spec(p),
        extrapolation=extrapolation_config(p),
        leading_value_output=leading_value_output_config(p),
        tag_names=_TAG_NAMES,
    )
