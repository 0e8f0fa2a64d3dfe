"""Input values of the S7-Technology FBs beyond the motion commands: parameter numbers and values of
MC_ReadSysParameter / MC_WriteParameter (§6.7.4, §6.7.5: numbers of §9.4 and invalid ones, REAL values in and
out of range, NaN, inf, huge; ENUM codes as ValueDInt), byte addresses and ANY areas of the periphery,
record and drive-parameter FBs (§6.7.6-§6.7.11: valid and wrong addresses, too short / too long / empty /
missing / read-only areas), diagnostic addresses of MC_ActivateDPSlave (§6.7.3), cam disks of
MC_SetCharacteristic (§6.2.13) and torques (§6.2.11, §6.2.12).
"""
from __future__ import annotations

import random
import struct
from typing import Any, Callable

from plcmotion.s7t.technology.enums import ENUMS
from plcmotion.s7t.technology.parameters import all_parameters
from plcmotion.s7t.technology.to_kinds import TOKind

from . import values as V
from .values import HUGE_INT, Ref

_PARAMS = sorted(all_parameters(TOKind.AXIS), key=lambda p: p.number)
_BY_NUMBER = {p.number: p for p in _PARAMS}
#: DP(DRIVE) addresses of the simulated bus (technology.dp_drive): base 256 + 32 k, diagnostic 1023 - k
DP_BASE, DP_DIAG = 256, 1023
#: drive parameters of the simulated drive (technology.dp_drive._parameters) and some it lacks
DRIVE_PARAMETERS = (922, 1082, 1120, 2000, 63, 947, 0, 1, 999, 65535)
_BAD_INT = (-1, 32768, -32769, 2 ** 31, HUGE_INT, None, "1", 1.5, float("nan"))


def _configured() -> tuple[int, ...]:
    """The numbers a plain positioning axis resolves (about a third of the list of §9.4: the others are
    parameters of features an axis has only when configured, or of other TOs' kinds), so that most reads
    and writes reach a value."""
    from plcmotion import Controller
    from plcmotion.s7t.technology import parameter_access as PA
    axis = Controller(family="S7-Technology").add_positioning_axis("A", {"Wizard.Virtual": 1})
    return tuple(p.number for p in _PARAMS if not isinstance(PA.resolve(axis, p.number, 1), int))


_CONFIGURED: list[tuple[int, ...]] = []


def parameter_number(rnd: random.Random) -> Any:
    r = rnd.random()
    if r < 0.6:
        if not _CONFIGURED:
            _CONFIGURED.append(_configured())
        return rnd.choice(_CONFIGURED[0])
    if r < 0.85:
        return rnd.choice(_PARAMS).number
    if r < 0.95:
        return rnd.randrange(0, 10000)
    return rnd.choice(_BAD_INT)


def _tiers(rnd: random.Random, good: Callable[[], Any] | None, p_good: float, near: tuple, bad: tuple) -> Any:
    """``good()`` with probability ``p_good`` (never when None), else one of ``near`` (plausible but often
    refused) up to 90 %, else one of ``bad`` (out of range, wrong type)."""
    r = rnd.random()
    if r < p_good and good is not None:
        return good()
    return rnd.choice(near) if r < 0.9 else rnd.choice(bad)


def parameter_index(rnd: random.Random) -> Any:
    return _tiers(rnd, lambda: 1, 0.6, (0, 2, 3, 4, 8, 16, 17), _BAD_INT)


def parameter_real(rnd: random.Random, number: Any) -> Any:
    """``Value`` (REAL): mostly within the parameter's printed range, else garbage, huge, at the REAL limit."""
    p = _BY_NUMBER.get(number) if isinstance(number, int) else None
    r = rnd.random()
    if r < 0.15:
        return rnd.choice(V.GARBAGE)
    if r < 0.25:
        return rnd.choice((1e12, -1e12, 9.99e11, 1e13, 2.0 ** 127, -1.0, 0.0))
    lo, hi = -1000.0, 1000.0
    if p is not None:
        lo = _bound(p.min_text, lo)
        hi = _bound(p.max_text, hi)
    if hi < lo:
        lo, hi = hi, lo
    lo, hi = max(lo, -1e6), min(hi, 1e6)
    return round(rnd.uniform(lo, hi), rnd.choice((0, 1, 3, 6)))


def _bound(text: str | None, default: float) -> float:
    try:
        return float(text) if text not in (None, "-") else default
    except ValueError:
        return default


def parameter_dint(rnd: random.Random, number: Any) -> Any:
    """``ValueDInt``: an ENUM code (ValueDint or expert value) of the parameter, a random DINT or garbage."""
    p = _BY_NUMBER.get(number) if isinstance(number, int) else None
    enum = ENUMS.get(p.data_type) if p is not None else None
    r = rnd.random()
    if enum is not None and r < 0.7:
        v = rnd.choice(enum.values)
        return v.value if rnd.random() < 0.8 else v.expert_value
    if r < 0.85:
        return rnd.choice((0, 1, 2, 3, 10, 100, -1, 1000, 2 ** 31 - 1, -2 ** 31))
    return rnd.choice(_BAD_INT + (2 ** 32,))


def dword(rnd: random.Random) -> Any:
    r = rnd.random()
    if r < 0.8:
        return rnd.choice((0, 1, 0xFFFF, 0xFFFF_FFFF, rnd.getrandbits(32), 1 << rnd.randrange(32)))
    return rnd.choice((-1, 2 ** 32, HUGE_INT, None, 1.5, float("nan")))


def byte_address(rnd: random.Random) -> Any:
    r = rnd.random()
    if r < 0.8:
        return rnd.choice((0, 0, 1, 2, 8, 32, 60, 63))
    return rnd.choice((-1, 64, 65, 1000, 32768, HUGE_INT, None, 2.5))


def _length(rnd: random.Random) -> int:
    return rnd.choice((1, 1, 2, 4, 4, 8, 16, 64, 65, 228, 229, 240, 241, 300))


def read_area(rnd: random.Random) -> Any:
    """A destination ANY area: a bytearray mostly; read-only bytes, empty, missing, wrong types otherwise."""
    r = rnd.random()
    if r < 0.8:
        return bytearray(_length(rnd))
    return rnd.choice((bytearray(), bytes(4), None, "abcd", [0, 0], 4, 1.0))


def write_area(rnd: random.Random) -> Any:
    """A source ANY area: random bytes, a REAL / WORD as the drive expects it, empty, missing, wrong types."""
    r = rnd.random()
    if r < 0.3:
        return struct.pack(">f", rnd.choice((0.0, 1.0, 100.0, 3000.0, -5.0, 1e30, float("nan"), float("inf"))))
    if r < 0.4:
        return struct.pack(">H", rnd.choice((0, 1, 3, 105, 999, 1000, 65535)))
    if r < 0.85:
        return bytes(rnd.getrandbits(8) for _ in range(_length(rnd)))
    return rnd.choice((b"", bytearray(2), None, "ab", [1, 2], 7))


def dp_address(rnd: random.Random, slaves: int) -> Any:
    return _tiers(rnd, (lambda: DP_BASE + 32 * rnd.randrange(slaves)) if slaves else None, 0.75,
                  (0, 64, 255, 257, DP_BASE + 32 * slaves, 1023), _BAD_INT)


def diagnostic_address(rnd: random.Random, slaves: int) -> Any:
    return _tiers(rnd, (lambda: DP_DIAG - rnd.randrange(slaves)) if slaves else None, 0.75,
                  (0, 256, DP_DIAG - slaves, 1024), _BAD_INT)


def record_number(rnd: random.Random) -> Any:
    return _tiers(rnd, lambda: 47, 0.7, (0, 1, 46, 48, 255), (-1, 256, HUGE_INT, None, 47.0))


def drive_parameter(rnd: random.Random) -> Any:
    return rnd.choice(DRIVE_PARAMETERS) if rnd.random() < 0.9 else rnd.choice(_BAD_INT + (65536,))


def sub_index(rnd: random.Random) -> Any:
    return rnd.choice((0, 0, 0, 1, 2, 7, 8, 100, 65535)) if rnd.random() < 0.9 else rnd.choice(_BAD_INT)


def elements(rnd: random.Random) -> Any:
    return rnd.choice((0, 0, 1, 1, 2, 8, 9, 228, 229, 234, 235)) if rnd.random() < 0.9 else rnd.choice(_BAD_INT)


def cam_table(rnd: random.Random, cams: list[tuple[str, int]], axes: list[str]) -> Any:
    """``CamTable``: a cam disk (object or technology DB number), an axis, a DB without a cam disk, garbage."""
    r = rnd.random()
    if cams and r < 0.5:
        return Ref(rnd.choice(cams)[0])
    if cams and r < 0.8:
        return rnd.choice(cams)[1]
    if r < 0.9:
        return Ref(rnd.choice(axes))
    return rnd.choice((0, 1, 699, 65535, -1, None, "Cam_1", 1.5))


def torque(rnd: random.Random) -> Any:
    r = rnd.random()
    if r < 0.75:
        return round(rnd.uniform(0.0, 4.0), rnd.choice((1, 3)))
    if r < 0.85:
        return rnd.choice((0.0, 3.2, 100.0, -1.0))
    return rnd.choice(V.GARBAGE)


__all__ = ["parameter_number", "parameter_index", "parameter_real", "parameter_dint", "dword", "byte_address",
           "read_area", "write_area", "dp_address", "diagnostic_address", "record_number", "drive_parameter",
           "sub_index", "elements", "cam_table", "torque"]
