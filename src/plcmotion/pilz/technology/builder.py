"""The kernel's typed configuration of a Pilz drive axis, built from its parameters.

:func:`axis_config` is the one place that knows which parameter (I10, I11, I22, ...) gives which value of the
neutral :class:`~plcmotion.kernel.axis_config.AxisConfig`.  The motion core runs inside the drive, so the
drive is a speed servo without a bus between position and speed loop (setpoint interface "none").
"""
from __future__ import annotations

import math
from types import MappingProxyType
from typing import Any, Mapping

from ...drives.spec import ActuatorKind, DriveSpec, EncoderInterface, EncoderKind, EncoderSpec, SetpointInterface
from ...kernel.axis_config import (AxisConfig, DriveSignals, DynamicDefaults, DynamicLimits,
                                   FollowingErrorMonitoring, HardwareLimits, Homing, HomingMethod, Modulo,
                                   PositionControl, PositioningMonitoring, PulseOutput, SoftwareLimits,
                                   StandstillMonitoring, Units)
from ...kernel.plant_schema import plant_spec

_TAG_NAMES = MappingProxyType({
    "limits.max_velocity": "I10", "defaults.acceleration": "I11", "defaults.jerk": "I16",
    "software_limits.minimum": "I51", "software_limits.maximum": "I50", "positioning.window": "I22",
    "homing.approach_velocity": "I32", "homing.referencing_velocity": "I33",
})


def _either(p: Mapping[str, Any], first: str, second: str) -> Any:
    return p[first] if p[first] is not None else p[second]


def drive_spec(p: Mapping[str, Any]) -> DriveSpec:
    feed = p["Drive.FeedPerRevolution"]
    # the mechanical end stops of the torque/force stop referencing are the drive model's (decisions.md)
    p = {**p, "Plant.EndStopMinPosition": _either(p, "Plant.EndStopMinPosition", "Drive.EndStopNegative"),
         "Plant.EndStopMaxPosition": _either(p, "Plant.EndStopMaxPosition", "Drive.EndStopPositive")}
    return DriveSpec(
        actuator=ActuatorKind.SPEED_SERVO, interface=SetpointInterface.NONE,
        reference_speed=p["Drive.MaxSpeed"], max_speed=p["Drive.MaxSpeed"], length_per_revolution=feed,
        ready_delay=p["Plant.ReadyDelay"], off_ramp_time=p["Plant.OffRampTime"],
        encoder=EncoderSpec(kind=EncoderKind.INCREMENTAL, rotary=True,
                            steps_per_revolution=p["Drive.EncoderIncrements"], fine_bits=11,
                            distance_per_revolution=feed, interface=EncoderInterface.DRIVE_TELEGRAM),
        plant=plant_spec(p, hw_min=(p["I102"], p["LimitSwitchLevel"]), hw_max=(p["I101"], p["LimitSwitchLevel"]),
                         homing_inputs=[(p["I103"], p["ReferenceSwitchLevel"])], ready_input=""),
    )


def sw_limits_used(p: Mapping[str, Any]) -> bool:
    """Software limit switches are in use when they span a range (I50 > I51; decisions.md, errata 21)."""
    return p["I00"] == 0 and p["I50"] > p["I51"]


def axis_config(p: Mapping[str, Any]) -> AxisConfig:
    """The configuration of a Pilz drive axis with valid parameter values ``p``."""
    drive = drive_spec(p)
    i11 = p["I11"]
    return AxisConfig(
        units=Units(length="unit"),
        modulo=Modulo(enabled=p["I00"] == 1, start=0.0, length=p["I01"]),
        limits=DynamicLimits(max_velocity=p["I10"], velocity=None, max_acceleration=i11 or None,
                             max_deceleration=i11 or None, max_jerk=p["I16"] or None),
        # the commands bring their own dynamics; the defaults are the maxima (quick stop: I11 without jerk)
        defaults=DynamicDefaults(acceleration=i11 or 1.0, deceleration=i11 or 1.0,
                                 emergency_deceleration=i11 or 1.0, jerk=p["I16"] or math.inf,
                                 velocity_override=None),
        software_limits=SoftwareLimits(enabled=sw_limits_used(p), minimum=p["I51"], maximum=p["I50"]),
        hardware_limits=HardwareLimits(enabled=bool(p["I101"] or p["I102"]), min_input=p["I102"],
                                       max_input=p["I101"], min_active_high=p["LimitSwitchLevel"],
                                       max_active_high=p["LimitSwitchLevel"]),
        # Pilz referencing is the family's (technology/referencing.py); the kernel part only holds the switch
        homing=Homing(approach_positive=p["I31"] == 0, approach_velocity=p["I32"], referencing_velocity=p["I33"],
                      auto_reversal=False,
                      active=HomingMethod(mode=2, input=p["I103"], active_high=p["ReferenceSwitchLevel"]),
                      passive=HomingMethod(mode=2, input="")),
        position_control=PositionControl(kv=p["I20"], precontrol=p["I25"]),
        # the motion core has no following error alarm in this manual; its monitoring stays off
        following_error=FollowingErrorMonitoring(enabled=False),
        positioning=PositioningMonitoring(tolerance_time=math.inf, min_dwell_time=p["I87"], window=p["I22"]),
        standstill=StandstillMonitoring(velocity_threshold=p["C40"], min_dwell_time=0.0),
        signals=DriveSignals(),
        pulse_output=PulseOutput(),
        drive=drive,
        tag_names=_TAG_NAMES,
    )


__all__ = ["axis_config", "drive_spec", "sw_limits_used"]
