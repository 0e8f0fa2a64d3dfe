"""Axis parameters that are no configuration tag and no plain system variable: the drive control / status
words (4500, 4501) and the absolute encoder adjustment (4010, 4011) (S7-Technology V4.1 §6.7.4, §6.7.5
examples "Drive control word" and "Backup of absolute encoder adjustment data", §9.4).

4500: the high word is CW2, the low word CW1.  The TO owns CW1 bits 0-7 and 10 and CW2 bits 12-15 (the
master sign of life); MC_WriteParameter writes ValueDword1 under the mask ValueDword2, and a mask that touches
a bit of the TO is refused with 16#8043 (the manual makes keeping them the criterion of a valid mask).  A read
gives both words unmasked: the TO's bits as the axis sets them (docs/s7t/decisions.md D93) and the bits the
program wrote.  The words reach no drive model: the simulated drive is switched by the axis directly.

4010 (Index = encoder): the adjustment of an absolute encoder as two DWORDs - the IEEE 754 double of the
offset, high half in ValueDword1, low half in ValueDword2 - so a read, kept in a DB, written back restores
it bit-exactly.  Writing it makes the encoder adjusted (4011 = YES) and is retained like MC_Home Mode 5.
"""
from __future__ import annotations

import math
import struct
import weakref
from typing import TYPE_CHECKING, Any

from .encoders import ABSOLUTE, encoder_type, retain_key
from .parameters import CONTROL_WORD_FREE_MASK, DWORD_MAX, ILLEGAL_PARAMETER, INVALID_NUMBER

if TYPE_CHECKING:  # pragma: no cover
    from .axes import AxisT

NOT_AVAILABLE = 0x8086
YES, NO = 1, 0                      # §9.4.12 EnumYesNo
#: CW1 of the TO: bits 0-6 (ON, no OFF2, no OFF3, inverter / ramp generator enable, setpoint enable) and 10
#: (control requested) while enabled; disabled only "no OFF2", "no OFF3", "control requested" (PROFIdrive)
CW1_ENABLED, CW1_DISABLED = 0x047F, 0x0406
#: ZSW1: ready to switch on (0), ready (1), operation enabled (2), no OFF2 (4), no OFF3 (5), in tolerance (8),
#: control requested (9); disabled: ready to switch on, no OFF2 / OFF3, control requested
ZSW1_ENABLED, ZSW1_DISABLED = 0x0337, 0x0231

_USER_BITS: "weakref.WeakKeyDictionary[Any, int]" = weakref.WeakKeyDictionary()


def _enabled(axis: "AxisT") -> bool:
    return axis.state in ("enabled", "disabling")


def control_words(axis: "AxisT") -> int:
    """4500 as MC_ReadSysParameter gives it in ValueDword1: CW2 high, CW1 low."""
    own = CW1_ENABLED if _enabled(axis) else CW1_DISABLED
    return own | _USER_BITS.get(axis, 0)


def write_control_words(axis: "AxisT", value: Any) -> int:
    """MC_WriteParameter 4500 with (ValueDword1, ValueDword2) = (words, mask): 0 or the ErrorID."""
    words, mask = value
    if mask & ~CONTROL_WORD_FREE_MASK & DWORD_MAX:
        return ILLEGAL_PARAMETER
    _USER_BITS[axis] = (_USER_BITS.get(axis, 0) & ~mask | words & mask) & CONTROL_WORD_FREE_MASK
    return 0


def status_words(axis: "AxisT") -> int:
    """4501: ZSW1 in the low word (ZSW2 high: 0, the model has no drive sign of life at this level)."""
    return ZSW1_ENABLED if _enabled(axis) else ZSW1_DISABLED


def _absolute(axis: "AxisT", x: int) -> bool:
    return not axis.virtual and 1 <= x <= axis.encoders.count and axis.eff.get(encoder_type(x)) == ABSOLUTE


def adjustment_available(axis: "AxisT", x: int) -> bool:
    """4010/4011 exist for an encoder configured as "absolute encoder" (not cyclic absolute, §6.7.5)."""
    return _absolute(axis, x)


def _pack(offset: float) -> int:
    return int.from_bytes(struct.pack(">d", offset), "big")


def read_adjustment(axis: "AxisT", x: int) -> int:
    """4010 of encoder ``x`` as one 64-bit value (MC_ReadSysParameter splits it into the two DWORDs)."""
    enc = axis.encoders
    return _pack(axis.abs_offset if x == enc.active else enc.adjustment[x])


def adjusted(axis: "AxisT", x: int) -> int:
    """4011: YES when encoder ``x`` carries an adjustment (homed by Mode 5 or restored by 4010)."""
    enc = axis.encoders
    return YES if (axis.homed if x == enc.active else enc.homed[x]) else NO


def write_adjustment(axis: "AxisT", x: int, value: Any) -> int:
    """Restore the adjustment of encoder ``x`` from (ValueDword1, ValueDword2) of a 4010 read.  Only on a
    disabled axis: the actual position jumps to the adjusted value (8086 otherwise, as while restarting)."""
    if not _absolute(axis, x):
        return INVALID_NUMBER
    if _enabled(axis):
        return NOT_AVAILABLE
    hi, lo = value
    offset = struct.unpack(">d", ((hi << 32) | lo).to_bytes(8, "big"))[0]
    if not math.isfinite(offset) or abs(offset) >= 1e12:
        return ILLEGAL_PARAMETER
    enc, ctl = axis.encoders, axis.ctl
    if x == enc.active:
        axis.abs_offset = offset
        axis.homed = True
        axis.drive.set_actual(ctl.bank, axis.homing.absolute_raw() + offset)
        ctl._retain_axis(axis)
    else:
        enc.adjustment[x] = enc.offset[x] = offset
        enc.homed[x] = True
        ctl.retain[retain_key(axis.name, x)] = {"AbsEncoderOffset": offset, "HomingDone": True}
    return 0


__all__ = ["control_words", "write_control_words", "status_words", "adjustment_available", "read_adjustment",
           "adjusted", "write_adjustment"]
