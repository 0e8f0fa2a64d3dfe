"""The S7-1500 flavour of the instruction machinery: technology object types, the dynamic input rule and
the ErrorIDs (no ErrorInfo output)."""
from __future__ import annotations

import math
from typing import Any, ClassVar

from .. import fb
from ..fb import InstructionError, as_bool, as_int, as_real
from .technology.axes import PositioningAxis1500, SynchronousAxis
from ..kernel.faults import Fault
from ..kernel.profiles import INF
from . import errors as E

AXES = (PositioningAxis1500,)


class _S71500:
    AXIS_TYPES: ClassVar[tuple[type, ...]] = AXES

    def _family_ok(self, to: Any) -> bool:
        return True

    def _axis_error(self, kind: str) -> InstructionError:
        return InstructionError(E.WRONG_TO)          # no technology object, or one of another type

    @classmethod
    def _instruction_name(cls) -> str:
        """The name of the manual's instruction this class is (a user subclass keeps its codes)."""
        return next((k.__name__ for k in cls.__mro__ if k.__name__ in E.INSTRUCTION_CODES), cls.__name__)

    def _rejected_at(self) -> object:
        """The technology object a rejected job is noted at."""
        return getattr(self, "Axis", None) or getattr(self, "Slave", None)

    def _fault_codes(self, fault: Fault) -> tuple[int, int]:
        """ErrorID of a fault that ended a job of this instruction.  A job the technology object rejected
        (a fault without acknowledgement) is also shown there as WarningWord.X3 (§7.1.1 "Job rejected")."""
        if not fault.ack:
            note = getattr(self._rejected_at(), "note_rejected", None)
            if note is not None:
                note(fault)
        return E.code(fault, self._instruction_name()), 0


class Instruction(_S71500, fb.Instruction):
    """Base of the S7-1500 instructions."""


class ExecuteInstruction(_S71500, fb.ExecuteInstruction):
    """S7-1500 instructions started by a rising edge at Execute."""

    OUTPUTS = {"Done": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0}


def real(name: str, value: Any) -> float:
    """A finite LREAL input, else the ErrorID of that input."""
    x = as_real(value)
    if x is None or abs(x) > 1.0e12:
        raise InstructionError(E.parameter(name))
    return x


def dynamic(name: str, value: Any, default: float, *, jerk: bool = False) -> float:
    """Dynamic inputs (§9.1): > 0 use the value, = 0 not permitted (Jerk: trapezoid), < 0 the default."""
    x = as_real(value)
    if x is None:
        raise InstructionError(E.parameter(name))
    if x < 0.0:
        x = default
        if jerk and x == 0.0:
            return INF
        return x
    if x == 0.0:
        if jerk:
            return INF
        raise InstructionError(E.parameter(name))
    if x > 1.0e12:
        raise InstructionError(E.parameter(name))
    return x


def dynamics(axis: PositioningAxis1500, inputs: Any, *, velocity: str | None = "Velocity",
             names: tuple[str, str, str] = ("Acceleration", "Deceleration", "Jerk")) -> dict[str, float]:
    """Resolve Velocity/Acceleration/Deceleration/Jerk inputs against the axis's DynamicDefaults."""
    e = axis.ueff
    out: dict[str, float] = {}
    if velocity is not None:
        out["velocity"] = dynamic(velocity, getattr(inputs, velocity), e["DynamicDefaults.Velocity"])
    acc, dec, jerk = names
    out["acceleration"] = dynamic(acc, getattr(inputs, acc), e["DynamicDefaults.Acceleration"])
    out["deceleration"] = dynamic(dec, getattr(inputs, dec), e["DynamicDefaults.Deceleration"])
    out["jerk"] = dynamic(jerk, getattr(inputs, jerk), e["DynamicDefaults.Jerk"], jerk=True)
    return out


def integer(name: str, value: Any, allowed) -> int:
    x = as_int(value)
    if x is None or x not in allowed:
        raise InstructionError(E.parameter(name))
    return x


__all__ = ["Instruction", "ExecuteInstruction", "InstructionError", "as_bool", "as_int", "as_real", "real",
           "dynamic", "dynamics", "integer", "AXES", "SynchronousAxis", "math"]
