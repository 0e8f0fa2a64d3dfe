"""The motion core of a Pilz drive axis: the command register evaluated every motion-core cycle A150.

Pilz V6.5 §1: a command is selected in I401 and started by a rising edge of Execute I402; its set values are
latched at that edge (the cyclic ones are read every cycle, ``cyclic.py``).  At every start the status of the
previous command goes and I91/I90/I92 stay 0 for at least one cycle A150 - also when the command is denied at
once or its end condition already holds (the handshake of the status tables).  This module keeps that
sequence and computes the status words; ``starts.py`` holds the denial rules and the hand-over to the kernel.

The motion-core cycle A150 is the controller's servo cycle: the core runs in the servo cycle's input stage of
its axis (before the axis's events and the interpolation), sees the register as the program left it in the
last application cycle and the actual values of this cycle.
"""
from __future__ import annotations

import math
from typing import Any

from ...kernel import faults as F
from ...kernel.jobs import JobKind, JobState
from . import command as C
from . import registers as R
from . import starts
from .brake import Brake
from .causes import Cause
from .cyclic import CyclicSetValues

_EPS = 1e-9

#: kernel fault kind -> the cause the motion core reports for a cancelled or refused command
_FAULT_CAUSE = {F.HW_LIMIT_MIN: Cause.LIMIT_SWITCH_FAULT, F.HW_LIMIT_MAX: Cause.LIMIT_SWITCH_FAULT,
                F.HW_LIMIT_FREE: Cause.HW_LIMIT, F.SW_LIMIT_MIN: Cause.SW_LIMIT_REACHED,
                F.SW_LIMIT_MAX: Cause.SW_LIMIT_REACHED, F.NOT_HOMED: Cause.NOT_REFERENCED,
                F.NOT_ENABLED: Cause.NOT_READY, F.PENDING_ALARM: Cause.NOT_READY,
                F.DIRECTION: Cause.DIRECTION_BLOCKED, F.REFERENCE_NOT_FOUND: Cause.REFERENCE_NOT_FOUND,
                F.QUEUE_FULL: Cause.BUFFER_FULL}


def cause_of(fault: Any) -> Cause:
    return _FAULT_CAUSE.get(getattr(fault, "kind", None), Cause.DRIVE_FAULT)


class MotionCore:
    """Command register, status words and the per-cycle sequence of one axis (``axis.core``)."""

    def __init__(self, axis: Any):
        self.axis = axis
        self.registers = R.CommandRegister(lambda: axis.ctl.time)
        self.status = R.StatusWords()
        self.cyclic = CyclicSetValues(self)
        self.brake = Brake(self)
        self.command: C.Command | None = None
        self.starts = 0                      # accepted rising edges of I402 (for the FB wrappers)
        self.set_position: float | None = None    # last valid set position (MC_MoveAdditive base, §1.4.6)
        self.stop_lock = False               # MC_Stop holds the axis until standstill and Execute = 0
        #: (application cycle, block) of the function block that wrote the register last (plcmotion.pilz)
        self.claimed: tuple[int, Any] | None = None
        self._execute = False
        self._override = 100.0
        self._enabled = False
        self._error_shown = False

    def reset(self) -> None:
        """The controller restarts (CPU STOP -> RUN, power cycle): the command register is written anew by the
        restarted program (start values), no command runs, the status words start from standstill."""
        self.registers = R.CommandRegister(lambda: self.axis.ctl.time)
        homed = self.status.I86
        self.status = R.StatusWords(I86=homed)
        self.cyclic.end()
        self.command = None
        self.set_position = None
        self.stop_lock = False
        self.claimed = None
        self._execute = False
        self._override = 100.0

    # --- helpers ----------------------------------------------------------------------------------------
    def actual_position(self) -> float:
        ax = self.axis
        return float(ax.ctl.bank.act_p[ax.index])

    def ready(self) -> bool:
        ax = self.axis
        return ax.state == "enabled" and not ax.alarms

    def at_standstill(self) -> bool:
        """Standstill for the denial rules of MC_Home, MC_Stop and MC_Halt: the core is in, or can go to,
        I89 = 2 (no motion left; an error stop at rest counts, its command has ended)."""
        s = self.status
        return self.ready() and not self._moving() and s.I89 in (R.STANDSTILL, R.ERROR_STOP)

    def _moving(self) -> bool:
        ax = self.axis
        job = ax.job
        p, v, a = ax._state_now()
        return abs(v) > _EPS or ax._interpolating and ax.profile.t_end > ax.ctl.time + _EPS or (
            job is not None and job.busy and job.kind != JobKind.HALT) or self.cyclic.running

    @property
    def execute_seen(self) -> bool:
        """I402 as the motion core sampled it in its last cycle (a new edge needs it low there first)."""
        return self._execute

    @property
    def override(self) -> float:
        """I230 as the profile commands use it [%] (negative values count as 0)."""
        return max(0.0, self.registers.live["I230"])

    def move_speed_velocity(self, cmd: C.Command) -> float:
        """MC_MoveSpeed set velocity: I426 with I04 (forbidden direction: 0) and the limit switches."""
        v = self.registers.I426 if self.axis.eff["I119"] == 0 else cmd.value("I426")
        v, blocked = self.cyclic.permitted(v)
        self.status.I193 = blocked or abs(v) * self.override / 100.0 > self.axis.eff["I10"]
        return v

    def move_speed_dynamics(self, cmd: C.Command) -> tuple[float, float]:
        """Cyclic acceleration / deceleration of MC_MoveSpeed: 0 keeps the last value (§1.9.2)."""
        e = self.axis.eff
        keep = cmd.cyclic
        src = self.registers if e["I119"] == 0 else None
        acc = abs(src.I216 if src else cmd.value("I216")) or keep.get("acc", e["I11"])
        dec = abs(src.I217 if src else cmd.value("I217")) or keep.get("dec", e["I11"])
        keep["acc"], keep["dec"] = acc, dec
        self.status.I195 = acc > e["I11"] or dec > e["I11"]
        return acc, dec

    # --- the cycle --------------------------------------------------------------------------------------
    def cycle(self, t: float) -> None:
        """One motion-core cycle A150 at time ``t``.

        Runs in every servo cycle of every axis, so it only looks at what can have changed: the edge of
        I402, the enable, a due brake, a new I230; the status words are computed from this cycle's values."""
        live = self.registers.live
        execute = live["I402"]
        edge = execute and not self._execute
        self._execute = execute
        enabled = self.axis.state == "enabled"
        if enabled is not self._enabled:
            self._watch_enable(t)
        if edge:
            self._start(t)
        if self.brake.due is not None:
            self.brake.cycle(t)
        cmd = self.command
        if cmd is not None:
            if cmd.waiting and not self._block_running():
                self._end_wait(cmd, t)
            driver = cmd.carrier if cmd.carrier is not None else cmd
            override = live["I230"]
            if (override if override > 0.0 else 0.0) != self._override:
                self._follow_override(driver)
            if driver.number in C.CYCLIC and driver.denied is None and not driver.waiting:
                self.cyclic.cycle(driver, t)
        self._update(t)

    def _end_wait(self, cmd: C.Command, t: float) -> None:
        """The block an MC_TorqueControl with I409 = 1 waited for has ended: it takes over - unless that block
        ended without success (as the kernel's buffered jobs, the follower goes with it) or the enable went."""
        job = cmd.carrier.job if cmd.carrier is not None else None
        cmd.waiting = False
        cmd.carrier = None
        if cmd.cancelled is not None:
            return
        if not self.ready() or (job is not None and job.state in (JobState.ERROR, JobState.ABORTED)):
            fault = job.fault if job is not None and job.state == JobState.ERROR else (
                self.axis.alarms[0] if self.axis.alarms else None)
            cmd.cancelled = Cause.ENABLE_OFF if self.axis.state != "enabled" else cause_of(fault)
            return
        cmd.t0 = t                              # its "second cycle after the start" counts from here
        cmd.state = R.CONTINUOUS
        self.cyclic.begin(cmd, t)

    def _block_running(self) -> bool:
        """A motion block of the job queue still runs or waits: what a command with I409 = 1 waits for.  A
        velocity job counts as ended once it is at its velocity, as for the kernel's buffered jobs."""
        ax = self.axis
        if ax.queue.pending:
            return True
        job = ax.job
        return job is not None and job.busy and not (job.kind == JobKind.VELOCITY and job.in_velocity)

    def _keeps_speed_reached(self, number: int, velocity: float) -> bool:
        """Fig. 14: I183 stays 1 when an MC_MoveVelocity follows one at speed with a lower set velocity (same
        direction) - the axis is at or above the new velocity while it slows down to it (decisions.md, E9)."""
        cmd = self.command
        if number != C.MOVE_VELOCITY or cmd is None or cmd.number != C.MOVE_VELOCITY or not self.status.I183:
            return False
        if cmd.denied is not None or cmd.cancelled is not None:
            return False
        act_v = self.axis.ctl.bank.act_v.item(self.axis.index)
        target = min(abs(velocity), self.axis.eff["I10"])
        return act_v * velocity > 0.0 and abs(act_v) >= target - self.axis.eff["C40"]

    def _watch_enable(self, t: float) -> None:
        enabled = self.axis.state == "enabled"
        if self._enabled and not enabled:
            self._enable_off(t)
        self._enabled = enabled

    def _enable_off(self, t: float) -> None:
        """The enable went off while a command ran: it is cancelled; MC_MoveAdditive's base is the set
        position only if the axis had reached the position window and stayed in it (§1.4.6)."""
        cmd = self.command
        if cmd is not None and cmd.number in C.POSITIONING:
            stayed = cmd.window_reached and self._in_window(cmd)
            if not stayed:
                self.set_position = None
        elif not (cmd is not None and cmd.number in C.STOPPING):
            self.set_position = None
        if cmd is not None and not cmd.done and cmd.denied is None and cmd.cancelled is None and (
                cmd.number not in C.STOPPING or not self.status.I199):
            cmd.cancelled = Cause.ENABLE_OFF
        self.cyclic.end()
        self.stop_lock = False
        self.brake.disabled()

    def _start(self, t: float) -> None:
        regs = self.registers
        number = regs.I401
        if number == C.DO_NOTHING:
            return                              # no status, no motion ID (§1.1)
        self.starts += 1
        s = self.status
        keep_i183 = self._keeps_speed_reached(number, regs.I404)
        s.clear_command()
        s.I183 = keep_i183
        s.I82 = regs.I400
        s.I80 = self.actual_position()
        cmd = C.Command(number, regs.values(), t)
        cmd.speed_reached = keep_i183
        previous = self.command
        self.command = cmd
        cyclic_running = self.cyclic.running
        if previous is not None and previous.number in C.CYCLIC:
            self.cyclic.end()
        cause = starts.denial(self, cmd)
        if cause is None and number in C.STOPPING:
            self.brake.on_start(cmd)
        if cause is None and number in C.STOPPING and 0.0 in (cmd.value("I406"), cmd.value("I407")):
            cmd.at_standstill = True            # §1.6.7: a denial at standstill is reported as Done
            cmd.state = R.STOPPING if number == C.STOP else R.DISCRETE
            if number == C.STOP:
                self.stop_lock = True
            return
        if cause is not None:
            cmd.denied = cause
            s.I183 = cmd.speed_reached = False  # Fig. 14 keeps I183 only for a command that runs
            if number in C.POSITIONING and cause is not Cause.STOP_ACTIVE and self._moving() and self.ready():
                self.quick_stop(t)              # §1.2.4, §1.3.4, §1.4.4: only the positionings stop the axis
            elif previous is not None:
                # the other commands' denials leave the running motion as it is (decisions.md, "Denial")
                cmd.carrier = previous.carrier if previous.denied is not None else previous
                self.cyclic.running = cyclic_running
            return
        if number == C.TORQUE_CONTROL and cmd.value("I409") == 1 and self._block_running():
            cmd.waiting = True                  # Tab. 31 I409 = 1: it starts at the end of the running block
            cmd.carrier = previous              # whose motion (and override) goes on until then
            cmd.state = s.I89 if s.I89 not in (R.ERROR_STOP, R.DISABLED) else R.CONTINUOUS
            return
        self.brake.on_start(cmd)
        starts.limit_flags(self, cmd)
        if number not in (C.STOP, C.HALT) and not (number in C.POSITIONING):
            self.set_position = None            # only positionings create a valid set position (§1.4.6)
        cmd.state = {C.MOVE_ABSOLUTE: R.DISCRETE, C.MOVE_RELATIVE: R.DISCRETE, C.MOVE_ADDITIVE: R.DISCRETE,
                     C.HALT: R.DISCRETE, C.MOVE_VELOCITY: R.CONTINUOUS, C.MOVE_SPEED: R.CONTINUOUS,
                     C.TORQUE_CONTROL: R.CONTINUOUS, C.STOP: R.STOPPING, C.HOME: R.HOMING,
                     C.CYCLIC_SPEED: R.CYCLIC, C.CYCLIC_POSITION: R.CYCLIC}[number]
        starts.start(self, cmd, t)
        job = cmd.job
        if number == C.HOME and job is not None and job.kind == JobKind.HOME_DIRECT:
            cmd.state = s.I89 if s.I89 not in (R.ERROR_STOP, R.DISABLED) else R.STANDSTILL
        if number in C.POSITIONING and job is not None and job.state == JobState.BUSY and not job.pending:
            self.set_position = job.target

    def quick_stop(self, t: float) -> None:
        """Stop the motion at once (a denied positioning while moving, §1.2.4; a cancellation): I11 without
        jerk limit."""
        ax = self.axis
        ax._abort_all(t)
        ax.queue.abort_all()
        self.cyclic.end()
        p, v, a = ax._state_now()
        plan = ax.motion.stop(t, p, v, a, emergency=True, jerk=False)
        ax._interpolating = True
        ax._start_profile(plan.profile, plan)

    def _follow_override(self, cmd: C.Command) -> None:
        """I230 is read every cycle; a change re-plans the running profile command (§1.2.5)."""
        override = self.override
        if override == self._override:
            return
        self._override = override
        job = cmd.job
        ax = self.axis
        if cmd.number in C.OVERRIDDEN and job is not None and job.busy and job is ax.job:
            if job.kind == JobKind.VELOCITY:
                job.in_velocity = False
                ax._plan_job(job, ax.now, new_command=False)     # a cruising velocity job plans anew
            else:
                ax._replan()
        if cmd.number in C.POSITIONING or cmd.number == C.MOVE_VELOCITY:
            v = abs(cmd.value("I404"))
            self.status.I193 = v <= self.axis.eff["I10"] < v * override / 100.0

    # --- status ------------------------------------------------------------------------------------------
    def _in_window(self, cmd: C.Command) -> bool:
        job = cmd.job
        if job is None or job.pending:
            return False
        return abs(self.actual_position() - job.target) <= self.axis.eff["I22"] + _EPS

    def _update(self, t: float) -> None:
        ax = self.axis
        s = self.status
        b, i = ax.ctl.bank, ax.index
        prof = ax.profile
        follow = b.follow_act.item(i)
        if t >= prof.t_end - _EPS and not follow:
            p, v, _a = prof.segments[-1].at(t)    # the profile's end state, without rounding of the segment before
        else:
            p, v, _a = prof.at(t)                 # the setpoint now (t is the controller's time)
            if follow:
                p = b.act_p.item(i)
        act_v = b.act_v.item(i)
        s.I86 = bool(ax.homed)
        s.I88 = act_v
        s.I96 = p
        s.E07 = v
        e = ax.parameters.effective
        s.I199 = abs(v) <= _EPS and abs(act_v) <= e["C40"]
        cmd = self.command
        if self.stop_lock and s.I199 and not self.registers.live["I402"] and not self._moving():
            self.stop_lock = False
        if cmd is None:
            s.I89 = self._rest_state()
            s.I83 = R.I83_IDLE
            return
        if t <= cmd.t0 + _EPS:                     # the handshake cycle: I91/I90/I92 stay 0
            s.I89 = self._rest_state() if cmd.denied is not None or cmd.at_standstill else cmd.state
            s.I83 = R.I83_ACTIVE
            return
        if cmd.denied is not None or cmd.cancelled is not None:
            self._show_error(cmd.denied if cmd.denied is not None else cmd.cancelled)
            return
        job = cmd.job
        if job is not None and job.state == JobState.ERROR and cmd.number != C.TORQUE_CONTROL:
            cmd.cancelled = cause_of(job.fault)
            self._show_error(cmd.cancelled)
            return
        if job is not None and job.state == JobState.ABORTED and cmd.number != C.TORQUE_CONTROL:
            # no later command took over, yet its job ended: the enable went off or a fault stopped the axis
            cmd.cancelled = Cause.ENABLE_OFF if ax.state != "enabled" else cause_of(ax.alarms[0] if ax.alarms
                                                                                    else None)
            self._show_error(cmd.cancelled)
            return
        if ax.state != "enabled":
            s.I89 = R.DISABLED
            return
        if ax.alarms and cmd.number in C.CYCLIC and cmd.number != C.TORQUE_CONTROL:
            cmd.cancelled = cause_of(ax.alarms[0])
            self._show_error(cmd.cancelled)
            return
        n = cmd.number
        if n in C.POSITIONING:
            self._positioning(cmd, t, p, v, act_v, b.act_p.item(i), e)
        elif n in C.VELOCITY:
            self._velocity(cmd, t, v, act_v)
        elif n in C.STOPPING:
            self._stopping(cmd, v, act_v)
        elif n == C.HOME:
            self._home(cmd)
        else:
            self._cyclic_status(cmd, t)
        if s.I92:
            self.brake.on_done(cmd, t)
        if job is not None and job.pending or cmd.waiting:
            s.I83 = R.I83_ACTIVE_WITH_FOLLOWER     # a block runs, this one waits behind it
        else:
            s.I83 = R.I83_DONE if s.I92 else R.I83_ACTIVE

    def _rest_state(self) -> int:
        ax = self.axis
        if ax.state != "enabled":
            return R.DISABLED
        if ax.alarms:
            return R.ERROR_STOP
        return R.STANDSTILL

    def _show_error(self, cause: Cause) -> None:
        s = self.status
        s.I91 = True
        s.I90 = int(cause)
        s.I92 = False
        s.I89 = R.ERROR_STOP if self.axis.state == "enabled" else R.DISABLED
        s.I83 = R.I83_ERROR

    def _positioning(self, cmd: C.Command, t: float, p: float, v: float, act_v: float, act_p: float,
                     e: Any) -> None:
        s = self.status
        ax = self.axis
        job = cmd.job
        if job is None or job.pending or job.state == JobState.ABORTED:
            s.I89 = cmd.state if job is not None and job.pending else s.I89
            return
        target = job.target
        self.set_position = target
        end_v = job.extra.get("end_velocity", 0.0)
        finished = ax.profile.t_end <= t + _EPS and (job is not ax.job or not ax._interpolating or bool(end_v))
        # with an end velocity the profile ends where it passes the target (decisions.md, E15)
        s.I85 = finished and (bool(end_v) or abs(p - target) <= 1e-6 * max(1.0, abs(target)))
        inside = abs(act_p - target) <= e["I22"] + _EPS         # the window I22 around the target
        s.I180 = inside
        if inside:
            cmd.window_reached = True
            if cmd.window_since is None:
                cmd.window_since = t
        else:
            cmd.window_since = None
        commanded = abs(job.velocity) * self._override / 100.0
        limit = e["I10"]
        if commanded > limit:
            commanded = limit
        if commanded > 0 and abs(v) >= commanded * (1 - 1e-9):
            cmd.speed_reached = True
        s.I183 = (cmd.speed_reached and abs(abs(v) - commanded) <= 1e-9 * max(1.0, commanded)
                  and abs(act_v - math.copysign(commanded, v)) <= e["C40"])
        if end_v and s.I85:
            cmd.done = True
        elif s.I85 and inside and cmd.window_since is not None and t - cmd.window_since >= e["I87"] - _EPS:
            cmd.done = True
        s.I92 = cmd.done
        s.I89 = R.STANDSTILL if (s.I85 and abs(v) <= _EPS) else cmd.state

    def _velocity(self, cmd: C.Command, t: float, v: float, act_v: float) -> None:
        s = self.status
        ax = self.axis
        job = cmd.job
        s.I89 = cmd.state
        if job is None or job.pending or not job.busy:
            return
        if cmd.number == C.MOVE_SPEED and ax.eff["I119"] == 0:
            self.cyclic.follow_move_speed(cmd, job)
        elif cmd.number == C.MOVE_VELOCITY and cmd.value("I424") == 1:
            self.cyclic.follow_move_velocity(cmd, job)
        e = ax.eff
        # Tab. 15 / Tab. 29: E07 = I404 (I426) - the set velocity itself, not as the override I230 scales it
        # (decisions.md "Override"); I10 caps it (§1.5.5)
        target = math.copysign(min(abs(job.velocity), e["I10"]), job.velocity)
        s.I85 = ax.profile.t_end <= t + _EPS and abs(v - target) <= 1e-9 * max(1.0, abs(target))
        near = abs(act_v - target) <= e["C40"]
        if cmd.speed_reached and not s.I85:
            # Fig. 14: kept from the previous command while the axis slows down to the lower velocity
            cmd.speed_reached = abs(act_v) >= abs(target) - e["C40"] and act_v * target > 0.0
            s.I183 = cmd.speed_reached
        else:
            cmd.speed_reached = False
            s.I183 = s.I85 and near
        # Done follows I85 and I183 (the command never ends by itself): an override or load that takes the
        # axis off the set velocity takes Done away until it is back (Tab. 15)
        cmd.done = s.I85 and s.I183
        s.I92 = cmd.done

    def _stopping(self, cmd: C.Command, v: float, act_v: float) -> None:
        s = self.status
        ax = self.axis
        window = ax.eff["C40"]
        s.I183 = abs(act_v) <= window
        job = cmd.job
        planned_out = cmd.at_standstill or (
            job is not None and (not job.busy or ax.profile.t_end <= ax.ctl.time + _EPS))
        s.I85 = planned_out and abs(v) <= _EPS
        if s.I85 and s.I199:
            cmd.done = True
        s.I92 = cmd.done
        held = self.registers.I402 or not cmd.done
        if cmd.number == C.STOP:
            s.I89 = R.STOPPING if (self.stop_lock or held) else R.STANDSTILL
        else:
            s.I89 = R.DISCRETE if held else R.STANDSTILL

    def _home(self, cmd: C.Command) -> None:
        s = self.status
        job = cmd.job
        if job is None:
            return
        if job.state == JobState.DONE:
            cmd.done = True
            s.I89 = R.STANDSTILL if cmd.state == R.HOMING else cmd.state
        else:
            s.I89 = cmd.state
        s.I92 = cmd.done

    def _cyclic_status(self, cmd: C.Command, t: float) -> None:
        s = self.status
        s.I89 = cmd.state
        if cmd.waiting:
            s.I92 = False
            return
        # "state after the second cycle time A150 after command start" (§1.8.7, §1.10.7, §1.11.7)
        if t >= cmd.t0 + 2 * self.axis.ctl.servo_cycle - _EPS:
            cmd.done = True
        s.I92 = cmd.done


__all__ = ["MotionCore", "cause_of"]
