"""Function block call semantics shared by the PLCopen-style dialects (S7-1200, S7-1500, ...).

An instruction instance is a plain object holding its inputs and outputs (the instance DB).  Calling it
sets the given inputs and evaluates it once.  Inputs keep their values between calls.  Input values are
checked when a job starts (rising edge of Execute) and a bad value becomes the manual's ErrorID, never
an exception; only programming mistakes (an input name that does not exist, a non-boolean for a BOOL
input) raise, which stops the controller like a faulty program would.

Output timing (PLCopen, S7-1200 V6 §9.5.2, S7-1500 the same): Busy while the job runs, FALSE at its end
whatever Execute is; then exactly one of Done / CommandAborted / Error, latched while Execute stays TRUE,
otherwise shown for exactly one call.

A dialect subclasses these with its axis type check and its ErrorID table (``_axis_error``,
``_fault_codes``).
"""
from __future__ import annotations

import math
import numbers
from typing import Any, ClassVar

import numpy as np

from .kernel.axis import PositioningAxis
from .kernel.faults import Fault
from .kernel.jobs import Job, JobState
from .kernel.power import ENABLED as _ENABLED, PowerControl
from .kernel.runtime import RUN as _RUN

_AXIS_POWER = PositioningAxis.power

_BOOL_TYPES = (bool, np.bool_)


class ProgramError(TypeError):
    """A programming mistake in an instruction call (an input name that does not exist, a non-boolean
    at a BOOL input, a constant at an InOut): raised like a program that would not compile."""


def as_bool(fb: "Instruction", name: str, value: Any) -> bool:
    if isinstance(value, _BOOL_TYPES):
        return bool(value)
    if isinstance(value, (int, np.integer)) and not isinstance(value, bool) and value in (0, 1):
        return bool(value)
    raise ProgramError(f"{type(fb).__name__}.{name} is a BOOL input; got {value!r}")


def as_real(value: Any) -> float | None:
    """REAL input value, None for an invalid number format (NaN, infinity, not a number, an integer
    beyond the REAL range)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        return None
    try:
        x = float(value)
    except (OverflowError, ValueError, TypeError):
        return None
    return x if math.isfinite(x) else None


def as_number(value: Any) -> float | None:
    """Like ``as_real``, but a number beyond the REAL range (a Python int such as 10**400) is +-inf, so
    that the range check of the input (e.g. > 1.0E12) names it; NaN, infinity and non-numbers: None."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        return None
    try:
        x = float(value)
    except OverflowError:
        return math.inf if value > 0 else -math.inf
    except (ValueError, TypeError):
        return None
    return x if math.isfinite(x) else None


def as_int(value: Any) -> int | None:
    """INT input value, None when not a whole number."""
    if isinstance(value, _BOOL_TYPES):
        return None
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)) and math.isfinite(value) and float(value).is_integer():
        return int(value)
    return None


class InstructionError(Exception):
    """Raised inside an instruction to end the command with (ErrorID, ErrorInfo)."""

    def __init__(self, error_id: int, error_info: int = 0):
        super().__init__(f"16#{error_id:04X}/16#{error_info:04X}" if error_info else f"16#{error_id:04X}")
        self.error_id = error_id
        self.error_info = error_info


class Instruction:
    """Base of all instructions: declared inputs/outputs, call semantics, instance registration."""

    INPUTS: ClassVar[dict[str, Any]] = {}
    OUTPUTS: ClassVar[dict[str, Any]] = {}

    def __init__(self, **inputs: Any):
        for name, default in self.INPUTS.items():
            object.__setattr__(self, name, default)
        self._reinit()
        self._set_inputs(inputs)

    def _reinit(self) -> None:
        """Outputs and internal state back to their start values (new instance DB, CPU STOP -> RUN)."""
        for name, default in self.OUTPUTS.items():
            object.__setattr__(self, name, default)

    def _set_inputs(self, inputs: dict[str, Any]) -> None:
        if inputs.keys() <= self.INPUTS.keys():
            self.__dict__.update(inputs)               # the common case, called every cycle: one update
            return
        for name in inputs:
            if name not in self.INPUTS:
                raise ProgramError(f"{type(self).__name__} has no input {name!r}; "
                                   f"inputs: {', '.join(self.INPUTS)}")

    def __setattr__(self, name: str, value: Any) -> None:
        if name in self.OUTPUTS:
            raise AttributeError(f"{type(self).__name__}.{name} is an output")
        object.__setattr__(self, name, value)

    def _out(self, **values: Any) -> None:
        self.__dict__.update(values)

    #: the class has a steady-state shortcut (``_steady``); set per class by the bases that have one
    _STEADY: ClassVar[bool] = False

    def __call__(self, **inputs: Any) -> "Instruction":
        if inputs:
            if inputs.keys() <= self.INPUTS.keys():
                self.__dict__.update(inputs)           # the common case, called every cycle: one update
            else:
                self._set_inputs(inputs)
        if self._STEADY and self._steady():
            return self
        try:
            self._evaluate()
        except ProgramError:
            raise
        except Exception as exc:       # a defect behind the instruction never reaches the user program
            self._internal_failure(exc)
        return self

    def _steady(self) -> bool:
        """True when this call, its inputs set, would change nothing: it returns at once (steady state)."""
        return False

    def _internal_failure(self, exc: Exception) -> None:
        """An unexpected exception while the instruction ran: the axis it works on is stopped with the
        internal-error alarm (16#8FFF, S7-1200 V6 §12.8 / S7-1500 'internal error') and the instruction
        shows the dialect's internal-error ErrorID."""
        from .kernel import faults as F
        fault = F.alarm(F.INTERNAL, "", F.Reaction.REMOVE_ENABLE, f"{type(exc).__name__}: {exc}")
        object.__setattr__(self, "_internal_fault", fault)
        for name in ("Axis", "Slave", "Master"):
            to = self.__dict__.get(name)
            handler = getattr(to, "_internal_error", None)
            if callable(handler):
                try:
                    handler(exc)
                except Exception:  # noqa: BLE001 - the axis is stopped as far as it can be
                    pass
                break
        try:
            error_id, error_info = self._fault_codes(fault)
        except Exception:  # noqa: BLE001
            error_id, error_info = 0x8FFF, 0
        self._show_internal(error_id, error_info)

    def _show_internal(self, error_id: int, error_info: int) -> None:
        values: dict[str, Any] = {name: default for name, default in self.OUTPUTS.items()
                                  if isinstance(default, bool)}
        if "Error" in self.OUTPUTS:
            values["Error"] = True
        if "ErrorID" in self.OUTPUTS:
            values["ErrorID"] = error_id
        if "ErrorInfo" in self.OUTPUTS:
            values["ErrorInfo"] = error_info
        self._out(**values)

    def _evaluate(self) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    #: the technology object type(s) the Axis input takes (set by the dialect)
    AXIS_TYPES: ClassVar[tuple[type, ...]] = ()

    def _axis_error(self, kind: str) -> InstructionError:
        """ErrorID for an Axis input of the wrong kind: "other_type" or "not_a_to" (dialect)."""
        raise NotImplementedError  # pragma: no cover

    def _fault_codes(self, fault: Fault) -> tuple[int, int]:
        """(ErrorID, ErrorInfo) of a kernel fault (dialect)."""
        raise NotImplementedError  # pragma: no cover

    def _register(self, to: Any) -> None:
        instances = to.ctl._instances
        if id(self) not in instances:
            instances[id(self)] = self

    def _accept(self, value: Any, types: tuple[type, ...]) -> bool:
        return isinstance(value, types) and self._family_ok(value)

    def _family_ok(self, to: Any) -> bool:
        return True

    def _axis(self, name: str = "Axis") -> Any:
        """The technology object at input ``name``, or the dialect's InstructionError."""
        axis = getattr(self, name, None)
        if self._accept(axis, self.AXIS_TYPES):
            self._register(axis)
            return axis
        if axis is not None and hasattr(axis, "ctl") and hasattr(axis, "tag"):
            raise self._axis_error("other_type")
        raise self._axis_error("not_a_to")

    @property
    def outputs(self) -> dict[str, Any]:
        return {name: getattr(self, name) for name in self.OUTPUTS}

    def __repr__(self) -> str:
        outs = " ".join(f"{k}={v}" for k, v in self.outputs.items() if v)
        return f"<{type(self).__name__} {outs}>"


_JOB_BUSY = JobState.BUSY

_DONE_OUTPUTS = {"Done": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0,
                 "ErrorInfo": 0}


class ExecuteInstruction(Instruction):
    """Instructions started by a rising edge at Execute and ending with Done/CommandAborted/Error."""

    INPUTS = {"Axis": None, "Execute": False}
    OUTPUTS = dict(_DONE_OUTPUTS)

    #: whether a call may take the steady-state shortcut of ``__call__`` (set per class: only for
    #: classes that keep this class's evaluation, see ``__init_subclass__``)
    _STEADY: ClassVar[bool] = True
    #: the class has its own ``_running`` hook (the shortcut calls it as the evaluation would)
    _RUNNING: ClassVar[bool] = False
    #: showing the held final output again writes the same outputs (the shortcut may skip it)
    _RESHOW: ClassVar[bool] = True
    #: the class shows Busy (``_set_busy`` writes it)
    _HAS_BUSY: ClassVar[bool] = True

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        base = ExecuteInstruction
        cls._STEADY = ("Execute" in cls.INPUTS and cls._evaluate is base._evaluate
                       and cls._update is base._update and cls._set_busy is base._set_busy)
        cls._RUNNING = cls._running is not base._running
        # the base's _show / _clear_outputs (and MC_Home's reference mark) depend on the final output alone
        cls._RESHOW = (cls._show in (base._show, ReferenceMarkOutput._show)
                       and cls._clear_outputs in (base._clear_outputs, ReferenceMarkOutput._clear_outputs))
        cls._HAS_BUSY = "Busy" in cls.OUTPUTS

    def _steady(self) -> bool:
        # Idle, running with Busy shown (only the class's _running hook runs), or a final output held by
        # Execute = TRUE and shown already.  Execute is compared by identity with the last sampled value, a
        # Python bool, so any other value (a numpy bool, an int, a bad value) takes the full evaluation.
        d = self.__dict__
        if d["Execute"] is d["_prev_execute"]:
            job = d["_job"]
            if d["_final"] is None:
                if job is None:
                    return True                               # idle: _update has nothing to do
                if (job.state is _JOB_BUSY and d["_busy_axis"] is not None
                        and (d["Busy"] is True or not self._HAS_BUSY)):
                    if self._RUNNING:                         # as in the evaluation, defects contained
                        try:
                            self._running(d["_prev_execute"])
                        except ProgramError:
                            raise
                        except Exception as exc:
                            self._internal_failure(exc)
                    return True
            elif d["_latched"] and d["_shown"] and d["_prev_execute"] is True and self._RESHOW:
                return True                                   # held final output, already shown
        return False

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_prev_execute", False)
        object.__setattr__(self, "_job", None)
        object.__setattr__(self, "_final", None)       # (output name, ErrorID, ErrorInfo) once ended
        object.__setattr__(self, "_latched", False)
        object.__setattr__(self, "_shown", False)
        object.__setattr__(self, "_busy_axis", None)

    # --- what subclasses provide -----------------------------------------------------------------------
    def _start(self, axis: Any) -> Job | None:
        """Validate inputs (raise InstructionError) and hand a job to the axis."""
        raise NotImplementedError  # pragma: no cover

    def _running(self, execute: bool) -> None:
        """Per-call hook while the job is busy (subclass specific outputs)."""

    # --- evaluation ------------------------------------------------------------------------------------
    def _evaluate(self) -> None:
        execute = as_bool(self, "Execute", self.Execute)
        edge = execute and not self._prev_execute
        object.__setattr__(self, "_prev_execute", execute)
        if edge:
            self._begin()
        self._update(execute)

    def _begin(self) -> None:
        self._clear_outputs()
        object.__setattr__(self, "_job", None)
        object.__setattr__(self, "_final", None)
        object.__setattr__(self, "_shown", False)
        try:
            axis = self._axis()
            job = self._start(axis)
        except InstructionError as err:
            self._end("Error", err.error_id, err.error_info)
            return
        object.__setattr__(self, "_job", job)

    def _clear_outputs(self) -> None:
        for name, default in self.OUTPUTS.items():
            object.__setattr__(self, name, default)

    def _show_internal(self, error_id: int, error_info: int) -> None:
        job = self._job
        if job is not None and job.busy:
            job.finish(JobState.ERROR, self.__dict__.get("_internal_fault"))
        object.__setattr__(self, "_job", None)
        self._end("Error", error_id, error_info)
        object.__setattr__(self, "_shown", True)
        self._show("Error", error_id, error_info)

    def _set_busy(self, busy: bool) -> None:
        if "Busy" in self.OUTPUTS:
            self._out(Busy=busy)
        axis = self._busy_axis
        if busy and axis is None:
            job_axis = getattr(self, "Axis", None) or getattr(self, "Slave", None)
            if job_axis is not None and hasattr(job_axis, "busy_commands"):
                job_axis.busy_commands.add(id(self))
                object.__setattr__(self, "_busy_axis", job_axis)
        elif not busy and axis is not None:
            axis.busy_commands.discard(id(self))
            object.__setattr__(self, "_busy_axis", None)

    def _end(self, output: str, error_id: int = 0, error_info: int = 0) -> None:
        object.__setattr__(self, "_final", (output, error_id, error_info))
        object.__setattr__(self, "_latched", bool(self._prev_execute))
        object.__setattr__(self, "_shown", False)
        self._set_busy(False)

    def _final_for(self, job: Job) -> tuple[str, int, int] | None:
        """Which final output a finished job shows (None: show nothing)."""
        if job.state == JobState.DONE:
            return ("Done", 0, 0)
        if job.state == JobState.ABORTED:
            return ("CommandAborted", 0, 0)
        assert job.fault is not None
        error_id, error_info = self._fault_codes(job.fault)
        return ("Error", error_id, error_info)

    def _update(self, execute: bool) -> None:
        job = self._job
        if job is not None and self._final is None:
            if job.state == JobState.BUSY:
                self._set_busy(True)
                self._running(execute)
                return
            final = self._final_for(job)
            object.__setattr__(self, "_job", None)
            if final is None:
                self._clear_outputs()
                self._set_busy(False)
                return
            self._end(*final)
        final = self._final
        if final is None:
            return
        show = execute if self._latched else not self._shown
        if show:
            output, error_id, error_info = final
            self._show(output, error_id, error_info)
            object.__setattr__(self, "_shown", True)
        else:
            self._clear_outputs()
            object.__setattr__(self, "_final", None)

    def _show(self, output: str, error_id: int, error_info: int) -> None:
        self._clear_outputs()
        values = {output: True, "ErrorID": error_id}
        if "ErrorInfo" in self.OUTPUTS:
            values["ErrorInfo"] = error_info
        self._out(**values)


class JogInstruction(Instruction):
    """MC_MoveJog machinery: a jog job runs while JogForward or JogBackward is TRUE.

    Velocity changes are taken over while a jog input is TRUE.  Both inputs TRUE brake the axis and end
    in an error.  A dialect provides ``_jog_velocity`` (validated speed), ``_jog_both`` (ErrorID,
    ErrorInfo) and ``_jog_job`` (the kernel job).
    """

    def _jog_velocity(self, axis: Any) -> float:
        raise NotImplementedError  # pragma: no cover

    def _jog_both(self) -> tuple[int, int]:
        raise NotImplementedError  # pragma: no cover

    def _jog_job(self, axis: Any, velocity: float, controlled: bool) -> Job:
        raise NotImplementedError  # pragma: no cover

    def _reinit(self) -> None:
        super()._reinit()
        for name, value in (("_prev_f", False), ("_prev_b", False), ("_job", None), ("_final", None),
                            ("_latched", False), ("_shown", False), ("_busy_axis", None)):
            object.__setattr__(self, name, value)

    def _set_busy(self, busy: bool) -> None:
        ExecuteInstruction._set_busy(self, busy)  # type: ignore[arg-type]

    def _clear(self) -> None:
        for name, default in self.OUTPUTS.items():
            object.__setattr__(self, name, default)

    def _show_internal(self, error_id: int, error_info: int) -> None:
        job = self._job
        if job is not None and job.busy:
            job.finish(JobState.ERROR, self.__dict__.get("_internal_fault"))
        object.__setattr__(self, "_job", None)
        self._clear()
        self._fail(error_id, error_info, bool(self._prev_f or self._prev_b))
        self._update(bool(self._prev_f or self._prev_b))

    def _fail(self, error_id: int, error_info: int, held: bool) -> None:
        object.__setattr__(self, "_final", ("Error", error_id, error_info))
        object.__setattr__(self, "_latched", held)
        object.__setattr__(self, "_shown", False)
        self._set_busy(False)

    def _evaluate(self) -> None:
        fwd = as_bool(self, "JogForward", self.JogForward)
        bwd = as_bool(self, "JogBackward", self.JogBackward)
        rise = (fwd and not self._prev_f) or (bwd and not self._prev_b)
        object.__setattr__(self, "_prev_f", fwd)
        object.__setattr__(self, "_prev_b", bwd)
        held = fwd or bwd
        job: Job | None = self._job
        try:
            axis = self._axis()
        except InstructionError as err:
            if rise:
                self._clear()
                self._fail(err.error_id, err.error_info, held)
            self._update(held)
            return
        if fwd and bwd:
            if job is not None and job.busy:
                axis.release_jog(job)
                object.__setattr__(self, "_job", None)
                self._clear()
                self._fail(*self._jog_both(), True)
            elif rise:
                self._clear()
                self._fail(*self._jog_both(), True)
        elif rise:
            self._clear()
            object.__setattr__(self, "_final", None)
            object.__setattr__(self, "_job", None)
            try:
                v = self._jog_velocity(axis)
                controlled = as_bool(self, "PositionControlled", self.PositionControlled)
                new = self._jog_job(axis, v if fwd else -v, controlled)
            except InstructionError as err:
                self._fail(err.error_id, err.error_info, True)
            else:
                axis.submit(new)
                object.__setattr__(self, "_job", new)
        elif job is not None and job.busy and not job.jog_released:
            if not held:
                axis.release_jog(job)
            else:
                v = as_real(self.Velocity)
                if v is not None and abs(v) != abs(job.velocity):
                    try:
                        v = self._jog_velocity(axis)
                    except InstructionError as err:
                        axis.release_jog(job)
                        object.__setattr__(self, "_job", None)
                        self._clear()
                        self._fail(err.error_id, err.error_info, True)
                    else:
                        axis.change_jog_velocity(job, v if job.velocity > 0 else -v)
        self._update(held)

    def _update(self, held: bool) -> None:
        job: Job | None = self._job
        if job is not None and self._final is None:
            if job.state == JobState.BUSY:
                self._set_busy(True)
                self._out(InVelocity=job.in_velocity)
                return
            object.__setattr__(self, "_job", None)
            self._set_busy(False)
            self._clear()
            if job.state == JobState.DONE:
                return
            if job.state == JobState.ABORTED:
                final = ("CommandAborted", 0, 0)
            else:
                assert job.fault is not None
                final = ("Error", *self._fault_codes(job.fault))
            object.__setattr__(self, "_final", final)
            object.__setattr__(self, "_latched", held)
            object.__setattr__(self, "_shown", False)
        final = self._final
        if final is None:
            return
        show = held if self._latched else not self._shown
        if show:
            self._clear()
            output, error_id, error_info = final
            values = {output: True, "ErrorID": error_id}
            if "ErrorInfo" in self.OUTPUTS:
                values["ErrorInfo"] = error_info
            self._out(**values)
            object.__setattr__(self, "_shown", True)
        else:
            self._clear()
            object.__setattr__(self, "_final", None)


class PowerInstruction(Instruction):
    """MC_Power machinery: Enable, StartMode, StopMode -> Status, Busy, Error, ErrorID (dialects add
    ErrorInfo).  A dialect provides ``_mode_error(input name)`` and ``_alarm_codes(axis)``."""

    INPUTS = {"Axis": None, "Enable": False, "StartMode": 1, "StopMode": 0}

    def _mode_error(self, name: str) -> tuple[int, int]:
        raise NotImplementedError  # pragma: no cover

    def _alarm_codes(self, axis: Any) -> tuple[int, int]:
        raise NotImplementedError  # pragma: no cover

    #: the class keeps this evaluation, so the steady-state shortcut of ``__call__`` applies
    _STEADY: ClassVar[bool] = True

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        base = PowerInstruction
        cls._STEADY = (cls._evaluate is base._evaluate and cls._status is base._status
                       and cls._axis is Instruction._axis and cls._register is Instruction._register)

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_stop_mode", 0)
        object.__setattr__(self, "_steady_key", None)

    def _steady(self) -> bool:
        # Enabled by this instance with the same input objects as the last call, which showed Status/Busy
        # and no error; the axis still enabled by it, without alarms, in RUN.  A full evaluation would only
        # write the same stop mode to the axis and the same outputs again.
        d = self.__dict__
        key = d["_steady_key"]
        if key is not None:
            axis = key[0]
            if (axis is d["Axis"] and key[1] is d["Enable"] and key[2] is d["StartMode"]
                    and key[3] is d["StopMode"] and axis.power_owner is self and axis.state == _ENABLED
                    and not axis.alarms and axis.ctl.mode == _RUN):
                axis.stop_mode = d["_stop_mode"]
                return True
            object.__setattr__(self, "_steady_key", None)
        return False

    def _steady_inputs(self, axis: Any, enable: bool) -> tuple[Any, ...] | None:
        """The inputs under which the next call may take the shortcut, or None.  Only for the kernel's
        own enable state machine, whose call in this state sets nothing but the stop mode."""
        if not (enable and self.Enable is True and type(axis).power is _AXIS_POWER
                and type(axis.power_control) is PowerControl):
            return None
        if not (axis.power_owner is self and axis.state == _ENABLED and not axis.alarms
                and axis.ctl.mode == _RUN):
            return None
        if axis.pto and axis.config.pulse_output.generator:
            # the pulse generator is held by this axis for as long as it is not disabled
            if axis.ctl._pto_holder.get(axis.config.pulse_output.generator) is not axis:
                return None
        return (axis, self.Enable, self.StartMode, self.StopMode)

    def _evaluate(self) -> None:
        enable = as_bool(self, "Enable", self.Enable)
        try:
            axis = self._axis()
        except InstructionError as err:
            self._status(None, enable, (err.error_id, err.error_info))
            return
        own: tuple[int, int] | None = None
        stop_mode, start_mode = as_int(self.StopMode), as_int(self.StartMode)
        if stop_mode not in (0, 1, 2):
            own = self._mode_error("StopMode")
        elif start_mode not in (0, 1):
            own = self._mode_error("StartMode")
        else:
            object.__setattr__(self, "_stop_mode", stop_mode)   # taken over while Enable = TRUE
        if own is not None and enable and axis.power_owner is not self and axis.state == "disabled":
            # an invalid mode keeps the axis from being enabled; correct it and the enable proceeds
            self._status(axis, enable, own)
            return
        reject = axis.power(self, enable, start_mode if start_mode in (0, 1) else 1, self._stop_mode)
        if reject is not None:
            self._status(axis, enable, self._fault_codes(reject))
            return
        self._status(axis, enable, own)
        if own is None and self._STEADY:
            object.__setattr__(self, "_steady_key", self._steady_inputs(axis, enable))

    def _status(self, axis: Any, enable: bool, own: tuple[int, int] | None) -> None:
        if axis is None:
            status, busy = False, enable
        else:
            owner = axis.power_owner is self
            status = owner and axis.state in ("enabled", "disabling")
            busy = enable or (owner and axis.state == "disabling")
            if own is None and axis.alarms:
                own = self._alarm_codes(axis)        # the errors of the axis show here too
        values = {"Status": status, "Busy": busy, "Error": own is not None, "ErrorID": own[0] if own else 0}
        if "ErrorInfo" in self.OUTPUTS:
            values["ErrorInfo"] = own[1] if own else 0
        self._out(**values)


class ReferenceMarkOutput:
    """MC_Home's ReferenceMarkPosition: shown with Done and kept valid after Done has gone."""

    def _show(self, output: str, error_id: int, error_info: int) -> None:
        super()._show(output, error_id, error_info)  # type: ignore[misc]
        if output == "Done" and self._done_job is not None:
            self._out(ReferenceMarkPosition=self._done_job.reference_position)  # type: ignore[attr-defined]

    def _clear_outputs(self) -> None:
        keep = self.ReferenceMarkPosition  # type: ignore[attr-defined]
        super()._clear_outputs()  # type: ignore[misc]
        self._out(ReferenceMarkPosition=keep)  # type: ignore[attr-defined]

    def _final_for(self, job: Job):
        object.__setattr__(self, "_done_job", job)
        return super()._final_for(job)  # type: ignore[misc]

    def _reinit(self) -> None:
        super()._reinit()  # type: ignore[misc]
        object.__setattr__(self, "_done_job", None)
