"""The referencing methods of MC_Home as data (Pilz V6.5 §1.7.5.1 Tab. 22, control type Tab. 19).

Each method has a letter (Tab. 22), an initial direction, whether the zero pulse of the encoder ends it, and
the feature the axis searches: a limit switch, a reference switch at one end of the travel range or in its
middle, the zero pulse alone, setting the reference without motion, or a torque/force stop.  A Drive Based
or PROFIdrive drive builds the method from I30 (type), I31 (direction) and I35 (zero pulse); a CiA 402 drive
selects one number in A586.  Tab. 19 gives the set of A586 numbers per control type but not which number is
which letter: the pairing below is our reading of the CiA 402 homing methods (docs/pilz/decisions.md).
"""
from __future__ import annotations

from dataclasses import dataclass
from enum import Enum


class Feature(Enum):
    LIMIT_SWITCH = "limit switch"
    SWITCH_AT_END = "reference switch at the end of travel"
    SWITCH_IN_MIDDLE = "reference switch in the middle"
    ZERO_PULSE = "zero pulse"
    SET_REFERENCE = "setting the reference"
    TORQUE_STOP = "torque/force stop"


@dataclass(frozen=True)
class Method:
    letter: str
    direction: int            # initial movement: +1 positive, -1 negative, 0 none
    zero_pulse: bool
    feature: Feature


_L, _E, _M, _Z, _O, _T = (Feature.LIMIT_SWITCH, Feature.SWITCH_AT_END, Feature.SWITCH_IN_MIDDLE,
                          Feature.ZERO_PULSE, Feature.SET_REFERENCE, Feature.TORQUE_STOP)

#: Tab. 22, row by row
METHODS: dict[str, Method] = {m.letter: m for m in (
    Method("A", -1, True, _L), Method("B", -1, True, _E), Method("C", -1, False, _L), Method("D", -1, False, _E),
    Method("E", +1, True, _L), Method("F", +1, True, _E), Method("G", +1, False, _L), Method("H", +1, False, _E),
    Method("I", +1, True, _M), Method("J", +1, False, _M), Method("K", -1, True, _M), Method("L", -1, False, _M),
    Method("M", -1, True, _Z), Method("N", +1, True, _Z), Method("O", 0, False, _O),
    Method("P", +1, False, _T), Method("Q", +1, True, _T), Method("R", -1, False, _T), Method("S", -1, True, _T),
)}

#: Tab. 19: CiA 402 method numbers by control type
POSITION_CONTROLLED = (1, 2, 3, 5, 7, 11, 17, 18, 19, 21, 23, 27, 33, 34)
VELOCITY_CONTROLLED = (-1, -2, -3, -4)
SET_REFERENCE = (35, 37)

#: A586 -> letter (CiA 402 reading; the order of the manufacturer-specific -1 ... -4: decisions.md)
CIA402_LETTER: dict[int, str] = {1: "A", 5: "B", 17: "C", 21: "D", 2: "E", 3: "F", 18: "G", 19: "H",
                                 7: "I", 23: "J", 11: "K", 27: "L", 33: "M", 34: "N", 35: "O", 37: "O",
                                 -1: "P", -2: "Q", -3: "R", -4: "S"}
#: the A586 numbers this drive model accepts
CIA402_METHODS: tuple[int, ...] = tuple(sorted(CIA402_LETTER))


def from_cia402(a586: int) -> Method | None:
    """The method of CiA 402 homing method ``a586``; None for 0 (inactive)."""
    letter = CIA402_LETTER.get(a586)
    return METHODS[letter] if letter else None


def from_drive_based(i30: int, i31: int, i35: int, in_middle: bool) -> Method | None:
    """The method a Drive Based / PROFIdrive drive builds from I30 (type), I31 (0 positive, 1 negative) and
    I35 (zero pulse); ``in_middle``: the reference switch of I30 = 1 lies in the middle of the travel range.
    None for I30 = 0 (inactive)."""
    d = -1 if i31 else +1
    zp = bool(i35)
    if i30 == 0:
        return None
    if i30 == 5:
        return METHODS["O"]
    if i30 == 3:
        return METHODS["N" if d > 0 else "M"]
    feature = {1: _M if in_middle else _E, 2: _L, 4: _T}[i30]
    for m in METHODS.values():
        if m.feature is feature and m.direction == d and m.zero_pulse == zp:
            return m
    raise ValueError(f"no referencing method for I30={i30}, I31={i31}, I35={i35}")   # pragma: no cover


def control_type(method: Method) -> str:
    """Tab. 19: the control type while referencing with ``method``."""
    if method.feature is _O:
        return "unchanged"
    if method.feature is _T:
        return "velocity"
    return "position"


__all__ = ["CIA402_LETTER", "CIA402_METHODS", "Feature", "METHODS", "Method", "POSITION_CONTROLLED",
           "SET_REFERENCE", "VELOCITY_CONTROLLED", "control_type", "from_cia402", "from_drive_based"]
