"""PROFIdrive cyclic data for simulated drives and encoders, bit-exact on the wire.

Four layers, each usable on its own (only the standard library and numpy-compatible integers are needed):

* **Control and status words** (:class:`STW1`, :class:`ZSW1`, :class:`STW2`, :class:`ZSW2`,
  :class:`STW2_ENC`, :class:`ZSW2_ENC`, :class:`G1_STW`, :class:`G1_ZSW`): immutable 16-bit values whose
  bits are named like the members of the ``PD_TELx`` data types of S7-1200 Motion Control V7 (e.g.
  ``ZSW1.SwitchingOnInhibited``, ``G1_ZSW.EncoderFaultAcknowledgeActive``, ``G1_STW.RequestParkingEncoder``;
  S7-1200 catalogue §10.3).  Bits the speed-control profile leaves to the manufacturer are called
  ``Reserved_BitNN`` so that every bit of the word can still be addressed by name.
* **Standard telegrams** 1, 2, 3, 4 (drive) and 81, 83 (encoder): ``TelegramNOut`` (controller -> device)
  and ``TelegramNIn`` (device -> controller) with ``pack()``/``unpack()`` in PROFINET byte order
  (big-endian; setpoints and speeds in two's complement, position values unsigned).
* **Speed scaling** between 1/min and NSOLL/NIST (:func:`speed_to_nsoll`, :func:`nsoll_to_speed`).
* **Device models**: :class:`IncrementalEncoder` (Gx_XIST1/Gx_XIST2, reference mark search, absolute value,
  error, parking) and :class:`DriveStateMachine` (the S1..S5 state machine of the speed-control
  application class, OFF1/OFF2/OFF3, faults, sign of life).

Where the public sources leave a detail open, the choice made here is stated in the docstring of the
class that makes it.
"""
from __future__ import annotations

import enum
import math
import operator
import struct
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any, ClassVar, Literal, Self, SupportsIndex, TypeAlias

__all__ = [
    "ENCODER_ERROR_SENSOR_GROUP",
    "ENCODER_ERROR_ZERO_MARK",
    "FAULT_SIGN_OF_LIFE",
    "G1_STW",
    "G1_ZSW",
    "G2_STW",
    "G2_ZSW",
    "STW1",
    "STW2",
    "STW2_ENC",
    "TELEGRAMS",
    "ZSW1",
    "ZSW2",
    "ZSW2_ENC",
    "DriveState",
    "DriveStateMachine",
    "EncoderCommand",
    "IncrementalEncoder",
    "SignOfLifeMonitor",
    "Telegram1In",
    "Telegram1Out",
    "Telegram2In",
    "Telegram2Out",
    "Telegram3In",
    "Telegram3Out",
    "Telegram4In",
    "Telegram4Out",
    "Telegram81In",
    "Telegram81Out",
    "Telegram83In",
    "Telegram83Out",
    "Word16",
    "next_sign_of_life",
    "nsoll_to_speed",
    "speed_to_nsoll",
    "telegram_types",
    "xist1_difference",
]

_U32_MOD = 1 << 32


# --------------------------------------------------------------------------------------------------------
# 16-bit control and status words
# --------------------------------------------------------------------------------------------------------

def _bit_property(bit: int, doc: str) -> property:
    mask = 1 << bit

    def get(self: Word16) -> bool:
        return bool(self._value & mask)

    return property(get, doc=f"Bit {bit}: {doc}")


class Word16:
    """An immutable 16-bit word with named bits.

    Subclasses declare ``_BITS`` as ``(bit, name, meaning)`` triples; each name becomes a read-only
    bool property.  Build a word from an int, from keyword bits, or both (keywords override the int)::

        STW1(0x047E, On=True) == STW1(0x047F)

    ``int(word)`` gives the raw value; :meth:`with_bits` returns a modified copy.  Words compare equal
    only to words of the same type; compare with numbers through ``int(word)``.
    """

    __slots__ = ("_value",)
    _value: int
    _BITS: ClassVar[tuple[tuple[int, str, str], ...]] = ()
    _BIT_OF: ClassVar[dict[str, int]] = {}

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        cls._BIT_OF = {}
        for bit, name, doc in cls._BITS:
            if not 0 <= bit <= 15 or bit in cls._BIT_OF.values() or name in cls._BIT_OF:
                raise TypeError(f"{cls.__name__}: bit {bit} ({name}) invalid or assigned twice")
            cls._BIT_OF[name] = bit
            setattr(cls, name, _bit_property(bit, doc))

    def __init__(self, value: SupportsIndex | Word16 = 0, /, **bits: bool) -> None:
        if isinstance(value, Word16):
            if type(value) is not type(self):
                raise TypeError(f"cannot build {type(self).__name__} from {type(value).__name__}")
            raw = value._value
        else:
            if isinstance(value, bool):
                raise TypeError("a word is built from an int, not a bool")
            raw = operator.index(value)
            if not 0 <= raw <= 0xFFFF:
                raise ValueError(f"{type(self).__name__} value {raw} outside 0..0xFFFF")
        for name, on in bits.items():
            if name not in self._BIT_OF:
                raise TypeError(f"{type(self).__name__} has no bit named {name!r}")
            mask = 1 << self._BIT_OF[name]
            raw = raw | mask if on else raw & ~mask
        object.__setattr__(self, "_value", raw)

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is immutable; use with_bits()")

    def with_bits(self, **bits: bool) -> Self:
        """A copy with the given bits changed."""
        return type(self)(self._value, **bits)

    def bit(self, n: int) -> bool:
        """Raw access to bit ``n`` (0 = least significant)."""
        if not 0 <= n <= 15:
            raise ValueError("bit number must be 0..15")
        return bool(self._value >> n & 1)

    @classmethod
    def bit_positions(cls) -> dict[str, int]:
        """Name -> bit number of every single-bit property."""
        return dict(cls._BIT_OF)

    def set_bits(self) -> list[str]:
        """Names of the named bits that are 1, lowest bit first."""
        return [name for bit, name, _ in sorted(self._BITS) if self._value >> bit & 1]

    def __int__(self) -> int:
        return self._value

    def __index__(self) -> int:
        return self._value

    def __eq__(self, other: object) -> bool:
        if type(other) is type(self):
            return self._value == other._value
        return NotImplemented

    def __hash__(self) -> int:
        return hash((type(self).__name__, self._value))

    def __repr__(self) -> str:
        parts = self.set_bits()
        return f"{type(self).__name__}(0x{self._value:04X}: {'|'.join(parts) or '-'})"


def _reserved(*bits: int) -> tuple[tuple[int, str, str], ...]:
    return tuple((b, f"Reserved_Bit{b:02d}", "not used by the speed-control profile modelled here")
                 for b in bits)


class STW1(Word16):
    """Control word 1, controller -> drive (speed-control application class)."""

    _BITS = (
        (0, "On", "1 = switch on; a falling edge (0) is OFF1: brake on the ramp, then drop the pulses"),
        (1, "NoCoastStop", "1 = no OFF2; 0 = pulses off at once, the motor coasts"),
        (2, "NoQuickStop", "1 = no OFF3; 0 = brake on the quick-stop ramp, then inhibit switching on"),
        (3, "EnableOperation", "1 = pulses may be enabled; 0 = pulses off (coast)"),
        (4, "EnableRampGenerator", "1 = ramp-function generator works; 0 = its output is forced to zero"),
        (5, "UnfreezeRampGenerator", "1 = ramp-function generator follows; 0 = it holds its output"),
        (6, "EnableSetpoint", "1 = the speed setpoint feeds the ramp generator; 0 = its input is zero"),
        (7, "AcknowledgeFault", "a 0 -> 1 edge acknowledges faults whose cause has gone"),
        *_reserved(8, 9),
        (10, "ControlByPlc", "1 = the controller's process data are valid and to be used"),
        *_reserved(11, 12, 13, 14, 15),
    )
    On: bool
    NoCoastStop: bool
    NoQuickStop: bool
    EnableOperation: bool
    EnableRampGenerator: bool
    UnfreezeRampGenerator: bool
    EnableSetpoint: bool
    AcknowledgeFault: bool
    ControlByPlc: bool


class ZSW1(Word16):
    """Status word 1, drive -> controller (speed-control application class)."""

    _BITS = (
        (0, "ReadyToSwitchOn", "drive is in S2 or beyond: power section may be switched on"),
        (1, "ReadyToOperate", "drive is switched on (S3 or beyond), waiting for the operation enable"),
        (2, "OperationEnabled", "pulses are enabled and the drive follows (or brakes to) its setpoint"),
        (3, "FaultPresent", "at least one fault is pending; the drive has switched off"),
        (4, "NoCoastStopActive", "1 = no OFF2 is requested"),
        (5, "NoQuickStopActive", "1 = no OFF3 is requested or in progress"),
        (6, "SwitchingOnInhibited", "drive is in S1: ON must be reset before it can be switched on"),
        (7, "WarningPresent", "an alarm (warning) is pending; the drive keeps running"),
        (8, "SpeedErrorWithinTolerance", "actual speed is close to the ramp-generator output"),
        (9, "ControlRequested", "the drive accepts control by the controller's process data"),
        (10, "ComparisonValueReached", "the speed magnitude has reached the configured comparison value"),
        *_reserved(11, 12, 13, 14, 15),
    )
    ReadyToSwitchOn: bool
    ReadyToOperate: bool
    OperationEnabled: bool
    FaultPresent: bool
    NoCoastStopActive: bool
    NoQuickStopActive: bool
    SwitchingOnInhibited: bool
    WarningPresent: bool
    SpeedErrorWithinTolerance: bool
    ControlRequested: bool
    ComparisonValueReached: bool


class STW2(Word16):
    """Control word 2, controller -> drive (telegrams 2, 3, 4); carries the controller's life sign."""

    _BITS = (
        (0, "DriveDataSetSelectionBit0", "drive data set selection, bit 0"),
        (1, "DriveDataSetSelectionBit1", "drive data set selection, bit 1"),
        (2, "DriveDataSetSelectionBit2", "drive data set selection, bit 2"),
        (3, "DriveDataSetSelectionBit3", "drive data set selection, bit 3"),
        (4, "DriveDataSetSelectionBit4", "drive data set selection, bit 4"),
        *_reserved(5, 6),
        (7, "ParkingAxisSelection", "request to park the axis (evaluation of its encoders stops)"),
        (8, "TravelToFixedEndstop", "request the travel-to-fixed-stop function"),
        *_reserved(9, 10),
        (11, "MotorSwitchoverFinished", "the controller has finished a motor changeover"),
        (12, "MasterSignOfLifeBit0", "controller life sign, bit 0"),
        (13, "MasterSignOfLifeBit1", "controller life sign, bit 1"),
        (14, "MasterSignOfLifeBit2", "controller life sign, bit 2"),
        (15, "MasterSignOfLifeBit3", "controller life sign, bit 3"),
    )
    DriveDataSetSelectionBit0: bool
    DriveDataSetSelectionBit1: bool
    DriveDataSetSelectionBit2: bool
    DriveDataSetSelectionBit3: bool
    DriveDataSetSelectionBit4: bool
    ParkingAxisSelection: bool
    TravelToFixedEndstop: bool
    MotorSwitchoverFinished: bool
    MasterSignOfLifeBit0: bool
    MasterSignOfLifeBit1: bool
    MasterSignOfLifeBit2: bool
    MasterSignOfLifeBit3: bool

    @property
    def master_sign_of_life(self) -> int:
        """Controller life sign (bits 12..15): 0 = not started, then 1..15 cyclically."""
        return self._value >> 12

    @classmethod
    def with_sign_of_life(cls, value: int, base: SupportsIndex = 0) -> STW2:
        """``base`` with bits 12..15 replaced by ``value``."""
        if not 0 <= value <= 15:
            raise ValueError("life sign must be 0..15")
        return cls((operator.index(base) & 0x0FFF) | value << 12)


class ZSW2(Word16):
    """Status word 2, drive -> controller (telegrams 2, 3, 4); carries the drive's life sign."""

    _BITS = (
        (0, "DriveDataSetEffectiveBit0", "effective drive data set, bit 0"),
        (1, "DriveDataSetEffectiveBit1", "effective drive data set, bit 1"),
        (2, "DriveDataSetEffectiveBit2", "effective drive data set, bit 2"),
        (3, "DriveDataSetEffectiveBit3", "effective drive data set, bit 3"),
        (4, "DriveDataSetEffectiveBit4", "effective drive data set, bit 4"),
        (5, "AlarmClassBit0", "class of the pending alarm, bit 0"),
        (6, "AlarmClassBit1", "class of the pending alarm, bit 1"),
        (7, "ParkingAxisActive", "the axis is parked"),
        (8, "TravelToFixedEndStopActive", "travel to fixed stop is in progress"),
        *_reserved(9),
        (10, "PulsesEnabled", "the power section is switching (pulses enabled)"),
        (11, "MotorDataSetChangeoverActive", "a motor data set changeover is in progress"),
        (12, "SlaveSignOfLifeBit0", "drive life sign, bit 0"),
        (13, "SlaveSignOfLifeBit1", "drive life sign, bit 1"),
        (14, "SlaveSignOfLifeBit2", "drive life sign, bit 2"),
        (15, "SlaveSignOfLifeBit3", "drive life sign, bit 3"),
    )
    DriveDataSetEffectiveBit0: bool
    DriveDataSetEffectiveBit1: bool
    DriveDataSetEffectiveBit2: bool
    DriveDataSetEffectiveBit3: bool
    DriveDataSetEffectiveBit4: bool
    AlarmClassBit0: bool
    AlarmClassBit1: bool
    ParkingAxisActive: bool
    TravelToFixedEndStopActive: bool
    PulsesEnabled: bool
    MotorDataSetChangeoverActive: bool
    SlaveSignOfLifeBit0: bool
    SlaveSignOfLifeBit1: bool
    SlaveSignOfLifeBit2: bool
    SlaveSignOfLifeBit3: bool

    @property
    def slave_sign_of_life(self) -> int:
        """Drive life sign (bits 12..15)."""
        return self._value >> 12


class STW2_ENC(Word16):
    """Control word 2 of an encoder telegram (81, 83), controller -> encoder."""

    _BITS = (
        *_reserved(0, 1, 2, 3, 4, 5, 6),
        (7, "FaultAcknowledge", "a 0 -> 1 edge acknowledges encoder faults"),
        *_reserved(8, 9),
        (10, "ControlByPlc", "1 = the controller's process data are valid"),
        *_reserved(11),
        (12, "MasterSignOfLifeBit0", "controller life sign, bit 0"),
        (13, "MasterSignOfLifeBit1", "controller life sign, bit 1"),
        (14, "MasterSignOfLifeBit2", "controller life sign, bit 2"),
        (15, "MasterSignOfLifeBit3", "controller life sign, bit 3"),
    )
    FaultAcknowledge: bool
    ControlByPlc: bool
    MasterSignOfLifeBit0: bool
    MasterSignOfLifeBit1: bool
    MasterSignOfLifeBit2: bool
    MasterSignOfLifeBit3: bool

    @property
    def master_sign_of_life(self) -> int:
        """Controller life sign (bits 12..15)."""
        return self._value >> 12


class ZSW2_ENC(Word16):
    """Status word 2 of an encoder telegram (81, 83), encoder -> controller."""

    _BITS = (
        *_reserved(0, 1, 2),
        (3, "FaultPresent", "the encoder has a pending fault"),
        *_reserved(4, 5, 6),
        (7, "AlarmPresent", "the encoder has a pending alarm"),
        *_reserved(8),
        (9, "ControlRequested", "the encoder accepts the controller's process data"),
        *_reserved(10, 11),
        (12, "SlaveLifeSignBit0", "encoder life sign, bit 0"),
        (13, "SlaveLifeSignBit1", "encoder life sign, bit 1"),
        (14, "SlaveLifeSignBit2", "encoder life sign, bit 2"),
        (15, "SlaveLifeSignBit3", "encoder life sign, bit 3"),
    )
    FaultPresent: bool
    AlarmPresent: bool
    ControlRequested: bool
    SlaveLifeSignBit0: bool
    SlaveLifeSignBit1: bool
    SlaveLifeSignBit2: bool
    SlaveLifeSignBit3: bool

    @property
    def slave_sign_of_life(self) -> int:
        """Encoder life sign (bits 12..15)."""
        return self._value >> 12


class EncoderCommand(enum.IntEnum):
    """Command field of G1_STW (bits 4..6) for the function selected in bits 0..3."""

    NONE = 0
    ACTIVATE = 1
    READ_VALUE = 2
    ABORT = 3


class G1_STW(Word16):
    """Encoder control word (Gx_STW), controller -> encoder."""

    _BITS = (
        (0, "RequestFunction1", "select function 1 (reference mark 1 / probe 1 rising edge)"),
        (1, "RequestFunction2", "select function 2"),
        (2, "RequestFunction3", "select function 3"),
        (3, "RequestFunction4", "select function 4"),
        (4, "CommandBit0", "command for the selected function, bit 0 (1 = activate)"),
        (5, "CommandBit1", "command for the selected function, bit 1 (2 = read value)"),
        (6, "CommandBit2", "command for the selected function, bit 2 (3 = abort)"),
        (7, "FlyingMeasurement", "mode of the functions: 0 = reference mark search, 1 = flying measurement"),
        *_reserved(8, 9, 10),
        (11, "HomePositionMode", "0 = set the home position to the preset, 1 = shift it by the preset"),
        (12, "RequestSetShiftHomePosition", "a 0 -> 1 edge executes the set/shift of the home position"),
        (13, "RequestAbsoluteValueCyclically", "ask the encoder to put its absolute value into Gx_XIST2"),
        (14, "RequestParkingEncoder", "ask the encoder to park (stop evaluating, freeze its values)"),
        (15, "AcknowledgeEncoderError", "a 0 -> 1 edge acknowledges an encoder error"),
    )
    RequestFunction1: bool
    RequestFunction2: bool
    RequestFunction3: bool
    RequestFunction4: bool
    CommandBit0: bool
    CommandBit1: bool
    CommandBit2: bool
    FlyingMeasurement: bool
    HomePositionMode: bool
    RequestSetShiftHomePosition: bool
    RequestAbsoluteValueCyclically: bool
    RequestParkingEncoder: bool
    AcknowledgeEncoderError: bool

    @property
    def command(self) -> int:
        """The 3-bit command (bits 4..6), see :class:`EncoderCommand`."""
        return self._value >> 4 & 0x7

    @property
    def requested_functions(self) -> int:
        """Bits 0..3 as a number (bit 0 = function 1)."""
        return self._value & 0xF

    @classmethod
    def build(cls, *, functions: int = 0, command: int = EncoderCommand.NONE, **bits: bool) -> G1_STW:
        """Word with function mask (bits 0..3), command (bits 4..6) and any named bits."""
        if not 0 <= functions <= 0xF or not 0 <= command <= 7:
            raise ValueError("functions must be 0..15 and command 0..7")
        return cls(functions | int(command) << 4, **bits)


class G1_ZSW(Word16):
    """Encoder status word (Gx_ZSW), encoder -> controller."""

    _BITS = (
        (0, "Function1Active", "function 1 is running"),
        (1, "Function2Active", "function 2 is running"),
        (2, "Function3Active", "function 3 is running"),
        (3, "Function4Active", "function 4 is running"),
        (4, "Value1Available", "a measured value of function 1 is waiting to be read"),
        (5, "Value2Available", "a measured value of function 2 is waiting to be read"),
        (6, "Value3Available", "a measured value of function 3 is waiting to be read"),
        (7, "Value4Available", "a measured value of function 4 is waiting to be read"),
        (8, "Probe1Deflected", "level of the probe 1 input"),
        (9, "Probe2Deflected", "level of the probe 2 input"),
        *_reserved(10),
        (11, "EncoderFaultAcknowledgeActive", "the encoder is processing an error acknowledgement"),
        (12, "HomePositionSetShiftExecuted", "the requested set/shift of the home position was done"),
        (13, "TransmitAbsoluteValueCyclically", "Gx_XIST2 carries the absolute value every cycle"),
        (14, "ParkingEncoderActive", "the encoder is parked; its values are frozen"),
        (15, "EncoderError", "the encoder reports an error; Gx_XIST2 carries the error code"),
    )
    Function1Active: bool
    Function2Active: bool
    Function3Active: bool
    Function4Active: bool
    Value1Available: bool
    Value2Available: bool
    Value3Available: bool
    Value4Available: bool
    Probe1Deflected: bool
    Probe2Deflected: bool
    EncoderFaultAcknowledgeActive: bool
    HomePositionSetShiftExecuted: bool
    TransmitAbsoluteValueCyclically: bool
    ParkingEncoderActive: bool
    EncoderError: bool


#: The second encoder of telegram 4 uses the same word layouts as the first.
G2_STW = G1_STW
G2_ZSW = G1_ZSW


# --------------------------------------------------------------------------------------------------------
# Standard telegrams
# --------------------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class _Kind:
    fmt: str
    bits: int
    signed: bool
    word: type[Word16] | None = None

    def coerce(self, value: Any, name: str) -> Any:
        if self.word is not None:
            return value if type(value) is self.word else self.word(value)
        if isinstance(value, (bool, Word16)):
            raise TypeError(f"{name} must be an int")
        v = operator.index(value)
        lo, hi = ((-(1 << (self.bits - 1)), (1 << (self.bits - 1)) - 1) if self.signed
                  else (0, (1 << self.bits) - 1))
        if not lo <= v <= hi:
            raise ValueError(f"{name} = {v} outside {lo}..{hi}")
        return v


_I16 = _Kind("h", 16, True)
_I32 = _Kind("i", 32, True)
_U32 = _Kind("I", 32, False)


def _w(cls: type[Word16]) -> _Kind:
    return _Kind("H", 16, False, cls)


class _Telegram:
    """Shared pack/unpack machinery; subclasses are dataclasses whose fields follow ``_LAYOUT``."""

    TELEGRAM: ClassVar[int]
    _LAYOUT: ClassVar[tuple[tuple[str, _Kind], ...]]
    _STRUCT: ClassVar[struct.Struct]

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        cls._STRUCT = struct.Struct(">" + "".join(kind.fmt for _, kind in cls._LAYOUT))

    def __post_init__(self) -> None:
        self._normalise()

    def _normalise(self) -> None:
        # Ints given for word fields become word objects; integers are range-checked (the dataclass is
        # mutable, so pack() checks again).
        for name, kind in self._LAYOUT:
            object.__setattr__(self, name, kind.coerce(getattr(self, name), name))

    def pack(self) -> bytes:
        """The telegram as sent on PROFINET: big-endian, fields in standard order."""
        self._normalise()
        return self._STRUCT.pack(*(int(getattr(self, name)) for name, _ in self._LAYOUT))

    @classmethod
    def unpack(cls, data: bytes | bytearray | memoryview) -> Self:
        """Inverse of :meth:`pack`; ``data`` must have exactly :meth:`size` bytes."""
        if len(data) != cls._STRUCT.size:
            raise ValueError(f"telegram {cls.TELEGRAM} needs {cls._STRUCT.size} bytes, got {len(data)}")
        raw = cls._STRUCT.unpack(bytes(data))
        return cls(**{name: (kind.word(v) if kind.word else v)
                      for (name, kind), v in zip(cls._LAYOUT, raw)})

    @classmethod
    def fields(cls) -> tuple[tuple[str, int, bool], ...]:
        """``(name, size in bits, signed)`` for each field in transmission order."""
        return tuple((name, kind.bits, kind.signed) for name, kind in cls._LAYOUT)

    @classmethod
    def size(cls) -> int:
        """Length of the packed telegram in bytes."""
        return cls._STRUCT.size

    def values(self) -> Iterator[tuple[str, Any]]:
        """``(name, value)`` pairs in transmission order."""
        return ((name, getattr(self, name)) for name, _ in self._LAYOUT)


# Aliases so the field annotations below do not shadow the word classes inside the class bodies.
_STW1: TypeAlias = STW1
_ZSW1: TypeAlias = ZSW1
_STW2: TypeAlias = STW2
_ZSW2: TypeAlias = ZSW2
_STW2E: TypeAlias = STW2_ENC
_ZSW2E: TypeAlias = ZSW2_ENC
_GSTW: TypeAlias = G1_STW
_GZSW: TypeAlias = G1_ZSW


@dataclass
class Telegram1Out(_Telegram):
    """Standard telegram 1, controller -> drive: STW1, 16-bit speed setpoint."""

    TELEGRAM: ClassVar[int] = 1
    _LAYOUT = (("STW1", _w(STW1)), ("NSOLL_A", _I16))
    STW1: _STW1 = field(default_factory=_STW1)
    NSOLL_A: int = 0


@dataclass
class Telegram1In(_Telegram):
    """Standard telegram 1, drive -> controller: ZSW1, 16-bit actual speed."""

    TELEGRAM: ClassVar[int] = 1
    _LAYOUT = (("ZSW1", _w(ZSW1)), ("NIST_A", _I16))
    ZSW1: _ZSW1 = field(default_factory=_ZSW1)
    NIST_A: int = 0


@dataclass
class Telegram2Out(_Telegram):
    """Standard telegram 2, controller -> drive: STW1, 32-bit speed setpoint, STW2."""

    TELEGRAM: ClassVar[int] = 2
    _LAYOUT = (("STW1", _w(STW1)), ("NSOLL_B", _I32), ("STW2", _w(STW2)))
    STW1: _STW1 = field(default_factory=_STW1)
    NSOLL_B: int = 0
    STW2: _STW2 = field(default_factory=_STW2)


@dataclass
class Telegram2In(_Telegram):
    """Standard telegram 2, drive -> controller: ZSW1, 32-bit actual speed, ZSW2."""

    TELEGRAM: ClassVar[int] = 2
    _LAYOUT = (("ZSW1", _w(ZSW1)), ("NIST_B", _I32), ("ZSW2", _w(ZSW2)))
    ZSW1: _ZSW1 = field(default_factory=_ZSW1)
    NIST_B: int = 0
    ZSW2: _ZSW2 = field(default_factory=_ZSW2)


@dataclass
class Telegram3Out(_Telegram):
    """Standard telegram 3, controller -> drive: as telegram 2 plus the encoder 1 control word."""

    TELEGRAM: ClassVar[int] = 3
    _LAYOUT = (("STW1", _w(STW1)), ("NSOLL_B", _I32), ("STW2", _w(STW2)), ("G1_STW", _w(G1_STW)))
    STW1: _STW1 = field(default_factory=_STW1)
    NSOLL_B: int = 0
    STW2: _STW2 = field(default_factory=_STW2)
    G1_STW: _GSTW = field(default_factory=_GSTW)


@dataclass
class Telegram3In(_Telegram):
    """Standard telegram 3, drive -> controller: as telegram 2 plus status and values of encoder 1."""

    TELEGRAM: ClassVar[int] = 3
    _LAYOUT = (("ZSW1", _w(ZSW1)), ("NIST_B", _I32), ("ZSW2", _w(ZSW2)), ("G1_ZSW", _w(G1_ZSW)),
               ("G1_XIST1", _U32), ("G1_XIST2", _U32))
    ZSW1: _ZSW1 = field(default_factory=_ZSW1)
    NIST_B: int = 0
    ZSW2: _ZSW2 = field(default_factory=_ZSW2)
    G1_ZSW: _GZSW = field(default_factory=_GZSW)
    G1_XIST1: int = 0
    G1_XIST2: int = 0


@dataclass
class Telegram4Out(_Telegram):
    """Standard telegram 4, controller -> drive: as telegram 3 plus the encoder 2 control word."""

    TELEGRAM: ClassVar[int] = 4
    _LAYOUT = (("STW1", _w(STW1)), ("NSOLL_B", _I32), ("STW2", _w(STW2)), ("G1_STW", _w(G1_STW)),
               ("G2_STW", _w(G1_STW)))
    STW1: _STW1 = field(default_factory=_STW1)
    NSOLL_B: int = 0
    STW2: _STW2 = field(default_factory=_STW2)
    G1_STW: _GSTW = field(default_factory=_GSTW)
    G2_STW: _GSTW = field(default_factory=_GSTW)


@dataclass
class Telegram4In(_Telegram):
    """Standard telegram 4, drive -> controller: as telegram 3 plus status and values of encoder 2."""

    TELEGRAM: ClassVar[int] = 4
    _LAYOUT = (("ZSW1", _w(ZSW1)), ("NIST_B", _I32), ("ZSW2", _w(ZSW2)), ("G1_ZSW", _w(G1_ZSW)),
               ("G1_XIST1", _U32), ("G1_XIST2", _U32),
               ("G2_ZSW", _w(G1_ZSW)), ("G2_XIST1", _U32), ("G2_XIST2", _U32))
    ZSW1: _ZSW1 = field(default_factory=_ZSW1)
    NIST_B: int = 0
    ZSW2: _ZSW2 = field(default_factory=_ZSW2)
    G1_ZSW: _GZSW = field(default_factory=_GZSW)
    G1_XIST1: int = 0
    G1_XIST2: int = 0
    G2_ZSW: _GZSW = field(default_factory=_GZSW)
    G2_XIST1: int = 0
    G2_XIST2: int = 0


@dataclass
class Telegram81Out(_Telegram):
    """Standard telegram 81, controller -> encoder: STW2_ENC, G1_STW."""

    TELEGRAM: ClassVar[int] = 81
    _LAYOUT = (("STW2_ENC", _w(STW2_ENC)), ("G1_STW", _w(G1_STW)))
    STW2_ENC: _STW2E = field(default_factory=_STW2E)
    G1_STW: _GSTW = field(default_factory=_GSTW)


@dataclass
class Telegram81In(_Telegram):
    """Standard telegram 81, encoder -> controller: ZSW2_ENC, G1_ZSW, G1_XIST1, G1_XIST2."""

    TELEGRAM: ClassVar[int] = 81
    _LAYOUT = (("ZSW2_ENC", _w(ZSW2_ENC)), ("G1_ZSW", _w(G1_ZSW)), ("G1_XIST1", _U32), ("G1_XIST2", _U32))
    ZSW2_ENC: _ZSW2E = field(default_factory=_ZSW2E)
    G1_ZSW: _GZSW = field(default_factory=_GZSW)
    G1_XIST1: int = 0
    G1_XIST2: int = 0


@dataclass
class Telegram83Out(_Telegram):
    """Standard telegram 83, controller -> encoder: same words as telegram 81."""

    TELEGRAM: ClassVar[int] = 83
    _LAYOUT = (("STW2_ENC", _w(STW2_ENC)), ("G1_STW", _w(G1_STW)))
    STW2_ENC: _STW2E = field(default_factory=_STW2E)
    G1_STW: _GSTW = field(default_factory=_GSTW)


@dataclass
class Telegram83In(_Telegram):
    """Standard telegram 83, encoder -> controller: telegram 81 followed by a 32-bit speed (NIST_B)."""

    TELEGRAM: ClassVar[int] = 83
    _LAYOUT = (("ZSW2_ENC", _w(ZSW2_ENC)), ("G1_ZSW", _w(G1_ZSW)), ("G1_XIST1", _U32), ("G1_XIST2", _U32),
               ("NIST_B", _I32))
    ZSW2_ENC: _ZSW2E = field(default_factory=_ZSW2E)
    G1_ZSW: _GZSW = field(default_factory=_GZSW)
    G1_XIST1: int = 0
    G1_XIST2: int = 0
    NIST_B: int = 0


#: Telegram number -> (controller-to-device type, device-to-controller type).
TELEGRAMS: Mapping[int, tuple[type[_Telegram], type[_Telegram]]] = {
    1: (Telegram1Out, Telegram1In),
    2: (Telegram2Out, Telegram2In),
    3: (Telegram3Out, Telegram3In),
    4: (Telegram4Out, Telegram4In),
    81: (Telegram81Out, Telegram81In),
    83: (Telegram83Out, Telegram83In),
}


def telegram_types(number: int) -> tuple[type[_Telegram], type[_Telegram]]:
    """``(Out, In)`` classes of a standard telegram; ValueError for numbers not supported here."""
    try:
        return TELEGRAMS[number]
    except KeyError:
        raise ValueError(f"standard telegram {number} is not supported (have {sorted(TELEGRAMS)})") from None


# --------------------------------------------------------------------------------------------------------
# Speed scaling
# --------------------------------------------------------------------------------------------------------

def _check_bits(bits: int) -> None:
    if bits not in (16, 32):
        raise ValueError("speed words are 16 or 32 bits wide")


def speed_to_nsoll(rpm: float, reference_rpm: float, bits: int = 32) -> int:
    """Speed [1/min] -> NSOLL/NIST word value.

    100 % of ``reference_rpm`` is 0x4000 (16 bit) or 0x40000000 (32 bit), so the word spans -200 % up to
    just under +200 %.  Rounds to the nearest value (halves away from zero, so the scaling is symmetric)
    and saturates instead of wrapping.
    """
    _check_bits(bits)
    if not reference_rpm > 0 or math.isinf(reference_rpm):
        raise ValueError("reference speed must be positive and finite")
    if math.isnan(rpm):
        raise ValueError("speed is NaN")
    lo, hi = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    x = rpm / reference_rpm * (1 << (bits - 2))
    if x >= hi:
        return hi
    if x <= lo:
        return lo
    return int(math.copysign(math.floor(abs(x) + 0.5), x))


def nsoll_to_speed(value: int, reference_rpm: float, bits: int = 32) -> float:
    """NSOLL/NIST word value -> speed [1/min]; inverse of :func:`speed_to_nsoll`."""
    _check_bits(bits)
    if not reference_rpm > 0 or math.isinf(reference_rpm):
        raise ValueError("reference speed must be positive and finite")
    v = operator.index(value)
    if not -(1 << (bits - 1)) <= v < (1 << (bits - 1)):
        raise ValueError(f"{v} is not a {bits}-bit signed value")
    return v / (1 << (bits - 2)) * reference_rpm


# --------------------------------------------------------------------------------------------------------
# Sign of life
# --------------------------------------------------------------------------------------------------------

def next_sign_of_life(value: int) -> int:
    """The life sign after ``value``: 1, 2, ..., 15, 1, ... (0 only ever means 'not started')."""
    return 1 if value >= 15 else value + 1


class SignOfLifeMonitor:
    """Checks a partner's 4-bit life sign once per cycle.

    Monitoring starts with the first non-zero value.  From then on every value must be the successor of
    the previous one (:func:`next_sign_of_life`); a repeated, skipped or zero value is a failure.  The
    monitor trips when more than ``tolerance`` failures occur in a row; a correct value resets the run.
    Choice made here: consecutive failures are counted (the SINAMICS tolerance parameter counts them this
    way); the comparison always continues from the value last received, so one skipped value costs one
    failure, not a permanent mismatch.
    """

    def __init__(self, tolerance: int = 1) -> None:
        if tolerance < 0:
            raise ValueError("tolerance must be >= 0")
        self.tolerance = tolerance
        self.reset()

    def reset(self) -> None:
        """Forget the history; monitoring restarts with the next non-zero value."""
        self._last: int | None = None
        self.failures = 0
        self.tripped = False

    @property
    def started(self) -> bool:
        return self._last is not None

    def check(self, value: int) -> bool:
        """Evaluate this cycle's value; returns False once the tolerance has been exceeded."""
        if not 0 <= value <= 15:
            raise ValueError("life sign must be 0..15")
        if self._last is None:
            if value != 0:
                self._last = value
            return not self.tripped
        if value != 0 and value == next_sign_of_life(self._last):
            self.failures = 0
        else:
            self.failures += 1
            if self.failures > self.tolerance:
                self.tripped = True
        if value != 0:
            self._last = value
        return not self.tripped


# --------------------------------------------------------------------------------------------------------
# Encoder
# --------------------------------------------------------------------------------------------------------

#: Gx_XIST2 error codes used by :meth:`IncrementalEncoder.inject_error`.
ENCODER_ERROR_SENSOR_GROUP = 0x0001
ENCODER_ERROR_ZERO_MARK = 0x0002


def xist1_difference(prev: int, new: int) -> int:
    """Signed count difference ``new - prev`` of a free-running 32-bit counter (shortest way round)."""
    return (operator.index(new) - operator.index(prev) + (1 << 31)) % _U32_MOD - (1 << 31)


class _RefSearch(enum.Enum):
    IDLE = 0
    SEARCHING = 1
    LATCHED = 2


class IncrementalEncoder:
    """A rotary PROFIdrive encoder channel (the Gx_ part of telegrams 3, 4, 81, 83).

    Counts: Gx_XIST1 = floor(position * steps * 2**fine_resolution_xist1) modulo 2**32, a free-running
    counter.  With ``determinable_revolutions >= 1`` the encoder is absolute and Gx_XIST2 can carry
    floor(position * steps * 2**fine_resolution_xist2) modulo (determinable_revolutions * steps *
    2**fine_resolution_xist2) -- single-turn when ``determinable_revolutions == 1``.  0 means incremental
    (the TO's ``DeterminableRevolutions`` convention).  Positions are shaft revolutions (float).

    Per cycle call :meth:`update` with the shaft position and the received Gx_STW; then read
    :attr:`zsw`, :attr:`xist1`, :attr:`xist2`.  Modelled:

    * reference mark search (function 1, mode 0): activation -> ``Function1Active``; the first zero mark
      crossed after that (one per revolution at ``zero_mark_angle``) latches the XIST1 value of the exact
      crossing point, computed from the positions at the start and end of the cycle ->
      ``Value1Available``; the "read value" command puts the latched value into Gx_XIST2; "abort", or
      withdrawing every function request with command 0, returns to idle.  A held "activate" does not
      re-arm a latched search; the controller must withdraw the request first.  ``Function1Active`` stays
      set while a value is latched.  Functions 2..4 and flying measurement are not modelled (requests
      for them are not acknowledged).
    * cyclic absolute value (bit 13), absolute encoders only;
    * error injection: ``EncoderError`` and the error code in Gx_XIST2 until acknowledged by a rising
      edge of ``AcknowledgeEncoderError`` after the cause has gone; ``EncoderFaultAcknowledgeActive``
      mirrors the acknowledge bit while it is held;
    * parking: only ``ParkingEncoderActive`` is reported, XIST1/XIST2 stay frozen, a running reference
      mark search is dropped;
    * set/shift home position (bits 11/12) by ``home_preset`` revolutions, applied to both XIST1 and
      XIST2 (zero marks stay where they are on the shaft);
    * the probe inputs ``probe1``/``probe2`` (set by the caller) are mirrored in bits 8/9.

    Priority of Gx_XIST2: error code > latched value being read > cyclic absolute value > 0.
    """

    def __init__(self, steps_per_revolution: int = 2048, fine_resolution_xist1: int = 11,
                 fine_resolution_xist2: int = 9, determinable_revolutions: int = 0,
                 zero_mark_angle: float = 0.0, home_preset: float = 0.0) -> None:
        if not 1 <= steps_per_revolution <= 8388608:
            raise ValueError("steps per revolution must be 1..8388608")
        if not 0 <= fine_resolution_xist1 <= 31 or not 0 <= fine_resolution_xist2 <= 31:
            raise ValueError("fine resolution must be 0..31 bits")
        if not 0 <= determinable_revolutions <= 8388608:
            raise ValueError("determinable revolutions must be 0..8388608")
        self.steps_per_revolution = steps_per_revolution
        self.fine_resolution_xist1 = fine_resolution_xist1
        self.fine_resolution_xist2 = fine_resolution_xist2
        self.determinable_revolutions = determinable_revolutions
        self.xist1_per_revolution = steps_per_revolution << fine_resolution_xist1
        self.xist2_per_revolution = steps_per_revolution << fine_resolution_xist2
        self.absolute_range = determinable_revolutions * self.xist2_per_revolution
        if self.absolute_range > _U32_MOD:
            raise ValueError("absolute value does not fit into 32 bits")
        self.zero_mark_angle = zero_mark_angle % 1.0
        self.home_preset = home_preset
        self.offset = 0.0           # revolutions added by set/shift home position
        self.probe1 = False
        self.probe2 = False
        self._prev_pos: float | None = None
        self._prev_stw = G1_STW()
        self._search = _RefSearch.IDLE
        self._latched: int | None = None
        self._reading = False
        self._home_done = False
        self._error = 0
        self._error_cause = False
        self._parked = False
        self._abs_cyclic = False
        self.xist1 = 0
        self.xist2 = 0
        self.zsw = G1_ZSW()

    # -- conversions -------------------------------------------------------------------------------------

    @property
    def absolute(self) -> bool:
        return self.determinable_revolutions >= 1

    def count_at(self, position: float) -> int:
        """Gx_XIST1 for a shaft position [rev] (home offset included)."""
        return math.floor((position + self.offset) * self.xist1_per_revolution) % _U32_MOD

    def absolute_value_at(self, position: float) -> int:
        """Gx_XIST2 absolute value for a shaft position [rev]; ValueError for an incremental encoder."""
        if not self.absolute:
            raise ValueError("an incremental encoder has no absolute value")
        return math.floor((position + self.offset) * self.xist2_per_revolution) % self.absolute_range

    def counts_to_revolutions_delta(self, prev: int, new: int) -> float:
        """Shaft travel [rev] between two Gx_XIST1 readings, across the 32-bit wrap-around."""
        return xist1_difference(prev, new) / self.xist1_per_revolution

    def zero_mark_crossing(self, start: float, end: float) -> float | None:
        """First zero mark passed when moving from ``start`` to ``end`` [rev], or None.

        The interval is half-open at ``start`` so a mark lying exactly there belongs to the previous cycle.
        """
        a = self.zero_mark_angle
        if end > start:
            z = math.floor(start - a) + 1 + a
            return z if z <= end else None
        if end < start:
            z = math.ceil(start - a) - 1 + a
            return z if z >= end else None
        return None

    # -- fault injection -------------------------------------------------------------------------------

    def inject_error(self, code: int = ENCODER_ERROR_SENSOR_GROUP, *, cause_active: bool = False) -> None:
        """Report an encoder error (code shown in Gx_XIST2).  With ``cause_active`` the error cannot be
        acknowledged until :meth:`clear_error_cause` is called."""
        if not 1 <= code <= 0xFFFFFFFF:
            raise ValueError("error code must be a non-zero 32-bit value")
        self._error = code
        self._error_cause = cause_active

    def clear_error_cause(self) -> None:
        """The condition behind the error has gone; the next acknowledgement clears it."""
        self._error_cause = False

    @property
    def error_code(self) -> int:
        """Pending error code, 0 if none."""
        return self._error

    @property
    def parked(self) -> bool:
        """The encoder is parked (values frozen)."""
        return self._parked

    @property
    def latched_value(self) -> int | None:
        """XIST1 value latched at the reference mark, if any."""
        return self._latched

    # -- cycle -------------------------------------------------------------------------------------------

    def update(self, position: float, g1_stw: G1_STW | int = 0) -> None:
        """One cycle: apply ``g1_stw`` (in force while the shaft moved to ``position``), then produce the
        status word and actual values."""
        stw = g1_stw if isinstance(g1_stw, G1_STW) else G1_STW(g1_stw)
        prev_stw, self._prev_stw = self._prev_stw, stw
        start, self._prev_pos = self._prev_pos, position

        if stw.AcknowledgeEncoderError and not prev_stw.AcknowledgeEncoderError and not self._error_cause:
            self._error = 0

        self._parked = stw.RequestParkingEncoder
        if self._parked:
            self._search, self._latched, self._reading = _RefSearch.IDLE, None, False
            self._home_done = False
            self.zsw = G1_ZSW(ParkingEncoderActive=True)
            return                  # XIST1/XIST2 keep their last values

        if stw.RequestSetShiftHomePosition and not prev_stw.RequestSetShiftHomePosition:
            if stw.HomePositionMode:
                self.offset += self.home_preset
            else:
                self.offset = self.home_preset - position
            self._home_done = True
        elif not stw.RequestSetShiftHomePosition:
            self._home_done = False

        self._reference_mark(stw, start, position)
        self._abs_cyclic = stw.RequestAbsoluteValueCyclically and self.absolute

        self.xist1 = self.count_at(position)
        if self._error:
            self.xist2 = self._error & 0xFFFFFFFF
        elif self._reading and self._latched is not None:
            self.xist2 = self._latched
        elif self._abs_cyclic:
            self.xist2 = self.absolute_value_at(position)
        else:
            self.xist2 = 0
        self.zsw = G1_ZSW(
            Function1Active=self._search is not _RefSearch.IDLE,
            Value1Available=self._search is _RefSearch.LATCHED,
            Probe1Deflected=self.probe1,
            Probe2Deflected=self.probe2,
            EncoderFaultAcknowledgeActive=stw.AcknowledgeEncoderError,
            HomePositionSetShiftExecuted=self._home_done,
            TransmitAbsoluteValueCyclically=self._abs_cyclic and not self._error,
            EncoderError=bool(self._error),
        )

    def _reference_mark(self, stw: G1_STW, start: float | None, end: float) -> None:
        cmd = stw.command
        if cmd == EncoderCommand.ABORT or (stw.requested_functions == 0 and cmd == EncoderCommand.NONE):
            self._search, self._latched, self._reading = _RefSearch.IDLE, None, False
            return
        if not stw.RequestFunction1:
            return
        if (cmd == EncoderCommand.ACTIVATE and not stw.FlyingMeasurement
                and self._search is _RefSearch.IDLE):
            self._search = _RefSearch.SEARCHING
        self._reading = cmd == EncoderCommand.READ_VALUE and self._search is _RefSearch.LATCHED
        if self._search is _RefSearch.SEARCHING and start is not None:
            z = self.zero_mark_crossing(start, end)
            if z is not None:
                self._latched = self.count_at(z)
                self._search = _RefSearch.LATCHED


# --------------------------------------------------------------------------------------------------------
# Drive state machine
# --------------------------------------------------------------------------------------------------------

#: Fault number used for a sign-of-life failure (the SINAMICS number of this fault is F01912).
FAULT_SIGN_OF_LIFE = 1912


class DriveState(enum.IntEnum):
    """Main states of the PROFIdrive drive state machine."""

    S1 = 1   #: switching on inhibited (also while a fault is pending)
    S2 = 2   #: ready for switching on
    S3 = 3   #: switched on, pulses still off
    S4 = 4   #: operation: pulses on, setpoints are followed
    S5 = 5   #: switching off: braking on the OFF1 or OFF3 ramp


def _approach(value: float, target: float, rate: float, dt: float) -> float:
    """Move ``value`` towards ``target`` by at most ``rate * dt`` (an infinite rate jumps, even for dt = 0)."""
    max_step = math.inf if math.isinf(rate) else rate * dt
    if abs(target - value) <= max_step:
        return target
    return value + math.copysign(max_step, target - value)


class DriveStateMachine:
    """The switching-on/off logic of a speed-controlled PROFIdrive drive plus its ramp-function generator.

    Per cycle: :meth:`write` the received STW1 (and STW2), :meth:`step` the time, ask
    :meth:`effective_setpoint` what the speed controller gets, and send :attr:`zsw1`/:attr:`zsw2` back.

    Transitions, highest priority first: pending fault -> S1 (pulses off); OFF2 -> S1 (coast);
    S1 -> S2 needs ON = 0 with neither OFF2 nor OFF3; OFF3 in S2/S3 -> S1, in S4 or during OFF1 ->
    S5 with the quick-stop ramp, which always runs to standstill and ends in S1; S2 -> S3 on ON;
    S3 -> S4 on enable operation (S3 -> S2 on ON = 0); in S4 ON = 0 starts the OFF1 ramp (S5, ends in
    S2) and removing enable operation drops the pulses (S3).

    Choices where the profile leaves room: standstill is "ramp-generator output is zero"; an OFF1 ramp
    is finished even if ON returns (the drive then passes S2 -> S3 -> S4 again); removing enable
    operation during a ramp drops the pulses (S2 after OFF1, S1 after OFF3); during S5 the ZSW1 bits
    0..2 stay set because the pulses are still on.  A fault lands in S1 with ``FaultPresent``; a rising
    edge of ``AcknowledgeFault`` clears every fault whose cause is gone, after which ON must be 0 again
    to reach S2.

    Ramp times are the time to go between 0 and ``reference_rpm``: ``off1_ramp_time`` and
    ``off3_ramp_time`` for OFF1/OFF3, ``ramp_time`` for the generator in S4 (0 = generator bypassed,
    the usual setting under a position controller).  With ``ramp_time > 0`` the generator moves
    towards the setpoint given in the previous call of :meth:`effective_setpoint`.

    Process data are taken over only when ``STW1.ControlByPlc`` is set and the drive has not been
    switched to local control (:meth:`request_local_control`); otherwise the last accepted STW1 and
    setpoint stay in force.  The controller's life sign in STW2 is monitored by a
    :class:`SignOfLifeMonitor` (starting with its first non-zero value; a cycle without :meth:`write`
    repeats the old value and so counts as a failure); exceeding the tolerance raises
    :data:`FAULT_SIGN_OF_LIFE`.  The drive's own life sign in ZSW2 advances on every :meth:`step`.
    """

    def __init__(self, reference_rpm: float = 3000.0, *, off1_ramp_time: float = 1.0,
                 off3_ramp_time: float = 0.1, ramp_time: float = 0.0, sign_of_life_tolerance: int = 1,
                 speed_tolerance_rpm: float = 30.0, comparison_rpm: float | None = None) -> None:
        if not reference_rpm > 0:
            raise ValueError("reference speed must be positive")
        if min(off1_ramp_time, off3_ramp_time, ramp_time) < 0:
            raise ValueError("ramp times must be >= 0")
        self.reference_rpm = reference_rpm
        self.off1_ramp_time = off1_ramp_time
        self.off3_ramp_time = off3_ramp_time
        self.ramp_time = ramp_time
        self.speed_tolerance_rpm = speed_tolerance_rpm
        self.comparison_rpm = reference_rpm if comparison_rpm is None else comparison_rpm
        self.sign_of_life = SignOfLifeMonitor(sign_of_life_tolerance)
        self.warning = False
        self._state = DriveState.S1
        self._stop: Literal["OFF1", "OFF3"] | None = None
        self._stw1 = STW1()             # last accepted control word
        self._pzd_valid = False         # the latest write() was accepted
        self._prev_ack = False
        self._stw2: STW2 | None = None
        self._faults: dict[int, bool] = {}   # code -> cause still active
        self._local = False
        self._rfg = 0.0                 # ramp-function generator output [1/min]
        self._input = 0.0               # setpoint last handed to effective_setpoint
        self._slave_life = 0
        self._actual: float | None = None

    # -- inputs --------------------------------------------------------------------------------------------

    def write(self, stw1: STW1 | int, stw2: STW2 | int | None = None) -> None:
        """Receive this cycle's control words (STW2 only with telegrams 2, 3, 4)."""
        word = stw1 if isinstance(stw1, STW1) else STW1(stw1)
        if stw2 is not None:
            self._stw2 = stw2 if isinstance(stw2, STW2) else STW2(stw2)
        self._pzd_valid = word.ControlByPlc and not self._local
        if self._pzd_valid:
            self._stw1 = word

    def inject_fault(self, code: int, *, cause_active: bool = False) -> None:
        """Raise a fault: pulses off at once.  With ``cause_active`` it survives acknowledgement until
        :meth:`clear_fault_cause` is called."""
        self._faults[code] = self._faults.get(code, False) or cause_active
        self._pulses_off(DriveState.S1)

    def clear_fault_cause(self, code: int | None = None) -> None:
        """The cause of fault ``code`` (default: all faults) has gone."""
        for c in self._faults:
            if code is None or c == code:
                self._faults[c] = False

    def request_local_control(self) -> None:
        """Another master (e.g. a commissioning tool) takes control: ``ControlRequested`` drops and the
        controller's process data are ignored."""
        self._local = True

    def release_local_control(self) -> None:
        self._local = False

    # -- outputs -------------------------------------------------------------------------------------------

    @property
    def state(self) -> DriveState:
        return self._state

    @property
    def switching_off(self) -> Literal["OFF1", "OFF3"] | None:
        """Which ramp is running in S5, else None."""
        return self._stop if self._state is DriveState.S5 else None

    @property
    def ready_for_setpoints(self) -> bool:
        """True in S4: the speed setpoint reaches the speed controller."""
        return self._state is DriveState.S4

    @property
    def fault_present(self) -> bool:
        return bool(self._faults)

    @property
    def faults(self) -> tuple[int, ...]:
        """Codes of the pending faults, oldest first."""
        return tuple(self._faults)

    @property
    def control_requested(self) -> bool:
        return not self._local

    @property
    def speed_output(self) -> float:
        """Current ramp-function generator output [1/min] (0 whenever the pulses are off)."""
        return self._rfg

    def effective_setpoint(self, nsoll_rpm: float) -> float:
        """Speed setpoint [1/min] the speed controller gets for the controller's setpoint ``nsoll_rpm``."""
        if self._pzd_valid and not self._local:
            self._input = nsoll_rpm       # otherwise the last accepted setpoint stays in force
        s = self._stw1
        if (self._state is DriveState.S4 and s.EnableRampGenerator and s.UnfreezeRampGenerator
                and s.EnableSetpoint and self.ramp_time == 0.0):
            self._rfg = self._input
        elif self._state is DriveState.S4 and not s.EnableRampGenerator:
            self._rfg = 0.0
        return self._rfg if self._state in (DriveState.S4, DriveState.S5) else 0.0

    @property
    def zsw1(self) -> ZSW1:
        st, s = self._state, self._stw1
        actual = self._rfg if self._actual is None else self._actual
        pulses = st in (DriveState.S4, DriveState.S5)
        return ZSW1(
            ReadyToSwitchOn=st >= DriveState.S2,
            ReadyToOperate=st >= DriveState.S3,
            OperationEnabled=pulses,
            FaultPresent=self.fault_present,
            NoCoastStopActive=s.NoCoastStop,
            NoQuickStopActive=s.NoQuickStop and self.switching_off != "OFF3",
            SwitchingOnInhibited=st is DriveState.S1,
            WarningPresent=self.warning or self.sign_of_life.failures > 0,
            SpeedErrorWithinTolerance=abs(self._rfg - actual) <= self.speed_tolerance_rpm,
            ControlRequested=not self._local,
            ComparisonValueReached=abs(actual) >= self.comparison_rpm,
        )

    @property
    def zsw2(self) -> ZSW2:
        return ZSW2(self._slave_life << 12, PulsesEnabled=self._state in (DriveState.S4, DriveState.S5))

    # -- time ----------------------------------------------------------------------------------------------

    def step(self, dt: float, actual_rpm: float | None = None) -> None:
        """Advance by ``dt`` seconds.  ``actual_rpm`` (measured speed) only feeds ZSW1 bits 8 and 10;
        without it the drive is taken to follow its ramp generator exactly."""
        if dt < 0:
            raise ValueError("dt must be >= 0")
        self._actual = actual_rpm
        self._slave_life = next_sign_of_life(self._slave_life)
        if (self._stw2 is not None and not self._faults
                and not self.sign_of_life.check(self._stw2.master_sign_of_life)):
            self.inject_fault(FAULT_SIGN_OF_LIFE)
            self.sign_of_life.reset()

        s = self._stw1
        ack = s.AcknowledgeFault
        if ack and not self._prev_ack:
            self._faults = {c: active for c, active in self._faults.items() if active}
        self._prev_ack = ack

        self._transition(s)
        self._ramp(s, dt)

    def _pulses_off(self, state: DriveState) -> None:
        self._state, self._stop, self._rfg = state, None, 0.0

    def _transition(self, s: STW1) -> None:
        st = self._state
        if self._faults or not s.NoCoastStop:
            self._pulses_off(DriveState.S1)
        elif st is DriveState.S1:
            if not s.On and s.NoQuickStop:
                self._state = DriveState.S2
        elif st is DriveState.S5:
            if not s.EnableOperation:
                self._pulses_off(DriveState.S1 if self._stop == "OFF3" else DriveState.S2)
            elif not s.NoQuickStop:
                self._stop = "OFF3"
        elif not s.NoQuickStop:
            if st is DriveState.S4:
                self._state, self._stop = DriveState.S5, "OFF3"
            else:
                self._pulses_off(DriveState.S1)
        elif st is DriveState.S2:
            if s.On:
                self._state = DriveState.S3
        elif st is DriveState.S3:
            if not s.On:
                self._state = DriveState.S2
            elif s.EnableOperation:
                self._state = DriveState.S4
        elif st is DriveState.S4:
            if not s.On:
                self._state, self._stop = DriveState.S5, "OFF1"
            elif not s.EnableOperation:
                self._pulses_off(DriveState.S3)

    def _rate(self, ramp_time: float) -> float:
        return math.inf if ramp_time == 0.0 else self.reference_rpm / ramp_time

    def _ramp(self, s: STW1, dt: float) -> None:
        if self._state is DriveState.S5:
            rate = self._rate(self.off3_ramp_time if self._stop == "OFF3" else self.off1_ramp_time)
            self._rfg = _approach(self._rfg, 0.0, rate, dt)
            if self._rfg == 0.0:
                self._pulses_off(DriveState.S1 if self._stop == "OFF3" else DriveState.S2)
        elif self._state is DriveState.S4:
            if not s.EnableRampGenerator:
                self._rfg = 0.0
            elif s.UnfreezeRampGenerator:
                target = self._input if s.EnableSetpoint else 0.0
                self._rfg = _approach(self._rfg, target, self._rate(self.ramp_time), dt)
        else:
            self._rfg = 0.0
