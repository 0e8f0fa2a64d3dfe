"""Configuration tags of the §9.4 axis parameters the model stores without giving them an effect
(S7-Technology V4.1 §9.4.1-§9.4.6; docs/s7t/decisions.md D92).

The hand-written tags of ``schema`` (and its helper modules) are the parameters the model acts on.  Every
other axis parameter of the list that is a configuration value becomes a tag here, generated from the
parameter table: its range, ENUM codes, access and effectiveness are the list's, so MC_ReadSysParameter,
MC_WriteParameter and project files treat it exactly like a modelled one.  The list gives no start values;
the generated start value is 0 / 0.0 moved into the printed range, 1 for a gear factor, YES for 2034 (the
model's controller precontrols with the weighting 2032), the modelled maxima
(numbers 8, 12, 16) for the directional limits of dynamics 4121-4125 / 4151-4155, and for an ENUM its lowest
ValueDint (EnumYesNo and EnumActiveInactive: NO / INACTIVE).  Data set 2-16 and encoder 2-8 values are optional: one a
project leaves out is data set 1's / encoder 1's (as ``datasets`` does for the modelled ones).
"""
from __future__ import annotations

from typing import Iterable

from ...kernel.schema import E12, INT, REAL, WP, R, Param
from .enums import ENUMS
from .parameters import DWORD_MAX, WORD_MAX, Parameter, all_parameters
from .to_kinds import TOKind

#: numbers whose value the technology computes or keeps outside the tags (parameter_access)
COMPUTED = frozenset({1, 10, 11, 2000, 3000, 4001, 4010, 4011, 4020, 4030, 4031, 4040, 4041, 4050, 4162, 4173,
                      4174, 4400, 4401, 4410, 4411, 4412, 4500, 4501, 5002, 5014, 5020})
#: start values the 0-rule would make meaningless: the start values of numbers 8, 12 and 16 in ``schema``
_LIMITS = {"velocity": 1000.0, "positiveaccel": 10000.0, "negativeaccel": 10000.0,
           "positiveacceljerk": 1.0e6, "negativeacceljerk": 1.0e6}
_MARKERS = ("DataSet_x", "Encoder_x", "Encoder_X")
_COUNTS = {"DataSet_x": 16, "Encoder_x": 8, "Encoder_X": 8}


def tag(p: Parameter, index: int) -> str:
    """The tag of parameter ``p`` at data set / encoder ``index``."""
    name = p.expert_name
    for marker in _MARKERS:
        name = name.replace(marker, marker[:-1] + str(index))
    return name


def _start(p: Parameter) -> int | float:
    head, _, leaf = p.expert_name.rpartition(".")
    if head in ("minuslimitsofdynamics", "pluslimitsofdynamics"):
        return _LIMITS[leaf]
    if leaf in ("numFactor", "denFactor"):
        return 1
    if p.number == 2034:                # the model's position controller always precontrols (weighting 2032)
        return 1
    if p.enum is not None:
        return min(ENUMS[p.enum].codes())
    lo, hi = p.minimum, p.maximum
    lo_open = p.min_text is not None and p.min_text.strip().startswith(">")
    if p.data_type == "REAL":
        v = 0.0
        if lo is not None and (v < lo or lo_open and v <= lo):
            v = float(lo) if not lo_open else float(lo) + 1.0
        return v if hi is None or v <= hi else float(hi)
    v = 0 if lo is None else max(0, int(lo))
    return v


def _param(p: Parameter, path: str, optional: bool) -> Param:
    access = WP if p.writable else R
    effective = (10,) if p.effective == "Immediately" else ()
    start = None if optional else _start(p)
    doc = f"number {p.number}: {p.description} (stored, no modelled effect)"
    if p.enum is not None:
        return Param(path, INT, start, access, effective, choices=tuple(sorted(ENUMS[p.enum].codes())),
                     optional=optional, doc=doc)
    if p.data_type == "REAL":
        lo = -E12 if p.minimum is None else max(-E12, float(p.minimum))
        hi = E12 if p.maximum is None else min(E12, float(p.maximum))
        lo_open = p.min_text is not None and p.min_text.strip().startswith(">")
        return Param(path, REAL, start, access, effective, lo, hi, lo_open=lo_open, optional=optional, doc=doc)
    top = {"WORD": WORD_MAX, "DWORD": DWORD_MAX}.get(p.data_type, 2 ** 31 - 1)
    lo = p.minimum if p.minimum is not None else (0 if p.data_type in ("WORD", "DWORD") else -(2 ** 31))
    hi = p.maximum if p.maximum is not None else top
    return Param(path, INT, start, access, effective, int(lo), int(hi), optional=optional, doc=doc)


def generated(existing: Iterable[str]) -> tuple[list[Param], frozenset[int]]:
    """(tags, numbers) of the axis parameters none of ``existing`` holds."""
    have = set(existing)
    out: list[Param] = []
    numbers: set[int] = set()
    for p in all_parameters(TOKind.AXIS):
        if p.number in COMPUTED:
            continue
        marker = next((m for m in _MARKERS if m in p.expert_name), None)
        count = _COUNTS[marker] if marker else 1
        for i in range(1, count + 1):
            path = tag(p, i)
            if path not in have:
                out.append(_param(p, path, optional=i > 1))
                have.add(path)
                if i == 1:
                    numbers.add(p.number)
    return out, frozenset(numbers)


__all__ = ["COMPUTED", "generated", "tag"]
