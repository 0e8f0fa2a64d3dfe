"""The technology parameters of S7-Technology V4.1 (§9.4), typed, with the checks MC_WriteParameter applies.

Every entry of the parameter list (318, tables in ``parameter_table_axis`` and ``parameter_table_other``)
becomes a :class:`Parameter`: number, index range, expert-list and DB-Param names, data type (REAL, DINT,
WORD, DWORD, 2xDWORD or the name of an ENUM of §9.4.12), range, access, when a write takes effect and which
axis technologies it serves.  :meth:`Parameter.check` gives the ErrorID MC_WriteParameter (FB 407, §6.7.5)
reports for a value, :func:`write_check` adds the "no such parameter" case.

Ranges: the REAL inputs of the FBs must lie strictly inside +/-1E+12 (§6.9.3), so a printed bound of 1E+12 is
open; other printed bounds are inclusive, "> 0.0" and "< 1E+7" are open.  The bound of parameter 1263 is
printed as a function of the servo cycle and is only checked when the cycle is given.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Iterable, Mapping

from .enums import ENUMS
from .parameter_table_axis import AXIS
from .parameter_table_other import CAM, CAM_TRACK, EXTERNAL_ENCODER, MEASURING_INPUT, OUTPUT_CAM, PRINTED_NAMES
from .to_kinds import AxisType, TOKind

# ErrorIDs of MC_WriteParameter (§6.7.5); the same numbers as plcmotion.s7t.fb_errors, kept here so the
# technology layer needs nothing from the instruction layer
ILLEGAL_PARAMETER = 0x8043     # value out of range, invalid ENUM code, value of the wrong kind
INVALID_NUMBER = 0x8080        # parameter number or index not supported by this TO
READ_ONLY = 0x8081             # parameter cannot be changed
INVALID_REAL = 0x808B          # value is no valid REAL (NaN, infinity)
RESTART_REQUIRED = 0x0020      # warning: the change becomes effective at the next restart of the TO

REAL_LIMIT = 1e12              # §6.9.3: -1E+12 < REAL < +1E+12 at every REAL input
DINT_MIN, DINT_MAX = -(2 ** 31), 2 ** 31 - 1
DWORD_MAX = 0xFFFF_FFFF
WORD_MAX = 0xFFFF
#: parameter 4500 (control words 1 and 2): bits the user program may set (high word CW2, low word CW1); the other
#: bits belong to the TO (§6.7.5 example "Drive control word")
CONTROL_WORD_FREE_MASK = 0x0FFF_FB00
#: parameter 1263: printed maximum "2^31 * Servotime * 9"
SERVO_TIME_FACTOR_1263 = 2 ** 31 * 9

IMMEDIATELY, RESTART = "Immediately", "Restart"
_AXIS_TYPES = {"V": AxisType.SPEED, "P": AxisType.POSITIONING, "Y": AxisType.SYNCHRONIZATION}
_PLAIN_TYPES = ("REAL", "DINT", "WORD", "DWORD", "2xDWORD")
_MASKED = {(TOKind.AXIS, 4500)}     # written as value + mask in ValueDword1 / ValueDword2


def _bound(text: str | None) -> tuple[float | int | None, bool]:
    """(number, open) of a printed Min./Max. entry."""
    if text is None or "Servotime" in text:
        return None, False
    t = text.strip()
    is_open = t[0] in "<>"
    t = t.lstrip("<> ").replace(" ", "")
    if re.fullmatch(r"[0-9A-F]{8}", t):
        return int(t, 16), is_open
    if re.fullmatch(r"[+-]?\d+", t):
        return int(t), is_open
    return float(t), is_open


@dataclass(frozen=True)
class Parameter:
    """One technology parameter of §9.4 for one TO type."""
    to: TOKind
    number: int
    index: tuple[int, int] | None       # (first, last) for data sets 1-16, encoders 1-8, sync objects 1-2
    expert_name: str                    # "Expert" display of DB-Param = expert-list name in S7T Config
    db_name: str                        # "Normal" display of DB-Param
    description: str
    data_type: str                      # REAL, DINT, WORD, DWORD, 2xDWORD or an ENUM type name
    min_text: str | None                # Min. / Max. as printed ("-" -> None)
    max_text: str | None
    access: str                         # "R" or "RW"
    effective: str | None               # "Immediately", "Restart" or None (printed "-")
    axis_types: frozenset[AxisType]     # empty for TOs other than the axis
    source_line: int                    # line of the entry in the manual's text
    firmware: str | None = None         # the list's "Firmware version" column (empty for every entry in V4.1)

    @property
    def writable(self) -> bool:
        return self.access == "RW"

    @property
    def enum(self) -> str | None:
        """Name of the ENUM type for a DINT Enum parameter, else None."""
        return None if self.data_type in _PLAIN_TYPES else self.data_type

    @property
    def hydraulic(self) -> bool:
        """A parameter of the hydraulic axis only (its DB-Param group is "Hydraulic", §9.4.6)."""
        return self.db_name.startswith("Hydraulic.")

    @property
    def needs_restart(self) -> bool:
        return self.effective == RESTART

    @property
    def value_input(self) -> str:
        """The MC_WriteParameter input (MC_ReadSysParameter output) that carries the value (§6.7.4, §6.7.5)."""
        if self.data_type == "REAL":
            return "Value"
        if self.data_type == "2xDWORD" or (self.to, self.number) in _MASKED:
            return "ValueDword1+ValueDword2"
        if self.data_type in ("DWORD", "WORD"):
            return "ValueDword1"
        return "ValueDInt"

    @property
    def minimum(self) -> float | int | None:
        return _bound(self.min_text)[0]

    @property
    def maximum(self) -> float | int | None:
        return _bound(self.max_text)[0]

    def indices(self) -> range:
        """Valid values of the Index input; a parameter without index ignores it (§6.7.5)."""
        return range(1, 2) if self.index is None else range(self.index[0], self.index[1] + 1)

    def check(self, value: Any, index: int | None = None, servo_cycle: float | None = None) -> int | None:
        """The ErrorID MC_WriteParameter gives for writing ``value`` (at ``index``), None if the write is
        accepted.  ``value`` is what the input of :attr:`value_input` holds: a float for REAL, an int for
        DINT/WORD/DWORD and ENUM codes, a pair of ints for two DWORDs.  Never raises."""
        if not self.writable:
            return READ_ONLY
        if self.index is not None and index is not None and (
                type(index) is not int or not self.index[0] <= index <= self.index[1]):
            return INVALID_NUMBER
        try:
            return self._check_value(value, servo_cycle)
        except Exception:                   # noqa: BLE001 - a value we cannot even compare is illegal
            return ILLEGAL_PARAMETER

    def _check_value(self, value: Any, servo_cycle: float | None) -> int | None:
        if self.data_type == "REAL":
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                return ILLEGAL_PARAMETER
            v = float(value)
            if not math.isfinite(v):
                return INVALID_REAL
            if not -REAL_LIMIT < v < REAL_LIMIT:
                return ILLEGAL_PARAMETER
            return None if self._in_range(v, servo_cycle) else ILLEGAL_PARAMETER
        if self.data_type == "2xDWORD" or (self.to, self.number) in _MASKED:
            ok = (isinstance(value, (tuple, list)) and len(value) == 2
                  and all(_is_int(w) and 0 <= w <= DWORD_MAX for w in value))
            return None if ok else ILLEGAL_PARAMETER
        if not _is_int(value):
            return ILLEGAL_PARAMETER
        if self.enum is not None:
            return None if value in ENUMS[self.enum].codes() else ILLEGAL_PARAMETER
        lo, hi = {"DINT": (DINT_MIN, DINT_MAX), "WORD": (0, WORD_MAX), "DWORD": (0, DWORD_MAX)}[self.data_type]
        if not lo <= value <= hi:
            return ILLEGAL_PARAMETER
        return None if self._in_range(value, servo_cycle) else ILLEGAL_PARAMETER

    def _in_range(self, v: float | int, servo_cycle: float | None) -> bool:
        lo, lo_open = _bound(self.min_text)
        hi, hi_open = _bound(self.max_text)
        if self.max_text is not None and "Servotime" in self.max_text and servo_cycle is not None:
            hi = SERVO_TIME_FACTOR_1263 * servo_cycle
        if lo is not None and (v < lo or (lo_open and v == lo)):
            return False
        return hi is None or not (v > hi or (hi_open and v == hi))


def _is_int(v: Any) -> bool:
    return isinstance(v, int) and not isinstance(v, bool)


def _build(to: TOKind, rows: Iterable[tuple]) -> dict[int, Parameter]:
    out = {}
    for no, idx, expert, normal, desc, dtype, lo, hi, acc, eff, types, line in rows:
        out[no] = Parameter(to, no, idx, expert, normal, desc, dtype, lo, hi, acc, eff,
                            frozenset(_AXIS_TYPES[c] for c in types), line)
    return out


_TABLES: Mapping[TOKind, Mapping[int, Parameter]] = MappingProxyType({
    TOKind.AXIS: MappingProxyType(_build(TOKind.AXIS, AXIS)),
    TOKind.EXTERNAL_ENCODER: MappingProxyType(_build(TOKind.EXTERNAL_ENCODER, EXTERNAL_ENCODER)),
    TOKind.OUTPUT_CAM: MappingProxyType(_build(TOKind.OUTPUT_CAM, OUTPUT_CAM)),
    TOKind.CAM_TRACK: MappingProxyType(_build(TOKind.CAM_TRACK, CAM_TRACK)),
    TOKind.CAM: MappingProxyType(_build(TOKind.CAM, CAM)),
    TOKind.MEASURING_INPUT: MappingProxyType(_build(TOKind.MEASURING_INPUT, MEASURING_INPUT)),
})


def _key(name: str) -> str:
    """Names compare without blanks and case: the print splits some names with blanks."""
    return re.sub(r"\s+", "", name).lower()


def _aliases(p: Parameter) -> set[str]:
    names = {p.expert_name, p.db_name}
    printed = PRINTED_NAMES.get((p.to.value, p.number))
    if printed:
        names.add(printed)
    if p.number == 4001:                # printed with and without a dot, depending on the TO
        names |= {"activationmodechangedconfigdata", "activationmodechanged.configdata"}
    if p.expert_name.startswith("SyncinMotion."):
        names.add(p.expert_name.replace("SyncinMotion.", "SyncingMotion."))
    return {_key(n) for n in names}


def _name_index() -> dict[TOKind, dict[str, tuple[Parameter, ...]]]:
    index: dict[TOKind, dict[str, tuple[Parameter, ...]]] = {}
    for to, table in _TABLES.items():
        names: dict[str, tuple[Parameter, ...]] = {}
        for p in table.values():
            for k in _aliases(p):
                names[k] = names.get(k, ()) + (p,)
        index[to] = names
    return index


_NAMES = _name_index()


def _kind(to_type: TOKind | str) -> TOKind:
    try:
        return TOKind(to_type)
    except ValueError:
        raise KeyError(f"no parameter list for TO type {to_type!r}; "
                       f"known: {', '.join(k.value for k in _TABLES)}") from None


def parameter(to_type: TOKind | str, number: int) -> Parameter:
    """The parameter ``number`` of a TO type; KeyError if the list has none (MC_* give 8080 then)."""
    kind = _kind(to_type)
    table = _TABLES.get(kind, {})
    if number not in table:
        raise KeyError(f"{kind.value} has no technology parameter {number}")
    return table[number]


def by_name(to_type: TOKind | str, name: str) -> Parameter:
    """The parameter of a TO type by its expert-list name or its DB-Param ("Normal" display) name, compared
    without blanks and case.  LookupError if no or more than one parameter has that name (two cam-track
    parameters share the DB-Param name "Configuration.Cam type")."""
    kind = _kind(to_type)
    found = _NAMES.get(kind, {}).get(_key(name), ())
    if len(found) != 1:
        what = "no parameter" if not found else f"parameters {', '.join(str(p.number) for p in found)}"
        raise LookupError(f"{kind.value}: {what} named {name!r}")
    return found[0]


def all_parameters(to_type: TOKind | str | None = None) -> tuple[Parameter, ...]:
    """All parameters (of one TO type, or of every TO type in the order of §9.4), each sorted by number."""
    kinds = list(_TABLES) if to_type is None else [_kind(to_type)]
    return tuple(p for k in kinds for _, p in sorted(_TABLES.get(k, {}).items()))


def write_check(to_type: TOKind | str, number: int, value: Any, index: int | None = None,
                servo_cycle: float | None = None) -> int | None:
    """ErrorID of MC_WriteParameter for a write to a TO of ``to_type``: 8080 for a number the TO does not have,
    else :meth:`Parameter.check`.  Never raises."""
    try:
        p = parameter(to_type, number)
    except (KeyError, TypeError):
        return INVALID_NUMBER
    return p.check(value, index, servo_cycle)
