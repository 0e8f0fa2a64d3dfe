"""PROFIdrive standard telegrams on the wire, and the scaling of their speed words.

Standard telegrams 1, 2, 3, 4 (drive) and 81, 83 (encoder): ``TelegramNOut`` (controller -> device) and
``TelegramNIn`` (device -> controller) with ``pack()``/``unpack()`` in PROFINET byte order (big-endian;
setpoints and speeds in two's complement, position values unsigned).  Speed scaling between 1/min and
the NSOLL/NIST word values: :func:`speed_to_nsoll`, :func:`nsoll_to_speed`.
"""
from __future__ import annotations

import math
import operator
import struct
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any, ClassVar, Self, TypeAlias

from .words import G1_STW, G1_ZSW, STW1, STW2, STW2_ENC, ZSW1, ZSW2, ZSW2_ENC, Word16


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
