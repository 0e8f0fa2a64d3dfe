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

Each family builds it from its own tags (its schema's builder, e.g. ``s7_1200.technology.builder``):
the kernel knows no tag path.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Mapping

from ..drives.spec import DriveSpec


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
    #: acceleration override [%] scaling the acceleration and deceleration of every motion but an emergency stop
    #: (the dynamic limits still hold); None: no such override
    acceleration_override: float | None = None


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
class ReferenceApproach:
    """The settings of a reference point approach with a velocity of its own for the travel to the home
    position, a zero mark before or after the cam, distance monitoring and directional passive homing
    (``kernel.reference_approach.ApproachHoming``; None in :class:`Homing` for the plain approach)."""

    entry_velocity: float = 40.0        #: travel from the homing event to the home position [length unit/s]
    zero_mark_after_cam: bool = True    #: the zero mark lies beyond the cam in the approach direction
    cam_distance: float | None = None   #: most travel from the start to the cam / external mark (None: off)
    zero_mark_distance: float | None = None  #: most travel from the cam (or the start) to the zero mark
    external_rising: bool = True        #: active homing on an external mark: its rising edge homes
    passive_direction: int = 0          #: passive homing only while moving +1 / -1; 0 either direction
    passive_rising: bool = True         #: passive homing on an external mark: its rising edge homes
    #: when corrections of the superimposed coordinate system go over to the basic one:
    #: "standstill" (also as "merge"), "merge" (a basic motion takes over, following mode, restart), "reset"
    #: (following mode, restart)
    transfer_superimposed: str = "standstill"


@dataclass(frozen=True, slots=True)
class Homing:
    approach_positive: bool = True      #: approach (and homing) direction is positive
    approach_velocity: float = 200.0    #: velocity of the switch search [length unit/s]
    referencing_velocity: float = 40.0  #: velocity over the reference edge / to the zero mark [length unit/s]
    auto_reversal: bool = False         #: reverse at a hardware limit switch during the search
    active: HomingMethod = HomingMethod()
    passive: HomingMethod = HomingMethod()
    approach: ReferenceApproach | None = None   #: settings of ``ApproachHoming`` (other homing ignores them)
    #: absolute positioning needs a homed axis, and software limit switches act only once it is homed;
    #: False: both regardless of the homed state
    required: bool = True


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
    #: standstill monitoring after a positioning: the actual value must stay within this distance of the
    #: target once ``standstill_delay`` has passed since the setpoint reached it [length unit]; None: off
    standstill_window: float | None = None
    standstill_delay: float = 0.0       #: [s]


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
