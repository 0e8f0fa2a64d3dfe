"""The kernel's typed configuration of an S7-Technology axis, built from its tags (S7-Technology V4.1 §9.4).

:func:`axis_config` is the one place that knows which S7-Technology tag (expert-list name of §9.4, or a
family tag of the axis wizard, see ``schema``) gives which value of the neutral
:class:`~plcmotion.kernel.axis_config.AxisConfig`; :func:`drive_spec` the one for the drive and its
encoder.  ENUM tags hold their ValueDint (§9.4.12): EnumYesNo YES = 1, EnumActiveInactive ACTIVE = 1,
EnumDirectionType POSITIVE = 5.
"""
from __future__ import annotations

import math
from types import MappingProxyType
from typing import Any, Mapping

from ...drives.spec import ActuatorKind, DriveSpec, EncoderInterface, EncoderKind, EncoderSpec, SetpointInterface
from ...kernel.axis_config import (AxisConfig, DriveSignals, DynamicDefaults, DynamicLimits, FollowingErrorMonitoring,
                                   HardwareLimits, Homing, HomingMethod, Modulo, PositionControl,
                                   PositioningMonitoring, PulseOutput, SoftwareLimits, StandstillMonitoring, Units)
from ...kernel.plant_schema import plant_spec
from .hydraulic_params import hydraulic, hydraulic_drive_spec
from .datasets import active as active_dataset, refine as refine_dataset
from .encoders import dataset_encoder, kind as encoder_kind
from .homing_params import plant_wiring, refine

#: §9.4.12 ValueDint of EnumYesNo / EnumActiveInactive / EnumDirectionType
YES, ACTIVE, POSITIVE = 1, 1, 5
#: the axis technologies of the wizard (§3.1.1): family tag ``Wizard.Technology``
SPEED, POSITIONING, SYNCHRONIZATION = 0, 1, 2
#: the PROFIdrive telegrams of §4.2.3 (Table 4-1) with one or two encoders; 1, 2 and 101 have none
TELEGRAMS_ONE_ENCODER = (3, 5, 102, 105)
TELEGRAMS_TWO_ENCODERS = (4, 6, 103, 106)
TELEGRAMS_NO_ENCODER = (1, 2, 101)

#: revolutions a simulated absolute encoder tells apart (a 12-bit multiturn encoder; docs/s7t/decisions.md D78)
ABSOLUTE_REVOLUTIONS = 4096

DS = "TypeOfAxis.NumberOfDataSets.DataSet_1"
PV = f"{DS}.ControllerStruct.PV_Controller"
FE = f"{DS}.DynamicFollowing"
GEAR = f"{DS}.Gear"
DYN = "userdefaultdynamics"

_TAG_NAMES = MappingProxyType({
    "homing.approach_velocity": "userdefaulthoming.homingapproachvelocity",
    "homing.referencing_velocity": "userdefaulthoming.homingentryvelocity",
    "software_limits.minimum": "swlimit.minusposition",
    "software_limits.maximum": "swlimit.plusposition",
})


def virtual(p: Mapping[str, Any]) -> bool:
    """A virtual axis (§3.1.5) has no drive and no encoder: its actual value is its setpoint."""
    return bool(p["Wizard.Virtual"])


def rotary(p: Mapping[str, Any]) -> bool:
    return p["Wizard.AxisType"] == 1


def distance_per_motor_revolution(p: Mapping[str, Any]) -> float:
    """Load travel per motor revolution: the leadscrew pitch (linear) or 360° (rotary) per load revolution,
    times load revolutions / motor revolutions of the load gear (§4.5.5)."""
    per_load_revolution = 360.0 if rotary(p) else p["LeadScrew.pitchVal"]
    return per_load_revolution * p[f"{GEAR}.denFactor"] / p[f"{GEAR}.numFactor"]


def max_drive_velocity(p: Mapping[str, Any]) -> float:
    """The load velocity at the drive's maximum speed [length unit/s]."""
    return p["Drive.MaxSpeed"] / 60.0 * distance_per_motor_revolution(p)


def drive_spec(p: Mapping[str, Any]) -> DriveSpec:
    """The drive, encoder and simulated machine of an axis with valid tag values ``p``."""
    per_revolution = distance_per_motor_revolution(p)
    ideal = virtual(p)
    telegram = p["Wizard.Telegram"]
    # the encoder of the data set in force (technology.encoders); a virtual axis has none
    kind = EncoderKind.INCREMENTAL if ideal else encoder_kind(p, dataset_encoder(p, active_dataset(p)))
    encoder = EncoderSpec(kind=kind, rotary=True, distance_per_revolution=per_revolution,
                          determinable_revolutions=0 if kind is EncoderKind.INCREMENTAL else ABSOLUTE_REVOLUTIONS,
                          interface=EncoderInterface.DRIVE_TELEGRAM)
    if hydraulic(p):
        return hydraulic_drive_spec(p, encoder, per_revolution, plant_wiring(p))   # a valve and a cylinder (§3.1.4, §4.6)
    return DriveSpec(
        actuator=ActuatorKind.IDEAL if ideal else ActuatorKind.SPEED_SERVO,
        interface=SetpointInterface.NONE if ideal else SetpointInterface.PROFIDRIVE,
        # the kernel's PROFIdrive link knows the standard telegrams 3 and 4: the setpoint and encoder words
        # of the DSC and torque-reduction telegrams are the same (§4.2.3); one without encoder acts as 3
        telegram=4 if telegram in TELEGRAMS_TWO_ENCODERS else 3,
        reference_speed=p["Drive.ReferenceSpeed"],
        max_speed=p["Drive.MaxSpeed"],
        length_per_revolution=per_revolution,
        ready_delay=p["Plant.ReadyDelay"],
        off_ramp_time=p["Plant.OffRampTime"],
        encoder=encoder,
        plant=plant_spec(p, **plant_wiring(p)),
    )


def axis_config(p: Mapping[str, Any]) -> AxisConfig:
    """The configuration of an S7-Technology axis with valid tag values ``p``."""
    # homing, limit switches, standstill: homing_params; the data set in force: datasets
    return refine_dataset(refine(_axis_config(p), p), p)


def _axis_config(p: Mapping[str, Any]) -> AxisConfig:
    jerk = p[f"{DYN}.positiveaccelstartjerk"]
    max_acc = p["TypeOfAxis.MaxAcceleration.maximum"]
    home_method = HomingMethod(mode=0, home_offset=0.0)
    return AxisConfig(
        units=Units(length="°" if rotary(p) else "mm"),
        modulo=Modulo(enabled=p["Modulo.state"] == ACTIVE, start=p["Modulo.startValue"], length=p["Modulo.length"]),
        limits=DynamicLimits(
            max_velocity=p["TypeOfAxis.MaxVelocity.maximum"],
            start_stop_velocity=0.0,
            # the limit in force is the maximum: a faster command is cut to it (warning 0021, §6.9.3)
            velocity=p["TypeOfAxis.MaxVelocity.maximum"],
            # §4.5.7.4 state-dependent model (the default): one maximum for acceleration and deceleration
            max_acceleration=max_acc,
            max_deceleration=max_acc,
            max_jerk=p["TypeOfAxis.MaxJerk.maximum"]),
        defaults=DynamicDefaults(
            acceleration=p[f"{DYN}.positiveaccel"],
            deceleration=p[f"{DYN}.negativeaccel"],
            emergency_deceleration=p["TypeOfAxis.EmergencyRampGenerator.maxDeceleration"],
            jerk=jerk if jerk > 0.0 else math.inf,
            velocity_override=p["override.velocity"],
            acceleration_override=p.get("override.acceleration")),
        software_limits=SoftwareLimits(
            enabled=p["swlimit.state"] == ACTIVE,
            minimum=p["swlimit.minusposition"],
            maximum=p["swlimit.plusposition"]),
        hardware_limits=HardwareLimits(),
        homing=Homing(
            approach_positive=p["TypeOfAxis.Homing.direction"] == POSITIVE,
            approach_velocity=p["userdefaulthoming.homingapproachvelocity"],
            referencing_velocity=p["userdefaulthoming.homingentryvelocity"],
            active=home_method, passive=home_method),
        position_control=PositionControl(kv=p[f"{PV}.kv"], precontrol=p[f"{PV}.kpc"]),
        following_error=FollowingErrorMonitoring(
            enabled=p[f"{FE}.enable"] == YES and not virtual(p),
            min_value=p[f"{FE}.minPositionTolerance"],
            max_value=p[f"{FE}.maxPositionTolerance"],
            min_velocity=p[f"{FE}.minVelocity"],
            warning_level=p[f"{FE}.warningLimit"]),
        positioning=PositioningMonitoring(
            tolerance_time=p["TypeOfAxis.PositionMonitoring.posWinTolTime"],
            min_dwell_time=p["TypeOfAxis.PositionMonitoring.posWinTolDelayTime"],
            window=p["TypeOfAxis.PositionMonitoring.tolerance"]),
        standstill=StandstillMonitoring(
            velocity_threshold=p["TypeOfAxis.StandStillSignal.maxVeloStandStill"],
            min_dwell_time=p["TypeOfAxis.StandStillSignal.delayTimeToActivate"]),
        signals=DriveSignals(),
        pulse_output=PulseOutput(),
        drive=drive_spec(p),
        tag_names=_TAG_NAMES,
    )


__all__ = ["axis_config", "drive_spec", "distance_per_motor_revolution", "max_drive_velocity", "virtual", "rotary",
           "SPEED", "POSITIONING", "SYNCHRONIZATION", "YES", "ACTIVE", "POSITIVE", "DS", "PV", "FE", "GEAR", "DYN"]
