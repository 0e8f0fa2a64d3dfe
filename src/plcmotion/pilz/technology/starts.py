"""What the motion core does at the rising edge of Execute: check the denial causes of the selected command
(Pilz V6.5 §1.2.2 ... §1.12.2, in the manual's order) and hand the motion to the kernel.

Positioning, velocity, stop and homing commands become kernel jobs on the axis's job queue (Command Mode
I409: 0 cancels the running command, 1 starts at its end - a buffered job).  The cyclic commands and the
torque control run on the motion core's own set values (``cyclic.py``).
"""
from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING, Any

from ...kernel.axis_queue import BufferMode
from ...kernel.jobs import Job, JobKind
from ...kernel.motion import limits, modulo_target, wrap
from ...kernel.profiles import PlanningError
from . import command as C
from .causes import Cause
from .homing_methods import Feature

if TYPE_CHECKING:  # pragma: no cover
    from .core import MotionCore

_EPS_V = 1e-9


def _direction_blocked(core: "MotionCore", sign: float) -> bool:
    i04 = core.axis.eff["I04"]
    return (i04 == 1 and sign < 0) or (i04 == 2 and sign > 0)


def _hw_limit_ahead(core: "MotionCore", sign: float) -> bool:
    approached = core.axis.limit_switches.approached
    return (sign > 0 and approached["max"]) or (sign < 0 and approached["min"])


def endless_target(ax: Any, job: Job, p: float, v: float, a: float) -> float:
    """The unwrapped target of an MC_MoveAbsolute job on an endless axis, placed with the job's own dynamics
    (how many turns the axis needs to brake, §1.2.4).  Dynamics the planner cannot brake with (a zero or
    vanishing deceleration or jerk: such a command is denied, or would never stop) place it by a ramp with
    the axis maximum instead, so that working out the denial cause never fails."""
    lim = limits(ax, ax.commanded_velocity(job.velocity) or None, job=job)
    try:
        return modulo_target(ax, job.position, job.direction, job.extra.get("sign", 1.0), p, v, a, lim,
                             ax.motion.planner)
    except PlanningError:
        safe = dataclasses.replace(lim, jerk=math.inf, deceleration=max(lim.deceleration, ax.eff["I11"], 1e-3))
        return modulo_target(ax, job.position, job.direction, job.extra.get("sign", 1.0), p, v, a, safe,
                             ax.motion.planner)


def absolute_target(core: "MotionCore", cmd: C.Command) -> tuple[float, int, float]:
    """(unwrapped target, kernel direction code, velocity sign) of MC_MoveAbsolute (§1.2.4 I411 rules)."""
    ax = core.axis
    position = cmd.value("I403")
    p, v, a = ax._state_now()
    if not ax.config.modulo.enabled:
        return position, 0, 1.0
    length = ax.config.modulo.length
    i411 = cmd.value("I411")
    moving = abs(v) > _EPS_V
    sign = math.copysign(1.0, v) if moving else 1.0
    if i411 in (0, 3):
        code = 0 if moving else 3            # from motion: keep the current direction; else the shortest way
    else:
        code = i411
        ahead = wrap(position - p, 0.0, length)
        shortest = min(ahead, length - ahead)
        if not moving and shortest <= ax.eff["I22"]:
            code = 3                         # already within the position window: the shortest way
    job = Job(JobKind.ABSOLUTE, position=position, velocity=abs(cmd.value("I404")), direction=code,
              extra={"sign": sign}, **_dynamics(cmd, "I405", "I406"))
    return endless_target(ax, job, p, v, a), code, sign


def relative_base(core: "MotionCore", cmd: C.Command) -> float:
    """MC_MoveRelative: the actual position at the start (§1.3); MC_MoveAdditive: the last valid set position,
    else the actual position (§1.4.6)."""
    act = core.actual_position()
    if cmd.number == C.MOVE_ADDITIVE and core.set_position is not None:
        return core.set_position
    return act


def denial(core: "MotionCore", cmd: C.Command) -> Cause | None:
    """The first cause (manual order) for which the motion core denies ``cmd``; None: it starts."""
    ax = core.axis
    n = cmd.number
    e = ax.eff
    if n in (C.CYCLIC_SPEED, C.TORQUE_CONTROL, C.CYCLIC_POSITION):
        return Cause.NOT_READY if not core.ready() else None      # "never denied" (§1.8.2): see decisions.md
    if not core.ready():
        return Cause.NOT_READY
    if core.stop_lock:
        return Cause.STOP_ACTIVE
    zero_max = e["I11"] == 0.0 or e["I16"] == 0.0
    if n in C.POSITIONING:
        endless = e["I00"] == 1
        if n == C.MOVE_ABSOLUTE:
            target, _code, _sign = absolute_target(core, cmd)
            here = ax._state_now()[0]
        else:
            here = relative_base(core, cmd)
            target = here + cmd.value("I403")
        sign = math.copysign(1.0, target - here) if target != here else 0.0
        if not endless and ax.config.software_limits.enabled and ax.homed and not (
                e["I51"] <= target <= e["I50"]):
            return Cause.SW_LIMIT
        if endless and sign and _direction_blocked(core, sign):
            return Cause.DIRECTION_BLOCKED
        if n == C.MOVE_ABSOLUTE and endless and not 0.0 <= cmd.value("I403") < e["I01"]:
            return Cause.REVOLUTION_LENGTH
        if sign and _hw_limit_ahead(core, sign):
            return Cause.HW_LIMIT
        if 0.0 in (cmd.value("I404"), cmd.value("I405"), cmd.value("I406"), cmd.value("I407")):
            return Cause.ZERO_DYNAMICS
        if zero_max:
            return Cause.ZERO_MAXIMUM
        if not ax.homed and (n == C.MOVE_ABSOLUTE or ax.config.software_limits.enabled):
            return Cause.NOT_REFERENCED
        return None
    if n == C.MOVE_VELOCITY:
        sign = math.copysign(1.0, cmd.value("I404")) if cmd.value("I404") else 0.0
        if e["I00"] == 1 and sign and _direction_blocked(core, sign):
            return Cause.DIRECTION_BLOCKED
        if sign and _hw_limit_ahead(core, sign):
            return Cause.HW_LIMIT
        if 0.0 in (cmd.value("I405"), cmd.value("I406"), cmd.value("I407")):
            return Cause.ZERO_DYNAMICS
        return Cause.ZERO_MAXIMUM if zero_max else None
    if n in C.STOPPING:
        if 0.0 in (cmd.value("I406"), cmd.value("I407")) and not core.at_standstill():
            return Cause.ZERO_DYNAMICS
        return Cause.ZERO_MAXIMUM if zero_max else None
    if n == C.MOVE_SPEED:
        if cmd.value("I407") == 0.0:
            return Cause.ZERO_DYNAMICS
        # I16 = 0 is the manual's cause; I11 = 0 leaves the velocity profile no acceleration (decisions.md)
        return Cause.ZERO_MAXIMUM if zero_max else None
    if n == C.HOME:
        if not core.at_standstill():
            return Cause.NOT_STANDSTILL
        method = ax.referencing.method()
        if method is None:
            return Cause.REFERENCING_INACTIVE
        if zero_max and method.feature is not Feature.SET_REFERENCE:
            return Cause.ZERO_MAXIMUM            # a search cannot move without I11 / I16 (decisions.md)
        return None
    return None


def _dynamics(cmd: C.Command, acc: str, dec: str) -> dict[str, float]:
    return {"acceleration": abs(cmd.value(acc)), "deceleration": abs(cmd.value(dec)),
            "jerk": abs(cmd.value("I407"))}


def limit_flags(core: "MotionCore", cmd: C.Command) -> None:
    """I190 / I191 / I193 of the profile commands (§1.2.3, §1.5.3, §1.6.3, §1.9.3, §1.12.3)."""
    e = core.axis.eff
    s = core.status
    n = cmd.number
    if n in C.POSITIONING or n == C.MOVE_VELOCITY:
        v = abs(cmd.value("I404"))
        s.I190 = v > e["I10"]
        s.I193 = v <= e["I10"] < v * core.override / 100.0
        s.I191 = (cmd.value("I405") > e["I11"] or cmd.value("I406") > e["I11"] or cmd.value("I407") > e["I16"])
    elif n in C.STOPPING:
        s.I191 = cmd.value("I406") > e["I11"] or cmd.value("I407") > e["I16"]
    elif n == C.MOVE_SPEED:
        s.I191 = cmd.value("I407") > e["I16"]


def start(core: "MotionCore", cmd: C.Command, t: float) -> None:
    """Hand an accepted command to the kernel (or to the cyclic set values)."""
    ax = core.axis
    n = cmd.number
    mode = BufferMode.BUFFERED if n in C.BUFFERABLE and cmd.value("I409") == 1 else BufferMode.ABORTING
    job: Job | None = None
    if n in C.POSITIONING:
        dyn = _dynamics(cmd, "I405", "I406")
        extra = {"command": n, "end_velocity": 0.0}
        if cmd.value("I429"):
            extra["end_velocity"] = abs(cmd.value("I429"))
        if n == C.MOVE_ABSOLUTE:
            _target, code, sign = absolute_target(core, cmd)
            extra["sign"] = sign
            job = Job(JobKind.ABSOLUTE, position=cmd.value("I403"), velocity=abs(cmd.value("I404")),
                      direction=code, extra=extra, **dyn)
        else:
            extra["relative_base"] = relative_base(core, cmd)
            job = Job(JobKind.RELATIVE, position=cmd.value("I403"), velocity=abs(cmd.value("I404")),
                      extra=extra, **dyn)
    elif n in C.VELOCITY:
        if n == C.MOVE_VELOCITY:
            job = Job(JobKind.VELOCITY, velocity=cmd.value("I404"), position_controlled=True,
                      extra={"command": n, "hold_zero": True}, **_dynamics(cmd, "I405", "I406"))
        else:
            acc, dec = core.move_speed_dynamics(cmd)
            job = Job(JobKind.VELOCITY, velocity=core.move_speed_velocity(cmd), position_controlled=False,
                      acceleration=acc, deceleration=dec, jerk=abs(cmd.value("I407")),
                      extra={"command": n, "hold_zero": True})
    elif n in C.STOPPING:
        job = Job(JobKind.HALT, extra={"command": n}, **_dynamics(cmd, "I406", "I406"))
        if n == C.STOP:
            core.stop_lock = True
    elif n == C.HOME:
        method = ax.referencing.method()
        if method is not None and method.feature is Feature.SET_REFERENCE:
            job = Job(JobKind.HOME_DIRECT, position=ax.eff["I34"], mode=0, extra={"command": n})
            cmd.job = job
            ax.home_direct(job)
            return
        job = Job(JobKind.HOME_ACTIVE, position=ax.eff["I34"], mode=3, extra={"command": n})
    if job is not None:
        job.owner = core
        cmd.job = job
        ax.submit(job, mode)
        return
    core.cyclic.begin(cmd, t)


__all__ = ["absolute_target", "denial", "limit_flags", "relative_base", "start"]
