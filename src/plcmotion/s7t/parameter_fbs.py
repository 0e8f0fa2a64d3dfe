"""FB 406 MC_ReadSysParameter and FB 407 MC_WriteParameter (S7-Technology V4.1 §6.7.4, §6.7.5, §5.16).

Both address a parameter of the axis by its number of §9.4 and, for data sets / encoders / synchronous
objects, ``Index``.  The value travels at the input/output of its data type: ``Value`` (REAL), ``ValueDInt``
(DINT and ENUM codes, §9.4.12), ``ValueDword1`` (WORD/DWORD), ``ValueDword1`` + ``ValueDword2`` (two DWORDs);
the other outputs of MC_ReadSysParameter are 0.  The command is carried out in the call of the rising edge
(it neither aborts another command nor can be aborted, §6.8).  What a write does to the axis is in
``technology.parameter_access``.
"""
from __future__ import annotations

from typing import Any

from ..fb import as_int
from ..kernel.jobs import Job, JobKind, JobState
from . import fb_errors as FE
from .base import ALL_AXES, ExecuteInstruction, InstructionError
from .technology import parameter_access as PA
from .technology.axes import AxisT

INT_RANGE = range(-32768, 32768)
DWORD_MAX = 0xFFFF_FFFF


def _int_input(value: Any) -> int:
    """ParameterNumber / Index (INT): a whole number in the INT range, else 16#8043."""
    x = as_int(value)
    if x is None or x not in INT_RANGE:
        raise InstructionError(FE.ILLEGAL_PARAMETER)
    return x


def _done(owner: Any, **extra: Any) -> Job:
    """A command the technology carries out at once: done in the call of its rising edge."""
    job = Job(JobKind.RESET, owner=owner)       # the kernel's kind of a job that never moves the axis
    job.extra.update(extra)
    job.finish(JobState.DONE)
    return job


class _ParameterFB(ExecuteInstruction):
    TECHNOLOGIES = ALL_AXES

    def _final_for(self, job: Job):
        if job.state == JobState.DONE:
            return ("Done", job.extra.get("warning", 0), 0)
        return super()._final_for(job)


class MC_ReadSysParameter(_ParameterFB):  # noqa: N801 - instruction name of the manual
    """FB 406: read a parameter or system variable of an axis by number (§6.7.4)."""

    INPUTS = {"Axis": 0, "Execute": False, "ParameterNumber": 0, "Index": 1}
    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0, "Value": 0.0, "ValueDInt": 0,
               "ValueDword1": 0, "ValueDword2": 0, "ValueBool": False}

    def _start(self, to: AxisT) -> Job:
        number, index = _int_input(self.ParameterNumber), _int_input(self.Index)
        code, output, value = PA.read(to, number, index)
        if code:
            raise InstructionError(code)
        return _done(self, output=output, value=value)

    def _final_for(self, job: Job):
        object.__setattr__(self, "_result", (job.extra.get("output"), job.extra.get("value")))
        return super()._final_for(job)

    def _show(self, output: str, error_id: int, error_info: int) -> None:
        super()._show(output, error_id, error_info)
        result = self.__dict__.get("_result")
        if output == "Done" and result is not None and result[0] is not None:
            name, value = result
            if name == PA.OUT_DWORD2:
                value = int(value)
                self._out(ValueDword1=(value >> 32) & DWORD_MAX, ValueDword2=value & DWORD_MAX)
            else:
                self._out(**{name: value})


class MC_WriteParameter(_ParameterFB):  # noqa: N801
    """FB 407: change a parameter of an axis by number (§6.7.5); Done with ErrorID 16#0020 when the change
    waits for a restart of the axis (MC_Reset Restart = TRUE).  A deactivated axis (MC_ActivateTO) takes
    no changes: 16#8086, the table of FB 407 has no 8045."""

    INPUTS = {"Axis": 0, "Execute": False, "ParameterNumber": 0, "Index": 1, "Value": 0.0, "ValueDInt": 0,
              "ValueDword1": 0, "ValueDword2": 0, "ValueBool": False}
    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0}
    WHILE_DEACTIVATED = True

    def _start(self, to: AxisT) -> Job:
        number, index = _int_input(self.ParameterNumber), _int_input(self.Index)
        acc = PA.resolve(to, number, index)
        if isinstance(acc, int):
            raise InstructionError(acc)
        code = PA.write(to, number, index, self._value(PA.input_of(acc.parameter)))
        if code >= 0x8000:
            raise InstructionError(code)
        return _done(self, warning=code)

    def _value(self, output: str) -> Any:
        """The input that carries the parameter's data type (the others are not evaluated)."""
        if output == PA.OUT_REAL:
            return self.Value
        raw = {PA.OUT_DINT: self.ValueDInt, PA.OUT_DWORD1: self.ValueDword1}.get(output)
        if output == PA.OUT_DWORD2:
            return (self.ValueDword1, self.ValueDword2)
        x = as_int(raw)
        return raw if x is None or isinstance(raw, float) else x


__all__ = ["MC_ReadSysParameter", "MC_WriteParameter"]
