"""The configuration of an axis in the words of motion control: the typed value the kernel reads.

An :class:`AxisConfig` is a frozen value: modulo range, dynamic limits and defaults, software and hardware
limit switches, homing, position control, the monitoring windows (following error, positioning,
standstill), the leading value extrapolation and output of a leading value source, and the neutral drive
specification (:class:`~plcmotion.drives.spec.DriveSpec` with its encoder).  Lengths are in the axis's
length unit (mm, degree, ...: ``units.length``), velocities in length unit/s, accelerations in length
unit/s^2, jerks in length unit/s^3, times in seconds.

The kernel reads this object only, by attribute, never a tag path.  It is built whenever an axis's
configuration becomes effective (creation, the moment a written tag takes effect, restart) and is then
constant until the next such moment: an axis keeps it in ``axis.config`` beside the kernel parameters it
was built from.

:func:`axis_config` is the one place that knows which tags of the kernel's parameter set (named like the
S7-1200 technology data block, S7-1200 Motion Control V6 §12.9, with the S7-1500 extensions the S7-1500
schema maps onto it) give which value; a family with its own schema will produce an ``AxisConfig``
directly later.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any, Mapping

from ..drives.spec import DriveSpec
from .drive_config import drive_spec


@dataclass(frozen=True, slots=True)
class Units:
    length: str = "mm"                  #: the length unit ("mm", "m", "in", "ft", "°", "pulse")


@dataclass(frozen=True, slots=True)
class Modulo:
    """A modulo axis counts its position in [start, start + length) (PLCopen: a rotary axis)."""

    enabled: bool = False
    start: float = 0.0                  #: lower end of the modulo range [length unit]
    length: float = 360.0               #: length of the modulo range [length unit]


@dataclass(frozen=True, slots=True)
class DynamicLimits:
    """The limits no motion of the axis exceeds.  ``None``: the axis has no such limit of its own."""

    max_velocity: float = 250.0         #: maximum velocity [length unit/s]
    #: start/stop velocity of a stepper: the velocity it may start and stop at without a ramp
    #: [length unit/s] (as configured; applies to pulse drives only)
    start_stop_velocity: float = 0.0
    velocity: float | None = None       #: current velocity limit (below ``max_velocity``) [length unit/s]
    max_acceleration: float | None = None    #: [length unit/s^2]
    max_deceleration: float | None = None    #: [length unit/s^2]
    max_jerk: float | None = None       #: [length unit/s^3]; 0: no jerk limit


@dataclass(frozen=True, slots=True)
class DynamicDefaults:
    """The dynamics a motion uses when its command gives none."""

    acceleration: float = 48.0          #: [length unit/s^2]
    deceleration: float = 48.0          #: [length unit/s^2]
    #: deceleration of an emergency stop, a ramp without jerk limit [length unit/s^2]
    emergency_deceleration: float = 120.0
    #: the jerk motions are planned with [length unit/s^3]; ``inf`` when the jerk limit is switched off
    jerk: float = math.inf
    velocity_override: float | None = None   #: velocity override [%] applied to every commanded velocity


@dataclass(frozen=True, slots=True)
class SoftwareLimits:
    """Software limit switches: the axis stops at them (act on a homed, non-modulo axis)."""

    enabled: bool = False
    minimum: float = -10000.0           #: [length unit]
    maximum: float = 10000.0            #: [length unit]


@dataclass(frozen=True, slots=True)
class HardwareLimits:
    """Hardware limit switches: digital inputs that stop the axis when actuated."""

    enabled: bool = False
    min_input: str = ""                 #: input address of the low switch ("" none)
    max_input: str = ""                 #: input address of the high switch ("" none)
    min_active_high: bool = False       #: the low switch is actuated while its input is TRUE (NO contact)
    max_active_high: bool = False


@dataclass(frozen=True, slots=True)
class HomingMethod:
    """How one kind of homing (active or passive) finds its reference."""

    #: 0 the encoder zero mark, 1 a proximity switch then the next zero mark, 2 the homing switch
    mode: int = 2
    input: str = ""                     #: input address of the homing switch ("" none)
    active_high: bool = True            #: the switch is actuated while its input is TRUE
    upper_side: bool = False            #: the reference is the switch's upper end (FALSE: its lower end)
    home_offset: float = 0.0            #: active homing: distance from the homing event to the home position


@dataclass(frozen=True, slots=True)
class Homing:
    approach_positive: bool = True      #: approach (and homing) direction is positive
    approach_velocity: float = 200.0    #: velocity of the switch search [length unit/s]
    referencing_velocity: float = 40.0  #: velocity over the reference edge / to the zero mark [length unit/s]
    auto_reversal: bool = False         #: reverse at a hardware limit switch during the search
    active: HomingMethod = HomingMethod()
    passive: HomingMethod = HomingMethod()


@dataclass(frozen=True, slots=True)
class PositionControl:
    kv: float = 10.0                    #: position loop gain [1/s]
    precontrol: float = 100.0           #: velocity precontrol [%]


@dataclass(frozen=True, slots=True)
class FollowingErrorMonitoring:
    """The admissible following error grows linearly from ``min_value`` at ``min_velocity`` to
    ``max_value`` at the maximum velocity."""

    enabled: bool = True
    min_value: float = 10.0             #: [length unit]
    max_value: float = 100.0            #: [length unit]
    min_velocity: float = 10.0          #: [length unit/s]
    warning_level: float | None = None  #: warning at this share of the admissible error [%]


@dataclass(frozen=True, slots=True)
class PositioningMonitoring:
    """A positioning ends when the actual position stays ``min_dwell_time`` in the window around the
    target, at the latest ``tolerance_time`` after the setpoint reached it."""

    tolerance_time: float = 1.0         #: [s]
    min_dwell_time: float = 0.1         #: [s]
    window: float = 1.0                 #: [length unit]


@dataclass(frozen=True, slots=True)
class StandstillMonitoring:
    velocity_threshold: float = 5.0     #: below this the axis stands still [length unit/s]
    min_dwell_time: float = 0.01        #: ... for at least this time [s]


@dataclass(frozen=True, slots=True)
class DriveSignals:
    """Digital signals between controller and drive."""

    enable_output: str = ""             #: output set while the drive is enabled ("" none)
    ready_input: str = ""               #: input the drive reports "ready" on ("" none: always ready)


@dataclass(frozen=True, slots=True)
class PulseOutput:
    """The pulse generator of a stepper axis."""

    generator: int = 0                  #: number of a pulse generator shared by axes (0: one of its own)
    #: permitted direction: 0 both, 1 positive only, 2 negative only
    direction_mode: int = 0
    slice_time: float = 0.002           #: a new command takes effect at the next multiple of this [s]


@dataclass(frozen=True, slots=True)
class Extrapolation:
    """Filters and extrapolation of an actual leading value (PT2 position and velocity filters)."""

    position_filter_t1: float = 0.0     #: [s]
    position_filter_t2: float = 0.0     #: [s]
    velocity_filter_t1: float = 0.0     #: [s]
    velocity_filter_t2: float = 0.0     #: [s]
    velocity_tolerance: float = 0.0     #: width of the velocity tolerance band [length unit/s]
    hysteresis: float = 0.0             #: [length unit]
    following_axis_time: float = 0.0    #: extrapolation time for the following axis [s]
    include_leading_axis_time: bool = False   #: add the leading axis's own delays to the extrapolation time
    differentiated_velocity: bool = False     #: velocity from the extrapolated position, not the filter


@dataclass(frozen=True, slots=True)
class LeadingValueOutput:
    """The leading value a source provides to other controllers."""

    enabled: bool = False
    local_delay_time: float = 0.0       #: delay of the locally delayed leading value [s]


@dataclass(frozen=True, slots=True)
class LeadingValueSourceConfig:
    """What the kernel reads of any leading value source (an axis or an encoder)."""

    modulo: Modulo = Modulo()
    extrapolation: Extrapolation | None = None
    leading_value_output: LeadingValueOutput = LeadingValueOutput()


@dataclass(frozen=True, slots=True)
class AxisConfig:
    """The whole effective configuration of one axis (see the module docstring)."""

    units: Units
    modulo: Modulo
    limits: DynamicLimits
    defaults: DynamicDefaults
    software_limits: SoftwareLimits
    hardware_limits: HardwareLimits
    homing: Homing
    position_control: PositionControl
    following_error: FollowingErrorMonitoring
    positioning: PositioningMonitoring
    standstill: StandstillMonitoring
    signals: DriveSignals
    pulse_output: PulseOutput
    drive: DriveSpec
    extrapolation: Extrapolation | None = None
    leading_value_output: LeadingValueOutput = LeadingValueOutput()
    #: the family's name of a configuration value, by field path (``"homing.approach_velocity"``): a
    #: configuration fault found at run time names the tag the user has to correct
    tag_names: Mapping[str, str] = field(default_factory=dict, compare=False)

    def tag_name(self, field: str) -> str:
        return self.tag_names.get(field, field)


# ----------------------------------------------------------------------------------------------------------
# the builder: the one place that knows the kernel parameters' tag names

_S = "Sensor[1]"
#: Units.LengthUnit (S7-1200 V6 §12.9.7): unit codes
_LENGTH_UNITS = {-1: "pulse", 1005: "°", 1010: "m", 1013: "mm", 1018: "ft", 1019: "in"}
#: S7-1200 V6 §5.4.4.4: a pulse drive plans without jerk limit below 0.004 pulses/s^3, a drive with
#: position control at and below 1e-9
_PTO_JERK_ENABLE = 4.0e-3
_SERVO_JERK_ENABLE = 1.0e-9

_TAG_NAMES = MappingProxyType({
    "homing.approach_velocity": "Homing.ApproachVelocity",
    "homing.referencing_velocity": "Homing.ReferencingVelocity",
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


def modulo_config(p: Mapping[str, Any]) -> Modulo:
    return Modulo(enabled=p["Modulo.Enable"], start=p["Modulo.StartValue"], length=p["Modulo.Length"])


def extrapolation_config(p: Mapping[str, Any]) -> Extrapolation | None:
    """The leading value extrapolation (S7-1500T V5 §3.3.6), None for a source without one."""
    if "Extrapolation.PositionFilter.T1" not in p:
        return None
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
    return LeadingValueOutput(
        enabled=bool(p.get("CrossPlcSynchronousOperation.Interface[1].EnableLeadingValueOutput")),
        local_delay_time=p.get("CrossPlcSynchronousOperation.LocalLeadingValueDelayTime", 0.0))


def source_config(p: Mapping[str, Any]) -> LeadingValueSourceConfig:
    """The leading value part of a configuration (an encoder that is a leading value source)."""
    return LeadingValueSourceConfig(modulo=modulo_config(p), extrapolation=extrapolation_config(p),
                                    leading_value_output=leading_value_output_config(p))


def axis_config(p: Mapping[str, Any]) -> AxisConfig:
    """The configuration of an axis with kernel parameters ``p`` (valid values)."""
    drive = drive_spec(p)
    return AxisConfig(
        units=Units(length=_LENGTH_UNITS.get(p["Units.LengthUnit"], str(p["Units.LengthUnit"]))),
        modulo=modulo_config(p),
        limits=DynamicLimits(
            max_velocity=p["DynamicLimits.MaxVelocity"],
            start_stop_velocity=p["DynamicLimits.MinVelocity"],
            velocity=p.get("DynamicLimits.Velocity"),
            max_acceleration=p.get("DynamicLimits.MaxAcceleration"),
            max_deceleration=p.get("DynamicLimits.MaxDeceleration"),
            max_jerk=p.get("DynamicLimits.MaxJerk")),
        defaults=DynamicDefaults(
            acceleration=p["DynamicDefaults.Acceleration"],
            deceleration=p["DynamicDefaults.Deceleration"],
            emergency_deceleration=p["DynamicDefaults.EmergencyDeceleration"],
            jerk=_jerk(p, drive),
            velocity_override=p.get("Override.Velocity")),
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
            warning_level=p.get("FollowingError.WarningLevel")),
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
        extrapolation=extrapolation_config(p),
        leading_value_output=leading_value_output_config(p),
        tag_names=_TAG_NAMES,
    )
