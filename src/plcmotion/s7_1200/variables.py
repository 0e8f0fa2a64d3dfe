"""Typed PLC variables: what the VARIANT ``Value`` of MC_ReadParam / MC_WriteParam points to.

In a PLC program ``Value`` is a pointer to a tag of the user program (a data block member or a memory
tag) with a fixed data type.  In Python a plain ``float`` cannot be written through, so the instructions
take one of these small mutable objects instead::

    >>> from plcmotion.s7_1200.variables import DInt, Real
    >>> v = Real()
    >>> v.value = 12.5
    >>> v
    Real(12.5)
    >>> v == 12.5
    True
    >>> DInt(7).data_type
    'DInt'

Each class checks what is assigned to ``.value`` the way the PLC compiler would check an assignment:
a value of another kind raises ``TypeError`` (no implicit BOOL <-> number or REAL -> integer conversion),
an integer outside the range of the data type raises ``ValueError``.  ``Real`` holds a 64-bit float
(decision 24 of docs/decisions.md) and, like an IEEE REAL tag, may hold NaN or infinity.
"""
from __future__ import annotations

import math
import numbers
from typing import Any, ClassVar

import numpy as np

__all__ = ["Variable", "Bool", "Int", "DInt", "UDInt", "Real", "type_of", "plain"]


class Variable:
    """A PLC tag of the user program with a data type (base class)."""

    DATA_TYPE: ClassVar[str] = ""
    START: ClassVar[Any] = None

    __slots__ = ("_value",)
    __hash__ = None  # type: ignore[assignment]   # mutable: not usable as a dict key

    def __init__(self, value: Any = None):
        self.value = self.START if value is None else value

    @property
    def data_type(self) -> str:
        """S7 data type name: 'Bool', 'Int', 'DInt', 'UDInt' or 'Real'."""
        return self.DATA_TYPE

    @property
    def value(self) -> Any:
        return self._value

    @value.setter
    def value(self, new: Any) -> None:
        self._value = self._check(new)

    def _check(self, new: Any) -> Any:  # pragma: no cover - abstract
        raise NotImplementedError

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self._value!r})"

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Variable):
            return self.DATA_TYPE == other.DATA_TYPE and self._value == other._value
        return bool(self._value == other)

    def __bool__(self) -> bool:
        return bool(self._value)


class Bool(Variable):
    """BOOL: ``True`` / ``False`` (numpy booleans are accepted)."""

    DATA_TYPE = "Bool"
    START = False
    __slots__ = ()

    def _check(self, new: Any) -> bool:
        if isinstance(new, (bool, np.bool_)):
            return bool(new)
        raise TypeError(f"a Bool variable takes True or False, not {new!r}")


class _Integer(Variable):
    LO: ClassVar[int] = 0
    HI: ClassVar[int] = 0
    START = 0
    __slots__ = ()

    def _check(self, new: Any) -> int:
        if isinstance(new, (bool, np.bool_)) or not isinstance(new, numbers.Integral):
            raise TypeError(f"a {self.DATA_TYPE} variable takes an integer, not {new!r}")
        value = int(new)
        if not self.LO <= value <= self.HI:
            raise ValueError(f"{value} is outside the range of {self.DATA_TYPE} ({self.LO} .. {self.HI})")
        return value

    def __int__(self) -> int:
        return self._value

    def __index__(self) -> int:
        return self._value

    def __float__(self) -> float:
        return float(self._value)


class Int(_Integer):
    """INT: 16-bit signed integer, -32768 .. 32767."""

    DATA_TYPE = "Int"
    LO, HI = -(2 ** 15), 2 ** 15 - 1
    __slots__ = ()


class DInt(_Integer):
    """DINT: 32-bit signed integer, -2147483648 .. 2147483647."""

    DATA_TYPE = "DInt"
    LO, HI = -(2 ** 31), 2 ** 31 - 1
    __slots__ = ()


class UDInt(_Integer):
    """UDINT: 32-bit unsigned integer, 0 .. 4294967295."""

    DATA_TYPE = "UDInt"
    LO, HI = 0, 2 ** 32 - 1
    __slots__ = ()


class Real(Variable):
    """REAL: a floating point number (integers are converted; NaN and infinity can be stored)."""

    DATA_TYPE = "Real"
    START = 0.0
    __slots__ = ()

    def _check(self, new: Any) -> float:
        if isinstance(new, (bool, np.bool_)) or not isinstance(new, numbers.Real):
            raise TypeError(f"a Real variable takes a number, not {new!r}")
        try:
            return float(new)
        except OverflowError:
            raise ValueError(f"{new} is outside the range of Real") from None

    def __float__(self) -> float:
        return self._value

    def __int__(self) -> int:
        return int(self._value)


def type_of(value: Any) -> str | None:
    """S7 data type of a value given to a VARIANT input.

    Typed variables have their own type.  Plain Python values are typed like constants of the S7
    languages: ``bool`` is Bool, ``int`` is DInt (an integer outside the DInt range would be an LInt,
    which no MC instruction accepts: None), ``float`` is Real.  Anything else (strings, None, lists ...)
    has no data type an MC instruction accepts: None.
    """
    if isinstance(value, Variable):
        return value.DATA_TYPE
    if isinstance(value, (bool, np.bool_)):
        return "Bool"
    if isinstance(value, numbers.Integral):
        return "DInt" if DInt.LO <= int(value) <= DInt.HI else None
    if isinstance(value, numbers.Real):
        return "Real"
    return None


def plain(value: Any) -> Any:
    """The Python value of a variable or plain value (bool, int or float)."""
    if isinstance(value, Variable):
        return value.value
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, numbers.Integral):
        return int(value)
    try:
        return float(value)
    except OverflowError:              # beyond the REAL range: the value checks report it as too large
        return math.inf if value > 0 else -math.inf
