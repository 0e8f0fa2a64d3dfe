"""The inside of the simulated CiA 402 servo drive: power state machine, operation modes and motor
(no bus here; ``simulated.py`` puts it behind a CANopen node).

Units are those of the profile without a factor group: position [inc], velocity [inc/s], acceleration
[inc/s^2], torque [per mille of rated torque].  The motor is a closed speed loop modelled as a first-order
lag (time constant ``MotorSpec.speed_time_constant``) and integrated exactly over each SYNC period; the
speed is limited to 0x6080 (max motor speed, 1/min).  What feeds the speed loop depends on the mode
(CiA 402-2 mode descriptions):

* csp: the drive's position loop, ``v = (target - previous target) / T + Kp (target - actual)``: the
  drive interpolates between the targets that arrive once per SYNC;
* csv: the target velocity 0x60FF;
* cst: no speed loop - the target torque 0x6071 accelerates the motor (``MotorSpec.rated_acceleration``
  at 1000 per mille) against viscous friction;
* pp: the drive's own trapezoidal profile (0x6081 velocity, 0x6083/0x6084 acceleration/deceleration) to
  0x607A, started by the new-set-point handshake (controlword bit 4, statusword bit 12), absolute or
  relative (bit 6), at once (bit 5) or after the running one;
* pv: a ramp (0x6083/0x6084) to the target velocity;
* hm: the homing methods of ``homing.py`` (1-14 with the index pulse, 17-30 without, 33/34, 35/37) on the
  switches and index pulses of ``MotorSpec.plant``, at the speeds 0x6099:1/2 with the acceleration
  0x609A.  After homing the position reads the home offset 0x607C at the home position.  Statusword bits
  13/12/10 as CiA 402-2 defines them for homing mode: 0/0/1 not started or interrupted (halt), 0/0/0 in
  progress, 0/1/0 home found and stopping, 0/1/1 attained, 1/0/0 error while moving, 1/0/1 error at
  standstill.

Without "operation enabled" the drive ramps down with the quick stop deceleration 0x6085 (quick stop,
fault reaction, disable).  A fault (``inject_fault``, or following error beyond 0x6065 in csp) sends the
drive through FAULT REACTION ACTIVE to FAULT and queues an EMCY message.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from dataclasses import field
from typing import Callable

from . import profile as P
from .homing import HomingRun, SwitchPlant
from .profile import Mode, PowerStateMachine, State


@dataclass(frozen=True)
class MotorSpec:
    """The motor and mechanics of a simulated drive."""

    speed_time_constant: float = 0.002    #: closed speed loop as a first-order lag [s]
    position_gain: float = 100.0          #: the drive's position loop in csp, pp and homing [1/s]
    rated_acceleration: float = 500.0     #: motor acceleration at rated torque, no load [rev/s^2]
    friction: float = 2.0                 #: viscous friction [1/s]
    position_window: int = 200            #: pp: target reached within this distance [inc]
    velocity_window: int = 2000           #: pv: target reached / speed zero within this [inc/s]
    #: limit switches, home switch and index pulses of the machine (mechanical position [inc])
    plant: SwitchPlant = field(default_factory=SwitchPlant)
    initial_position: float = 0.0         #: where the motor is at power on [inc]


def _s32(x: float) -> int:
    """A position or velocity as INTEGER32 on the bus (wraps like a drive's counter)."""
    n = int(round(x)) & 0xFFFFFFFF
    return n - (1 << 32) if n & 0x80000000 else n


class DriveCore:
    """State and motion of one simulated drive; ``param(index, sub)`` reads its object dictionary."""

    def __init__(self, param: Callable[[int, int], int], motor: MotorSpec):
        self.param = param
        self.motor = motor
        self.sm = PowerStateMachine()
        self.x = float(motor.initial_position)   # motor position [inc], mechanical (no home offset)
        self.v = 0.0                              # [inc/s]
        self.acc = 0.0
        self.offset = 0.0                         # position actual = sign * x + offset (homing)
        self.mode = 0                             # mode of operation display
        self.cw = 0
        self.target_position = 0
        self.target_velocity = 0
        self.target_torque = 0
        self.torque = 0.0
        self._prev_target: float | None = None
        self.gp = self.x                          # profile generator position / velocity (mechanical)
        self.gv = 0.0
        self.goal: float | None = None            # pp: the running target (mechanical)
        self.pending_goal: float | None = None
        self.ack = False                          # pp: set-point acknowledge (statusword bit 12)
        self.home_phase = ""                      # "", "running", "stop", "done", "error", "interrupted"
        self.home_run: HomingRun | None = None
        self._x_before = self.x
        self.error_code = 0
        self.cause = False                        # a fault cause that a reset cannot clear
        self.emcy: list[tuple[int, int]] = []     # (code, error register) to send
        self._fault_request: tuple[int, bool] | None = None

    # --- helpers ---------------------------------------------------------------------------------------
    @property
    def sign(self) -> float:
        return -1.0 if self.param(0x607E, 0) & 0x80 else 1.0

    @property
    def vmax(self) -> float:
        inc = self.param(0x608F, 1) / max(self.param(0x608F, 2), 1)
        return self.param(0x6080, 0) * inc / 60.0

    def position_actual(self) -> int:
        return _s32(self.sign * self.x + self.offset)

    def velocity_actual(self) -> int:
        return _s32(self.sign * self.v)

    def torque_actual(self) -> int:
        return max(-32768, min(32767, int(round(self.sign * self.torque))))

    def digital_inputs(self) -> int:
        return self.motor.plant.digital_inputs(self.x)

    def _mech(self, user: float) -> float:
        return self.sign * (user - self.offset)

    # --- faults ------------------------------------------------------------------------------------------
    def inject_fault(self, code: int, cause: bool) -> None:
        """A fault with EMCY ``code`` at the next step; ``cause``: it stays until ``clear_cause``."""
        self._fault_request = (code, cause)

    def clear_cause(self) -> None:
        self.cause = False

    def _fault(self, code: int) -> None:
        if self.sm.state in (State.FAULT, State.FAULT_REACTION_ACTIVE):
            return
        self.sm.fault()
        self.error_code = code
        self.emcy.append((code, self.error_register))

    @property
    def error_register(self) -> int:
        """0x1001: bit 0 generic error, bit 1 current, bit 5 device profile specific (CiA 301)."""
        if not self.error_code:
            return 0
        return 0x01 | (0x02 if self.error_code & 0xF000 == 0x2000 else 0) | (0x20 if self.error_code >> 12 == 8 else 0)

    # --- controlword and set values ------------------------------------------------------------------
    def apply(self, cw: int, mode: int, target_position: int, target_velocity: int, target_torque: int) -> None:
        """The drive takes a controlword and the set values (at SYNC for synchronous RPDOs)."""
        before = self.sm.state
        rising = cw & ~self.cw
        self.cw = cw
        self.target_velocity, self.target_torque = target_velocity, target_torque
        if self.sm.command(cw, cause_present=self.cause) == 15:
            self.error_code = 0
            self.emcy.append((0, 0))              # EMCY "error reset / no error" (CiA 301)
        if mode != self.mode and mode in {m.value for m in Mode}:
            self.mode = mode
            self._prev_target = None
            self.gp, self.gv, self.goal, self.pending_goal = self.x, self.v, None, None
            self.home_phase = ""
        enabled = self.sm.state is State.OPERATION_ENABLED
        if enabled and before is not State.OPERATION_ENABLED:
            self.gp, self.gv, self.goal, self.pending_goal = self.x, self.v, None, None
            self._prev_target = None
        if self.mode == Mode.PROFILE_POSITION:
            if enabled and rising & P.CW_NEW_SETPOINT:
                base = self.goal if (cw & P.CW_RELATIVE and self.goal is not None) else None
                user = target_position + (self.sign * (base if base is not None else self.x) + self.offset
                                          if cw & P.CW_RELATIVE else 0)
                goal = self._mech(user)
                if cw & P.CW_CHANGE_IMMEDIATELY or self.goal is None:
                    self.goal, self.pending_goal = goal, None
                else:
                    self.pending_goal = goal
                self.ack = True
            if not cw & P.CW_NEW_SETPOINT:
                self.ack = False
        elif self.mode == Mode.HOMING and enabled and rising & P.CW_NEW_SETPOINT:
            self._start_homing()
        self.target_position = target_position

    # --- one SYNC period ---------------------------------------------------------------------------------
    def step(self, dt: float) -> None:
        """Move the motor over ``dt`` with the set values in force, then update states and monitoring."""
        if self._fault_request is not None:
            code, cause = self._fault_request
            self._fault_request = None
            self.cause = cause
            self._fault(code)
        m = self.motor
        st = self.sm.state
        vmax = self.vmax
        self._x_before = self.x
        if st is State.OPERATION_ENABLED and self.mode == Mode.CYCLIC_SYNC_TORQUE:
            limit = self.param(0x6072, 0)
            self.torque = self.sign * max(-limit, min(limit, self.target_torque))
            a = self.torque / 1000.0 * m.rated_acceleration * self._inc_per_rev()
            d = m.friction
            e = math.exp(-d * dt)
            v_inf = a / d
            v1 = v_inf + (self.v - v_inf) * e
            dx = v_inf * dt + (self.v - v_inf) * (1 - e) / d
            if abs(v1) > vmax:
                v1 = math.copysign(vmax, v1)
            self.x += dx
            self.acc, self.v = (v1 - self.v) / dt, v1
            return self._after_step(dt)
        if st is State.OPERATION_ENABLED and not (self.cw & P.CW_HALT and self.mode in (1, 3, 6)):
            ref = self._reference(dt)
        else:
            if self.mode == Mode.HOMING and self.home_phase == "running":
                self.home_phase = "interrupted"           # halt or leaving operation ends the homing run
            # halt, quick stop, fault reaction, disabled: ramp down (0x6084 for halt, else 0x6085)
            dec = self.param(0x6084 if st is State.OPERATION_ENABLED else 0x6085, 0) or 1.0
            self.gv = math.copysign(max(abs(self.gv if st is State.OPERATION_ENABLED else self.v) - dec * dt, 0.0),
                                    self.v)
            self.gp = self.x
            ref = self.gv
            if st is not State.OPERATION_ENABLED:
                self._move_direct(ref, dt)
                return self._after_step(dt)
        ref = max(-vmax, min(vmax, ref))
        tau = m.speed_time_constant
        v0 = self.v
        if tau > 0:
            e = math.exp(-dt / tau)
            v1 = ref + (v0 - ref) * e
            dx = ref * dt + (v0 - ref) * tau * (1 - e)
        else:
            v1, dx = ref, ref * dt
        self.x += dx
        self.acc, self.v = (v1 - v0) / dt, v1
        self._after_step(dt)

    def _move_direct(self, v1: float, dt: float) -> None:
        """Drive-side ramp without the speed loop lag (the drive's own ramp down)."""
        self.x += 0.5 * (self.v + v1) * dt
        self.acc, self.v = (v1 - self.v) / dt, v1

    def _inc_per_rev(self) -> float:
        return self.param(0x608F, 1) / max(self.param(0x608F, 2), 1)

    def _after_step(self, dt: float) -> None:
        m = self.motor
        rated = m.rated_acceleration * self._inc_per_rev()
        if self.mode != Mode.CYCLIC_SYNC_TORQUE or self.sm.state is not State.OPERATION_ENABLED:
            self.torque = 1000.0 * (self.acc + m.friction * self.v) / rated if rated else 0.0
        st = self.sm.state
        if self.mode == Mode.HOMING and self.home_run is not None:
            self._homing_moved()
        if st in (State.QUICK_STOP_ACTIVE, State.FAULT_REACTION_ACTIVE) and self.v == 0.0:
            self.sm.quick_stop_done()
            self.sm.reaction_done()
        if (st is State.OPERATION_ENABLED and self.mode == Mode.CYCLIC_SYNC_POSITION
                and self._prev_target is not None):
            window = self.param(0x6065, 0)
            if window != 0xFFFFFFFF and abs(self._mech(self.target_position) - self.x) > window:
                self._fault(P.EMCY_FOLLOWING_ERROR)

    def _reference(self, dt: float) -> float:
        """The speed loop's setpoint in operation enabled [inc/s, mechanical]."""
        kp = self.motor.position_gain
        mode = self.mode
        if mode == Mode.CYCLIC_SYNC_POSITION:
            target = self._mech(self.target_position)
            prev = self._prev_target if self._prev_target is not None else target
            self._prev_target = target
            return (target - prev) / dt + kp * (target - self.x)
        if mode == Mode.CYCLIC_SYNC_VELOCITY:
            return self.sign * self.target_velocity
        if mode == Mode.PROFILE_VELOCITY:
            self._ramp_to(self.sign * self.target_velocity, dt)
            return self.gv
        if mode == Mode.PROFILE_POSITION:
            self._profile(dt)
            return self.gv + kp * (self.gp - self.x)
        if mode == Mode.HOMING:
            return self._homing(dt)
        return 0.0

    def _ramp_to(self, v: float, dt: float) -> None:
        up = abs(v) > abs(self.gv) and v * self.gv >= 0
        lim = (self.param(0x6083, 0) if up else self.param(0x6084, 0)) * dt
        self.gv += max(-lim, min(lim, v - self.gv))

    def _profile(self, dt: float) -> None:
        """pp: the trapezoidal profile generator towards ``goal``."""
        if self.goal is None:
            return
        d = self.goal - self.gp
        dec = float(self.param(0x6084, 0)) or 1.0
        if abs(d) < 1e-9 and abs(self.gv) < 1e-9:
            self.gp, self.gv = self.goal, 0.0
            if self.pending_goal is not None:
                self.goal, self.pending_goal = self.pending_goal, None
            return
        v_des = math.copysign(min(float(self.param(0x6081, 0)), math.sqrt(2.0 * dec * abs(d))), d)
        self._ramp_to(v_des, dt)
        nxt = self.gp + self.gv * dt
        if (self.goal - nxt) * math.copysign(1.0, d) <= 0:      # would pass the goal: arrive
            self.gp, self.gv = self.goal, 0.0
        else:
            self.gp = nxt

    # --- homing -----------------------------------------------------------------------------------------
    def _start_homing(self) -> None:
        pitch = self.motor.plant.index_pitch or self._inc_per_rev()
        run = HomingRun(self.param(0x6098, 0), self.motor.plant, self.x, pitch, self.param(0x6099, 1),
                        self.param(0x6099, 2))
        self.home_run, self.home_phase = run, "running"
        self.gv = self.v
        self._x_before = self.x                   # 35/37 (home here) and refused methods end at once
        self._homing_moved()

    def _homing_moved(self) -> None:
        """After a SYNC period of homing: feed the motion to the run; set the home position once found."""
        run = self.home_run
        if self.home_phase == "running":
            run.moved(self._x_before, self.x)
            if run.error:
                self.home_phase = "error"
            elif run.home is not None:
                # the home position reads the home offset 0x607C from now on
                self.offset = self.param(0x607C, 0) - self.sign * run.home
                self.home_phase = "stop"
        if self.home_phase == "stop" and abs(self.v) < 1e-9 and abs(self.gv) < 1e-9:
            self.home_phase = "done"

    def _homing(self, dt: float) -> float:
        want = self.home_run.velocity() if self.home_phase == "running" and self.home_run else 0.0
        acc = float(self.param(0x609A, 0)) or 1.0
        lim = acc * dt
        self.gv += max(-lim, min(lim, want - self.gv))
        return self.gv

    # --- statusword -------------------------------------------------------------------------------------
    def statusword(self) -> int:
        st = self.sm.state
        sw = P.state_bits(st) | P.SW_REMOTE
        if st in (State.READY_TO_SWITCH_ON, State.SWITCHED_ON, State.OPERATION_ENABLED, State.QUICK_STOP_ACTIVE):
            sw |= P.SW_VOLTAGE_ENABLED
        if st is not State.OPERATION_ENABLED:
            return sw
        m = self.motor
        mode = self.mode
        halted = bool(self.cw & P.CW_HALT) and mode in (1, 3, 6)
        if mode in (Mode.CYCLIC_SYNC_POSITION, Mode.CYCLIC_SYNC_VELOCITY, Mode.CYCLIC_SYNC_TORQUE):
            sw |= P.SW_OMS12                     # the drive follows the target values
        elif mode == Mode.PROFILE_POSITION:
            if self.ack:
                sw |= P.SW_OMS12
            done = self.goal is None or (self.gp == self.goal and self.pending_goal is None
                                         and abs(self.x - self.goal) <= m.position_window)
            if (halted and abs(self.v) < m.velocity_window) or (not halted and done):
                sw |= P.SW_TARGET_REACHED
        elif mode == Mode.PROFILE_VELOCITY:
            target = 0.0 if halted else self.sign * self.target_velocity
            if abs(self.v - target) <= m.velocity_window:
                sw |= P.SW_TARGET_REACHED
            if abs(self.v) <= m.velocity_window:
                sw |= P.SW_OMS12
        elif mode == Mode.HOMING:
            phase = self.home_phase
            still = abs(self.v) < 1e-9
            if phase in ("", "interrupted", "done") or halted or (phase == "error" and still):
                sw |= P.SW_TARGET_REACHED
            if phase in ("stop", "done"):
                sw |= P.SW_OMS12
            if phase == "error":
                sw |= P.SW_OMS13
        return sw
