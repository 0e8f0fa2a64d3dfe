"""Single-axis motion instructions (S7-1200 Motion Control V6 §11.1.4 - §11.1.8):
MC_Halt, MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity, MC_MoveJog.

Which command aborts which is decided by the axis (override lists of §11.1.x): every one of these
aborts the running motion command of the axis, and is aborted by the next one.
"""
from __future__ import annotations

from typing import Any

from ..kernel.axis import PositioningAxis
from ..kernel.jobs import Job, JobKind, JobState
from . import errors as E
from .base import ExecuteInstruction, Instruction, InstructionError, as_bool, as_int, as_real
from .homing import check_position


def check_velocity(axis: PositioningAxis, value: Any, *, negative_ok: bool = False, zero_ok: bool = False) -> float:
    """Velocity input: start/stop velocity <= |Velocity| <= maximum velocity (§12.8 16#8402)."""
    v = as_real(value)
    if v is None:
        raise InstructionError(E.VELOCITY, E.INVALID_FORMAT)
    if v < 0 and not negative_ok:
        raise InstructionError(E.VELOCITY, E.BELOW_ZERO)
    speed = abs(v)
    if speed > axis.eff["DynamicLimits.MaxVelocity"] * (1 + 1e-12):
        raise InstructionError(E.VELOCITY, E.ABOVE_MAX_VELOCITY)
    if speed == 0.0 and zero_ok:
        return v
    if speed < axis.eff["DynamicLimits.MinVelocity"] * (1 - 1e-12):
        raise InstructionError(E.VELOCITY, E.BELOW_START_STOP)
    if speed == 0.0:
        # a servo axis has start/stop velocity 0: a positioning at zero velocity would never arrive
        raise InstructionError(E.VELOCITY, E.OUT_OF_RANGE)
    return v


class MC_Halt(ExecuteInstruction):  # noqa: N801
    """Brake the axis to standstill with the configured deceleration (§11.1.4)."""

    def _start(self, axis: PositioningAxis) -> Job:
        job = Job(JobKind.HALT, owner=self)
        axis.submit(job)
        return job


class MC_MoveAbsolute(ExecuteInstruction):  # noqa: N801
    """Move to an absolute position; the axis must be homed (§11.1.5).

    Direction (modulo axes only): 0 sign of Velocity, 1 positive, 2 negative, 3 shortest distance.
    """

    INPUTS = {"Axis": None, "Execute": False, "Position": 0.0, "Velocity": 10.0, "Direction": 1}

    def _start(self, axis: PositioningAxis) -> Job:
        position = check_position(self.Position, E.POSITION)
        modulo = axis.eff["Modulo.Enable"] and not axis.pto
        direction = as_int(self.Direction)
        if modulo and direction not in (0, 1, 2, 3):
            raise InstructionError(E.DIRECTION, E.INVALID_SELECTION)
        velocity = check_velocity(axis, self.Velocity, negative_ok=modulo and direction == 0)
        job = Job(JobKind.ABSOLUTE, position=position, velocity=abs(velocity),
                  direction=direction if modulo else 1, owner=self, extra={"sign": velocity})
        axis.submit(job)
        return job


class MC_MoveRelative(ExecuteInstruction):  # noqa: N801
    """Move by Distance from the position at the start of the command (§11.1.6)."""

    INPUTS = {"Axis": None, "Execute": False, "Distance": 0.0, "Velocity": 10.0}

    def _start(self, axis: PositioningAxis) -> Job:
        distance = check_position(self.Distance, E.DISTANCE)
        velocity = check_velocity(axis, self.Velocity)
        job = Job(JobKind.RELATIVE, position=distance, velocity=velocity, owner=self)
        axis.submit(job)
        return job


class MC_MoveVelocity(ExecuteInstruction):  # noqa: N801
    """Move at constant velocity (§11.1.7, status rules §9.5.3).

    Busy and InVelocity stay TRUE after Execute has gone until another command takes over; an abort or an
    axis error after the velocity was reached with Execute FALSE is not shown here (only at MC_Power).
    Velocity = 0.0 brakes like MC_Halt; at standstill InVelocity shows TRUE for at least one call.
    """

    INPUTS = {"Axis": None, "Execute": False, "Velocity": 10.0, "Direction": 0, "Current": False,
              "PositionControlled": True}
    OUTPUTS = {"InVelocity": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0,
               "ErrorInfo": 0}

    def _start(self, axis: PositioningAxis) -> Job:
        current = as_bool(self, "Current", self.Current)
        controlled = as_bool(self, "PositionControlled", self.PositionControlled)
        signed = 0.0
        if not current:
            v = as_real(self.Velocity)
            if v is None:
                raise InstructionError(E.VELOCITY, E.INVALID_FORMAT)
            direction = as_int(self.Direction)
            if direction not in (0, 1, 2):
                raise InstructionError(E.DIRECTION, E.INVALID_SELECTION)
            check_velocity(axis, abs(v), zero_ok=True)
            signed = v if direction == 0 else abs(v) if direction == 1 else -abs(v)
        job = Job(JobKind.VELOCITY, velocity=signed, current=current, position_controlled=controlled or axis.pto,
                  owner=self)
        axis.submit(job)
        return job

    def _running(self, execute: bool) -> None:
        job = self._job
        self._out(InVelocity=bool(job is not None and job.in_velocity))

    def _final_for(self, job: Job):
        if job.state == JobState.DONE:                      # Velocity = 0.0 reached standstill
            return ("InVelocity", 0, 0)
        # §9.5.3 exceptions: velocity reached (InVelocity was shown) and Execute FALSE -> no
        # CommandAborted / Error here (the error shows at MC_Power)
        if self.InVelocity and not self._prev_execute:
            return None
        return super()._final_for(job)

    def _show(self, output: str, error_id: int, error_info: int) -> None:
        if output == "InVelocity":
            self._clear_outputs()
            self._out(InVelocity=True, Busy=True)
            return
        super()._show(output, error_id, error_info)


class MC_MoveJog(Instruction):  # noqa: N801
    """Jog while JogForward or JogBackward is TRUE (§11.1.8, status rules §9.5.4).

    Velocity changes are taken over while a jog input is TRUE.  Both inputs TRUE stop the axis with the
    configured deceleration and give 16#8406.
    """

    INPUTS = {"Axis": None, "JogForward": False, "JogBackward": False, "Velocity": 10.0,
              "PositionControlled": True}
    OUTPUTS = {"InVelocity": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0,
               "ErrorInfo": 0}

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
                self._fail(E.JOG_BOTH, 0x0001, True)
            elif rise:
                self._clear()
                self._fail(E.JOG_BOTH, 0x0001, True)
        elif rise:
            self._clear()
            object.__setattr__(self, "_final", None)
            object.__setattr__(self, "_job", None)
            try:
                v = check_velocity(axis, self.Velocity, zero_ok=axis.eff["DynamicLimits.MinVelocity"] == 0.0)
                controlled = as_bool(self, "PositionControlled", self.PositionControlled)
            except InstructionError as err:
                self._fail(err.error_id, err.error_info, True)
            else:
                new = Job(JobKind.JOG, velocity=v if fwd else -v, position_controlled=controlled or axis.pto,
                          owner=self)
                axis.submit(new)
                object.__setattr__(self, "_job", new)
        elif job is not None and job.busy and not job.jog_released:
            if not held:
                axis.release_jog(job)
            else:
                v = as_real(self.Velocity)
                if v is not None and abs(v) != abs(job.velocity):
                    try:
                        v = check_velocity(axis, self.Velocity,
                                           zero_ok=axis.eff["DynamicLimits.MinVelocity"] == 0.0)
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
                final = ("Error", *E.codes(job.fault))
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
            self._out(**{output: True}, ErrorID=error_id, ErrorInfo=error_info)
            object.__setattr__(self, "_shown", True)
        else:
            self._clear()
            object.__setattr__(self, "_final", None)
