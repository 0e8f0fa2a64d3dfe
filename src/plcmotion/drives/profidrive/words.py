"""PROFIdrive control and status words: immutable 16-bit values with named bits.

:class:`STW1`, :class:`ZSW1`, :class:`STW2`, :class:`ZSW2`, :class:`STW2_ENC`, :class:`ZSW2_ENC`,
:class:`G1_STW`, :class:`G1_ZSW`: the bits are named like the members of the ``PD_TELx`` data types of
S7-1200 Motion Control V7 (e.g. ``ZSW1.SwitchingOnInhibited``, ``G1_ZSW.EncoderFaultAcknowledgeActive``,
``G1_STW.RequestParkingEncoder``; S7-1200 catalogue §10.3).  Bits the speed-control profile leaves to the
manufacturer are called ``Reserved_BitNN`` so that every bit of the word can still be addressed by name.
"""
from __future__ import annotations

import enum
import operator
from typing import Any, ClassVar, Self, SupportsIndex


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
