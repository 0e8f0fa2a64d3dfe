"""Single-axis motion instructions (S7-Technology V4.1 §6.2.6-§6.2.10): FB 410 MC_MoveAbsolute, FB 411
MC_MoveRelative, FB 412 MC_MoveAdditive, FB 413 MC_MoveSuperImposed, FB 414 MC_MoveVelocity.

Dynamic inputs follow §6.9.3 (``base.dynamic``) with the axis's default dynamics (``userdefaultdynamics``);
values above the axis's limits are cut to them and the technology DB shows warning 16#0021.  ``Mode``:
0 override, 1 append (the axis stops at the transition), 2 overlay (the transition at the lower of the two
velocities, at standstill when the direction reverses) - the axis job queue's Aborting, Buffered and
BlendingLow (``technology.policy_basic``).  Appending or overlaying onto a running MC_Halt, a running
MC_MoveVelocity (MC_MoveVelocity onto MC_MoveVelocity) or a synchronous operation: 16#8055.
"""
from __future__ import annotations

from typing import Any

from ..kernel import faults as F
from ..kernel.jobs import POSITIONING_KINDS, Job, JobKind, JobState
from . import errors as E
from .base import POSITION_AXES, ALL_AXES, ExecuteInstruction, InstructionError, as_bool, dynamic, integer, real
from .technology.axes import AxisT

#: §9.4.12 EnumDirection ValueDint of ``userdefaultdynamics.direction``
EFFECTIVE, NEGATIVE, POSITIVE, BY_VALUE, SHORTEST_WAY = 3, 4, 5, 38, 39
#: the kernel's modulo directions (kernel.motion.modulo_target): 1 positive, 2 negative, 3 shortest
_K_POSITIVE, _K_NEGATIVE, _K_SHORTEST = 1, 2, 3


def _current(axis: AxisT) -> int:
    return _K_POSITIVE if axis.last_direction > 0 else _K_NEGATIVE


def _default_direction(axis: AxisT) -> int:
    """Direction = 0: the configured default (``userdefaultdynamics.direction``); BY_VALUE moves positive,
    the instructions have no negative velocity (§6.2.6 footnote)."""
    d = axis.eff["userdefaultdynamics.direction"]
    if d == NEGATIVE:
        return _K_NEGATIVE
    if d == SHORTEST_WAY:
        return _K_SHORTEST
    if d == EFFECTIVE:
        return _current(axis)
    return _K_POSITIVE


class _Move(ExecuteInstruction):
    """What the motion instructions share: their dynamics and Mode."""

    TECHNOLOGIES = POSITION_AXES
    MODES: tuple[int, ...] = (0,)

    def _dynamics(self, axis: AxisT, *, velocity: str | None = "Velocity", zero_acc=None,
                  zero_dec=None) -> dict[str, float]:
        e = axis.eff
        out: dict[str, float] = {}
        if velocity is not None:
            out["velocity"] = dynamic(velocity, getattr(self, velocity), e["userdefaultdynamics.velocity"])
        out["acceleration"] = dynamic("Acceleration", self.Acceleration, e["userdefaultdynamics.positiveaccel"],
                                      zero=zero_acc)
        out["deceleration"] = dynamic("Deceleration", self.Deceleration, e["userdefaultdynamics.negativeaccel"],
                                      zero=zero_dec)
        out["jerk"] = dynamic("Jerk", self.Jerk, e["userdefaultdynamics.positiveaccelstartjerk"], jerk=True)
        return out

    def _mode(self, axis: AxisT) -> int:
        mode = integer("Mode", getattr(self, "Mode", 0), self.MODES)
        if mode and axis.stop_job is None:
            job = axis.job
            running = job.kind if job is not None and job.busy else None
            follower = axis.follower
            if running == JobKind.HALT or (follower is not None and follower.coupling is not None) or (
                    running == JobKind.VELOCITY and isinstance(self, MC_MoveVelocity)):
                raise InstructionError(E.LATCHING_NOT_ALLOWED)
        return mode

    def _submit(self, axis: AxisT, job: Job, mode: int = 0) -> Job:
        axis.submit(job, axis.policy.buffer_mode(mode))
        return job


def _job(kind: JobKind, owner: Any, dyn: dict[str, float], **kw: Any) -> Job:
    return Job(kind, velocity=dyn.get("velocity", 0.0), acceleration=dyn["acceleration"],
               deceleration=dyn["deceleration"], jerk=dyn["jerk"], owner=owner, **kw)


class MC_MoveAbsolute(_Move):  # noqa: N801 - instruction name of the manual
    """FB 410: position the axis at Position.  Direction on modulo axes: 0 the configured default,
    1 positive, 2 shortest distance, 3 negative, 4 the current direction (Mode 2 with Direction 4, or 0
    configured as the current direction: 16#8043).  Needs a homed axis when "Homing required" is YES
    (else the command ends with CommandAborted and 16#8041 in the technology DB)."""

    INPUTS = {"Axis": 0, "Execute": False, "Position": 0.0, "Velocity": -1.0, "Acceleration": -1.0,
              "Deceleration": -1.0, "Jerk": -1.0, "Direction": 0, "Mode": 0, "DoneFlag": 0}
    MODES = (0, 1, 2)

    def _start(self, axis: AxisT) -> Job:
        position = real("Position", self.Position)
        direction = integer("Direction", self.Direction, range(5))
        mode = self._mode(axis)
        self._flag()
        dyn = self._dynamics(axis)
        kdir = _K_POSITIVE
        if axis.config.modulo.enabled:
            current = direction == 4 or (direction == 0 and axis.eff["userdefaultdynamics.direction"] == EFFECTIVE)
            if mode == 2 and current:
                raise InstructionError(E.ILLEGAL_PARAMETER)
            kdir = {0: _default_direction(axis), 1: _K_POSITIVE, 2: _K_SHORTEST, 3: _K_NEGATIVE,
                    4: _current(axis)}[direction]
        return self._submit(axis, _job(JobKind.ABSOLUTE, self, dyn, position=position, direction=kdir), mode)


class MC_MoveRelative(_Move):  # noqa: N801
    """FB 411: move the axis by Distance from the position where the command starts (Mode 1/2: from the
    target of the command it follows).  Distance = 0.0 ends speed-controlled operation without motion."""

    INPUTS = {"Axis": 0, "Execute": False, "Distance": 0.0, "Velocity": -1.0, "Acceleration": -1.0,
              "Deceleration": -1.0, "Jerk": -1.0, "Mode": 0, "DoneFlag": 0}
    MODES = (0, 1, 2)

    def _start(self, axis: AxisT) -> Job:
        distance = real("Distance", self.Distance)
        mode = self._mode(axis)
        self._flag()
        dyn = self._dynamics(axis)
        return self._submit(axis, _job(JobKind.RELATIVE, self, dyn, position=distance), mode)


class MC_MoveAdditive(_Move):  # noqa: N801
    """FB 412: move by Distance from the target of the running positioning (which it always overrides);
    at standstill or over a motion without target (MC_MoveVelocity) like MC_MoveRelative.  On a modulo
    axis Distance, the distance still to go and their sum must each stay below one modulo length."""

    INPUTS = {"Axis": 0, "Execute": False, "Distance": 0.0, "Velocity": -1.0, "Acceleration": -1.0,
              "Deceleration": -1.0, "Jerk": -1.0, "DoneFlag": 0}

    def _start(self, axis: AxisT) -> Job:
        distance = real("Distance", self.Distance)
        self._flag()
        dyn = self._dynamics(axis)
        job = _job(JobKind.RELATIVE, self, dyn, position=distance)
        running = axis.job
        positioning = running is not None and running.busy and running.kind in POSITIONING_KINDS
        p, v, _a = axis._state_now()
        to_go = running.target - p if positioning else 0.0
        m = axis.config.modulo
        if m.enabled and (abs(distance) >= m.length or abs(to_go) >= m.length or abs(distance + to_go) >= m.length):
            raise InstructionError(E.ILLEGAL_PARAMETER)
        if positioning:
            job.extra["relative_base"] = running.target          # target correction (§6.2.8)
        over_velocity = running is not None and running.busy and running.kind == JobKind.VELOCITY
        if axis.homing_required and not axis.homed and (positioning or (abs(v) > 0.0 and not over_velocity)):
            # §6.2.8: a homed axis is needed when it moves (unless an MC_MoveVelocity is overridden) or a
            # positioning is overridden; the check is the technology's: CommandAborted, 16#8041 in the DB
            job.finish(JobState.ERROR, F.reject(F.NOT_HOMED))
            return job
        return self._submit(axis, job)


class MC_MoveSuperImposed(_Move):  # noqa: N801
    """FB 413: a positioning by Distance added to the basic motion (superimposed motion layer); a new one
    aborts the running one, whose remaining distance is lost.  VelocityDiff, Acceleration, Deceleration and
    Jerk are the dynamics of the superimposed part.  The axis must be position-controlled (16#8040)."""

    INPUTS = {"Axis": 0, "Execute": False, "Distance": 0.0, "VelocityDiff": -1.0, "Acceleration": -1.0,
              "Deceleration": -1.0, "Jerk": -1.0, "DoneFlag": 0}

    def _start(self, axis: AxisT) -> Job:
        distance = real("Distance", self.Distance)
        self._flag()
        dyn = self._dynamics(axis, velocity="VelocityDiff")
        if axis.state == "enabled" and not axis.position_controlled:
            raise InstructionError(E.AXIS_DISABLED)              # speed-controlled: the wrong mode
        return self._submit(axis, _job(JobKind.SUPERIMPOSED, self, dyn, position=distance))


class MC_MoveVelocity(_Move):  # noqa: N801
    """FB 414: accelerate to Velocity and keep it (InVelocity once reached, also under the velocity
    override).  Velocity = 0.0 is allowed: InVelocity at standstill, and the command is complete.
    Direction: 0 the configured default, 1 positive, 3 negative, 4 the current direction (2: 16#8043).
    Current = TRUE keeps the present velocity.  PositionControl = FALSE switches a positioning axis to
    speed control (it stays so until a positioning or MC_MoveVelocity with PositionControl = TRUE);
    Mode 0 override, 1 append.  Acceleration / Deceleration = 0 only where none is needed."""

    INPUTS = {"Axis": 0, "Execute": False, "Velocity": -1.0, "Acceleration": -1.0, "Deceleration": -1.0,
              "Jerk": -1.0, "Direction": 0, "Current": False, "PositionControl": True, "Mode": 0, "DoneFlag": 0}
    OUTPUTS = {"InVelocity": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0}
    TECHNOLOGIES = ALL_AXES
    MODES = (0, 1)

    def _start(self, axis: AxisT) -> Job:
        current = as_bool(self, "Current", self.Current)
        controlled = as_bool(self, "PositionControl", self.PositionControl) and axis.positioning
        direction = integer("Direction", self.Direction, (0, 1, 3, 4))
        mode = self._mode(axis)
        self._flag()
        v = real("Velocity", self.Velocity)
        speed = axis.eff["userdefaultdynamics.velocity"] if v < 0.0 else v
        sign = {0: _default_direction(axis), 1: _K_POSITIVE, 3: _K_NEGATIVE, 4: _current(axis)}[direction]
        target = 0.0 if current else (-speed if sign == _K_NEGATIVE else speed)
        now = float(axis.ctl.bank.sp_v[axis.index])
        same = target * now > 0.0 or target == 0.0
        dyn = self._dynamics(axis, velocity=None,
                             zero_acc=lambda: current or (same and abs(target) <= abs(now)),
                             zero_dec=lambda: current or now == 0.0 or (same and abs(target) >= abs(now)))
        job = _job(JobKind.VELOCITY, self, dyn, current=current, position_controlled=controlled)
        job.velocity = target
        return self._submit(axis, job, mode)

    def _completed(self, job: Job) -> bool:
        return job.in_velocity or job.reached_once or job.state == JobState.DONE

    def _running(self, execute: bool) -> None:
        job = self._job
        self._out(InVelocity=bool(job is not None and job.in_velocity))

    def _show(self, output: str, error_id: int, error_info: int) -> None:
        # Velocity 0.0 reached: the command is complete, shown as InVelocity (the instruction has no Done)
        super()._show("InVelocity" if output == "Done" else output, error_id, error_info)


__all__ = ["MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveSuperImposed", "MC_MoveVelocity"]
