"""The set values of the commands that bypass the profile generator's job: MC_CyclicSpeed, MC_CyclicPosition
and MC_TorqueControl (Pilz V6.5 §1.8, §1.10, §1.11), and the cyclic takeover of MC_MoveVelocity (I424) and
MC_MoveSpeed (I119).

The controller's cycle A291 is the application cycle of the program that writes the register.  The fine
interpolator interpolates cyclic set positions linearly over A291; a set value counts as missing when the
program has not written it within A291, and is then extrapolated from the last one for at most I423, after
which the command is cancelled (event 78 cause 3).  Set values towards an actuated limit switch or in a
direction the permitted direction I04 forbids become zero (I193, and I192 for positions).

MC_TorqueControl: the simulated drive closes a speed loop, not a current loop, so the torque acts on a rigid
load model of the family (``Drive.Inertia``, ``Drive.Friction``): acceleration = (torque - friction x
velocity) / inertia, the velocity never above I10 (§1.10.5), the torque ramped with I430/I431 and limited to
E65/E66 (I194).
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ...kernel.jobs import Job
from ...kernel.profiles import Profile, Segment
from . import command as C
from .causes import Cause

if TYPE_CHECKING:  # pragma: no cover
    from .core import MotionCore

_EPS = 1e-12


class CyclicSetValues:
    """The interpolator of the cyclic commands of one axis (``core.cyclic``)."""

    def __init__(self, core: "MotionCore"):
        self.core = core
        self.running = False

    # --- shared rules --------------------------------------------------------------------------------------
    def permitted(self, value: float) -> tuple[float, bool]:
        """``value`` with the direction rules: (value or 0, whether I04 forbade it).  A set value towards an
        actuated limit switch is 0 as well (§1.8.3)."""
        if value == 0.0:
            return 0.0, False
        ax = self.core.axis
        i04 = ax.eff["I04"]
        if (i04 == 1 and value < 0) or (i04 == 2 and value > 0):
            return 0.0, True
        approached = ax.limit_switches.approached
        if (value > 0 and approached["max"]) or (value < 0 and approached["min"]):
            return 0.0, False
        return value, False

    def _timed_out(self, name: str, t: float) -> bool:
        ax = self.core.axis
        return t - self.core.registers.written_at(name) > ax.ctl.app_cycle + ax.eff["I423"] + 1e-9

    def _segment(self, t: float, v: float, a: float = 0.0) -> None:
        ax = self.core.axis
        p = ax._state_now()[0]
        ax._start_profile(Profile([Segment(t, p, v, a, 0.0)], t))

    # --- start / end --------------------------------------------------------------------------------------
    def begin(self, cmd: C.Command, t: float) -> None:
        """The command takes the axis over at once (§1.8 info box): whatever ran ends."""
        ax = self.core.axis
        ax._abort_all(t)
        ax.queue.abort_all()
        ax._stop_positioning_monitor()
        ax._set_position_control(cmd.number == C.CYCLIC_POSITION)
        p, v, _a = ax._state_now()
        cmd.cyclic.update(v=v, p=p, torque=0.0, last=None)
        self.running = True
        ax._interpolating = True

    def end(self) -> None:
        self.running = False

    def _cancel(self, cmd: C.Command, cause: Cause, t: float) -> None:
        cmd.cancelled = cause
        self.core.quick_stop(t)

    # --- every cycle ------------------------------------------------------------------------------------------
    def cycle(self, cmd: C.Command, t: float) -> None:
        if not self.running or cmd.cancelled is not None:
            return
        if not self.core.ready():
            self.end()
            return
        if cmd.number == C.CYCLIC_SPEED:
            self._speed(cmd, t)
        elif cmd.number == C.CYCLIC_POSITION:
            self._position(cmd, t)
        else:
            self._torque(cmd, t)

    def _speed(self, cmd: C.Command, t: float) -> None:
        ax = self.core.axis
        regs = self.core.registers
        takeover = ax.eff["I119"] == 0
        if takeover and self._timed_out("I426", t) and t > cmd.t0:
            self._cancel(cmd, Cause.CYCLIC_TIMEOUT, t)
            return
        raw = regs.I426 if takeover else cmd.value("I426")
        v, blocked = self.permitted(raw)
        self.core.status.I193 = blocked
        v = math.copysign(min(abs(v), ax.eff["I10"]), v)
        x = cmd.cyclic
        if x.get("set") != v:
            x["set"] = v
            self._segment(t, v)

    def _position(self, cmd: C.Command, t: float) -> None:
        ax = self.core.axis
        regs = self.core.registers
        e = ax.eff
        x = cmd.cyclic
        written = regs.written_at("I421")
        if x["last"] is None:
            x["last"] = written
        if self._timed_out("I421", t) and t > cmd.t0:
            self._cancel(cmd, Cause.CYCLIC_TIMEOUT, t)
            return
        if written == x.get("taken"):
            return                                   # extrapolating: the last segment goes on
        x["taken"] = written
        value = regs.I421
        p = ax._state_now()[0]
        if e["I00"] == 1:
            if not 0.0 <= value < e["I01"]:
                self._cancel(cmd, Cause.CYCLIC_POSITION_RANGE, t)
                return
            length = e["I01"]
            delta = math.fmod(value - p, length)     # whole turns counted internally (§1.11.1)
            if delta > length / 2:
                delta -= length
            elif delta < -length / 2:
                delta += length
            goal = p + delta
        else:
            goal = value
        v = (goal - p) / ax.ctl.app_cycle           # linear over A291
        v_ok, blocked = self.permitted(v)
        self.core.status.I192 = self.core.status.I193 = blocked
        v = math.copysign(min(abs(v_ok), e["I10"]), v_ok)
        self._segment(t, v)

    def _torque(self, cmd: C.Command, t: float) -> None:
        ax = self.core.axis
        regs = self.core.registers
        e = ax.eff
        x = cmd.cyclic
        dt = ax.ctl.servo_cycle
        wanted = regs.I428
        now = x["torque"]
        ramp = regs.I430 if abs(wanted) > abs(now) else regs.I431
        if ramp > 0.0:
            step = ramp * dt
            wanted = min(max(wanted, now - step), now + step)
        limited = min(max(wanted, -e["E66"]), e["E65"])
        self.core.status.I194 = limited != wanted
        torque, blocked = self.permitted(limited)
        x["torque"] = limited
        self.core.status.E02 = torque
        p, v, _a = ax._state_now()
        if torque == 0.0 and (blocked or limited != 0.0):
            # a set value that is ignored: the speed loop brings the axis to a standstill (§1.10.5)
            acc = -math.copysign(min(e["I11"], abs(v) / dt), v) if abs(v) > _EPS else 0.0
        else:
            acc = (torque - e["Drive.Friction"] * v) / self.load_inertia()
        v_next = v + acc * dt
        if abs(v_next) > e["I10"]:                   # the velocity never exceeds I10
            v_next = math.copysign(e["I10"], v_next)
            acc = (v_next - v) / dt
        if self._beyond_sw_limit(p + v * dt + acc * dt * dt / 2, v_next):
            self._cancel(cmd, Cause.SW_LIMIT_REACHED, t)
            return
        ax._start_profile(Profile([Segment(t, p, v, acc, 0.0), Segment(t + dt, p + v * dt + acc * dt * dt / 2,
                                                                      v_next, 0.0, 0.0)], t + dt))

    def _beyond_sw_limit(self, p_next: float, v_next: float) -> bool:
        """Whether the quick stop (I11) from the next cycle's state would end beyond an active software limit
        switch.  The torque has no target the planner could guard, so the check runs on every cycle: cancelling
        one cycle early brakes from a state whose stopping point was still inside (docs/pilz/decisions.md, Commands)."""
        ax = self.core.axis
        lim = ax.config.software_limits
        if not lim.enabled or not ax.homed:
            return False
        dec = ax.eff["I11"]
        # without position control the drive's speed loop lags the ramp by its time constant (and one cycle)
        lag = abs(v_next) * (ax.config.drive.plant.speed_time_constant + ax.ctl.servo_cycle)
        reach = p_next + math.copysign(v_next * v_next / (2.0 * dec) + lag if dec > 0.0 else lag, v_next)
        return reach > lim.maximum or reach < lim.minimum

    def load_inertia(self) -> float:
        """Torque per unit/s² of load acceleration: ``Drive.Inertia``, or when unset the inertia the simulated
        drive's speed loop works against (motor and load at the shaft, ``Plant.Inertia`` [kg m²], times the
        motor's angular acceleration per unit/s², 2 pi / ``Drive.FeedPerRevolution``) - so the set torque E02
        and the torque the drive reports (``axis.drive.torque``) are the same quantity."""
        ax = self.core.axis
        inertia = ax.eff["Drive.Inertia"]
        if inertia is not None:
            return inertia
        spec = ax.config.drive
        return spec.plant.inertia * 2.0 * math.pi / spec.length_per_revolution

    # --- cyclic takeover of the profile commands -------------------------------------------------------------
    def follow_move_speed(self, cmd: C.Command, job: Job) -> None:
        """MC_MoveSpeed with I119 = 0: a new set velocity or cyclic acceleration is taken at once (§1.9.1)."""
        core = self.core
        v = core.move_speed_velocity(cmd)
        acc, dec = core.move_speed_dynamics(cmd)
        if (v, acc, dec) != (job.velocity, job.acceleration, job.deceleration):
            job.velocity, job.acceleration, job.deceleration = v, acc, dec
            self._replan(job)

    def follow_move_velocity(self, cmd: C.Command, job: Job) -> None:
        """MC_MoveVelocity with I424 = 1: the set velocity I404 is taken every cycle; the command's own
        acceleration, deceleration and jerk are ignored (§1.5.1) - the maxima I11 / I16 apply."""
        e = self.core.axis.eff
        v = self.core.registers.I404
        if v != job.velocity:
            job.velocity = v
            job.acceleration = job.deceleration = e["I11"]
            job.jerk = e["I16"]
            self._replan(job)

    def _replan(self, job: Job) -> None:
        ax = self.core.axis
        if job is ax.job and job.busy:
            job.in_velocity = False
            ax._plan_job(job, ax.now)


__all__ = ["CyclicSetValues"]
