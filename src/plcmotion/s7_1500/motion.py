"""Single-axis motion instructions of the S7-1500 (technology version V5): MC_Halt, MC_Stop,
MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity, MC_MoveJog, MC_MoveSuperimposed.

Dynamic inputs follow the rule of §9.1: > 0 use the value, = 0 not permitted (Jerk = 0: trapezoidal
profile), < 0 use ``DynamicDefaults``.  Values above ``DynamicLimits`` are limited, not rejected; the axis
then shows ``WarningWord.X6 (DynamicWarning)``.  Which job aborts which is decided by the axis with the
tables of §9.3.
"""
from __future__ import annotations

from typing import Any

from .. import fb
from ..kernel.jobs import Job, JobKind, JobState
from . import errors as E
from .base import ExecuteInstruction, InstructionError, _S71500, as_bool, as_int, as_real, dynamic, dynamics, integer, real

_DYN = {"Velocity": -1.0, "Acceleration": -1.0, "Deceleration": -1.0, "Jerk": -1.0}


def _job(kind: JobKind, owner: Any, dyn: dict[str, float], **kw: Any) -> Job:
    return Job(kind, velocity=dyn.get("velocity", 0.0), acceleration=dyn.get("acceleration"),
               deceleration=dyn.get("deceleration"), jerk=dyn.get("jerk"), owner=owner, **kw)


class MC_Halt(ExecuteInstruction):  # noqa: N801
    """Brake the axis to standstill with Deceleration and Jerk."""

    INPUTS = {"Axis": None, "Execute": False, "Deceleration": -1.0, "Jerk": -1.0}

    def _start(self, axis: Any) -> Job:
        e = axis.ueff
        dyn = {"deceleration": dynamic("Deceleration", self.Deceleration, e["DynamicDefaults.Deceleration"]),
               "jerk": dynamic("Jerk", self.Jerk, e["DynamicDefaults.Jerk"], jerk=True)}
        job = _job(JobKind.HALT, self, dyn)
        axis.submit(job)
        return job


class MC_Stop(ExecuteInstruction):  # noqa: N801
    """Stop the axis and keep it from other motion jobs while Execute is TRUE (StatusWord2.X0).

    Mode 0: with the emergency stop ramp (``DynamicDefaults.EmergencyDeceleration``, no jerk limit);
    Mode 2: with the maximum dynamic values (``DynamicLimits.MaxDeceleration``, ``MaxJerk``).  A new
    MC_Stop aborts one with the same or a weaker stop response (§9.3.1 "B").
    """

    INPUTS = {"Axis": None, "Execute": False, "Mode": 0}

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_stop", None)

    def _start(self, axis: Any) -> Job:
        mode = integer("Mode", self.Mode, (0, 2))
        job = Job(JobKind.STOP, mode=mode, owner=self)
        axis.submit(job)
        object.__setattr__(self, "_stop", (axis, job))
        return job

    def _evaluate(self) -> None:
        super()._evaluate()
        stop = self._stop
        if stop is not None and not self._prev_execute:
            axis, job = stop
            axis.release_stop(job)
            if not job.busy:
                object.__setattr__(self, "_stop", None)


class MC_MoveAbsolute(ExecuteInstruction):  # noqa: N801
    """Position the axis at Position; the axis must be homed.  Direction (modulo axes): 1 positive,
    2 negative, 3 shortest distance."""

    INPUTS = {"Axis": None, "Execute": False, "Position": 0.0, "Direction": 1, **_DYN}

    def _start(self, axis: Any) -> Job:
        position = real("Position", self.Position)
        direction = integer("Direction", self.Direction, (1, 2, 3)) if axis.config.modulo.enabled else 1
        dyn = dynamics(axis, self)
        job = _job(JobKind.ABSOLUTE, self, dyn, position=position, direction=direction)
        axis.submit(job)
        return job


class MC_MoveRelative(ExecuteInstruction):  # noqa: N801
    """Move the axis by Distance from its position at the start of the job."""

    INPUTS = {"Axis": None, "Execute": False, "Distance": 0.0, **_DYN}

    def _start(self, axis: Any) -> Job:
        distance = real("Distance", self.Distance)
        dyn = dynamics(axis, self)
        job = _job(JobKind.RELATIVE, self, dyn, position=distance)
        axis.submit(job)
        return job


class MC_MoveVelocity(ExecuteInstruction):  # noqa: N801
    """Move at constant velocity until another job takes over.

    Direction: 0 the sign of Velocity, 1 positive, 2 negative.  Current = TRUE keeps the present
    velocity.  InVelocity: the velocity is reached (Velocity = 0.0: standstill); Busy stays TRUE until
    the job is overridden.
    """

    INPUTS = {"Axis": None, "Execute": False, "Velocity": 10.0, "Acceleration": -1.0, "Deceleration": -1.0,
              "Jerk": -1.0, "Direction": 0, "Current": False, "PositionControlled": True}
    OUTPUTS = {"InVelocity": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0}

    def _start(self, axis: Any) -> Job:
        current = as_bool(self, "Current", self.Current)
        controlled = as_bool(self, "PositionControlled", self.PositionControlled)
        signed = 0.0
        if not current:
            v = as_real(self.Velocity)
            if v is None or abs(v) > 1.0e12:
                raise InstructionError(E.parameter("Velocity"))
            direction = integer("Direction", self.Direction, (0, 1, 2))
            signed = v if direction == 0 else abs(v) if direction == 1 else -abs(v)
        dyn = dynamics(axis, self, velocity=None)
        job = _job(JobKind.VELOCITY, self, dyn, current=current, position_controlled=controlled)
        job.velocity = signed
        job.extra["hold_zero"] = True
        axis.submit(job)
        return job

    def _running(self, execute: bool) -> None:
        job = self._job
        self._out(InVelocity=bool(job is not None and job.in_velocity))


class MC_MoveJog(_S71500, fb.JogInstruction):  # noqa: N801
    """Jog while JogForward or JogBackward is TRUE; both TRUE brake the axis (ErrorID 16#8007)."""

    INPUTS = {"Axis": None, "JogForward": False, "JogBackward": False, "Velocity": 10.0, "Acceleration": -1.0,
              "Deceleration": -1.0, "Jerk": -1.0, "PositionControlled": True}
    OUTPUTS = {"InVelocity": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0}

    def _jog_velocity(self, axis: Any) -> float:
        v = as_real(self.Velocity)
        if v is None or v < 0.0 or v > 1.0e12:
            raise InstructionError(E.parameter("Velocity"))
        return v

    def _jog_both(self) -> tuple[int, int]:
        return E.JOG_BOTH, 0

    def _jog_job(self, axis: Any, velocity: float, controlled: bool) -> Job:
        dyn = dynamics(axis, self, velocity=None)
        return _job(JobKind.JOG, self, {**dyn, "velocity": velocity}, position_controlled=controlled)


class MC_MoveSuperimposed(ExecuteInstruction):  # noqa: N801
    """Add a positioning by Distance to the running motion (basic motion, synchronous operation or
    standstill).  VelocityDiff, AccelerationDiff, DecelerationDiff and JerkDiff are the dynamics of the
    superimposed part; a new MC_MoveSuperimposed continues from the state of the previous one."""

    INPUTS = {"Axis": None, "Execute": False, "Distance": 0.0, "VelocityDiff": -1.0, "AccelerationDiff": -1.0,
              "DecelerationDiff": -1.0, "JerkDiff": -1.0}

    def _start(self, axis: Any) -> Job:
        distance = real("Distance", self.Distance)
        dyn = dynamics(axis, self, velocity="VelocityDiff",
                       names=("AccelerationDiff", "DecelerationDiff", "JerkDiff"))
        job = _job(JobKind.SUPERIMPOSED, self, dyn, position=distance)
        axis.submit(job)
        return job


__all__ = ["MC_Halt", "MC_Stop", "MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveVelocity", "MC_MoveJog",
           "MC_MoveSuperimposed", "JobState", "as_int"]
