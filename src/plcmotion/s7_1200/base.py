"""The S7-1200 flavour of the instruction machinery (``plcmotion.fb``): the Axis input takes an S7-1200
positioning axis, and faults become the ErrorID/ErrorInfo pairs of S7-1200 V6 §12.8."""
from __future__ import annotations

from typing import Any, ClassVar

from .. import fb
from ..fb import InstructionError, as_bool, as_int, as_real
from ..kernel.axis import PositioningAxis
from ..kernel.faults import Fault
from . import errors as E


class _S71200:
    AXIS_TYPES: ClassVar[tuple[type, ...]] = (PositioningAxis,)

    def _family_ok(self, to: Any) -> bool:
        # an S7-1200 instruction works on the technology objects of an S7-1200 controller only
        return getattr(getattr(to, "ctl", None), "family", None) == "S7-1200"

    def _axis_error(self, kind: str) -> InstructionError:
        # 16#8408: 16#001B a technology object of another type, 16#001C not a technology object (§12.8)
        return InstructionError(E.AXIS, 0x001B if kind == "other_type" else 0x001C)

    def _fault_codes(self, fault: Fault) -> tuple[int, int]:
        return E.codes(fault)


class Instruction(_S71200, fb.Instruction):
    """Base of the S7-1200 instructions."""


class ExecuteInstruction(_S71200, fb.ExecuteInstruction):
    """S7-1200 instructions started by a rising edge at Execute."""


def fault_codes(fault: Fault) -> tuple[int, int]:
    return E.codes(fault)


__all__ = ["Instruction", "ExecuteInstruction", "InstructionError", "as_bool", "as_int", "as_real",
           "fault_codes"]
