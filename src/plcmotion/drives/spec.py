"""What a drive is, in the words of motion control: the neutral specification every drive model takes.

A :class:`DriveSpec` describes one axis's actuator (how it is commanded and how fast it may turn), the
mechanics between motor and load, the encoder (:class:`EncoderSpec`) and, for a simulated drive, the
machine around it (:class:`PlantSpec`).  Lengths are in the axis's length unit ("length unit", e.g. mm
or degree), speeds of the motor in revolutions per minute, times in seconds.

The specs are frozen values built once when the axis is created (and again when the axis configuration
changes at run time): drive models read them at creation or on change, never per servo cycle.  Who
builds them is the family's business; the builders are ``s7_1200.technology.builder.drive_spec`` and ``s7_1500.technology.builder.drive_spec``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from enum import Enum

from .hydraulic_spec import CylinderSpec, HydraulicSpec
from .spec_errors import DriveSpecError, finite


class ActuatorKind(str, Enum):
    """How the actuator is commanded.  (A ``str`` enum: the value names the drive group.)"""

    #: a drive that closes its own speed loop; the controller closes the position loop and sends a speed
    #: setpoint (PROFIdrive telegram, analog +-10 V, CiA 402 cyclic synchronous velocity)
    SPEED_SERVO = "servo"
    #: a stepper on a pulse output: open loop, the actual position is the number of pulses sent
    PULSE = "stepper"
    #: no drive: the actual value is the setpoint (simulated or virtual axis)
    IDEAL = "ideal"
    #: a proportional valve on a +-10 V output moving a cylinder (``DriveSpec.hydraulic``,
    #: ``PlantSpec.cylinder``); the controller closes the position loop as for a speed servo
    HYDRAULIC = "hydraulic"


class SetpointInterface(str, Enum):
    """How the setpoint travels to the drive (it decides how the speed setpoint is quantised)."""

    #: PROFIdrive standard telegram: 16#4000 (16 bit) or 16#40000000 (32 bit) = 100 % of the reference speed
    PROFIDRIVE = "profidrive"
    #: analog output: 27648 = 10 V = 100 % of the reference speed
    ANALOG = "analog"
    #: pulse train (direction and pulses)
    PULSES = "pulses"
    #: no physical setpoint (ideal drive)
    NONE = "none"


class EncoderKind(str, Enum):
    INCREMENTAL = "incremental"          #: counts from where it was switched on; needs homing
    ABSOLUTE = "absolute"                #: knows its position over ``determinable_revolutions``
    CYCLIC_ABSOLUTE = "cyclic_absolute"  #: absolute within its range, the range repeats


class EncoderInterface(str, Enum):
    """Where the encoder's actual value comes from (decides e.g. whether it has zero marks on the bus)."""

    DRIVE_TELEGRAM = "drive_telegram"    #: the encoder of the drive, in the drive's telegram
    PROFIDRIVE = "profidrive"            #: an encoder with its own PROFIdrive telegram
    TECHNOLOGY_MODULE = "technology_module"
    HIGH_SPEED_COUNTER = "high_speed_counter"


@dataclass(frozen=True)
class EncoderSpec:
    """The position measuring system.

    A rotary encoder has ``steps_per_revolution`` marks per turn and turns once per
    ``distance_per_revolution`` of load travel; a linear encoder has a mark every ``step_length``.  The
    cyclic actual value resolves each step into ``2 ** fine_bits`` counts (PROFIdrive Gx_XIST1, fine
    resolution), the absolute value into ``2 ** fine_bits_absolute`` (Gx_XIST2).  The actual position
    therefore moves in whole :attr:`increment` steps.
    """

    kind: EncoderKind = EncoderKind.INCREMENTAL
    rotary: bool = True
    steps_per_revolution: int = 2048     #: marks per encoder revolution (rotary)
    fine_bits: int = 11                  #: fine resolution of the cyclic actual value [bit]
    fine_bits_absolute: int = 9          #: fine resolution of the absolute value [bit]
    #: load travel per encoder revolution [length unit]; also the length over which an absolute value
    #: counts one revolution and, by default, the distance between zero marks
    distance_per_revolution: float = 10.0
    step_length: float = 0.001           #: linear encoder: distance between two marks [length unit]
    #: revolutions an absolute encoder tells apart (0: incremental, it tells none)
    determinable_revolutions: int = 0
    #: the encoder counts against the axis's positive direction.  Values at the drive interface are always
    #: in axis coordinates: a drive adapter corrects the sign on its side (the simulated machine is wired
    #: consistently, so the inversion cancels and nothing is observable: decision 53)
    inverse_direction: bool = False
    interface: EncoderInterface = EncoderInterface.DRIVE_TELEGRAM

    @property
    def absolute(self) -> bool:
        return self.kind is not EncoderKind.INCREMENTAL

    @property
    def increment(self) -> float:
        """Length of one count of the cyclic actual value [length unit] (S7-1200 V6 §5.4.3.3, §12.9.6.3)."""
        fine = 2 ** self.fine_bits
        if self.rotary:
            return self.distance_per_revolution / (self.steps_per_revolution * fine)
        return self.step_length / fine


@dataclass(frozen=True)
class SwitchSpec:
    """A switch of the simulated machine, actuated while the load is in [low, high] (machine coordinates),
    repeating every ``period`` if given, wired to input ``address``."""

    address: str
    low: float = -math.inf
    high: float = math.inf
    active_high: bool = True             #: FALSE: an NC contact, the input is FALSE while actuated
    name: str = "switch"
    period: float | None = None


@dataclass(frozen=True)
class PlantSpec:
    """The simulated machine behind a drive (no meaning for a real drive)."""

    initial_position: float = 0.0        #: load position at controller start [length unit]
    #: time constant of the drive's closed speed loop, modelled as a first-order lag [s] (0: ideal)
    speed_time_constant: float = 0.002
    #: distance between the encoder's zero marks [length unit]; None: one per encoder revolution
    #: (a linear encoder has a single one)
    zero_mark_distance: float | None = None
    zero_mark_offset: float = 0.0        #: machine position of one zero mark [length unit]
    switches: tuple[SwitchSpec, ...] = ()    #: limit and homing switches the load actuates
    ready_input: str = ""                #: input wired to the drive's "ready" signal ("" for none)
    #: fixed end stops: machine positions [length unit] the load cannot pass (None: none on that side);
    #: a drive pushing against one stands there with its torque (force) at the limit
    end_stop_min: float | None = None
    end_stop_max: float | None = None
    #: moment of inertia of motor and load at the motor shaft [kg m²]: the torque of a speed servo is
    #: inertia times angular acceleration
    inertia: float = 1.0e-3
    #: the cylinder of a hydraulic drive (None: ``CylinderSpec()``)
    cylinder: CylinderSpec | None = None

    def __post_init__(self) -> None:
        lo, hi = self.travel()
        if not lo < hi:
            raise DriveSpecError("PlantSpec.end_stop_min/end_stop_max", (self.end_stop_min, self.end_stop_max),
                                 "the load needs room between its end stops (and inside the cylinder's stroke)")
        if not lo <= self.initial_position <= hi:
            raise DriveSpecError("PlantSpec.initial_position", self.initial_position,
                                 f"must lie between the end stops [{lo:g}, {hi:g}]")
        if finite("PlantSpec.inertia", self.inertia) <= 0.0:
            raise DriveSpecError("PlantSpec.inertia", self.inertia, "must be > 0 kg m²")
        if self.cylinder is not None and not isinstance(self.cylinder, CylinderSpec):
            raise DriveSpecError("PlantSpec.cylinder", self.cylinder, "must be a CylinderSpec or None")

    def travel(self, hydraulic: bool = False) -> tuple[float, float]:
        """[low, high]: where the load can be - between the end stops (and, for a hydraulic drive, inside
        the cylinder's stroke)."""
        lo = -math.inf if self.end_stop_min is None else finite("PlantSpec.end_stop_min", self.end_stop_min)
        hi = math.inf if self.end_stop_max is None else finite("PlantSpec.end_stop_max", self.end_stop_max)
        cyl = self.cylinder
        if cyl is not None or hydraulic:
            cyl = cyl or CylinderSpec()
            lo, hi = max(lo, cyl.stroke_min), min(hi, cyl.stroke_max)
        return lo, hi


@dataclass(frozen=True)
class DriveSpec:
    """One axis's drive: actuator, interface, speed range, mechanics, timing, encoder and plant."""

    actuator: ActuatorKind = ActuatorKind.SPEED_SERVO
    interface: SetpointInterface = SetpointInterface.PROFIDRIVE
    telegram: int = 3                    #: PROFIdrive standard telegram (1, 2, 3, 4) of a PROFIdrive drive
    reference_speed: float = 3000.0      #: motor speed of a 100 % speed setpoint [1/min]
    max_speed: float = 3000.0            #: the drive limits the motor speed to this [1/min]
    length_per_revolution: float = 10.0  #: load travel per motor revolution (lead screw, gear) [length unit]
    pulses_per_revolution: int = 1000    #: pulse drive: pulses per motor revolution
    ready_delay: float = 0.0             #: from enable until the drive reports "ready" [s]
    #: the drive ramps from ``max_speed`` to standstill in this time when its enable is removed or when it
    #: faults (the power section stops following the setpoint) [s]; 0: at once
    off_ramp_time: float = 0.1
    fault_code: int = 7900               #: fault number the drive reports for a fault of its own
    encoder: EncoderSpec = field(default_factory=EncoderSpec)
    plant: PlantSpec = field(default_factory=PlantSpec)
    #: the highest torque the drive gives [N m] (None: no limit modelled); a torque limit set at run time
    #: (``DriveChannel.set_torque_limit``) can only lower it
    max_torque: float | None = None
    #: the valve output of a hydraulic drive (None: ``HydraulicSpec()``)
    hydraulic: HydraulicSpec | None = None

    def __post_init__(self) -> None:
        if self.max_torque is not None and finite("DriveSpec.max_torque", self.max_torque) <= 0.0:
            raise DriveSpecError("DriveSpec.max_torque", self.max_torque, "must be > 0 N m (or None)")
        if self.hydraulic is not None and not isinstance(self.hydraulic, HydraulicSpec):
            raise DriveSpecError("DriveSpec.hydraulic", self.hydraulic, "must be a HydraulicSpec or None")
        if self.actuator is ActuatorKind.HYDRAULIC:
            if self.interface not in (SetpointInterface.ANALOG, SetpointInterface.PROFIDRIVE):
                raise DriveSpecError("DriveSpec.interface", self.interface,
                                     "a hydraulic drive takes a +-10 V output: SetpointInterface.ANALOG (an "
                                     "analog output module) or SetpointInterface.PROFIDRIVE (IM 174/ADI4)")
            lo, hi = self.plant.travel(hydraulic=True)
            if not lo < hi or not lo <= self.plant.initial_position <= hi:
                raise DriveSpecError("PlantSpec.initial_position", self.plant.initial_position,
                                     f"must lie inside the cylinder's stroke and end stops [{lo:g}, {hi:g}]")

    @property
    def max_velocity(self) -> float:
        """Load velocity at ``max_speed`` [length unit/s]."""
        return self.max_speed / 60.0 * self.length_per_revolution

    @property
    def pulse_length(self) -> float:
        """Load travel of one pulse of a pulse drive [length unit]."""
        return self.length_per_revolution / self.pulses_per_revolution
