"""MC_ChangeDynamic, MC_ReadParam and MC_WriteParam (S7-1200 Motion Control V6 §11.1.10 - §11.1.12).

VARIANT pointers
----------------
``Parameter`` is a reference to one tag of a positioning axis, ``axis.ref("StatusBits.Enable")`` (a
:class:`~plcmotion.kernel.tag_views.TagRef`, what ``"Axis_1".StatusBits.Enable`` is at a VARIANT input in a
PLC program).  ``Value`` stands for the user-program tag the other pointer designates: a typed variable
of :mod:`plcmotion.s7_1200.variables` (``Bool``, ``Int``, ``DInt``, ``UDInt``, ``Real``); MC_WriteParam
also takes a plain ``bool`` (Bool), ``int`` (DInt) or ``float`` (Real).

* ``Parameter`` that is not a TagRef: 16#8410/16#0029 (does not point to the technology DB).
* MC_ReadParam reads the tags marked RP in §12.9 (Position, Velocity, ActualPosition, ActualVelocity,
  StatusPositioning.*, StatusDrive.*, StatusSensor.*, StatusBits.*, ErrorBits.* except ErrorBits.HWLimit,
  which is RCCP only); any other tag: 16#8410/16#002A.
* MC_WriteParam writes the tags marked RW (at any time) and WP (only while the axis is disabled,
  ``axis.state == "disabled"``: not enabled, not waiting for "Drive ready" after the enable, not in the
  stop that follows a disable -- otherwise 16#8410/16#002C); status tags and tags with access R only:
  16#8410/16#002B.
* Data types must be the same (§12.8 16#8410/16#0028), no widening: an INT tag needs an ``Int``, a REAL
  tag a ``Real`` or a ``float`` (a plain ``int`` is a DINT and does not match a REAL tag); a ``str``,
  ``None`` or an ``int`` beyond the DINT range has no admissible data type (16#0028 as well).  For
  MC_ReadParam's InOut ``Value`` anything but a typed variable is a programming error (``TypeError``),
  the way a constant at an InOut parameter does not compile.
* A REAL ``Value`` of MC_WriteParam that is NaN or infinite: 16#8411/16#0002; beyond +-1.0E12:
  16#8411/16#0005 / 16#0006 (codes of the V7 list).
* Order of the checks: Parameter (16#0029, 16#002A/16#002B), data type (16#0028), Value (16#8411), axis
  state (16#002C).  16#8410/16#0002 and /16#000B have no counterpart here: a TagRef always designates an
  existing tag of a configured axis.

Decisions (where the manual is silent)
--------------------------------------
* MC_WriteParam and MC_ChangeDynamic complete in the call with the rising edge of Execute: Done
  ("value was written to the technology DB") at that call, latched while Execute stays TRUE, otherwise
  for exactly that one call (§9.5.2).  MC_WriteParam's Busy is never TRUE; MC_ChangeDynamic has no Busy.
* The written value takes effect as the tag's effective code says (§12.9: PROFIdrive/analog at the next
  servo cycle, PTO e.g. at the next motion command start), exactly as a direct assignment.  The value is
  not range-checked by MC_WriteParam: a value outside the tag's range (e.g. Acceleration -1.0) is written,
  Done is shown, and the axis reports the tag's configuration error 16#86xx at the moment the value
  takes effect (at the instruction that triggers that moment and at MC_Power, §9.6).
* MC_ChangeDynamic converts with the relations of §5.4.4.4, using the values of the technology DB at the
  call (the tag values, including WP changes that are not effective yet):
  ``Acceleration = (MaxVelocity - start/stop velocity) / RampUpTime``, likewise Deceleration
  (RampDownTime) and EmergencyDeceleration (EmergencyRampTime); ``Jerk = Acceleration / JerkTime``.
  The start/stop velocity is DynamicLimits.MinVelocity on a PTO axis and 0 on PROFIdrive/analog axes
  (§5.4.4.4).  When RampUpTime and JerkTime are changed in the same call, the jerk is computed from the
  new acceleration, so that the DB afterwards satisfies both relations.  The default inputs (5.0, 5.0,
  2.0, 0.25 s) reproduce the default dynamics 48 / 48 / 120 / 192 with MaxVelocity 250 and start/stop
  velocity 10.
* Only the times whose Change input is TRUE are checked (16#840C..16#840F: 16#0002 invalid number,
  16#000A <= 0, 16#0005 > 1.0E12).  The V7 list prints 16#0005 under 16#840C only; it is applied to all
  four times alike.  Nothing is written when any check fails.
* The conversion itself can fail: a velocity span MaxVelocity - start/stop velocity that is not a positive
  number gives 16#8208 (16#0002 / 16#000A), an acceleration that is not a positive number when the jerk is
  converted gives 16#8209 (16#0002 / 16#000A).  §12.8 lists both as errors without axis stop with the
  remedy "correct the value; restart the command", and MC_ChangeDynamic is the only instruction that
  computes with these values.  Block parameter errors are checked first (decision 12).
* Results outside the admissible range of the tags are not errors of MC_ChangeDynamic (§11.1.10.1 note):
  they become the configuration errors of those tags when they take effect.
* MC_ReadParam reads at every call while Enable = TRUE (the value is determined when the instruction is
  called, legend "RP"): Valid and Busy are TRUE from the first call with Enable = TRUE.  An error sets
  Error with ErrorID/ErrorInfo, Valid and Busy FALSE, and stops the updates until Enable goes FALSE (the
  remedy is "restart the command").  Enable = FALSE resets all outputs; ``Value`` keeps its last value.
"""
from __future__ import annotations

import math
import numbers
from typing import Any

import numpy as np

from ..kernel.axis import PositioningAxis
from ..kernel.jobs import Job, JobKind, JobState
from ..kernel.schema import E12
from ..kernel.tag_views import TagAccessError, TagRef
from . import errors as E
from ..fb import ProgramError, as_number
from .base import ExecuteInstruction, Instruction, InstructionError, as_bool
from .variables import Variable, plain, type_of

__all__ = ["MC_ChangeDynamic", "MC_ReadParam", "MC_WriteParam", "dynamics_from_times"]

# --- ErrorIDs / ErrorInfos of §12.8 used here (errors.py has no names for them) ----------------------------
VELOCITY_SPAN = 0x8208          # difference between maximum and start/stop velocity invalid
ACCELERATION = 0x8209           # invalid acceleration
RAMP_UP_TIME = 0x840C
RAMP_DOWN_TIME = 0x840D
EMERGENCY_RAMP_TIME = 0x840E
JERK_TIME = 0x840F
PARAMETER = 0x8410
VALUE = 0x8411

DATA_TYPE_MISMATCH = 0x0028
NOT_TECHNOLOGY_DB = 0x0029
NOT_READABLE = 0x002A
NOT_WRITABLE = 0x002B
NOT_DISABLED = 0x002C

#: (Change input, time input, ErrorID, tag written) of MC_ChangeDynamic
_TIMES = (
    ("ChangeRampUp", "RampUpTime", RAMP_UP_TIME, "DynamicDefaults.Acceleration"),
    ("ChangeRampDown", "RampDownTime", RAMP_DOWN_TIME, "DynamicDefaults.Deceleration"),
    ("ChangeEmergency", "EmergencyRampTime", EMERGENCY_RAMP_TIME, "DynamicDefaults.EmergencyDeceleration"),
    ("ChangeJerkTime", "JerkTime", JERK_TIME, "DynamicDefaults.Jerk"),
)


def _done_job(owner: Any) -> Job:
    """A job that is complete when it is created (it never reaches the motion of the axis)."""
    job = Job(JobKind.RESET, owner=owner)        # RESET: the kernel's kind of jobs that never move the axis
    job.finish(JobState.DONE)
    return job


def _check_time(value: Any, error_id: int) -> float:
    """A time input of MC_ChangeDynamic: a number, > 0, <= 1.0E12 (§12.8, V7 16#0005)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise InstructionError(error_id, E.INVALID_FORMAT)   # not a REAL (base.as_real would parse "5")
    x = as_number(value)                     # an integer beyond the REAL range counts as > 1.0E12
    if x is None:
        raise InstructionError(error_id, E.INVALID_FORMAT)
    if x <= 0.0:
        raise InstructionError(error_id, E.NOT_POSITIVE)
    if x > E12:
        raise InstructionError(error_id, E.ABOVE_1E12)
    return x


def _positive(value: float, error_id: int) -> float:
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real) or not math.isfinite(value):
        raise InstructionError(error_id, E.INVALID_FORMAT)
    if value <= 0.0:
        raise InstructionError(error_id, E.NOT_POSITIVE)
    return float(value)


def dynamics_from_times(axis: PositioningAxis, *, ramp_up: float | None = None, ramp_down: float | None = None,
                        emergency: float | None = None, jerk_time: float | None = None) -> dict[str, float]:
    """Tag values for the given times (None: not changed) with the relations of §5.4.4.4.

    Raises InstructionError 16#8208 / 16#8209 when the conversion has no valid basis.
    """
    out: dict[str, float] = {}
    if ramp_up is not None or ramp_down is not None or emergency is not None:
        start_stop = axis.cfg["DynamicLimits.MinVelocity"] if axis.pto else 0.0
        span = _positive(axis.cfg["DynamicLimits.MaxVelocity"] - start_stop, VELOCITY_SPAN)
        for path, time in (("DynamicDefaults.Acceleration", ramp_up), ("DynamicDefaults.Deceleration", ramp_down),
                           ("DynamicDefaults.EmergencyDeceleration", emergency)):
            if time is not None:
                out[path] = span / time
    if jerk_time is not None:
        acceleration = out.get("DynamicDefaults.Acceleration", axis.cfg["DynamicDefaults.Acceleration"])
        out["DynamicDefaults.Jerk"] = _positive(acceleration, ACCELERATION) / jerk_time
    return out


class MC_ChangeDynamic(ExecuteInstruction):  # noqa: N801 - instruction name of the manual
    """Change acceleration, deceleration, emergency deceleration and jerk through ramp times (§11.1.10).

    Inputs: Axis, Execute, ChangeRampUp/RampUpTime (5.0 s), ChangeRampDown/RampDownTime (5.0 s),
    ChangeEmergency/EmergencyRampTime (2.0 s), ChangeJerkTime/JerkTime (0.25 s).
    Outputs: Done, Error, ErrorID, ErrorInfo (completes at once: no Busy, no CommandAborted, §9.5.2).
    """

    INPUTS = {"Axis": None, "Execute": False, "ChangeRampUp": False, "RampUpTime": 5.0, "ChangeRampDown": False,
              "RampDownTime": 5.0, "ChangeEmergency": False, "EmergencyRampTime": 2.0, "ChangeJerkTime": False,
              "JerkTime": 0.25}
    OUTPUTS = {"Done": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}

    def _start(self, axis: PositioningAxis) -> Job:
        times: dict[str, float | None] = {}
        for change, name, error_id, _path in _TIMES:
            selected = as_bool(self, change, getattr(self, change))
            times[name] = _check_time(getattr(self, name), error_id) if selected else None
        values = dynamics_from_times(axis, ramp_up=times["RampUpTime"], ramp_down=times["RampDownTime"],
                                     emergency=times["EmergencyRampTime"], jerk_time=times["JerkTime"])
        for path, value in values.items():
            axis.write_tag(path, value)          # RW tags: effective per §12.9.11 like a direct assignment
        return _done_job(self)

    def _set_busy(self, busy: bool) -> None:
        """No Busy output: the command is complete in the call that starts it."""


def _tag_ref(fb: Instruction) -> TagRef:
    ref = getattr(fb, "Parameter", None)
    if not isinstance(ref, TagRef) or not isinstance(ref.axis, PositioningAxis):
        raise InstructionError(PARAMETER, NOT_TECHNOLOGY_DB)
    ref.axis.ctl._instances.setdefault(id(fb), fb)     # reinitialised with the controller (STOP -> RUN)
    return ref


def _check_real_value(value: Any) -> float:
    value = as_number(value)                 # a number beyond the REAL range is above 1.0E12
    if value is None:
        raise InstructionError(VALUE, E.INVALID_FORMAT)
    if value > E12:
        raise InstructionError(VALUE, E.ABOVE_1E12)
    if value < -E12:
        raise InstructionError(VALUE, E.BELOW_MINUS_1E12)
    return value


class MC_WriteParam(ExecuteInstruction):  # noqa: N801
    """Write a tag of the positioning axis (§11.1.12): RW tags at any time, WP tags while disabled.

    Inputs: Parameter (``axis.ref("<tag>")``), Value (typed variable or bool/int/float), Execute.
    Outputs: Done, Busy, Error, ErrorID, ErrorInfo.
    """

    INPUTS = {"Parameter": None, "Value": None, "Execute": False}
    OUTPUTS = {"Done": False, "Busy": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}

    def _axis(self) -> PositioningAxis:
        return _tag_ref(self).axis

    def _start(self, axis: PositioningAxis) -> Job:
        ref: TagRef = self.Parameter
        if ref.status or ref.access not in ("RW", "WP"):
            raise InstructionError(PARAMETER, NOT_WRITABLE)
        value_type = type_of(self.Value)
        if value_type is None or value_type != ref.data_type:
            raise InstructionError(PARAMETER, DATA_TYPE_MISMATCH)
        if value_type == "Real":
            raw = self.Value.value if isinstance(self.Value, Variable) else self.Value
            value = _check_real_value(raw)
        else:
            value = plain(self.Value)
        if ref.access == "WP" and axis.state != "disabled":
            raise InstructionError(PARAMETER, NOT_DISABLED)
        try:
            axis.write_tag(ref.path, value, via_write_param=True)
        except TagAccessError:                       # pragma: no cover - excluded by the access check
            raise InstructionError(PARAMETER, NOT_WRITABLE) from None
        except TypeError:                            # pragma: no cover - excluded by the data type check
            raise InstructionError(PARAMETER, DATA_TYPE_MISMATCH) from None
        return _done_job(self)


_CONVERT = {"Bool": bool, "Int": int, "DInt": int, "UDInt": int, "Real": float}


class MC_ReadParam(Instruction):  # noqa: N801
    """Read a status tag of the positioning axis into ``Value`` at every call while Enable = TRUE (§11.1.11).

    Inputs: Enable, Parameter (``axis.ref("<tag>")``), Value (InOut: a typed variable).
    Outputs: Valid, Busy, Error, ErrorID, ErrorInfo.
    """

    INPUTS = {"Enable": False, "Parameter": None, "Value": None}
    OUTPUTS = {"Valid": False, "Busy": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_failed", False)

    def _evaluate(self) -> None:
        enable = as_bool(self, "Enable", self.Enable)
        if not enable:
            object.__setattr__(self, "_failed", False)
            self._out(Valid=False, Busy=False, Error=False, ErrorID=0, ErrorInfo=0)
            return
        if self._failed:
            return                                   # error shown until Enable goes FALSE
        target = self.Value
        if not isinstance(target, Variable):
            raise ProgramError(f"MC_ReadParam.Value is an InOut VARIANT: give a typed variable "
                            f"(plcmotion.s7_1200.variables Bool/Int/DInt/UDInt/Real), not {target!r}")
        try:
            ref = _tag_ref(self)
            if not ref.readable_by_read_param:
                raise InstructionError(PARAMETER, NOT_READABLE)
            if target.data_type != ref.data_type:
                raise InstructionError(PARAMETER, DATA_TYPE_MISMATCH)
        except InstructionError as err:
            object.__setattr__(self, "_failed", True)
            self._out(Valid=False, Busy=False, Error=True, ErrorID=err.error_id, ErrorInfo=err.error_info)
            return
        target.value = _CONVERT[ref.data_type](ref.read())
        self._out(Valid=True, Busy=True, Error=False, ErrorID=0, ErrorInfo=0)
