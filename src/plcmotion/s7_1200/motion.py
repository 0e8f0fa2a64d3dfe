"""Single-axis motion instructions (S7-1200 Motion Control V6 §11.1.4 - §11.1.8):
MC_Halt, MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity, MC_MoveJog.

Which command aborts which is decided by the axis (override lists of §11.1.x): every one of these
aborts the running motion command of the axis, and is aborted by the next one.
"""
from __future__ import annotations

import math
from typing import Any

from ..kernel.axis import PositioningAxis
from ..kernel.jobs import Job, JobKind, JobState
from . import errors as E
from .. import fb
from .base import ExecuteInstruction, InstructionError, _S71200, as_bool, as_int, as_real
from .homing import check_position


def check_velocity(axis: PositioningAxis, value: Any, *, negative_ok: bool = False, zero_ok: bool = False) -> float:
    """Velocity input: start/stop velocity <= |Velocity| <= maximum velocity (§12.8 16#8402)."""
    v = fb.as_number(value)
    if v is None:
        raise InstructionError(E.VELOCITY, E.INVALID_FORMAT)
    if v < 0 and not negative_ok:
        raise InstructionError(E.VELOCITY, E.BELOW_ZERO)
    speed = abs(v)
    if speed > axis.config.limits.max_velocity * (1 + 1e-12):
        raise InstructionError(E.VELOCITY, E.ABOVE_MAX_VELOCITY)
    if speed == 0.0 and zero_ok:
        return v
    if speed < axis.config.limits.start_stop_velocity * (1 - 1e-12):
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
        modulo = axis.config.modulo.enabled and not axis.pto
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
            v = fb.as_number(self.Velocity)
            if v is None:
                raise InstructionError(E.VELOCITY, E.INVALID_FORMAT)
            direction = as_int(self.Direction)
            if direction not in (0, 1, 2):
                raise InstructionError(E.DIRECTION, E.INVALID_SELECTION)
            if math.isinf(v):                        # an integer beyond the REAL range
                raise InstructionError(E.VELOCITY, E.ABOVE_MAX_VELOCITY)
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


class MC_MoveJog(_S71200, fb.JogInstruction):  # noqa: N801
    """Jog while JogForward or JogBackward is TRUE (§11.1.8, status rules §9.5.4).

    Velocity changes are taken over while a jog input is TRUE.  Both inputs TRUE stop the axis with the
    configured deceleration and give 16#8406.
    """

    INPUTS = {"Axis": None, "JogForward": False, "JogBackward": False, "Velocity": 10.0,
              "PositionControlled": True}
    OUTPUTS = {"InVelocity": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0,
               "ErrorInfo": 0}

    def _jog_velocity(self, axis: PositioningAxis) -> float:
        return check_velocity(axis, self.Velocity, zero_ok=axis.config.limits.start_stop_velocity == 0.0)

    def _jog_both(self) -> tuple[int, int]:
        return E.JOG_BOTH, 0x0001

    def _jog_job(self, axis: PositioningAxis, velocity: float, controlled: bool) -> Job:
        return Job(JobKind.JOG, velocity=velocity, position_controlled=controlled or axis.pto, owner=self)
